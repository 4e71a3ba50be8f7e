#include "pathref/reproduce/stats.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::reproduce {

namespace {
void require_finite(std::span<const double> values, const char* what) {
  for (const double v : values)
    if (!std::isfinite(v)) throw DomainError(std::string(what) + ": every value must be finite");
}
}  // namespace

double mean(std::span<const double> values) {
  require(!values.empty(), "mean: needs at least one value");
  require_finite(values, "mean");
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

double sample_std(std::span<const double> values) {
  require(values.size() >= 2, "sample_std: needs at least two values");
  require_finite(values, "sample_std");
  const double m = mean(values);
  double ss = 0.0;
  for (const double v : values) ss += (v - m) * (v - m);
  return std::sqrt(ss / static_cast<double>(values.size() - 1));
}

double minimum(std::span<const double> values) {
  require(!values.empty(), "minimum: needs at least one value");
  double best = values[0];
  for (const double v : values) {
    require(!std::isnan(v), "minimum: NaN value");
    if (v < best) best = v;
  }
  return best;
}

double maximum(std::span<const double> values) {
  require(!values.empty(), "maximum: needs at least one value");
  double best = values[0];
  for (const double v : values) {
    require(!std::isnan(v), "maximum: NaN value");
    if (v > best) best = v;
  }
  return best;
}

Summary summarize(std::span<const double> values) {
  require_finite(values, "summarize");
  Summary s;
  s.n = values.size();
  if (values.empty()) return s;
  s.mean = mean(values);
  if (values.size() >= 2) s.std = sample_std(values);
  s.min = minimum(values);
  s.max = maximum(values);
  return s;
}

// ---- quantile ------------------------------------------------------------------------------

double quantile_sorted(std::span<const double> sorted, double p) {
  require(!sorted.empty(), "quantile: needs at least one value");
  require_finite(sorted, "quantile");
  require(std::isfinite(p) && p >= 0.0 && p <= 1.0, "quantile: p must lie in [0, 1]");
  for (std::size_t i = 1; i < sorted.size(); ++i)
    require(sorted[i - 1] <= sorted[i], "quantile: values must be ascending");
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const double fj = std::floor(h);
  const auto j = static_cast<std::size_t>(fj);
  if (j >= sorted.size() - 1) return sorted[sorted.size() - 1];
  return sorted[j] + (h - fj) * (sorted[j + 1] - sorted[j]);
}

double quantile(std::span<const double> values, double p) {
  require_finite(values, "quantile");
  std::vector<double> copy(values.begin(), values.end());
  std::sort(copy.begin(), copy.end());
  return quantile_sorted(copy, p);
}

// ---- bootstrap -----------------------------------------------------------------------------

std::string_view to_string(BootStatistic s) noexcept {
  switch (s) {
    case BootStatistic::mean: return "mean";
    case BootStatistic::minimum: return "minimum";
    case BootStatistic::mean_difference: return "mean_difference";
    case BootStatistic::reduction_percent: return "reduction_percent";
    case BootStatistic::sd_difference: return "sd_difference";
  }
  return "mean";
}

BootStatistic parse_boot_statistic(std::string_view name) {
  for (const BootStatistic s : {BootStatistic::mean, BootStatistic::minimum, BootStatistic::mean_difference,
                                BootStatistic::reduction_percent, BootStatistic::sd_difference})
    if (to_string(s) == name) return s;
  throw UsageError("unknown bootstrap statistic '" + std::string(name) +
                   "' (expected mean, minimum, mean_difference, reduction_percent or sd_difference)");
}

namespace {
bool two_sample(BootStatistic s) {
  return s == BootStatistic::mean_difference || s == BootStatistic::reduction_percent ||
         s == BootStatistic::sd_difference;
}

void check_boot_options(const BootstrapOptions& o) {
  require(o.resamples >= 1 && o.resamples <= 1000000, "bootstrap: resamples must lie in [1, 10^6]");
  require(std::isfinite(o.level) && o.level > 0.0 && o.level < 1.0, "bootstrap: level must lie in (0, 1)");
}

void resample(rng::Stream& stream, std::span<const double> from, std::vector<double>& into) {
  for (double& v : into) v = from[rng::uniform_index(stream.next_double(), from.size())];
}

Interval percentile_interval(std::vector<double>& replicates, double level) {
  std::sort(replicates.begin(), replicates.end());
  const double alpha = 1.0 - level;
  return Interval{quantile_sorted(replicates, alpha / 2.0), quantile_sorted(replicates, 1.0 - alpha / 2.0)};
}
}  // namespace

Interval bootstrap_ci(std::span<const double> a, BootStatistic statistic, const BootstrapOptions& options) {
  require(!two_sample(statistic), "bootstrap_ci: '" + std::string(to_string(statistic)) +
                                      "' is a two-sample statistic (use bootstrap_two_sample_ci)");
  require(a.size() >= 2, "bootstrap_ci: needs at least two values");
  require_finite(a, "bootstrap_ci");
  check_boot_options(options);
  rng::Stream stream(options.seed);
  std::vector<double> star(a.size());
  std::vector<double> replicates(options.resamples);
  for (double& r : replicates) {
    resample(stream, a, star);
    r = statistic == BootStatistic::mean ? mean(star) : minimum(star);
  }
  return percentile_interval(replicates, options.level);
}

Interval bootstrap_two_sample_ci(std::span<const double> a, std::span<const double> b, BootStatistic statistic,
                                 const BootstrapOptions& options) {
  require(two_sample(statistic), "bootstrap_two_sample_ci: '" + std::string(to_string(statistic)) +
                                     "' is a one-sample statistic (use bootstrap_ci)");
  require(a.size() >= 2 && b.size() >= 2, "bootstrap_two_sample_ci: each sample needs at least two values");
  require_finite(a, "bootstrap_two_sample_ci");
  require_finite(b, "bootstrap_two_sample_ci");
  if (statistic == BootStatistic::reduction_percent)
    for (const double v : b) require(v > 0.0, "bootstrap_two_sample_ci: reduction_percent needs every b value > 0");
  check_boot_options(options);
  rng::Stream stream(options.seed);
  std::vector<double> sa(a.size());
  std::vector<double> sb(b.size());
  std::vector<double> replicates(options.resamples);
  for (double& r : replicates) {
    resample(stream, a, sa);
    resample(stream, b, sb);
    switch (statistic) {
      case BootStatistic::mean_difference: r = mean(sa) - mean(sb); break;
      case BootStatistic::reduction_percent: r = reduction_percent(mean(sb), mean(sa)); break;
      default: r = sample_std(sa) - sample_std(sb); break;
    }
  }
  return percentile_interval(replicates, options.level);
}

Interval bootstrap_paired_ci(std::span<const double> a, std::span<const double> b, BootStatistic statistic,
                             const BootstrapOptions& options) {
  require(statistic == BootStatistic::mean_difference || statistic == BootStatistic::reduction_percent,
          "bootstrap_paired_ci: the statistic must be mean_difference or reduction_percent");
  require(a.size() == b.size(), "bootstrap_paired_ci: a and b must have the same length (pairs)");
  require(a.size() >= 2, "bootstrap_paired_ci: needs at least two pairs");
  require_finite(a, "bootstrap_paired_ci");
  require_finite(b, "bootstrap_paired_ci");
  if (statistic == BootStatistic::reduction_percent)
    for (const double v : b) require(v > 0.0, "bootstrap_paired_ci: reduction_percent needs every b value > 0");
  check_boot_options(options);
  rng::Stream stream(options.seed);
  std::vector<double> sa(a.size());
  std::vector<double> sb(b.size());
  std::vector<double> replicates(options.resamples);
  for (double& r : replicates) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::size_t k = rng::uniform_index(stream.next_double(), a.size());
      sa[i] = a[k];
      sb[i] = b[k];
    }
    r = statistic == BootStatistic::mean_difference ? mean(sa) - mean(sb) : reduction_percent(mean(sb), mean(sa));
  }
  return percentile_interval(replicates, options.level);
}

