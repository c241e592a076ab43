// include/gyrores/sweep/summary.hpp: reals as text, the mergeable accumulator, its quantiles.
#include <gyrores/sweep/summary.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <gyrores/core/error.hpp>

namespace gyrores {

std::string sweep_double_text(double v) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

double sweep_text_double(const std::string& s) {
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) throw compute_error("not a real number: '" + s + "'");
  return v;
}

namespace {

// Keeps the k earliest examples; input may come out of order (merging shards).
void add_example(sweep_tally& t, const sweep_pair_id& p, std::size_t k) {
  if (t.examples.size() < k) {
    t.examples.push_back(p);
    return;
  }
  if (k > 0 && sweep_pair_before(p, t.examples.back())) {
    t.examples.back() = p;
    std::sort(t.examples.begin(), t.examples.end(), sweep_pair_before);
  }
}

void merge_tally(sweep_tally& t, const sweep_tally& o, std::size_t k) {
  t.checked += o.checked;
  t.violations += o.violations;
  std::vector<sweep_pair_id> all = t.examples;
  all.insert(all.end(), o.examples.begin(), o.examples.end());
  std::sort(all.begin(), all.end(), sweep_pair_before);
  all.erase(std::unique(all.begin(), all.end()), all.end());
  if (all.size() > k) all.resize(k);
  t.examples = std::move(all);
}

// floor(num/den * (n-1)) without overflow for n < 2^63.
std::uint64_t quantile_rank(std::uint64_t n, std::uint64_t num, std::uint64_t den) {
  return std::uint64_t((unsigned __int128)(n - 1) * num / den);
}

// v as a double the way a merge of rows reads it back; for T wider than double also its text.
template <class T> double record_value(const T& v, unsigned digits, std::string* text) {
  if constexpr (std::is_same_v<T, double>) {
    return v;
  } else {
    std::string t = sweep_real_text(v, digits);
    if (text) *text = t;
    return sweep_text_double(t);
  }
}

}  // namespace

template <class T> void sweep_record_fill(sweep_record& s, const sweep_row<T>& r, unsigned digits) {
  s.tau = r.tau, s.sigma = r.sigma, s.delta_mod4 = r.delta_mod4, s.failed = r.failed, s.status = r.status;
  s.first_at_paper_node = r.first_at_paper_node, s.has_ratio = r.has_ratio, s.has_asy = r.has_asy;
  s.t_ratio = r.has_ratio ? record_value(r.t_ratio, digits, nullptr) : 0;
  s.asy_ratio_text.clear();
  s.asy_constant_text.clear();
  s.asy_ratio = r.has_asy ? record_value(r.asy_ratio, digits, &s.asy_ratio_text) : 0;
  s.asy_constant = r.has_asy ? record_value(r.asy_constant, digits, &s.asy_constant_text) : 0;
}

GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_RECORD_INSTANCES, )

bool sweep_pair_before(const sweep_pair_id& x, const sweep_pair_id& y) {
  std::int64_t ax = x.first + x.second, ay = y.first + y.second;
  return ax != ay ? ax < ay : x.second < y.second;
}

std::string sweep_extreme::str() const { return text.empty() ? sweep_double_text(value) : text; }

void sweep_extreme::offer(double v, const std::string& t, const sweep_pair_id& p) {
  if (std::isnan(v)) return;
  if (!set || v > value || (v == value && sweep_pair_before(p, pair))) {
    set = true;
    value = v;
    text = t;
    pair = p;
  }
}

void sweep_extreme::merge(const sweep_extreme& o) {
  if (o.set) offer(o.value, o.text, o.pair);
}

bool sweep_extreme::operator==(const sweep_extreme& o) const {
  return set == o.set && (!set || (value == o.value && pair == o.pair && str() == o.str()));
}

void sweep_accumulator::add(const sweep_record& r) {
  const sweep_pair_id id{r.tau, r.sigma};
  ++pairs;
  if (r.delta_mod4 == 2) ++degenerate;
  if (r.failed) {
    ++errors.violations;
    add_example(errors, id, max_examples);
    return;
  }
  for (int i = 0; i < sweep_check_count; ++i) {
    if (r.status[i] == sweep_status::none) continue;
    ++checks[i].checked;
    if (r.status[i] == sweep_status::fail) {
      ++checks[i].violations;
      add_example(checks[i], id, max_examples);
    }
  }
  if (r.first_at_paper_node == 1) ++first_at_paper_node;
  if (r.has_ratio) t_ratios.add(r.t_ratio);
  if (r.has_asy) {
    asy_ratio_max.offer(r.asy_ratio, r.asy_ratio_text, id);
    sharp_constant.offer(r.asy_constant, r.asy_constant_text, id);
  }
}

void sweep_accumulator::merge(const sweep_accumulator& o) {
  pairs += o.pairs;
  degenerate += o.degenerate;
  first_at_paper_node += o.first_at_paper_node;
  for (int i = 0; i < sweep_check_count; ++i) merge_tally(checks[i], o.checks[i], max_examples);
  merge_tally(errors, o.errors, max_examples);
  asy_ratio_max.merge(o.asy_ratio_max);
  sharp_constant.merge(o.sharp_constant);
  t_ratios.merge(o.t_ratios);
}

sweep_quantiles sweep_accumulator::quantiles() const {
  sweep_quantiles q;
  const std::uint64_t n = t_ratios.size();
  q.count = n;
  if (n == 0) return q;
  sweep_selection_options opt;
  // In memory a pass is cheap (~2.5 ns a value) and collecting is not: with up to 2^22
  // candidates the first pass would collect every value of a mid-sized sweep into one group and
  // pick all 7 ranks from it (3.2e6 values, order 5000: 67 ms, against 15 ms for counting first
  // by 16 bits, 2^16 counters that stay in cache, and collecting at most n/16). From a file each
  // pass reads it all again: there the defaults save a pass.
  if (t_ratios.in_memory()) {
    opt.bits = 16;
    opt.collect_limit = std::clamp<std::uint64_t>(n / 16, std::uint64_t(1) << 12, std::uint64_t(1) << 20);
  }
  std::vector<std::uint64_t> ranks;
  for (std::uint64_t percent : {0, 1, 10, 50, 90, 99, 100}) ranks.push_back(quantile_rank(n, percent, 100));
  const auto v = sweep_order_statistics([this](const sweep_value_sink& s) { t_ratios.replay(s); }, n, ranks, opt);
  double* out[] = {&q.min, &q.p01, &q.p10, &q.median, &q.p90, &q.p99, &q.max};
  for (std::size_t i = 0; i < v.size(); ++i) *out[i] = v[i];
  return q;
}

}  // namespace gyrores
