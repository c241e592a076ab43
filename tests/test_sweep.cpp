// Sweeps (sweep/, io/sweep_*.hpp): counts against independent counting, rows against known
// values and the independent high-precision reference (every working type), determinism across
// thread counts (MPFR rows too, whatever the process-wide precision), shards + merge = single
// run, resume after interruption (and refusal of states of earlier versions), atomic files.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gyrores/io/files.hpp>
#include <gyrores/app/sweep.hpp>
#include <gyrores/io/sweep_files.hpp>
#include <gyrores/io/sweep_summary.hpp>
#include <gyrores/io/sweep_values_file.hpp>
#include <gyrores/model/enumerate.hpp>
#include <gyrores/sweep/engine.hpp>
#include <gyrores/sweep/testing.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/minimum_series.hpp>
#include <gyrores/theorem/paper.hpp>
#include <gyrores/theorem/root.hpp>

#include "reference/lattice.hpp"  // pass_frame
#include "testing/cli_run.hpp"
#include "testing/high_precision_reference.hpp"
#include "sweep_summary_core.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using gyrores::test::path_exists;
using gyrores::test::read_text;
using gyrores::test::temp_dir;

namespace {

// The file without its last line (the end line carries the run time).
std::string without_last_line(const std::string& s) {
  if (s.empty()) return s;
  auto cut = s.rfind('\n', s.size() - 2);
  return cut == std::string::npos ? std::string() : s.substr(0, cut + 1);
}

json read_json(const std::string& p) { return json::parse(read_text(p)); }

// The names of the entries of a directory, sorted.
std::vector<std::string> file_names(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

sweep_config config(std::int64_t max_order, std::int64_t min_order = 3) {
  sweep_config c;
  c.max_order = max_order;
  c.min_order = min_order;
  return c;
}

sweep_engine_options engine(unsigned threads, std::size_t block = 7) {
  sweep_engine_options e;
  e.threads = threads;
  e.block_size = block;
  return e;
}

sweep_accumulator run_acc(const sweep_config& c, const sweep_engine_options& e) {
  sweep_accumulator acc;
  acc.max_examples = c.max_examples;
  auto out = sweep_run<double>(c, e, [&](sweep_block& b) { acc.merge(b.summary); });
  REQUIRE(out.complete);
  return acc;
}

std::int64_t phi(std::int64_t n) {
  std::int64_t r = 0;
  for (std::int64_t k = 1; k <= n; ++k) r += std::gcd(k, n) == 1;
  return r;
}

}  // namespace

TEST_CASE("sweep: check lists parse; unknown names are usage errors", "[sweep]") {
  CHECK(sweep_parse_checks("all") == sweep_all_checks);
  CHECK(sweep_parse_checks("default") == sweep_default_checks);
  CHECK(sweep_parse_checks("degeneracy,paper-node,asy-bound,structure") == sweep_default_checks);
  CHECK(sweep_default_checks == sweep_all_checks);
  CHECK(sweep_config{}.checks == sweep_default_checks);
  CHECK(sweep_parse_checks("degeneracy,asy-bound") == ((1u << 0) | (1u << 2)));
  // The check of sweep files before version 2 is named in the refusal (docs/formats.md).
  CHECK_THROWS_WITH(sweep_parse_checks("default,cross-check"), Catch::Contains("no longer part of sweeps"));
  CHECK_THROWS_AS(sweep_parse_checks("degeneracy,bogus"), usage_error);
  CHECK_THROWS_AS(sweep_parse_checks(""), usage_error);
  sweep_config c = config(2);
  CHECK_THROWS_AS(sweep_validate(c), usage_error);
  c = config(10, 11);
  CHECK_THROWS_AS(sweep_validate(c), usage_error);
  c = config(10);
  c.shard_index = 4;
  c.shard_count = 4;
  CHECK_THROWS_AS(sweep_validate(c), usage_error);
  // The library names its parameters, never a CLI flag.
  CHECK_THROWS_WITH(sweep_validate(config(2)), "max_order must be >= 3, got 2");
  CHECK_THROWS_WITH(sweep_validate(config(10, 11)), "min_order 11 exceeds max_order 10");
  CHECK(sweep_parse_format("jsonl") == sweep_format::jsonl);
  CHECK_THROWS_WITH(sweep_parse_format("xml"), "rows format must be csv or jsonl, got 'xml'");
}

TEST_CASE("sweep: CSV fields and JSON Lines text read back as written", "[sweep]") {
  const std::vector<std::string> written = {"plain", "a,b", "say \"hi\"", "", "1e-5"};
  std::string line;
  for (std::size_t i = 0; i < written.size(); ++i) {
    if (i) line += ',';
    csv_append_field(line, written[i]);
  }
  CHECK(line == "plain,\"a,b\",\"say \"\"hi\"\"\",,1e-5");
  CHECK(csv_split_line(line) == written);
  // A row whose note holds quotes, a backslash and a tab: valid JSON, and the same text back.
  sweep_row<double> r = sweep_evaluate<double>(resonant_pair<std::int64_t>(9, 4), config(30));
  r.note = "a \"note\" with \\ and \t";
  std::string out;
  sweep_format_row(out, r, sweep_format::jsonl, 17);
  REQUIRE(out.back() == '\n');
  const json j = json::parse(out);
  CHECK(j["note"] == r.note);
  CHECK(j["tau"] == 9);
  CHECK(j["check_paper_node"] == "fail");
  CHECK(j["t_first_over_proxy"] == sweep_double_text(r.t_ratio));
  out.clear();
  sweep_format_row(out, r, sweep_format::csv, 17);
  const auto fields = csv_split_line(out.substr(0, out.size() - 1));
  REQUIRE(fields.size() == sweep_row_columns().size());
  CHECK(fields.back() == r.note);
}

TEST_CASE("sweep: counts at order 60 agree with independent counting", "[sweep]") {
  const std::int64_t M = 60;
  std::uint64_t pairs = 0, degenerate = 0, small_x = 0, phi_sum = 0;
  for (std::int64_t tau = 2; tau < M; ++tau)
    for (std::int64_t sigma = 1; sigma < tau && tau + sigma <= M; ++sigma) {
      if (std::gcd(tau, sigma) != 1) continue;
      ++pairs;
      if ((tau - sigma) % 4 == 2) ++degenerate;
      if (2 * (tau - sigma) < tau + sigma) ++small_x;
    }
  for (std::int64_t a = 3; a <= M; ++a) phi_sum += std::uint64_t(phi(a) / 2);
  REQUIRE(pairs == phi_sum);
  CHECK(sweep_total_pairs(3, M) == pairs);
  CHECK(sweep_total_pairs(1, M) == pairs);

  sweep_config all = config(M);
  all.checks = sweep_all_checks;
  auto acc = run_acc(all, engine(2));
  CHECK(acc.pairs == pairs);
  CHECK(acc.degenerate == degenerate);
  CHECK(acc.errors.violations == 0);
  const auto nondeg = pairs - degenerate;
  CHECK(acc.checks[int(sweep_check::degeneracy)].checked == pairs);
  CHECK(acc.checks[int(sweep_check::degeneracy)].violations == 0);
  CHECK(acc.checks[int(sweep_check::structure)].checked == pairs);
  CHECK(acc.checks[int(sweep_check::structure)].violations == 0);
  CHECK(acc.checks[int(sweep_check::asy_bound)].checked == small_x);
  CHECK(acc.checks[int(sweep_check::asy_bound)].violations == 0);
  CHECK(acc.checks[int(sweep_check::paper_node)].checked == nondeg);
  CHECK(acc.t_ratios.size() == nondeg);

  // The examples are the first violating pairs in enumeration order (order, then sigma).
  const auto& ex = acc.checks[int(sweep_check::paper_node)].examples;
  CHECK(ex.size() == std::min<std::size_t>(5, acc.checks[int(sweep_check::paper_node)].violations));
  CHECK(std::is_sorted(ex.begin(), ex.end(), sweep_pair_before));

  // P7's worst case at b = 1 and the largest a: (30, 29); ratio -> 0.0049967 (asymptotic.hpp).
  REQUIRE(acc.asy_ratio_max.set);
  CHECK(acc.asy_ratio_max.pair == sweep_pair_id{30, 29});
  CHECK(acc.asy_ratio_max.value < 0.005);
  CHECK(acc.asy_ratio_max.value > 0.0049);
  CHECK(acc.sharp_constant.pair == sweep_pair_id{30, 29});
  CHECK(acc.sharp_constant.value == Approx(acc.asy_ratio_max.value * std::numbers::pi * std::numbers::pi * std::numbers::pi).epsilon(1e-12));

  // Quantiles: exact order statistics of the rows' t_first/proxy, sorted here.
  std::vector<double> ref;
  for (auto p : coprime_pairs(3, M))
    if (!p.degenerate()) ref.push_back(sweep_evaluate<double>(p, config(M)).t_ratio);
  std::sort(ref.begin(), ref.end());
  auto q = acc.quantiles();
  CHECK(q.count == ref.size());
  CHECK(q.min == ref.front());
  CHECK(q.max == ref.back());
  CHECK(q.median == ref[(ref.size() - 1) / 2]);
  CHECK(q.p10 == ref[(ref.size() - 1) / 10]);
}

TEST_CASE("sweep: per-pair rows for the paper's examples", "[sweep]") {
  sweep_config c = config(100);
  // (9,4): the global minimum is near 3 pi/5, not in the lobe of pi/5 (docs/mathematics.md §2, P5).
  auto r94 = sweep_evaluate<double>(resonant_pair<std::int64_t>(9, 4), c);
  REQUIRE_FALSE(r94.failed);
  CHECK(r94.status[int(sweep_check::paper_node)] == sweep_status::fail);
  CHECK(r94.first_at_paper_node == 0);
  CHECK(r94.minimiser_count == 2);
  CHECK(r94.t_ratio == Approx(3.0).epsilon(0.1));  // theta_first ~ 3 pi/5, b = 5
  // (6,5): the paper's lobe (a tie, b = 1) holds the minimum.
  auto r65 = sweep_evaluate<double>(resonant_pair<std::int64_t>(6, 5), c);
  CHECK(r65.status[int(sweep_check::paper_node)] == sweep_status::pass);
  CHECK(r65.status[int(sweep_check::asy_bound)] == sweep_status::pass);
  CHECK(r65.asy_error == Approx(1.16e-4).epsilon(0.01));  // printed in the paper (asymptotic.hpp)
  // (7,5): degenerate (delta = 2); R(pi/2) = 0, no paper-node verdict, ratio not collected.
  auto r75 = sweep_evaluate<double>(resonant_pair<std::int64_t>(7, 5), c);
  CHECK(r75.status[int(sweep_check::degeneracy)] == sweep_status::pass);
  CHECK(r75.status[int(sweep_check::paper_node)] == sweep_status::none);
  CHECK_FALSE(r75.has_ratio);
  CHECK(r75.r_res == 0);
  // delta = 0 mod 4: four minimisers.
  auto r51 = sweep_evaluate<double>(resonant_pair<std::int64_t>(5, 1), c);
  CHECK(r51.minimiser_count == 4);
  CHECK(r51.status[int(sweep_check::structure)] == sweep_status::pass);
  CHECK_FALSE(r51.has_asy);  // x = 2/3 >= 1/2
}

TEST_CASE("sweep: P3's r_res^2 <= R(pi/2) is decided by the enclosure within rounding of the threshold", "[sweep]") {
  // (9,4), (6,5), (5,1), (1000,999): delta odd and = 0 mod 4, small and large orders.
  for (auto [tau, sigma] : {std::pair<std::int64_t, std::int64_t>{9, 4}, {6, 5}, {5, 1}, {1000, 999}}) {
    const resonant_pair<std::int64_t> p(tau, sigma);
    const std::int64_t a = std::int64_t(p.order());
    const int128 N = sweep_quarter_R_scaled(a, p.delta());
    const double R = double(N) / (4 * double(a) * double(a));
    const auto r = sweep_evaluate<double>(p, config(a));
    REQUIRE(r.r_res > 0);
    CHECK(sweep_testing::r_below_quarter_R(p, r.r_res, N));
    // An r_res a rounding above sqrt(R(pi/2)): the double comparison says no, but the true
    // r_res (which the enclosure proves) is below: the decision must not follow the rounding.
    const double above = std::sqrt(R) * (1 + 0x1p-44);
    REQUIRE(above * above > R);
    CHECK(sweep_testing::r_below_quarter_R(p, above, N));
    // Far above (beyond any rounding): the double comparison decides.
    CHECK_FALSE(sweep_testing::r_below_quarter_R(p, std::sqrt(R) * (1 + 0x1p-30), N));
  }
}

namespace {

// The row of p in T at `digits` (wider types: their own precision, mpfr_real digits + 8).
template <class T> sweep_row<T> row_of(std::int64_t tau, std::int64_t sigma, unsigned digits = 17, bool certified = false) {
  sweep_config c = config(3);
  c.max_order = tau + sigma;
  c.digits = digits;
  c.certified = certified;
  auto r = sweep_evaluate<T>(resonant_pair<std::int64_t>(tau, sigma), c);
  REQUIRE_FALSE(r.failed);
  return r;
}

// |v - ref| <= tol |ref|, in MPFR at the reference's precision.
template <class T> bool near(const T& v, const mpfr_real& ref, const mpfr_real& tol) {
  const mpfr_real x = real_to_mpfr(v);
  return abs(x - ref) <= tol * abs(ref);
}

}  // namespace

TEST_CASE("sweep: rows agree with the values of earlier versions and with the independent reference", "[sweep]") {
  // The double rows of earlier versions (lattice method): r_res and theta_first to ~1 ulp.
  auto r65 = row_of<double>(6, 5);
  CHECK(r65.r_res == Approx(0.0507458057910334).epsilon(2e-15));
  CHECK(r65.theta_first == Approx(2.9852847488375807).epsilon(2e-16));
  CHECK(row_of<double>(9, 4).r_res == Approx(0.00871882504953).epsilon(1e-12));
  CHECK(row_of<double>(5, 1).r_res == Approx(0.0738392921404633).epsilon(2e-15));
  CHECK(row_of<double>(5, 1).minimiser_count == 4);
  // Every working type against the high-precision reference (naive forms, every critical
  // point), at its own precision: double 1e-15, long double 1e-18, float128 1e-32, mpfr 40
  // digits 1e-39. Also through the enclosure path (certified rows) in double.
  const std::vector<std::pair<std::int64_t, std::int64_t>> pairs = {{6, 5}, {9, 4}, {5, 1}, {2, 1}, {13, 7}, {101, 60},
                                                                     {1000, 999}, {997, 3}, {7, 5}};
  for (auto [tau, sigma] : pairs) {
    INFO(tau << "," << sigma);
    scoped_digits sd(60);
    const auto ref = test::hp::hp_reference(big_int(tau), big_int(sigma), 50);
    const bool degenerate = (tau - sigma) % 4 == 2;
    auto check_row = [&](const auto& r, const char* tol) {
      INFO(sweep_real_text(r.r_res, 45) << " " << sweep_real_text(r.theta_first, 45));
      if (degenerate) CHECK(r.r_res == 0);
      else CHECK(near(r.r_res, ref.r_res, mpfr_real(tol)));
      CHECK(near(r.theta_first, ref.theta_first, mpfr_real(tol)));
      CHECK(near(r.t_first, ref.t_first, mpfr_real(tol)));
    };
    check_row(row_of<double>(tau, sigma), "4e-15");
    check_row(row_of<double>(tau, sigma, 17, true), "4e-15");
    check_row(row_of<long double>(tau, sigma, 20), "1e-18");
    check_row(row_of<float128>(tau, sigma, 30), "1e-32");
    check_row(row_of<mpfr_real>(tau, sigma, 40), "1e-39");
    check_row(row_of<mpfr_real>(tau, sigma, 40, true), "1e-39");
  }
  // Rows in MPFR carry the working precision's bits, not the process-wide default's.
  sweep_config c40 = config(11);
  c40.digits = 40;
  REQUIRE(sweep_bits<mpfr_real>(c40) == 161);
  for (unsigned global : {10u, 300u}) {
    scoped_digits sd(global);
    const auto r = row_of<mpfr_real>(6, 5, 40);
    CHECK(mpfr_get_prec(r.r_res.backend().data()) == 161);
    CHECK(mpfr_get_prec(r.asy_ratio.backend().data()) == 161);
  }
}

TEST_CASE("sweep: rows beyond order 2^31 (int64 lobe products would overflow) are right", "[sweep]") {
  // Below 2^31 double rows come from theorem_minimum_double, beyond from the enclosures; both
  // against the reference in local mode (the row's theta_first is only its starting guess).
  const std::int64_t big = std::int64_t(1) << 39;
  const std::vector<std::pair<std::int64_t, std::int64_t>> pairs = {
      {1073741824, 1073741823},                  // a = 2^31 - 1, b = 1
      {1610612735, 536870912},                    // a = 2^31 - 1, b ~ a/2
      {3 * (std::int64_t(1) << 32) + 1, (std::int64_t(1) << 32) + 1},  // a ~ 2^34, x ~ 1/2
      {big + 1, big - 1 - 2 * 1000},              // delta = 2002 = 2 mod 4: degenerate
      {big + 1, big - 3},                         // a = 2^40 - 2, b = 4 (delta = 0 mod 4)
      {(std::int64_t(1) << 40) - 5, 4}};          // x -> 1
  for (auto [tau, sigma] : pairs) {
    const resonant_pair<std::int64_t> p(tau, sigma);
    INFO(p.str());
    sweep_config c = config(std::int64_t(p.order()));
    const auto r = sweep_evaluate<double>(p, c);
    REQUIRE_FALSE(r.failed);
    CHECK(r.status[int(sweep_check::structure)] == sweep_status::pass);
    CHECK(r.status[int(sweep_check::degeneracy)] == sweep_status::pass);
    scoped_digits sd(40);
    const auto ref = test::hp::hp_reference(big_int(tau), big_int(sigma), 25, mpfr_real(r.theta_first), true);
    if (p.degenerate()) CHECK(r.r_res == 0);
    else CHECK(near(r.r_res, ref.r_res, mpfr_real("4e-15")));
    CHECK(near(r.theta_first, ref.theta_first, mpfr_real("4e-15")));
  }
}

TEST_CASE("sweep: an MPFR sweep on 2 threads equals the same sweep on 1 thread, row for row", "[sweep]") {
  temp_dir d("test_sweep");
  sweep_config c = config(90);
  c.digits = 40;
  c.checks = sweep_all_checks;
  std::vector<std::string> rows, summaries;
  // The process-wide MPFR precision differs between the runs: the rows must not depend on it.
  for (auto [threads, global] : {std::pair{1u, 20u}, std::pair{2u, 500u}, std::pair{2u, 20u}}) {
    scoped_digits sd(global);
    sweep_files f;
    const std::string n = std::to_string(threads) + "_" + std::to_string(global);
    f.rows_path = d / ("rows" + n + ".csv");
    f.summary_path = d / ("sum" + n + ".json");
    const auto rep = app::sweep_to_files<mpfr_real>(c, f, engine(threads, 16));
    REQUIRE(rep.complete);
    CHECK(rep.threads == threads);
    rows.push_back(without_last_line(read_text(f.rows_path)));
    summaries.push_back(sweep_summary_core(read_json(f.summary_path)).dump());
    CHECK(mpfr_real::default_precision() == global);  // neither read into the rows nor changed
  }
  CHECK(rows[0].find("\"type\":\"mpfr(161 bits)\"") != std::string::npos);
  CHECK(rows[1] == rows[0]);
  CHECK(rows[2] == rows[0]);
  CHECK(summaries[1] == summaries[0]);
  CHECK(summaries[2] == summaries[0]);
  // 40 significant digits printed for each real.
  const auto ex = rows[0].find("\n6,5,");
  REQUIRE(ex != std::string::npos);
  CHECK(rows[0].find("5.074580579103337", ex) != std::string::npos);
}

TEST_CASE("sweep: paper-node verdicts agree with the minimiser thetas", "[sweep]") {
  // Independent of the lobe-frame integers and of the theorem: the minimisers of the
  // high-precision reference (every critical point, naive forms), whose lobe is
  // round(a theta/(2 pi)) mod a; the paper's is round(a/(2b)) (both neighbours when a/(2b) is a
  // half-integer).
  sweep_config c = config(80);
  int checked = 0;
  for (auto p : coprime_pairs(3, 80)) {
    if (p.degenerate()) continue;
    const std::int64_t a = p.order(), b = p.delta();
    struct {
      std::vector<double> minimisers;
      double theta_first;
    } lr;
    {
      scoped_digits sd(30);
      const auto ref = test::hp::hp_reference(big_int(p.tau()), big_int(p.sigma()), 20);
      for (const auto& t : ref.minimisers) lr.minimisers.push_back(double(t));
      lr.theta_first = double(ref.theta_first);
    }
    auto lobe = [&](double th) {
      std::int64_t k = std::llround(double(a) * th / (2 * std::numbers::pi));
      return ((k % a) + a) % a;
    };
    std::vector<std::int64_t> paper;
    if ((a % (2 * b)) == b) paper = {(a - b) / (2 * b) % a, ((a - b) / (2 * b) + 1) % a};
    else paper = {std::llround(double(a) / double(2 * b)) % a};
    auto in_paper = [&](double th) { return std::find(paper.begin(), paper.end(), lobe(th)) != paper.end(); };
    bool any = false;
    for (double th : lr.minimisers) any = any || in_paper(th);
    auto row = sweep_evaluate<double>(p, c);
    INFO(p.str());
    CHECK(row.first_at_paper_node == (in_paper(lr.theta_first) ? 1 : 0));
    CHECK(row.paper_lobe_min == (any ? 1 : 0));
    CHECK(row.minimiser_count == int(lr.minimisers.size()));
    ++checked;
  }
  CHECK(checked == 809);  // non-degenerate pairs of order <= 80
}

TEST_CASE("sweep: rows and summary identical for 1 and 2 threads", "[sweep]") {
  temp_dir d("test_sweep");
  const sweep_config c = config(70);
  json s1, s2;
  for (unsigned threads : {1u, 2u}) {
    sweep_files f;
    f.rows_path = d / ("rows" + std::to_string(threads) + ".csv");
    f.summary_path = d / ("sum" + std::to_string(threads) + ".json");
    auto rep = app::sweep_to_files<double>(c, f, engine(threads, threads == 1 ? 64 : 5));
    REQUIRE(rep.complete);
    CHECK(rep.threads == threads);
    (threads == 1 ? s1 : s2) = read_json(f.summary_path);
  }
  CHECK(without_last_line(read_text(d / "rows1.csv")) == without_last_line(read_text(d / "rows2.csv")));
  CHECK(sweep_summary_core(s1) == sweep_summary_core(s2));
  CHECK(s1["run"]["threads"] == 1);
  CHECK(s2["run"]["threads"] == 2);
  // The summary file carries the documented keys.
  for (const char* k : {"pairs", "degenerate", "checks", "asy_ratio_max", "sharp_constant", "t_first_over_proxy", "seconds"})
    CHECK(s1.contains(k));
  CHECK(s1["checks"].size() == 4);  // the default checks
  for (auto& [name, t] : s1["checks"].items()) {
    CHECK(t.contains("violations"));
    CHECK(t.contains("examples"));
  }
  CHECK(s1["asy_ratio_max"]["value"].is_string());
  CHECK(s1["asy_ratio_max"]["pair"].size() == 2);
  for (const char* k : {"min", "median", "max"}) CHECK(s1["t_first_over_proxy"][k].is_string());
  // Rows: one per pair between the two metadata lines.
  std::istringstream rows(read_text(d / "rows1.csv"));
  std::string line;
  int n = 0;
  while (std::getline(rows, line)) ++n;
  CHECK(std::uint64_t(n) == s1["pairs"].get<std::uint64_t>() + 3);
}

TEST_CASE("sweep: 4 shards merged equal the single run (rows, jsonl and shard summaries)", "[sweep]") {
  temp_dir d("test_sweep");
  const std::int64_t M = 90;
  sweep_files single;
  single.summary_path = d / "single.json";
  auto rep = app::sweep_to_files<double>(config(M), single, engine(2));
  REQUIRE(rep.complete);
  const json want = sweep_summary_core(read_json(single.summary_path));

  std::vector<std::string> csv, jsonl, summaries;
  for (int i = 0; i < 4; ++i) {
    const sweep_config c = shard_of(config(M), i, 4);
    sweep_files f;
    f.rows_path = d / ("shard" + std::to_string(i) + ".csv");
    f.summary_path = d / ("shard" + std::to_string(i) + ".json");
    REQUIRE(app::sweep_to_files<double>(c, f, engine(2)).complete);
    sweep_files g;
    g.rows_path = d / ("shard" + std::to_string(i) + ".jsonl");
    g.rows_format = sweep_format::jsonl;
    REQUIRE(app::sweep_to_files<double>(c, g, engine(1)).complete);
    csv.push_back(f.rows_path);
    jsonl.push_back(g.rows_path);
    summaries.push_back(f.summary_path);
    CHECK(path_exists(f.summary_path + ".values"));
  }
  CHECK(sweep_summary_core(sweep_merge(csv)) == want);
  CHECK(sweep_summary_core(sweep_merge(jsonl)) == want);
  CHECK(sweep_summary_core(sweep_merge(summaries)) == want);
  CHECK(sweep_summary_core(sweep_merge({csv[2], jsonl[0], summaries[3], csv[1]})) == want);
  // The merge insists on one complete set of shards.
  CHECK_THROWS_AS(sweep_merge({csv[0], csv[1], csv[2]}), usage_error);
  CHECK_THROWS_AS(sweep_merge({csv[0], csv[1], csv[2], jsonl[2]}), usage_error);
  sweep_files other;
  other.rows_path = d / "other.csv";
  sweep_config oc = config(M - 1);
  oc.shard_index = 3;
  oc.shard_count = 4;
  REQUIRE(app::sweep_to_files<double>(oc, other, engine(1)).complete);
  CHECK_THROWS_AS(sweep_merge({csv[0], csv[1], csv[2], other.rows_path}), usage_error);
  // A single complete run merges to itself.
  sweep_files whole;
  whole.rows_path = d / "whole.csv";
  REQUIRE(app::sweep_to_files<double>(config(M), whole, engine(2)).complete);
  CHECK(sweep_summary_core(sweep_merge({whole.rows_path})) == want);
}

namespace {

// An uninterrupted run of config(80) in a fresh directory: what every resumed run must reproduce.
class resume_fixture {
 protected:
  temp_dir d{"test_sweep"};
  const sweep_config c = config(80);
  std::string ref_rows;  // CSV, without the end line
  json ref_summary;      // sweep_summary_core