// ---- distributions -------------------------------------------------------------------------

namespace {
/// The continued fraction of I_x(a, b) (DLMF 8.17.22) by the modified Lentz method, times the
/// prefactor x^a y^b / (a B(a, b)), y = 1 - x given separately for accuracy.
double betainc_cf(double a, double b, double x, double y) {
  constexpr double tiny = 1e-300;
  constexpr double eps = 1e-16;
  const auto guard = [](double v) { return std::fabs(v) < tiny ? tiny : v; };
  double c = 1.0;
  double d = 1.0 / guard(1.0 - (a + b) * x / (a + 1.0));
  double h = d;
  for (int m = 1; m <= 100000; ++m) {
    const double dm = static_cast<double>(m);
    const double even = dm * (b - dm) * x / ((a + 2.0 * dm - 1.0) * (a + 2.0 * dm));
    d = 1.0 / guard(1.0 + even * d);
    c = guard(1.0 + even / c);
    h *= d * c;
    const double odd = -(a + dm) * (a + b + dm) * x / ((a + 2.0 * dm) * (a + 2.0 * dm + 1.0));
    d = 1.0 / guard(1.0 + odd * d);
    c = guard(1.0 + odd / c);
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < eps) break;
  }
  const double log_prefactor =
      a * std::log(x) + b * std::log(y) - (std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b));
  return std::exp(log_prefactor) * h / a;
}

