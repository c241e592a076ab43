// Fuzz target: the inputs of `gyrores coupling` (model/inputs.hpp, model/coupling.hpp), as
// src/cli/cmd_coupling.cpp parses them. The first byte picks the parser, the rest is its text:
//   0 horizon "100pi", "1e30", "5/2"      1 level "1%", "1e-3", "1/200"
//   2 band "N1:N2" (then check_band)      3 tolerance "N|P%" around n
//   4 coupling N (from_n)                 5 coupling --n2 (from_n2)
// Each either refuses with usage_error (one line naming the argument) or gives a value that
// satisfies its contract and whose exact text parses back to the same value; any other
// exception or a broken contract is a crash.
#include <gyrores/core/error.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/inputs.hpp>

#include "fuzz_support.hpp"

namespace {

using namespace gyrores;

void require(bool ok) {
  if (!ok) std::abort();
}

// A usage_error's message is one line that names the argument.
void named(const usage_error& e, const std::string& what) {
  const std::string m = e.what();
  require(m.find('\n') == std::string::npos && m.find(what) != std::string::npos);
}

void parse(unsigned which, const std::string& text) {
  switch (which) {
    case 0: {
      const horizon_time T = parse_horizon_time(text, "--horizon");
      require(T.value >= 0);
      const horizon_time back = parse_horizon_time(rational_str(T.value) + (T.times_pi ? "pi" : ""), "--horizon");
      require(back.value == T.value && back.times_pi == T.times_pi);
      return;
    }
    case 1: {
      const big_rational E = parse_energy_level(text, "--below");
      require(E >= 0 && parse_energy_level(rational_str(E), "--below") == E);
      return;
    }
    case 2: {
      const auto [n1, n2] = parse_band(text, "--band");
      check_band(n1, n2, "--band");
      require(n1 > 0 && n2 > n1);
      return;
    }
    case 3: {
      const auto parts = fuzz::split(text, "|", 2);
      if (parts.size() != 2) return;
      const big_rational n = parse_rational(parts[0], "N");
      const auto [n1, n2] = parse_tolerance_band(n, parts[1], "--tolerance");
      const big_rational an = n < 0 ? big_rational(-n) : n;
      // A band around |n| when n != 0 (the CLI refuses n = 0 as a coupling first).
      require(an == 0 ? n1 == 0 && n2 == 0 : 0 < n1 && n1 < an && an < n2);
      return;
    }
    default: {
      const big_rational q = parse_rational(text, which == 4 ? "N" : "--n2");
      const coupling_spec c = which == 4 ? coupling_spec::from_n(q) : coupling_spec::from_n2(q);
      require(c.n2 > 0 && c.n2 == (which == 4 ? big_rational(q * q) : q));
      require(parse_rational(rational_str(c.n2), "--n2") == c.n2);
      return;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 4096) return -1;
  const unsigned which = data[0] % 6;
  const std::string text(fuzz::as_text(data + 1, size - 1));
  static const char* const names[] = {"--horizon", "--below", "--band", "--tolerance", "N", "--n2"};
  try {
    parse(which, text);
  } catch (const usage_error& e) {
    // The band's ends are "--band N1" and "--band N2"; the tolerance input also parses its n ("N");
    // a coupling n = 0 or n^2 <= 0 is named as the coupling itself.
    const std::string m = e.what();
    if (m.rfind("n = 0", 0) == 0 || m.rfind("n^2", 0) == 0) return 0;
    named(e, which == 3 && m.find("--tolerance") == std::string::npos ? "N" : names[which]);
  }
  return 0;
}
