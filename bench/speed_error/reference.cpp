// speed_error/reference.hpp: the references (src/testing/high_precision_reference.hpp) as decimal
// text, and the error metric.
#include "reference.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <gyrores/theorem/lobes.hpp>
#include "pre_theorem.hpp"
#include "testing/high_precision_reference.hpp"  // src/testing/: the independent reference
#include "testing/test_support.hpp"

namespace gyrores::bench {

namespace {

unsigned bit_length(const big_int& v) { return unsigned(boost::multiprecision::msb(v)) + 1u; }

std::string text_digits(const mpfr_real& v, unsigned digits) {
  return v.str(std::streamsize(digits), std::ios_base::scientific);
}

// theta_c: the root of q' inside the paper's lobe |a theta/2 - k pi| < pi/2, k = round(a/(2b))
// (the smaller on a tie).
std::string lobe_root_reference(const bench_pair& bp, unsigned digits) {
  const big_int k = paper_fast_node(bp.order(), bp.delta()).k;
  const auto r = test::hp::hp_lobe_root(bp.p.tau(), bp.p.sigma(), k, digits);
  gyrores::scoped_digits d(gyrores::digits10_for_bits(r.bits));
  return text_digits(r.theta, digits + 10);
}

}  // namespace

reference compute_reference(const bench_pair& bp, unsigned digits) {
  namespace hp = gyrores::test::hp;
  auto t0 = std::chrono::steady_clock::now();
  reference ref;
  ref.digits = digits;
  const big_int tau = bp.p.tau(), sigma = bp.p.sigma(), a = tau + sigma;
  hp::hp_result h;
  if (a <= 100000) {
    h = hp::hp_reference(tau, sigma, digits);
  } else {
    // A guess to pick the fast half-periods, accurate to far below pi/tau: the reference lattice
    // (pre-theorem), not the theorem's path that the benchmark measures.
    mpfr_real guess;
    {
      gyrores::scoped_digits d(gyrores::digits10_for_bits(2 * bit_length(a) + 64));
      guess = gyrores::inscribed_lattice<mpfr_real>(bp.p, mpfr_real(1)).theta_first;
    }
    h = hp::hp_reference(tau, sigma, digits, guess, true);
  }
  ref.global = h.global;
  {
    gyrores::scoped_digits d(gyrores::digits10_for_bits(h.bits));
    ref.r_res = text_digits(h.r_res, digits + 10);
    ref.theta_first = text_digits(h.theta_first, digits + 10);
    for (const auto& m : h.minimisers) ref.minimisers.push_back(text_digits(m, digits + 10));
    ref.first_half_period = h.first_half_period;
  }
  if (bp.small_x()) ref.theta_c = lobe_root_reference(bp, digits);
  ref.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return ref;
}

double correct_digits(const std::string& value, const std::string& ref, unsigned ref_digits) {
  gyrores::scoped_digits d(ref_digits + 20);
  mpfr_real x, r;
  if (mpfr_set_str(x.backend().data(), value.c_str(), 10, MPFR_RNDN) != 0)
    throw std::invalid_argument("correct_digits: not a number: '" + value.substr(0, 40) + "'");
  if (mpfr_set_str(r.backend().data(), ref.c_str(), 10, MPFR_RNDN) != 0)
    throw std::invalid_argument("correct_digits: bad reference");
  if (!mpfr_number_p(x.backend().data())) return 0;
  const mpfr_real err = abs(x - r);
  if (err == 0) return double(ref_digits);
  const mpfr_real rel = r == 0 ? err : mpfr_real(err / abs(r));
  const double dg = -double(log10(rel));
  if (!(dg > 0)) return 0;
  return dg > double(ref_digits) ? double(ref_digits) : dg;
}

double correct_digits_nearest(const std::string& value, const std::vector<std::string>& refs, unsigned ref_digits) {
  double best = 0;
  for (const auto& r : refs) {
    double d = correct_digits(value, r, ref_digits);
    if (d > best) best = d;
  }
  return best;
}

void score(measurement& m, const outcome& o, const reference& ref) {
  if (o.theta) {
    if (o.theta_is_c)
      m.digits_theta = correct_digits(*o.theta, ref.theta_c, ref.digits);
    else if (o.theta_any_minimiser)
      m.digits_theta = correct_digits_nearest(*o.theta, ref.minimisers, ref.digits);
    else
      m.digits_theta = correct_digits(*o.theta, ref.theta_first, ref.digits);
  }
  if (o.r_res) m.digits_r = correct_digits(*o.r_res, ref.r_res, ref.digits);
  if (o.r_enclosure) {
    gyrores::scoped_digits d(ref.digits + 20);
    mpfr_real lo, hi, r;
    mpfr_set_str(lo.backend().data(), o.r_enclosure->first.c_str(), 10, MPFR_RNDD);
    mpfr_set_str(hi.backend().data(), o.r_enclosure->second.c_str(), 10, MPFR_RNDU);
    mpfr_set_str(r.backend().data(), ref.r_res.c_str(), 10, MPFR_RNDN);
    const bool inside = lo <= r && r <= hi;
    if (!inside) m.note += (m.note.empty() ? "" : "; ") + std::string("ENCLOSURE MISSES THE REFERENCE");
  }
  m.evaluations = o.evaluations;
  if (!o.note.empty()) m.note += (m.note.empty() ? "" : "; ") + o.note;
}

}  // namespace gyrores::bench