/// I_x(a, b) with y = 1 - x supplied exactly by the caller.
double betainc_xy(double a, double b, double x, double y) {
  if (x <= 0.0) return 0.0;
  if (y <= 0.0) return 1.0;
  if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - betainc_cf(b, a, y, x);
  return betainc_cf(a, b, x, y);
}
}  // namespace

double betainc(double a, double b, double x) {
  require(std::isfinite(a) && a > 0.0 && std::isfinite(b) && b > 0.0, "betainc: a and b must be finite and > 0");
  require(std::isfinite(x) && x >= 0.0 && x <= 1.0, "betainc: x must lie in [0, 1]");
  return std::clamp(betainc_xy(a, b, x, 1.0 - x), 0.0, 1.0);
}

double student_t_two_sided_p(double t, double df) {
  require(std::isfinite(df) && df > 0.0, "student_t_two_sided_p: df must be finite and > 0");
  require(!std::isnan(t), "student_t_two_sided_p: t is NaN");
  if (std::isinf(t)) return 0.0;
  const double t2 = t * t;
  if (std::isinf(t2)) return 0.0;
  const double x = df / (df + t2);
  const double y = t2 / (df + t2);
  return std::clamp(betainc_xy(df / 2.0, 0.5, x, y), 0.0, 1.0);
}

double normal_two_sided_p(double z) {
  require(!std::isnan(z), "normal_two_sided_p: z is NaN");
  return std::min(1.0, std::erfc(z / std::sqrt(2.0)));
}

// ---- Mann-Whitney ----------------------------------------------------------------------------

namespace {
/// P(U >= u) under H0 without ties: the coefficients of the Gaussian binomial [m + n choose m]_q
/// (the number of orderings with U = k), computed exactly in 128-bit integers as
/// prod_{i=1..m} (1 - q^{n+i}) / (1 - q^i), m = min(n_a, n_b) <= 8.
double exact_upper_tail(std::size_t m, std::size_t n, std::size_t u) {
  __extension__ using i128 = __int128;
  const std::size_t top = m * n;
  std::vector<i128> c(top + m + n + 1, 0);
  c[0] = 1;
  std::size_t deg = 0;
  for (std::size_t i = 1; i <= m; ++i) {
    const std::size_t shift = n + i;
    for (std::size_t k = deg + shift; k >= shift; --k) c[k] -= c[k - shift];
    for (std::size_t k = i; k <= deg + shift; ++k) c[k] += c[k - i];
    deg += n;
  }
  i128 total = 0;
  i128 tail = 0;
  for (std::size_t k = 0; k <= top; ++k) {
    total += c[k];
    if (k >= u) tail += c[k];
  }
  return static_cast<double>(tail) / static_cast<double>(total);
}
}  // namespace

