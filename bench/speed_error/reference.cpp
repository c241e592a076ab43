#include "reference.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <gyrores/inscribed/lattice.hpp>
#include "testing/high_precision_reference.hpp"  // src/testing/: the independent reference

namespace gyrores::bench {

namespace {

unsigned bit_length(const big_int& v) { return unsigned(boost::multiprecision::msb(v)) + 1u; }

std::string text_digits(const mpfr_real& v, unsigned digits) {
  return v.str(std::streamsize(digits), std::ios_base::scientific);
}

// The paper's lobe index: k = round(a/(2b)), the smaller one on a tie (a/(2b) = K + 1/2).
big_int paper_k(const big_int& a, const big_int& b) {
  big_int twob = 2 * b;
  big_int r = a % twob;
  if (r == b) return (a - b) / twob;
  return (a + b) / twob;  // floor((a + b)/(2b)) = round(a/(2b)), a, b > 0
}

// theta_c: the root of q' inside the lobe |a theta/2 - k pi| < pi/2 (see the header).
std::string lobe_root_reference(const bench_pair& bp, unsigned digits) {
  namespace hp = gyrores::test::hp;
  const big_int tau = bp.p.tau(), sigma = bp.p.sigma(), a = tau + sigma, b = tau - sigma;
  const big_int k = paper_k(a, b);
  const unsigned a_bits = bit_length(a);
  const big_int ilo = ((2 * k - 1) * tau) / a, ihi = ((2 * k + 1) * tau) / a;  // floors (k >= 1)
  const unsigned low_bits = 2 * a_bits + 160;
  big_int found = -1;
  int count = 0;
  for (big_int i = ilo; i <= ihi; ++i) {
    auto r = hp::detail::refine(tau, sigma, 0, i, a_bits, 64, low_bits);
    gyrores::scoped_digits d(gyrores::digits10_for_bits(low_bits));
    const mpfr_real pi = boost::math::constants::pi<mpfr_real>();
    const mpfr_real alpha = mpfr_real(a) * r.theta / 2 - mpfr_real(k) * pi;
    if (abs(alpha) < pi / 2) {
      found = i;
      ++count;
    }
  }
  if (count != 1)
    throw std::logic_error("reference: " + std::to_string(count) + " roots of q' in the paper's lobe of " + bp.name);
  const unsigned want_bits = unsigned(std::ceil(digits * 3.3219280948873623)) + 8;
  const unsigned full_bits = want_bits + 2 * a_bits + 96;
  auto r = hp::detail::refine(tau, sigma, 0, found, a_bits, want_bits, full_bits);
  gyrores::scoped_digits d(gyrores::digits10_for_bits(full_bits));
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
    // A guess to pick the fast half-periods; accurate to far below pi/tau.
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
    const mpfr_real pi = boost::math::constants::pi<mpfr_real>();
    ref.first_half_period = hp::detail::floor_to_int(h.theta_first * mpfr_real(tau) / pi);
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
