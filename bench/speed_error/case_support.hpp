// Helpers to build cases: dispatch on the real type, scope the MPFR precision, keep the
// conversion to text out of the timed region.
#pragma once
#include <benchmark/benchmark.h>

#include <optional>
#include <string>

#include "core.hpp"

namespace gyrores::bench {

template <class T> struct type_tag {
  using type = T;
};

// Calls fn(type_tag<T>{}) for the real type of `pr`.
template <class Fn> auto dispatch_real(const precision& pr, Fn&& fn) {
  switch (pr.kind) {
    case real_kind::dbl: return fn(type_tag<double>{});
    case real_kind::ldbl: return fn(type_tag<long double>{});
    case real_kind::f128: return fn(type_tag<float128>{});
    case real_kind::mp: break;
  }
  return fn(type_tag<mpfr_real>{});
}

// The MPFR default precision for the duration of one call (no-op for fixed types).
class precision_scope {
 public:
  precision_scope(bool mp, unsigned digits) {
    if (mp) s_.emplace(digits);
  }

 private:
  std::optional<scoped_digits> s_;
};

// compute(): the measured computation; convert(result): outcome (untimed). Both run inside
// the precision scope of `pr`.
template <class Compute, class Convert>
bench_case make_case(const std::string& method, const precision& pr, const bench_pair& bp, Compute compute,
                     Convert convert) {
  bench_case c;
  c.method = method;
  c.precision = pr.name;
  c.pair = bp.name;
  const bool mp = pr.is_mp();
  const unsigned d = pr.digits;
  c.timed = [=] {
    precision_scope s(mp, d);
    auto r = compute();
    benchmark::DoNotOptimize(r);
  };
  c.pilot = [=] {
    precision_scope s(mp, d);
    auto r = compute();
    return convert(r);
  };
  return c;
}

inline std::string join_reason(const std::string& a, const std::string& b) { return a.empty() ? b : a; }

}  // namespace gyrores::bench