MannWhitney mann_whitney(std::span<const double> a, std::span<const double> b) {
  require(!a.empty() && !b.empty(), "mann_whitney: each sample needs at least one value");
  require(a.size() <= 100000 && b.size() <= 100000, "mann_whitney: at most 100000 values per sample");
  require_finite(a, "mann_whitney");
  require_finite(b, "mann_whitney");
  const std::size_t na = a.size();
  const std::size_t nb = b.size();
  const std::size_t n = na + nb;
  std::vector<std::pair<double, bool>> pooled;  // (value, from a)
  pooled.reserve(n);
  for (const double v : a) pooled.emplace_back(v, true);
  for (const double v : b) pooled.emplace_back(v, false);
  std::stable_sort(pooled.begin(), pooled.end(),
                   [](const auto& l, const auto& r) { return l.first < r.first; });
  double rank_sum_a = 0.0;
  std::uint64_t tie_term = 0;
  bool ties = false;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && pooled[j + 1].first == pooled[i].first) ++j;
    const std::size_t t = j - i + 1;
    if (t > 1) ties = true;
    tie_term += static_cast<std::uint64_t>(t) * t * t - t;
    const double midrank = static_cast<double>(i + j + 2) / 2.0;  // 1-based ranks i+1 .. j+1
    for (std::size_t k = i; k <= j; ++k)
      if (pooled[k].second) rank_sum_a += midrank;
    i = j + 1;
  }
  const double dna = static_cast<double>(na);
  const double dnb = static_cast<double>(nb);
  MannWhitney r;
  r.u_a = rank_sum_a - dna * (dna + 1.0) / 2.0;
  r.u_b = dna * dnb - r.u_a;
  const double u = std::max(r.u_a, r.u_b);
  if (std::min(na, nb) <= 8 && !ties) {
    r.exact = true;
    r.p = std::min(1.0, 2.0 * exact_upper_tail(std::min(na, nb), std::max(na, nb), static_cast<std::size_t>(u)));
    return r;
  }
  const double dn = static_cast<double>(n);
  const double sigma =
      std::sqrt(dna * dnb / 12.0 * ((dn + 1.0) - static_cast<double>(tie_term) / (dn * (dn - 1.0))));
  if (!(sigma > 0.0)) {
    r.p = 1.0;
    return r;
  }
  const double z = (u - dna * dnb / 2.0 - 0.5) / sigma;
  r.z = z;
  r.p = normal_two_sided_p(z);
  return r;
}

// ---- Welch -----------------------------------------------------------------------------------

Welch welch(std::span<const double> a, std::span<const double> b) {
  require(a.size() >= 2 && b.size() >= 2, "welch: each sample needs at least two values");
  require_finite(a, "welch");
  require_finite(b, "welch");
  const double sa = sample_std(a);
  const double sb = sample_std(b);
  const double va = sa * sa / static_cast<double>(a.size());
  const double vb = sb * sb / static_cast<double>(b.size());
  const double se2 = va + vb;
  Welch w;
  w.mean_difference = mean(a) - mean(b);
  if (se2 == 0.0) {
    w.t = w.mean_difference == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), w.mean_difference);
    w.p = w.mean_difference == 0.0 ? 1.0 : 0.0;
    return w;
  }
  w.t = w.mean_difference / std::sqrt(se2);
  const double df = se2 * se2 / (va * va / static_cast<double>(a.size() - 1) + vb * vb / static_cast<double>(b.size() - 1));
  w.df = df;
  w.p = student_t_two_sided_p(w.t, df);
  return w;
}

std::optional<double> welch_t(std::span<const double> a, std::span<const double> b) {
  const Welch w = welch(a, b);
  if (!w.df) return std::nullopt;
  return w.t;
}

// ---- judging ---------------------------------------------------------------------------------

std::string_view to_string(Verdict v) noexcept {
  switch (v) {
    case Verdict::holds: return "holds";
    case Verdict::fails: return "does not hold";
    case Verdict::not_significant: return "not significant";
    case Verdict::inconclusive: return "inconclusive";
    case Verdict::untestable: return "cannot be tested";
  }
  return "cannot be tested";
}

std::string_view to_string(Direction d) noexcept {
  switch (d) {
    case Direction::none: return "none";
    case Direction::pathref_better: return "pathref better";
    case Direction::pathref_worse: return "pathref worse";
    case Direction::as_claimed: return "as claimed";
    case Direction::opposite: return "opposite";
    case Direction::equal: return "equal";
  }
  return "none";
}

std::string verdict_text(Verdict v, Direction d) {
  switch (v) {
    case Verdict::holds: return "holds";
    case Verdict::untestable: return "cannot be tested";
    case Verdict::fails:
      if (d == Direction::pathref_better) return "does not hold — pathref better";
      if (d == Direction::pathref_worse) return "does not hold — pathref worse";
      if (d == Direction::opposite) return "does not hold — the opposite is significant";
      return "does not hold";
    case Verdict::not_significant:
      if (d == Direction::as_claimed) return "not significant — difference as claimed";
      if (d == Direction::opposite) return "not significant — difference opposite";
      return "not significant — no difference";
    case Verdict::inconclusive:
      if (d == Direction::pathref_better) return "inconclusive — pathref better";
      if (d == Direction::pathref_worse) return "inconclusive — pathref worse";
      return "inconclusive — interval wider than the margin";
  }
  return "cannot be tested";
}

