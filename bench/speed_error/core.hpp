// Speed against error (gyrores-bench): the shared vocabulary of the harness.
//
// A *case* is one (method, precision, pair). Its `timed` closure runs the computation alone
// (Google Benchmark times it); its `pilot` closure runs the same computation once more and
// converts what it computed into decimal text, outside the timed region, so that the error can
// be measured against the reference (reference.hpp). Everything is deterministic: fixed pairs,
// fixed amplitude v = 1, no randomness.
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/model/pair.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores::bench {

// A benchmark pair: its display name ("(10^12+1,10^12)"), size class and the pair itself.
struct bench_pair {
  std::string name;
  std::string group;  // "low", "mid", "huge"
  resonant_pair<big_int> p;

  bool fits64() const { return pair_fits_int64(p) && to_big(p.order()) < (big_int(1) << 62); }
  // The lattice method's integers fit in int128 (a b and a tau below 2^124, as lattice.hpp checks).
  bool fits_int128_lattice() const {
    if (!fits64()) return false;
    const unsigned la = unsigned(boost::multiprecision::msb(order())) + 1,
                   lb = unsigned(boost::multiprecision::msb(delta())) + 1,
                   lt = unsigned(boost::multiprecision::msb(p.tau())) + 1;
    return la + lb <= 124 && la + lt <= 124;
  }
  resonant_pair<std::int64_t> p64() const { return pair_cast<std::int64_t>(p); }
  big_int order() const { return to_big(p.order()); }
  big_int delta() const { return to_big(p.delta()); }
  bool small_x() const { return 2 * delta() < order(); }  // x = b/a < 1/2: the paper's lobe asymptotics apply
};

enum class real_kind { dbl, ldbl, f128, mp };

// A working precision. `digits`: decimal digits requested (mp), or the type's own for the
// fixed-precision types (used only for labels and the reference's margin).
struct precision {
  std::string name;  // double, long_double, float128, mp30, mp50, mp100, mp1000, mp10000
  real_kind kind;
  unsigned digits;
  bool is_mp() const { return kind == real_kind::mp; }
};

// What one run of a method produced, as decimal text.
struct outcome {
  std::optional<std::string> theta;  // theta_first, or theta_c when theta_is_c
  bool theta_is_c = false;           // the paper's lobe root theta_c (asymptotics)
  bool theta_any_minimiser = false;  // compare with the nearest reference minimiser (simulation)
  std::optional<std::string> r_res;
  std::optional<std::pair<std::string, std::string>> r_enclosure;  // certificates: [lo, hi]
  std::optional<std::uint64_t> evaluations;
  std::string note;
};

struct bench_case {
  std::string method, precision, pair;
  std::function<outcome()> pilot;
  std::function<void()> timed;
};

// One row of the report (and of the CSV).
struct measurement {
  std::string method, precision, pair;
  double median_ns = std::numeric_limits<double>::quiet_NaN();  // CPU time per call, median of repetitions
  std::vector<double> round_ns;  // CPU time per call in each repetition, in round order (runner.cpp)
  double digits_theta = std::numeric_limits<double>::quiet_NaN();
  double digits_r = std::numeric_limits<double>::quiet_NaN();
  std::optional<std::uint64_t> evaluations;
  int repetitions = 0;
  std::int64_t iterations = 0;  // calls per repetition
  std::string note;             // failures, enclosure checks, timing source
  bool failed = false;
  // Correct digits of the row: the smaller over the quantities it computes (NaN: none, e.g. one_eval).
  double digits() const {
    bool t = digits_theta == digits_theta, r = digits_r == digits_r;
    if (t && r) return digits_theta < digits_r ? digits_theta : digits_r;
    return t ? digits_theta : (r ? digits_r : std::numeric_limits<double>::quiet_NaN());
  }
};

struct skip_note {
  std::string method, precision, pair, reason;  // precision/pair "*" = every one
};

// A method of the harness: name, what it computes, when it is skipped (and why), and how a
// case is built. `skip` returns the reason, or an empty string to run the combination.
struct reference;
struct method_def {
  std::string name;
  std::string family;       // series of the plot
  std::string description;  // for the report
  std::function<std::string(const bench_pair&, const precision&)> skip;
  std::function<bench_case(const bench_pair&, const precision&, const reference&)> make;
};

// Which run: the full report or the quick check.
struct run_config {
  bool quick = false;
  unsigned reference_digits = 0;
  double rep_seconds = 0.05;  // target CPU time of one repetition
  int repetitions = 5;
};

// Decimal text of a real at its full precision (round-trip for the fixed types).
std::string real_text(double v);
std::string real_text(long double v);
std::string real_text(const float128& v);
std::string real_text(const mpfr_real& v);

}  // namespace gyrores::bench