  resume_fixture() {
    sweep_files f;
    f.rows_path = d / "ref.csv";
    f.summary_path = d / "ref.json";
    REQUIRE(app::sweep_to_files<double>(c, f, engine(2)).complete);
    ref_rows = without_last_line(read_text(f.rows_path));
    ref_summary = sweep_summary_core(read_json(f.summary_path));
  }

  // Resumes the sweep of f to its end: the state is gone, the summary (and CSV rows) are the reference's.
  void resume_to_end(sweep_files f, sweep_engine_options e) {
    f.resume = true;
    e.max_pairs = 0;
    e.stop = nullptr;
    const auto rep = app::sweep_to_files<double>(c, f, e);
    REQUIRE(rep.complete);
    CHECK_FALSE(path_exists(rep.state_path));
    CHECK(sweep_summary_core(read_json(f.summary_path)) == ref_summary);
    if (!f.rows_path.empty() && f.rows_format == sweep_format::csv)
      CHECK(without_last_line(read_text(f.rows_path)) == ref_rows);
  }
};

// A sweep of config(80) into `summary`, stopped after 50 pairs: its state kept for a resume.
struct stopped_sweep {
  sweep_config c = config(80);
  sweep_files f;
  sweep_engine_options e = engine(1);
  explicit stopped_sweep(const std::string& summary) {
    f.summary_path = summary;
    e.max_pairs = 50;
    REQUIRE_FALSE(app::sweep_to_files<double>(c, f, e).complete);
  }
};

}  // namespace

TEST_CASE_METHOD(resume_fixture, "sweep: resume after max_pairs limits, twice, gives the uninterrupted result", "[sweep]") {
  sweep_files f;
  f.rows_path = d / "a.csv";
  f.summary_path = d / "a.json";
  auto e = engine(2);
  e.max_pairs = 100;
  auto r1 = app::sweep_to_files<double>(c, f, e);
  CHECK_FALSE(r1.complete);
  CHECK(r1.done == 100);
  CHECK_FALSE(path_exists(f.rows_path));  // only a.csv.part: never a partial a.csv
  CHECK(path_exists(f.rows_path + ".part"));
  CHECK_FALSE(path_exists(f.summary_path));
  CHECK(path_exists(r1.state_path));
  f.resume = true;
  e.max_pairs = 333;
  auto r2 = app::sweep_to_files<double>(c, f, e);
  CHECK_FALSE(r2.complete);
  CHECK(r2.done == 433);
  resume_to_end(f, e);
}

TEST_CASE_METHOD(resume_fixture, "sweep: resume after the stop flag (as set by SIGINT), summary only", "[sweep]") {
  sweep_files f;
  f.summary_path = d / "b.json";
  std::atomic<bool> stop{false};
  auto e = engine(2, 16);
  e.stop = &stop;
  auto r1 = app::sweep_to_files<double>(c, f, e, [&](const sweep_progress_info& p) {
    if (p.done >= 200) stop = true;
  });
  CHECK_FALSE(r1.complete);
  CHECK(r1.done >= 200);
  CHECK(r1.done < ref_summary["pairs"].get<std::uint64_t>());
  CHECK_FALSE(path_exists(f.summary_path));
  resume_to_end(f, e);
}

TEST_CASE_METHOD(resume_fixture, "sweep: resume after a crash drops the rows written past the last checkpoint", "[sweep]") {
  sweep_files f;
  f.rows_path = d / "c.jsonl";
  f.rows_format = sweep_format::jsonl;
  f.summary_path = d / "c.json";
  f.checkpoint_seconds = 1e-9;  // a checkpoint after every block
  auto e = engine(1, 10);
  int blocks = 0;
  CHECK_THROWS_AS(app::sweep_to_files<double>(c, f, e,
                                         [&](const sweep_progress_info&) {
                                           if (++blocks == 25) throw compute_error("simulated crash");
                                         }),
                  compute_error);
  CHECK_FALSE(path_exists(f.rows_path));
  CHECK_FALSE(path_exists(f.summary_path));
  // Append junk, as a crash in the middle of a write would leave.
  {
    std::ofstream junk(f.rows_path + ".part", std::ios::app);
    junk << "{\"tau\": 99, \"sigma\"";
  }
  f.checkpoint_seconds = 300;
  resume_to_end(f, e);
  // Same pairs as the CSV reference, in the same order.
  auto in = sweep_read_rows(f.rows_path);
  CHECK(in.acc.pairs == ref_summary["pairs"].get<std::uint64_t>());
}

TEST_CASE("sweep: resume refuses, in one line, a state of an earlier version or of other checks", "[sweep]") {
  temp_dir d("test_sweep");
  stopped_sweep s(d / "old.json");
  const sweep_config& c = s.c;
  sweep_files& f = s.f;
  sweep_engine_options& e = s.e;
  const std::string state = sweep_default_state_path(f);
  json st = read_json(state);
  const json run = st["run"];
  REQUIRE(run["method"] == "lattice-theorem/1");
  // A state written before the rows came from the theorem: no "method" in its run.
  st["run"].erase("method");
  write_file_atomically(state, st.dump());
  f.resume = true;
  auto message = [&](const sweep_config& cfg) {
    try {
      app::sweep_to_files<double>(cfg, f, e);
    } catch (const usage_error& err) {
      return std::string(err.what());
    }
    return std::string("no error");
  };
  const std::string old = message(c);
  INFO(old);
  CHECK(old.find("earlier version of gyrores") != std::string::npos);
  CHECK(old.find('\n') == std::string::npos);
  // A state of format version 1 (with the cross-check's run field): refused, naming the version.
  st["run"] = run;
  st["version"] = 1;
  st["run"]["cross_check_max_order"] = 300;
  write_file_atomically(state, st.dump());
  const std::string v1 = message(c);
  INFO(v1);
  CHECK(v1.find("has sweep format version 1") != std::string::npos);
  CHECK(v1.find("--fresh") != std::string::npos);
  CHECK(v1.find('\n') == std::string::npos);
  // Another set of checks: the keys are named.
  st["version"] = 2;
  st["run"] = run;
  const sweep_check_set some = sweep_parse_checks("degeneracy,structure");
  st["run"]["checks"] = sweep_check_names(some);
  write_file_atomically(state, st.dump());
  const std::string other = message(c);
  INFO(other);
  CHECK(other.find("it differs in checks") != std::string::npos);
  CHECK(other.find('\n') == std::string::npos);
  // The same checks asked for: it resumes.
  sweep_config same = c;
  same.checks = some;
  e.max_pairs = 0;
  CHECK(app::sweep_to_files<double>(same, f, e).complete);
}

TEST_CASE("sweep: resume refuses a different sweep, and a missing state", "[sweep]") {
  temp_dir d("test_sweep");
  stopped_sweep s(d / "e.json");
  sweep_files& f = s.f;
  const sweep_engine_options& e = s.e;
  f.resume = true;
  CHECK_THROWS_AS(app::sweep_to_files<double>(config(81), f, e), usage_error);
  sweep_files g;
  g.summary_path = d / "nothing.json";
  g.resume = true;
  CHECK_THROWS_AS(app::sweep_to_files<double>(s.c, g, e), usage_error);
}

TEST_CASE("sweep: files are written atomically", "[sweep]") {
  temp_dir d("test_sweep");
  const std::string p = d / "f.txt";
  write_file_atomically(p, "one\n");
  CHECK(read_text(p) == "one\n");
  write_file_atomically(p, "two\n");
  CHECK(read_text(p) == "two\n");
  CHECK(file_names(d) == std::vector<std::string>{"f.txt"});  // no temporary file left behind
  // Written in pieces; a failing piece leaves the old content and no temporary file.
  write_file_atomically(p, [](const byte_writer& w) {
    w("thr");
    w("ee\n");
  });
  CHECK(read_text(p) == "three\n");
  CHECK_THROWS_AS(write_file_atomically(p, [](const byte_writer& w) {
                    w("four");
                    throw usage_error("stop");
                  }),
                  usage_error);
  CHECK(read_text(p) == "three\n");
  CHECK(file_names(d) == std::vector<std::string>{"f.txt"});
  // Temporaries of a killed writer (a pid that cannot be running) go; a live process's stay.
  const std::string dead = p + ".tmp.999999999", live = p + ".tmp." + std::to_string(::getpid());
  write_file_atomically(dead, "x");
  write_file_atomically(live, "x");
  write_file_atomically(p + ".tmp.12ab", "x");  // not a temporary of ours
  remove_stale_temporaries(p);
  std::vector<std::string> kept = {"f.txt", "f.txt.tmp." + std::to_string(::getpid()), "f.txt.tmp.12ab"};
  std::sort(kept.begin(), kept.end());
  CHECK(file_names(d) == kept);
  std::filesystem::remove(live);
  std::filesystem::remove(p + ".tmp.12ab");
  // A directory that does not exist: nothing is created; usage_error (the user named the path).
  CHECK_THROWS_AS(write_file_atomically(d / "no/such/dir.txt", "x"), usage_error);
  CHECK_FALSE(path_exists(d / "no"));
  // A sweep whose summary cannot be written leaves no partial summary and no final rows.
  sweep_files f;
  f.rows_path = d / "rows.csv";
  f.summary_path = d / "missing/summary.json";
  CHECK_THROWS_AS(app::sweep_to_files<double>(config(30), f, engine(1)), usage_error);
  CHECK_FALSE(path_exists(f.summary_path));
  CHECK_FALSE(path_exists(f.summary_path + ".part"));
  CHECK_FALSE(path_exists(d / "missing"));
  CHECK_FALSE(path_exists(f.rows_path));
}

TEST_CASE("sweep: float128 agrees with double", "[sweep]") {
  sweep_config c = config(40);
  c.digits = 25;
  sweep_accumulator a128;
  a128.max_examples = c.max_examples;
  REQUIRE(sweep_run<float128>(c, engine(2), [&](sweep_block& b) { a128.merge(b.summary); }).complete);
  auto a64 = run_acc(config(40), engine(2));
  CHECK(a128.pairs == a64.pairs);
  CHECK(a128.degenerate == a64.degenerate);
  for (int i = 0; i < sweep_check_count; ++i) {
    CHECK(a128.checks[i].violations == a64.checks[i].violations);
    CHECK(a128.checks[i].examples == a64.checks[i].examples);
  }
  CHECK(a128.asy_ratio_max.pair == a64.asy_ratio_max.pair);
  CHECK(a128.asy_ratio_max.value == Approx(a64.asy_ratio_max.value).epsilon(1e-12));
  CHECK(a128.asy_ratio_max.text.size() >= 25);  // printed at the working precision
  auto q128 = a128.quantiles(), q64 = a64.quantiles();
  CHECK(q128.median == Approx(q64.median).epsilon(1e-12));
}

// The engine enumerates with its own windowed coprimality table (src/lib/sweep/engine.cpp); the
// pairs it hands out, in order, must be exactly those of the plain gcd enumeration
// (model/enumerate.hpp) for any order range, shard, resume start and block size, including
// orders beyond one table window (2 * 4096).
TEST_CASE("sweep: the engine's pairs are coprime_pairs' pairs in order, for shards, starts and windows", "[sweep]") {
  struct range_case {
    std::int64_t min, max, shard, shards;
    std::uint64_t start;
  };
  for (auto rc : {range_case{3, 200, 0, 1, 0}, range_case{1, 97, 2, 3, 5}, range_case{50, 60, 0, 1, 7},
                  range_case{8190, 8200, 0, 1, 0}, range_case{16383, 16386, 1, 4, 3}}) {
    sweep_config cfg;
    cfg.min_order = rc.min;
    cfg.max_order = rc.max;
    cfg.shard_index = rc.shard;
    cfg.shard_count = rc.shards;
    std::vector<std::pair<std::int64_t, std::int64_t>> expected, got;
    std::uint64_t skip = rc.start;
    for (auto p : coprime_pairs(cfg.min_order, cfg.max_order, cfg.shard_index, cfg.shard_count)) {
      if (skip) { --skip; continue; }
      expected.emplace_back(p.tau(), p.sigma());
    }
    sweep_engine_options opt;
    opt.threads = 2;
    opt.block_size = 37;
    opt.start = rc.start;
    auto evaluate = [&](const std::vector<resonant_pair<std::int64_t>>& pairs, sweep_block& blk) {
      std::string s;
      for (const auto& p : pairs) s += std::to_string(p.tau()) + " " + std::to_string(p.sigma()) + "\n";
      blk.rows = s;
    };
    auto out = sweep_run_blocks(cfg, opt, evaluate, [&](sweep_block& blk) {
      std::istringstream is(blk.rows);
      std::int64_t t, s;
      while (is >> t >> s) got.emplace_back(t, s);
    });
    INFO("orders " << rc.min << ".." << rc.max << ", shard " << rc.shard << "/" << rc.shards << ", start " << rc.start);
    CHECK(out.complete);
    CHECK(out.done == rc.start + expected.size());
    CHECK(got == expected);
  }
}

// Inputs found by fuzzing (tests/fuzz/, docs/testing.md): each must be a usage_error.
TEST_CASE("sweep: malformed values files, states and shard outputs are usage errors", "[sweep]") {
  temp_dir d("test_sweep");
  // A values file whose count n = 2^61 made 16 + 8n wrap around to 16, the file's own size.
  std::string header = "GYRVAL01";
  const std::uint64_t huge = std::uint64_t(1) << 61;
  header.append(reinterpret_cast<const char*>(&huge), sizeof huge);
  write_file_atomically(d / "v.values", header);
  CHECK_THROWS_AS(sweep_read_values_file(d / "v.values"), usage_error);
  std::string one = header.substr(0, 8);
  const std::uint64_t n1 = 1;
  one.append(reinterpret_cast<const char*>(&n1), sizeof n1);
  one.append(8, '\0');
  write_file_atomically(d / "one.values", one);
  const sweep_values one_value = sweep_read_values_file(d / "one.values");
  CHECK(one_value.size() == 1);
  std::vector<double> got;
  one_value.replay([&](const double* v, std::size_t n) { got.insert(got.end(), v, v + n); });
  CHECK(got == std::vector<double>{0.0});
}

TEST_CASE("sweep: a state or shard output with a bad field is a usage error, not a JSON exception", "[sweep]") {
  temp_dir d("test_sweep");
  // A resume state without "done" (the JSON library threw out_of_range: 'internal error').
  sweep_files f;
  f.summary_path = d / "s.json";
  auto e = engine(1);
  e.max_pairs = 20;
  REQUIRE_FALSE(app::sweep_to_files<double>(config(30), f, e).complete);
  const std::string state = sweep_default_state_path(f);
  json st = read_json(state);
  write_file_atomically(state + ".bak", st.dump());
  st.erase("done");
  write_file_atomically(state, st.dump());
  f.resume = true;
  CHECK_THROWS_AS(app::sweep_to_files<double>(config(30), f, engine(1)), usage_error);
  // A count beyond 64 bits (parsed as a double; converting it was undefined behaviour, UBSan).
  st = read_json(state + ".bak");
  REQUIRE(st.contains("summary"));
  for (const char* where : {"summary", "top"}) {
    json big = st;
    const json huge = json::parse("222222222222222222222222222222");
    if (std::string(where) == "summary") big["summary"]["pairs"] = huge;
    else big["done"] = huge;
    write_file_atomically(state, big.dump());
    INFO(where);
    CHECK_THROWS_AS(app::sweep_to_files<double>(config(30), f, engine(1)), usage_error);
  }
  // A rows file naming shard 0 of 0 (merge divided by the shard count), or shard 3 of 2.
  sweep_files r;
  r.rows_path = d / "r.jsonl";
  r.rows_format = sweep_format::jsonl;
  REQUIRE(app::sweep_to_files<double>(config(30), r, engine(1)).complete);
  const std::string rows = read_text(r.rows_path);
  REQUIRE(rows.find("\"shard\":[0,1]") != std::string::npos);
  for (const std::string shard : {"[0,0]", "[3,2]", "[\"x\",1]"}) {
    std::string bad = rows;
    bad.replace(bad.find("\"shard\":[0,1]") + 8, 5, shard);
    write_file_atomically(d / "bad.jsonl", bad);
    INFO(shard);
    CHECK_THROWS_AS(sweep_merge({d / "bad.jsonl"}), usage_error);
  }
  // A CSV row whose t_first/proxy is not a number (sweep_text_double threw compute_error: exit 3,
  // "could not compute", for what is a malformed file).
  sweep_files c;
  c.rows_path = d / "r.csv";
  REQUIRE(app::sweep_to_files<double>(config(30), c, engine(1)).complete);
  std::string csv = read_text(c.rows_path);
  const auto row = csv.find("\n2,1,3,");
  REQUIRE(row != std::string::npos);
  const auto field = csv.find(",0.8", row);  // t_first_over_proxy of (2, 1): 0.819...
  REQUIRE(field != std::string::npos);
  csv.replace(field + 1, 1, "z");
  write_file_atomically(d / "bad.csv", csv);
  CHECK_THROWS_AS(sweep_merge({d / "bad.csv"}), usage_error);
}

TEST_CASE("sweep: integer fields of shard summaries beyond their type are usage errors naming the file", "[sweep]") {
  // nlohmann's get<int64_t> converts a floating value (an integer beyond 64 bits parses as one)
  // with undefined behaviour, and get<size_t> of a negative one wraps.
  temp_dir d("test_sweep");
  std::vector<std::string> shards;
  for (int i = 0; i < 2; ++i) {
    sweep_config c = config(40);
    c.shard_index = i;
    c.shard_count = 2;
    sweep_files f;
    f.summary_path = d / ("s" + std::to_string(i) + ".json");
    REQUIRE(app::sweep_to_files<double>(c, f, engine(1)).complete);
    shards.push_back(f.summary_path);
  }
  REQUIRE_NOTHROW(sweep_merge(shards));
  const json good = read_json(shards[0]);
  REQUIRE(good.at("checks").at("paper-node").at("examples").size() > 0);
  const json huge = json::parse("1e30"), big = json::parse("222222222222222222222222222222"), neg = json(-1);
  std::vector<std::pair<std::string, std::function<void(json&)>>> edits = {
      {"example tau 1e30", [&](json& j) { j["checks"]["paper-node"]["examples"][0][0] = huge; }},
      {"example sigma > 2^64", [&](json& j) { j["checks"]["paper-node"]["examples"][0][1] = big; }},
      {"extreme pair", [&](json& j) { j["asy_ratio_max"]["pair"][0] = huge; }},
      {"max_examples -1", [&](json& j) { j["run"]["max_examples"] = neg; }},
      {"shard count 1e30", [&](json& j) { j["run"]["shard"][1] = huge; }},
      {"max_order 2^64+", [&](json& j) { j["run"]["max_order"] = big; }},
  };
  for (auto& [what, edit] : edits) {
    json bad = good;
    edit(bad);
    write_file_atomically(shards[0], bad.dump());
    INFO(what);
    try {
      sweep_merge(shards);
      FAIL("no error");
    } catch (const usage_error& e) {
      CHECK(std::string(e.what()).find("s0.json") != std::string::npos);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Quantiles in bounded memory (sweep/values.hpp): radix selection must give sorted[rank] exactly.

namespace {

// Values that make radix selection work: ties, one binade, both signs, zeros of both signs,
// subnormals, infinities.
std::vector<double> selection_data(std::mt19937_64& rng, int kind, std::size_t n) {
  std::vector<double> v(n);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (auto& x : v) {
    switch (kind) {
      case 0: x = u(rng); break;
      case 1: x = double(rng() % 7) - 3; break;                                   // heavy ties, -0 absent
      case 2: x = std::nextafter(1.0, 2.0 + double(rng() % 50)) + 1e-15 * double(rng() % 1000); break;  // one binade
      case 3: {
        const double special[] = {0.0, -0.0, 4.9e-324, -4.9e-324, 2.2e-308, INFINITY, -INFINITY, 1.0, -1.0};
        x = rng() % 2 ? special[rng() % 9] : u(rng);
        break;
      }
      default: x = std::ldexp(1.0 + double(rng() % 3), int(rng() % 5)); break;  // few distinct values
    }
  }
  return v;
}

}  // namespace

TEST_CASE("sweep: value keys order doubles as < does", "[sweep]") {
  std::mt19937_64 rng(7);
  const auto v = selection_data(rng, 3, 4000);
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double a = v[i - 1], b = v[i];
    CHECK(sweep_value_of_key(sweep_value_key(a)) == a);
    if (a < b) CHECK(sweep_value_key(a) < sweep_value_key(b));
    if (b < a) CHECK(sweep_value_key(b) < sweep_value_key(a));
  }
  CHECK(sweep_value_key(-0.0) < sweep_value_key(0.0));  // apart: sweep_values stores +0
}

TEST_CASE("sweep: order statistics by radix selection equal those of a sort", "[sweep]") {
  std::mt19937_64 rng(11);
  const sweep_selection_options options[] = {{20, 1u << 23}, {1, 1}, {3, 7}, {8, 100}, {12, 2}, {16, 0}, {22, 1u << 10}};
  for (int kind = 0; kind < 5; ++kind)
    for (std::size_t n : {1, 2, 3, 50, 1000, 20000}) {
      const auto data = selection_data(rng, kind, n);
      // The values in three pieces: two sources and memory, as a sweep read back from files has.
      sweep_values vals;
      const std::size_t c1 = n / 3, c2 = n / 2;
      auto piece = [&](std::size_t lo, std::size_t hi) {
        return [&data, lo, hi](const sweep_value_sink& s) {
          for (std::size_t i = lo; i < hi; i += 97) s(data.data() + i, std::min<std::size_t>(97, hi - i));
        };
      };
      vals.add_source(piece(0, c1), c1);
      vals.add_source(piece(c1, c2), c2 - c1);
      for (std::size_t i = c2; i < n; ++i) vals.add(data[i]);
      REQUIRE(vals.size() == n);
      std::vector<double> sorted = data;
      for (auto& x : sorted)
        if (x == 0) x = 0.0;
      std::sort(sorted.begin(), sorted.end());
      std::vector<std::uint64_t> ranks = {0, n - 1, n / 2, (n - 1) / 100, 99 * (n - 1) / 100};
      for (int i = 0; i < 5; ++i) ranks.push_back(rng() % n);
      for (const auto& opt : options) {
        INFO("kind " << kind << ", n " << n << ", bits " << opt.bits << ", collect " << opt.collect_limit);
        const auto got =
            sweep_order_statistics([&](const sweep_value_sink& s) { vals.replay(s); }, n, ranks, opt);
        for (std::size_t i = 0; i < ranks.size(); ++i) {
          INFO("rank " << ranks[i]);
          CHECK(sweep_value_key(got[i]) == sweep_value_key(sorted[ranks[i]]));  // -0 and NaN-safe equality
        }
      }
    }
  // A replay that gives a different number of values than announced is caught.
  sweep_values v;
  v.add(1);
  CHECK_THROWS_AS(sweep_order_statistics([&](const sweep_value_sink& s) { v.replay(s); }, 2, {0}), compute_error);
  CHECK_THROWS_AS(sweep_order_statistics([&](const sweep_value_sink& s) { v.replay(s); }, 1, {1}), std::invalid_argument);
}

TEST_CASE("sweep: values spilled to the state's file give the in-memory summary, through resumes and shards", "[sweep]") {
  temp_dir d("test_sweep");
  const sweep_config c = config(120);
  sweep_files mem;
  mem.summary_path = d / "mem.json";
  REQUIRE(app::sweep_to_files<double>(c, mem, engine(2)).complete);
  const json want = sweep_summary_core(read_json(mem.summary_path));
  REQUIRE(want.at("t_first_over_proxy").at("count").get<std::uint64_t>() > 1500);

  for (std::size_t keep : {std::size_t(1), std::size_t(37), std::size_t(1000)}) {
    INFO("values in memory " << keep);
    sweep_files f;
    f.summary_path = d / ("spill" + std::to_string(keep) + ".json");
    f.values_in_memory = keep;
    auto e = engine(2, 16);
    e.max_pairs = 700;  // stop, resume, stop, resume: the file is cut back and appended to
    REQUIRE_FALSE(app::sweep_to_files<double>(c, f, e).complete);
    f.resume = true;
    REQUIRE_FALSE(app::sweep_to_files<double>(c, f, e).complete);
    e.max_pairs = 0;
    REQUIRE(app::sweep_to_files<double>(c, f, e).complete);
    CHECK(sweep_summary_core(read_json(f.summary_path)) == want);
    CHECK_FALSE(path_exists(sweep_default_state_path(f) + ".values"));

    std::vector<std::string> shards;
    for (int i = 0; i < 3; ++i) {
      sweep_config sc = c;
      sc.shard_index = i;
      sc.shard_count = 3;
      sweep_files g;
      g.summary_path = d / ("shard" + std::to_string(keep) + "_" + std::to_string(i) + ".json");
      g.values_in_memory = keep;
      REQUIRE(app::sweep_to_files<double>(sc, g, engine(1)).complete);
      shards.push_back(g.summary_path);
    }
    CHECK(sweep_summary_core(sweep_merge(shards)) == want);
  }
}

TEST_CASE("sweep: values kept in memory through checkpoints and resumes give the same summary", "[sweep]") {
  // A run within the memory budget writes its values only at checkpoints and keeps them in
  // memory: here a checkpoint after every block, and stops and resumes (the resumed runs read
  // the earlier runs' values from the state's file and keep their own in memory).
  temp_dir d("test_sweep_mem");
  const sweep_config c = config(60);
  sweep_files mem;
  mem.summary_path = d / "mem.json";
  REQUIRE(app::sweep_to_files<double>(c, mem, engine(2)).complete);
  const json want = sweep_summary_core(read_json(mem.summary_path));
  REQUIRE(want.at("t_first_over_proxy").at("count").get<std::uint64_t>() > 400);

  sweep_files f;
  f.summary_path = d / "checkpointed.json";
  f.checkpoint_seconds = 1e-9;  // after every block
  REQUIRE(f.values_in_memory >= (std::size_t(1) << 20));  // the default budget holds this run
  auto e = engine(2, 16);
  e.max_pairs = 200;
  REQUIRE_FALSE(app::sweep_to_files<double>(c, f, e).complete);
  const std::string values = sweep_default_state_path(f) + ".values";
  REQUIRE(path_exists(values));
  f.resume = true;
  REQUIRE_FALSE(app::sweep_to_files<double>(c, f, e).complete);
  e.max_pairs = 0;
  REQUIRE(app::sweep_to_files<double>(c, f, e).complete);
  CHECK(sweep_summary_core(read_json(f.summary_path)) == want);
  CHECK_FALSE(path_exists(values));

  // And in one run with a checkpoint after every block: the file written, memory read.
  sweep_files g;
  g.summary_path = d / "one_run.json";
  g.checkpoint_seconds = 1e-9;
  REQUIRE(app::sweep_to_files<double>(c, g, engine(2, 16)).complete);
  CHECK(sweep_summary_core(read_json(g.summary_path)) == want);
}

// ---- the fast path without rows (src/lib/sweep/fast.cpp) ----

namespace {

// The accumulator of a run whose rows are formatted (and dropped): every pair the row's way.
sweep_accumulator run_acc_rows(const sweep_config& c, const sweep_engine_options& e) {
  sweep_accumulator acc;
  acc.max_examples = c.max_examples;
  const sweep_row_sink<double> drop = [](sweep_block&, const sweep_row<double>&) {};
  auto out = sweep_run<double>(c, e, [&](sweep_block& b) { acc.merge(b.summary); }, drop);
  REQUIRE(out.complete);
  return acc;
}

std::vector<double> sorted_values(const sweep_values& v) {
  std::vector<double> all;
  v.replay([&](const double* d, std::size_t n) { all.insert(all.end(), d, d + n); });
  std::sort(all.begin(), all.end());
  return all;
}

// |x - y| in units of the last place of y.
double ulps(double x, double y) { return std::fabs(x - y) / (std::nextafter(std::fabs(y), INFINITY) - std::fabs(y)); }

}  // namespace

TEST_CASE("sweep: without rows the fast path gives the rows' summary", "[sweep]") {
  // Orders up to 700 and a window near 3000: delta from 1 to ~3000, both sides of the fast
  // path's delta >= 64, every check, failures of paper-node (most pairs) included.
  for (auto [lo, hi] : {std::pair<std::int64_t, std::int64_t>{3, 700}, {2990, 3010}}) {
    sweep_config c = config(hi, lo);
    c.max_examples = 7;
    for (unsigned threads : {1u, 2u}) {
      const sweep_accumulator fast = run_acc(c, engine(threads, 61));
      const sweep_accumulator rows = run_acc_rows(c, engine(threads, 61));
      CHECK(fast.pairs == rows.pairs);
      CHECK(fast.degenerate == rows.degenerate);
      CHECK(fast.first_at_paper_node == rows.first_at_paper_node);
      for (int i = 0; i < sweep_check_count; ++i) CHECK(fast.checks[i] == rows.checks[i]);
      CHECK(fast.errors == rows.errors);
      // The asy extremes: bit for bit, same pair (the skipped pairs cannot reach them).
      CHECK(fast.asy_ratio_max == rows.asy_ratio_max);
      CHECK(fast.sharp_constant == rows.sharp_constant);
      // t_first/(pi/|n|): each within an ulp of the row's (theta_first within an ulp of the
      // exact value on both ways), and nearly all equal.
      const auto fv = sorted_values(fast.t_ratios), rv = sorted_values(rows.t_ratios);
      REQUIRE(fv.size() == rv.size());
      std::size_t differ = 0;
      for (std::size_t i = 0; i < fv.size(); ++i) {
        CHECK(ulps(fv[i], rv[i]) <= 2);
        differ += fv[i] != rv[i];
      }
      CHECK(differ * 100 <= fv.size());
    }
  }
}

namespace {
// The series form's u* of the pair (a, b) with m_min = m, and its theta_first (theorem/minimum_series.hpp).
double series_root(std::int64_t a, std::int64_t b, int m) {
  return theorem_root_series(double(b) / double(a), std::numbers::pi / 4 * double(m) / double(b));
}
double series_theta(std::int64_t a, std::int64_t k, double su) { return lobe_theta_double(double(a), 1 / double(a), k, su); }
}  // namespace

TEST_CASE("sweep: the fast path's u* and theta_first against theorem_minimum_double", "[sweep]") {
  std::mt19937_64 rng(20261127);
  int tested = 0;
  // The largest u* (delta near 64, m_min = 1 and 2: v up to pi/128) and x near 1 and near 0.
  for (std::int64_t a : {131, 1001, 1002, 100003, 100002, 99999998})
    for (std::int64_t b : {64, 65, 66, 67, 68, 69, 72, 76, 80, 1000, 1001})
      for (std::int64_t bb : {b, a - b}) {
        if ((a - bb) % 2 != 0 || bb >= a || bb < series_min_delta || a % 4 == 0) continue;
        const std::int64_t tau = (a + bb) / 2, sigma = (a - bb) / 2;
        if (sigma < 1 || std::gcd(tau, sigma) != 1) continue;
        const minimum_double M = theorem_minimum_double(resonant_pair<std::int64_t>(tau, sigma));
        const double u = series_root(a, bb, M.m_min);
        INFO(tau << "," << sigma);
        CHECK(ulps(u, M.u_star) <= 8);
        const auto& f = M.lobes[0];
        CHECK(ulps(series_theta(a, f.k, f.m < 0 ? -u : u), M.theta_first) <= 1);
        ++tested;
      }
  CHECK(tested >= 40);
  for (std::int64_t a : {131, 1000, 4097, 99999, 1000003, 123456789}) {
    std::uniform_int_distribution<std::int64_t> sig(1, (a - 1) / 2);
    for (int n = 0; n < 400; ++n) {
      const std::int64_t sigma = sig(rng), tau = a - sigma, b = tau - sigma;
      if (std::gcd(tau, sigma) != 1 || b < series_min_delta || a % 4 == 0) continue;
      const resonant_pair<std::int64_t> p(tau, sigma);
      const minimum_double M = theorem_minimum_double(p);
      const double u = series_root(a, b, M.m_min);
      INFO(tau << "," << sigma);
      CHECK(ulps(u, M.u_star) <= 8);
      const auto& f = M.lobes[0];
      const double theta = series_theta(a, f.k, f.m < 0 ? -u : u);
      CHECK(ulps(theta, M.theta_first) <= 1);
      ++tested;
    }
  }
  CHECK(tested > 1000);
}

TEST_CASE("sweep: the fast path's R(pi/2) in int64 is sweep_quarter_R_scaled", "[sweep]") {
  for (std::int64_t a = 3; a <= 400; ++a)
    for (std::int64_t b = a - 2; b >= 1; b -= 2) CHECK(sweep_quarter_R_scaled<std::int64_t>(a, b) == std::int64_t(sweep_quarter_R_scaled(a, b)));
  const std::int64_t big = (std::int64_t(1) << 28) - 1;
  for (std::int64_t a : {big, big - 1, big - 2, big - 3})
    for (std::int64_t b : {std::int64_t(1), std::int64_t(2), a - 2, a / 2, a / 2 + 1})
      if ((a - b) % 2 == 0 && b > 0) CHECK(sweep_quarter_R_scaled<std::int64_t>(a, b) == std::int64_t(sweep_quarter_R_scaled(a, b)));
}

TEST_CASE("sweep: the fast path's P3 bound holds, and refuses what it cannot prove", "[sweep]") {
  // The bound r_res^2 <= (sigma/tau) pi^4 m^4/(64 a^2 b^2) against the theorem's r_res (one
  // ulp), and the decision for every pair with delta >= 64 up to order 400.
  for (std::int64_t a = 67; a <= 400; ++a)
    for (std::int64_t sigma = 1; 2 * sigma < a - 63; ++sigma) {
      const std::int64_t tau = a - sigma, b = tau - sigma;
      if (std::gcd(tau, sigma) != 1 || a % 4 == 0) continue;
      const resonant_pair<std::int64_t> p(tau, sigma);
      const minimum_double M = theorem_minimum_double(p);
      const double m4 = std::pow(double(M.m_min), 4), pi4 = std::pow(std::numbers::pi, 4);
      const double bound = double(sigma) / double(tau) * pi4 * m4 / (64 * double(a) * double(a) * double(b) * double(b));
      CHECK(M.r_res * M.r_res <= bound * (1 + 1e-14));
      CHECK(sweep_testing::fast_r_below_quarter_R(tau, sigma, M.m_min, std::int64_t(sweep_quarter_R_scaled(a, b))));
    }
  // pi^4 sigma <= 16 b^2 tau N with tau = 2, sigma = 1 (b = 1), m = 1: 97.41 <= 32 N from N = 4 on.
  CHECK_FALSE(sweep_testing::fast_r_below_quarter_R(2, 1, 1, 3));
  CHECK(sweep_testing::fast_r_below_quarter_R(2, 1, 1, 4));
  CHECK_FALSE(sweep_testing::fast_r_below_quarter_R(2, 1, 1, 0));
  // m = 2: 16 pi^4 = 1558.5 <= 32 N from N = 49 on.
  CHECK_FALSE(sweep_testing::fast_r_below_quarter_R(2, 1, 2, 48));
  CHECK(sweep_testing::fast_r_below_quarter_R(2, 1, 2, 49));
}

TEST_CASE("sweep: the fast path's asy bound is above every computed constant, and the skip keeps a margin", "[sweep]") {
  // t_max = tan u_a(pi/2), rounded up in the bound.
  const double ua = paper_root_double(std::numbers::pi / 2);
  CHECK(std::tan(ua) * (1 + 1e-15) < 0.860333589019381);
  CHECK(std::tan(ua) * (1 + 4e-15) > 0.860333589019381);  // and not by much
  // The bound as one double for the pair (a, b) and its offset am (the sweep's fast path compares
  // products instead, src/lib/sweep/fast.cpp).
  const auto paper_constant_bound_of = [](std::int64_t a, std::int64_t b, std::int64_t am) {
    const paper_bound_fraction f = paper_constant_bound(double(b) / double(a), double(am) / double(b));
    return f.num / f.den;
  };
  std::size_t tested = 0;
  for (std::int64_t a = 5; a <= 700; ++a)
    for (std::int64_t b = (a % 2 ? 1 : 2); 2 * b < a; b += 2) {
      const std::int64_t am = paper_offset(a, b);
      const auto v = paper_error_of(a, b, am);
      const double bound = paper_constant_bound_of(a, b, am);
      INFO(a << " " << b << " " << am);
      CHECK(v.constant <= bound * (1 + 0x1p-47));
      ++tested;
    }
  CHECK(tested > 50000);
  // Where s = pi/2 (b = 1, a tie: |m| = b) and x is small the bound is nearly the constant.
  const auto v = paper_error_of(2999, 1, 1);
  CHECK(paper_constant_bound_of(2999, 1, 1) <= v.constant * (1 + 1e-6));
  // The skip: only strictly below a known constant, beyond the 2^-36 margin.
  CHECK_FALSE(sweep_testing::fast_asy_below(0.1, 0));
  CHECK_FALSE(sweep_testing::fast_asy_below(0.1, 0.1));
  CHECK_FALSE(sweep_testing::fast_asy_below(0.1 * (1 - 0x1p-40), 0.1));
  CHECK(sweep_testing::fast_asy_below(0.1 * (1 - 0x1p-35), 0.1));
}

TEST_CASE("sweep: the fast path's batch inverses give the pass frames' k", "[sweep]") {
  // Blocks spanning several orders (odd, 2 mod 4, and 0 mod 4, which gets 0), as the engine
  // hands them out; and single pairs near 2^31 (Barrett's products near 2^62).
  std::vector<resonant_pair<std::int64_t>> pairs;
  for (std::int64_t a = 3; a <= 260; ++a)
    for (std::int64_t sigma = 1; 2 * sigma < a; ++sigma)
      if (std::gcd(a, sigma) == 1) pairs.emplace_back(a - sigma, sigma);
  const std::int64_t big = (std::int64_t(1) << 31) - 1;  // odd
  for (std::int64_t sigma : {std::int64_t(1), std::int64_t(2), big / 2, big / 3})
    if (std::gcd(big, sigma) == 1) pairs.emplace_back(big - sigma, sigma);
  for (std::int64_t sigma : {std::int64_t(1), std::int64_t(3), (big - 5) / 2 - 2})
    if (std::gcd(big - 5, sigma) == 1) pairs.emplace_back(big - 5 - sigma, sigma);  // 2 mod 4
  std::vector<std::int64_t> ks;
  pass_ks_of_block(pairs, ks);
  REQUIRE(ks.size() == pairs.size());
  std::size_t checked = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::int64_t a = std::int64_t(pairs[i].order()), b = pairs[i].delta();
    INFO(pairs[i].tau() << "," << pairs[i].sigma());
    if (a % 4 == 0) {
      CHECK(ks[i] == 0);
      continue;
    }
    CHECK(ks[i] == std::int64_t(pass_frame(int128(a), int128(b)).k));
    ++checked;
  }
  CHECK(checked > 8000);
}
