// What both independent checkers (certificate_checker.hpp, horizon_checker.hpp) read and decide
// with: their two verdicts' exceptions, FLINT integers and Arb balls that clean up after
// themselves, the strict readers of decimal fields and of JSON with no key twice, and the
// one-line verdict text. Like the checkers, nothing here includes include/gyrores/.
#pragma once
#include <arb.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>

#include <cstddef>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>

namespace gyrores_checker::support {

using nlohmann::json;

// The certificate cannot be read as its format says (verdict 2), or a claim is false (1).
struct malformed : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct fails : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The init, clear and set of each type that `owned` holds (overloads, so that the template's
// arguments stay types: the functions are static inline in FLINT's and Arb's headers).
inline void init(fmpz* x) { fmpz_init(x); }
inline void clear(fmpz* x) { fmpz_clear(x); }
inline void set(fmpz* x, const fmpz* y) { fmpz_set(x, y); }
inline void init(fmpq* x) { fmpq_init(x); }
inline void clear(fmpq* x) { fmpq_clear(x); }
inline void set(fmpq* x, const fmpq* y) { fmpq_set(x, y); }
inline void init(arb_ptr x) { arb_init(x); }
inline void clear(arb_ptr x) { arb_clear(x); }
inline void set(arb_ptr x, arb_srcptr y) { arb_set(x, y); }

// An Arb or FLINT value of type T (fmpz_t, fmpq_t, arb_t) that cleans up after itself.
template <class T>
struct owned {
  T v;
  owned() { init(v); }
  owned(const owned& o) {
    init(v);
    set(v, o.v);
  }
  owned& operator=(const owned& o) {
    set(v, o.v);
    return *this;
  }
  ~owned() { clear(v); }
};
struct Z : owned<fmpz_t> {
  Z() = default;
  explicit Z(long x) { fmpz_set_si(v, x); }
};
using B = owned<arb_t>;
using Q = owned<fmpq_t>;

// The decimal text of z, abbreviated past 60 digits (for messages).
std::string text_of(const Z& z);

// s[from..] is non-empty and all decimal digits.
bool all_digits(const std::string& s, std::size_t from);

// A decimal number -?digits(.digits)?(e[+-]?digits)? of at most max_len characters, else malformed.
std::string decimal_field(const json& j, const std::string& name, std::size_t max_len);

// A claim or bracket ["lo", "hi"] of two such decimals.
struct bracket {
  std::string lo, hi;
};
bracket bracket_field(const json& j, const std::string& name, std::size_t max_len);

// The exact value of a decimal read by decimal_field into out; false (out unchanged) when its
// decimal exponent lies beyond -max_exp10..max_exp10 (the caller's work bound).
bool decimal_exact(const std::string& decimal, long max_exp10, fmpq_t out);

// A claim [lo, hi] holds the enclosure and is at most 10^-digits wide relative to lo: 1 holds, 0
// undecided at prec; fails when false. For a value that is exactly 0, zero_rule is the message
// (after the name) when the claim is not [0, 0]; nullptr otherwise.
int claim_holds(const bracket& claim, const B& enclosure, long digits, const char* zero_rule, const std::string& name,
                long prec);

// The exact decimal as a ball (exact when its binary form fits prec bits, else a tight ball).
B ball_of(const std::string& decimal, long prec);

// json::parse, refusing an object with a key twice (nlohmann keeps the last: a certificate could
// otherwise show a reader one value and the checker another; docs/formats.md); malformed "not
// JSON: ..." for text that is not JSON.
json parse_without_duplicate_keys(const std::string& text);

// The verdict is one line: a field quoted in a message may hold a newline or another control
// character from the file (a JSON string may hold one), shown escaped instead.
std::string one_line(const std::string& s);

// A checker's verdict V from its body, or 2 "malformed: ..." and 1 "FAILS: ..." from what it
// throws (any other exception, e.g. an exponent beyond a long: malformed).
template <class V, class Body> V verdict_of(Body&& body) {
  try {
    return body();
  } catch (const malformed& e) {
    return {2, one_line(std::string("malformed: ") + e.what())};
  } catch (const fails& e) {
    return {1, one_line(std::string("FAILS: ") + e.what())};
  } catch (const std::exception& e) {
    return {2, one_line(std::string("malformed: ") + e.what())};
  }
}

// {0, holds(p)} at the first p = prec, 2 prec, ..., 16 prec where every inequality is decided.
template <class V, class Holds> V first_decided(long prec, Holds&& holds) {
  for (int round = 0; round < 5; ++round, prec *= 2)
    if (std::string text = holds(prec); !text.empty()) return {0, text};
  return {1, "FAILS: an inequality could not be decided at " + std::to_string(prec / 2) + " bits"};
}

// Malformed unless j is an object with exactly the fields `keys` (`where` names it in the message).
void exact_keys(const json& j, const std::set<std::string>& keys, const std::string& where);

// A JSON integer in [lo, hi] (0 <= hi), read exactly (no wrap: 2^64 - 1 is not -1), else malformed.
long integer_in(const json& j, const std::string& name, long lo, long hi);

// The lobe equations of the checkers, in balls (proofs/horizon-theorem.md, Notation):
// H(u) = x u + atan2(x sin u, cos u) for |u| < pi/2, and
// G(u) = (1 - x^2) x^2 sin^4 u/(cos^2 u + x^2 sin^2 u), R at a lobe minimiser (lattice-theorem.md Step C).
B lobe_H(const B& x, const B& u, long prec);
B lobe_G(const B& x2, const B& one_m_x2, const B& u, long prec);

}  // namespace gyrores_checker::support
