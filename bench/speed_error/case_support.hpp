// Helpers to build cases: dispatch on the real type, scope the MPFR precision, keep the
// conversion to text out of the timed region.
#pragma once
#include <benchmark/benchmark.h>

#include <optional>
#include <string>

#include <gyrores/model/resonant.hpp>

#include "core.hpp"
#include "testing/test_support.hpp"  // src/testing/: precision_scope

namespace gyrores::bench {

template <class T> struct type_tag {
  using type = T;
};
template <class Tag> using real_of = typename Tag::type;

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

// A case with its labels and no closures yet.
inline bench_case new_case(const std::string& method, const precision& pr, const bench_pair& bp) {
  bench_case c;
  c.method = method;
  c.precision = pr.name;
  c.pair = bp.name;
  return c;
}

// compute(): the measured computation; convert(result): outcome (untimed). Both run inside
// the precision scope of `pr`.
template <class Compute, class Convert>
bench_case make_case(const std::string& method, const precision& pr, const bench_pair& bp, Compute compute,
                     Convert convert) {
  bench_case c = new_case(method, pr, bp);
  const bool mp = pr.is_mp();
  const unsigned d = pr.digits;
  c.timed = [=] {
    test::precision_scope s(mp, d);
    auto r = compute();
    benchmark::DoNotOptimize(r);
  };
  c.pilot = [=] {
    test::precision_scope s(mp, d);
    auto r = compute();
    return convert(r);
  };
  return c;
}

// make_case in the real type T of `pr`: compute(type_tag<T>) is measured, convert(result) makes
// the outcome (untimed; a generic lambda, it receives the result in T).
template <class Compute, class Convert>
bench_case typed_case(const std::string& method, const precision& pr, const bench_pair& bp, Compute compute,
                      Convert convert) {
  return dispatch_real(pr, [&](auto tag) {
    return make_case(method, pr, bp, [compute, tag] { return compute(tag); }, convert);
  });
}

}  // namespace gyrores::bench