std::string_view to_string(Quantity q) noexcept {
  switch (q) {
    case Quantity::length: return "length";
    case Quantity::turns: return "turns";
    case Quantity::iterations: return "iterations";
    case Quantity::time: return "time";
    case Quantity::percent: return "percent";
  }
  return "length";
}

Quantity parse_quantity(std::string_view name) {
  for (const Quantity q : {Quantity::length, Quantity::turns, Quantity::iterations, Quantity::time, Quantity::percent})
    if (to_string(q) == name) return q;
  throw UsageError("unknown quantity '" + std::string(name) +
                   "' (expected length, turns, iterations, time or percent)");
}

double equivalence_margin(Quantity q, double paper_value) {
  require(std::isfinite(paper_value), "equivalence_margin: the paper's value must be finite");
  const double mag = std::fabs(paper_value);
  switch (q) {
    case Quantity::length: return 0.01 * mag;
    case Quantity::turns: return 1.0;
    case Quantity::iterations: return std::max(1.0, 0.1 * mag);
    case Quantity::time: return 0.05 * mag;
    case Quantity::percent: return 5.0;
  }
  return 0.0;
}

Judgement judge_equivalence(Interval ci, double paper, double margin, Sense sense) {
  require(std::isfinite(ci.lo) && std::isfinite(ci.hi) && ci.lo <= ci.hi,
          "judge_equivalence: the interval must be finite with lo <= hi");
  require(std::isfinite(paper), "judge_equivalence: the paper's value must be finite");
  require(std::isfinite(margin) && margin >= 0.0, "judge_equivalence: the margin must be finite and >= 0");
  const double low_edge = paper - margin;
  const double high_edge = paper + margin;
  const Direction lower = sense == Sense::lower_is_better ? Direction::pathref_better : Direction::pathref_worse;
  const Direction higher = sense == Sense::lower_is_better ? Direction::pathref_worse : Direction::pathref_better;
  if (low_edge <= ci.lo && ci.hi <= high_edge) return {Verdict::holds, Direction::none};
  if (ci.hi < low_edge) return {Verdict::fails, lower};
  if (ci.lo > high_edge) return {Verdict::fails, higher};
  const bool below = ci.lo < low_edge;
  const bool above = ci.hi > high_edge;
  if (below && above) return {Verdict::inconclusive, Direction::none};
  return {Verdict::inconclusive, below ? lower : higher};
}

Judgement judge_comparison(double p, double alpha, Direction observed) {
  require(std::isfinite(p) && p >= 0.0 && p <= 1.0, "judge_comparison: p must lie in [0, 1]");
  require(std::isfinite(alpha) && alpha > 0.0 && alpha < 1.0, "judge_comparison: alpha must lie in (0, 1)");
  require(observed == Direction::as_claimed || observed == Direction::opposite || observed == Direction::equal,
          "judge_comparison: the observed direction must be as_claimed, opposite or equal");
  if (p < alpha && observed == Direction::as_claimed) return {Verdict::holds, Direction::as_claimed};
  if (p < alpha && observed == Direction::opposite) return {Verdict::fails, Direction::opposite};
  return {Verdict::not_significant, observed};
}

Judgement judge_interval_comparison(Interval ci, Claimed claim) {
  require(std::isfinite(ci.lo) && std::isfinite(ci.hi) && ci.lo <= ci.hi,
          "judge_interval_comparison: the interval must be finite with lo <= hi");
  // Work in "a - b below 0 is as claimed" terms.
  const double lo = claim == Claimed::a_less ? ci.lo : -ci.hi;
  const double hi = claim == Claimed::a_less ? ci.hi : -ci.lo;
  if (hi < 0.0) return {Verdict::holds, Direction::as_claimed};
  if (lo > 0.0) return {Verdict::fails, Direction::opposite};
  const double mid = lo / 2.0 + hi / 2.0;
  return {Verdict::not_significant, mid < 0.0 ? Direction::as_claimed : mid > 0.0 ? Direction::opposite : Direction::equal};
}

ValueAssessment assess_value(std::span<const double> runs, double paper, Quantity quantity, Sense sense,
                             const BootstrapOptions& options, BootStatistic statistic) {
  ValueAssessment v;
  v.summary = summarize(runs);
  v.statistic = statistic;
  v.ci = bootstrap_ci(runs, statistic, options);
  v.paper = paper;
  v.quantity = quantity;
  v.margin = equivalence_margin(quantity, paper);
  v.judgement = judge_equivalence(v.ci, paper, v.margin, sense);
  return v;
}

ValueAssessment assess_exact_value(double x, double paper, Quantity quantity, Sense sense) {
  require(std::isfinite(x), "assess_exact_value: the value must be finite");
  const double one[] = {x};
  ValueAssessment v;
  v.summary = summarize(one);
  v.ci = Interval{x, x};
  v.paper = paper;
  v.quantity = quantity;
  v.margin = equivalence_margin(quantity, paper);
  v.judgement = judge_equivalence(v.ci, paper, v.margin, sense);
  return v;
}

ComparisonAssessment compare_samples(std::span<const double> a, std::span<const double> b, Claimed claim,
                                     double alpha) {
  require(std::isfinite(alpha) && alpha > 0.0 && alpha < 1.0, "compare_samples: alpha must lie in (0, 1)");
  ComparisonAssessment c;
  c.claim = claim;
  c.alpha = alpha;
  c.mann_whitney = mann_whitney(a, b);
  c.a = summarize(a);
  c.b = summarize(b);
  if (a.size() >= 2 && b.size() >= 2) c.welch = welch(a, b);
  const double half = static_cast<double>(a.size()) * static_cast<double>(b.size()) / 2.0;
  const double ua = c.mann_whitney.u_a;
  Direction observed = Direction::equal;
  if (ua != half) {
    const bool a_lower = ua < half;
    observed = (a_lower == (claim == Claimed::a_less)) ? Direction::as_claimed : Direction::opposite;
  }
  c.judgement = judge_comparison(c.mann_whitney.p, alpha, observed);
  return c;
}

// ---- printed numbers -------------------------------------------------------------------------

double reduction_percent(double from, double to) {
  require(std::isfinite(from) && from > 0.0, "reduction_percent: 'from' must be finite and > 0");
  require(std::isfinite(to), "reduction_percent: 'to' must be finite");
  return 100.0 * (from - to) / from;
}

int printed_decimals(std::string_view printed) {
  std::size_t i = 0;
  if (i < printed.size() && printed[i] == '-') ++i;
  const std::size_t int_start = i;
  while (i < printed.size() && printed[i] >= '0' && printed[i] <= '9') ++i;
  require(i > int_start, "printed_decimals: expected digits in '" + std::string(printed) + "'");
  if (i == printed.size()) return 0;
  require(printed[i] == '.', "printed_decimals: expected a decimal number, got '" + std::string(printed) + "'");
  ++i;
  const std::size_t frac_start = i;
  while (i < printed.size() && printed[i] >= '0' && printed[i] <= '9') ++i;
  require(i == printed.size() && i > frac_start,
          "printed_decimals: expected a decimal number, got '" + std::string(printed) + "'");
  return static_cast<int>(i - frac_start);
}

std::string fixed(double value, int decimals) {
  require(std::isfinite(value), "fixed: value must be finite");
  require(decimals >= 0 && decimals <= 17, "fixed: decimals must lie in [0, 17]");
  return fmt::format("{:.{}f}", value, decimals);
}

bool matches_printed(double value, std::string_view printed) {
  return fixed(value, printed_decimals(printed)) == printed;
}

Judgement judge_printed(double value, std::string_view printed, Sense sense) {
  if (matches_printed(value, printed)) return Judgement{Verdict::holds, Direction::none};
  const double paper = std::stod(std::string(printed));
  const bool higher = value > paper;
  const bool better = sense == Sense::higher_is_better ? higher : !higher;
  return Judgement{Verdict::fails, better ? Direction::pathref_better : Direction::pathref_worse};
}

Verdict judge_about_percent(double ours, double claimed) {
  require(std::isfinite(ours) && std::isfinite(claimed), "judge_about_percent: values must be finite");
  return std::fabs(ours - claimed) <= about_percent_tolerance ? Verdict::holds : Verdict::fails;
}

}  // namespace pathref::reproduce
