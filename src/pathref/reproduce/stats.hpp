#pragma once
/// \file stats.hpp
/// The statistics of every `pathref reproduce` report as small pure functions: summaries (mean,
/// sample sd, min, max), the type-7 quantile, a seeded percentile bootstrap drawing only from
/// rng::Stream, the Mann-Whitney U test, Welch's t test (with the regularized incomplete beta
/// function behind Student's t), the equivalence margins per kind of quantity, and the rules that
/// turn them into a verdict on a paper's claim.
///
/// How a reproduction uses it (spec/stats.md "Judging a claim"):
///  - a claimed VALUE ("IHA's mean length is 29.8"): `assess_value(runs, paper, Quantity::length,
///    Sense::lower_is_better, {seed})` -> summary, 95 % bootstrap CI, margin, verdict, direction;
///  - a COMPARISON ("A is shorter than B"): `compare_samples(a, b, Claimed::a_less)` ->
///    Mann-Whitney U (the deciding test, alpha = 0.05, two-sided) and Welch's t (reported);
///  - a comparison of a statistic other than location (e.g. "A's sd is smaller"):
///    `bootstrap_two_sample_ci(a, b, BootStatistic::sd_difference, {seed})` and
///    `judge_interval_comparison(ci, Claimed::a_less)`.
///  - text for a report: `verdict_text(verdict, direction)`; JSON: report.hpp `*_json`.
///
/// Spec: spec/stats.md (stats.*), spec/reproduce.md (how the reports apply them)
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace pathref::reproduce {

// ---------------------------------------------------------------------------------------------
// Summaries
// ---------------------------------------------------------------------------------------------

/// Arithmetic mean: (x_0 + x_1 + ... + x_{n-1}) / n, summed left to right in binary64.
/// Spec: stats.mean (also reproduce.stats). Pre: n >= 1, every value finite (DomainError).
[[nodiscard]] double mean(std::span<const double> values);

/// Sample standard deviation (Bessel's n - 1): sqrt(sum_i (x_i - m)^2 / (n - 1)), m = mean(x),
/// two passes, sums left to right. Spec: stats.sd (also reproduce.stats). Pre: n >= 2, every
/// value finite (DomainError). Post: >= 0; 0 iff all values are equal.
[[nodiscard]] double sample_std(std::span<const double> values);

/// The smallest value. Spec: reproduce.stats. Pre: n >= 1, no NaN (DomainError).
[[nodiscard]] double minimum(std::span<const double> values);
/// The largest value. Spec: reproduce.stats. Pre: n >= 1, no NaN (DomainError).
[[nodiscard]] double maximum(std::span<const double> values);

/// Summary of a sample: n, mean, sample std (nullopt for n < 2), min, max; all nullopt for n = 0.
struct Summary {
  std::size_t n = 0;
  std::optional<double> mean;
  std::optional<double> std;
  std::optional<double> min;
  std::optional<double> max;
};
/// summary of `values` (any n >= 0). Spec: reproduce.stats. Pre: every value finite (DomainError).
[[nodiscard]] Summary summarize(std::span<const double> values);

/// Quantile of type 7 (Hyndman & Fan 1996; NumPy's and R's default) of an ascending sample:
/// h = fl((n - 1) p), j = floor(h); x_j + (h - j)(x_{j+1} - x_j) for j < n - 1, else x_{n-1}.
/// Spec: stats.quantile. Pre: n >= 1, values finite and ascending, 0 <= p <= 1 (DomainError).
[[nodiscard]] double quantile_sorted(std::span<const double> sorted, double p);
/// quantile_sorted of an ascending copy of `values`. Spec: stats.quantile. Pre: as above, any order.
[[nodiscard]] double quantile(std::span<const double> values, double p);

// ---------------------------------------------------------------------------------------------
// Seeded percentile bootstrap
// ---------------------------------------------------------------------------------------------

/// A closed interval [lo, hi].
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

/// What a bootstrap replicate computes. One sample: `mean`, `minimum` (of the resample a*).
/// Two samples (a* and b* resampled independently): `mean_difference` = mean(a*) - mean(b*),
/// `reduction_percent` = 100 (mean(b*) - mean(a*)) / mean(b*) (a's reduction against b),
/// `sd_difference` = sd(a*) - sd(b*).
enum class BootStatistic { mean, minimum, mean_difference, reduction_percent, sd_difference };
/// "mean" | "minimum" | "mean_difference" | "reduction_percent" | "sd_difference".
[[nodiscard]] std::string_view to_string(BootStatistic s) noexcept;
/// The inverse of to_string (UsageError naming the valid values otherwise).
[[nodiscard]] BootStatistic parse_boot_statistic(std::string_view name);

/// Bootstrap settings: the stream's seed, the number B of resamples, the confidence level.
struct BootstrapOptions {
  std::uint32_t seed = 1;
  std::size_t resamples = 2000;
  double level = 0.95;
};

/// Percentile bootstrap confidence interval of a one-sample statistic (`mean` or `minimum`).
/// Draw order: rng::Stream(seed); for r = 0 .. B-1, for i = 0 .. n-1: a*_i = a[uniform_index(u, n)]
/// (one double u each); replicate r = statistic(a*) (sums left to right in draw order); the B
/// replicates sorted ascending; alpha = fl(1 - level); [quantile_sorted(alpha / 2),
/// quantile_sorted(1 - alpha / 2)]. Spec: stats.bootstrap_ci.
/// Pre: n >= 2, values finite, 1 <= B <= 10^6, 0 < level < 1, statistic one-sample (DomainError).
/// Post: lo <= hi, both within [min a, max a].
[[nodiscard]] Interval bootstrap_ci(std::span<const double> a, BootStatistic statistic,
                                    const BootstrapOptions& options);

/// Percentile bootstrap interval of a two-sample statistic (`mean_difference`,
/// `reduction_percent`, `sd_difference`): as bootstrap_ci, each replicate drawing all n_a indices
/// of a* first, then all n_b indices of b*, from the one stream. Spec: stats.bootstrap_ci.
/// Pre: n_a, n_b >= 2, values finite, 1 <= B <= 10^6, 0 < level < 1, statistic two-sample;
/// reduction_percent: every b value > 0 (DomainError).
[[nodiscard]] Interval bootstrap_two_sample_ci(std::span<const double> a, std::span<const double> b,
                                               BootStatistic statistic,
                                               const BootstrapOptions& options);

/// Paired percentile bootstrap interval over the pairs (a_i, b_i) (maps on which both arms ran):
/// as bootstrap_ci, each replicate drawing n indices k_0 .. k_{n-1} (one double each, rng.index(u, n))
/// and taking a*_i = a[k_i] AND b*_i = b[k_i] (the pairs stay together); statistics
/// `mean_difference` = mean(a*) - mean(b*) and `reduction_percent` = 100 (mean(b*) - mean(a*)) /
/// mean(b*) (a's reduction against b, e.g. a = the kinematic A*'s child nodes, b = the 8-direction
/// search's on the same maps). Spec: stats.bootstrap_ci (paired).
/// Pre: n_a = n_b >= 2, values finite, 1 <= B <= 10^6, 0 < level < 1, statistic mean_difference or
/// reduction_percent; reduction_percent: every b value > 0 (DomainError).
[[nodiscard]] Interval bootstrap_paired_ci(std::span<const double> a, std::span<const double> b,
                                           BootStatistic statistic, const BootstrapOptions& options);

// ---------------------------------------------------------------------------------------------
// Distributions and tests
// ---------------------------------------------------------------------------------------------

/// Regularized incomplete beta function I_x(a, b) = B(x; a, b) / B(a, b), by the continued
/// fraction of the spec (modified Lentz), on I_{1-x}(b, a) = 1 - I_x(a, b) when
/// x > (a + 1) / (a + b + 2). Spec: stats.betainc.
/// Pre: a > 0, b > 0, 0 <= x <= 1, all finite (DomainError). Post: in [0, 1].
[[nodiscard]] double betainc(double a, double b, double x);

/// Two-sided p of Student's t: P(|T_df| >= |t|) = I_{df / (df + t^2)}(df / 2, 1 / 2); 0 for
/// |t| = inf. Spec: stats.student_t. Pre: df > 0 finite, t not NaN (DomainError).
[[nodiscard]] double student_t_two_sided_p(double t, double df);

/// Two-sided p of the standard normal: min(1, erfc(z / sqrt 2)) for the signed z of a one-sided
/// statistic doubled (z < 0 gives 1); erfc(|z| / sqrt 2) is P(|Z| >= |z|) when z >= 0.
/// Spec: stats.mann_whitney. Pre: z not NaN (DomainError).
[[nodiscard]] double normal_two_sided_p(double z);

/// Result of the Mann-Whitney U test of samples a and b (two-sided).
struct MannWhitney {
  double u_a = 0.0;  ///< #pairs (i, j) with a_i > b_j + 0.5 #ties (= R_a - n_a (n_a + 1) / 2)
  double u_b = 0.0;  ///< n_a n_b - u_a
  bool exact = false;       ///< the exact null distribution was used (else the normal one)
  std::optional<double> z;  ///< normal approximation: (max(u_a, u_b) - n_a n_b / 2 - 1/2) / sigma
  double p = 1.0;           ///< two-sided p value
};
/// Mann-Whitney U test (Wilcoxon rank-sum), two-sided, as SciPy's mannwhitneyu(method='auto',
/// use_continuity=True): midranks for ties; EXACT null distribution of U iff min(n_a, n_b) <= 8
/// and no two pooled values are equal: p = min(1, 2 P(U >= max(u_a, u_b))); otherwise the NORMAL
/// approximation with tie correction sigma^2 = n_a n_b / 12 ((n + 1) - sum(t^3 - t) / (n (n - 1)))
/// and continuity correction 1/2: p = normal_two_sided_p(z); all values equal (sigma = 0): p = 1.
/// Spec: stats.mann_whitney. Pre: n_a, n_b >= 1, n_a + n_b >= 3, values finite,
/// n_a, n_b <= 100000 (DomainError).
[[nodiscard]] MannWhitney mann_whitney(std::span<const double> a, std::span<const double> b);

/// Result of Welch's unequal-variance t test of a against b (two-sided).
struct Welch {
  double mean_difference = 0.0;  ///< mean(a) - mean(b)
  double t = 0.0;                ///< mean_difference / sqrt(s_a^2/n_a + s_b^2/n_b); +-inf or 0 (se = 0)
  std::optional<double> df;      ///< Welch-Satterthwaite degrees of freedom (nullopt when se = 0)
  double p = 1.0;                ///< two-sided p (student_t_two_sided_p); se = 0: 1 if equal means, else 0
};
/// Welch's t test. Spec: stats.welch. Pre: n_a, n_b >= 2, values finite (DomainError).
[[nodiscard]] Welch welch(std::span<const double> a, std::span<const double> b);

/// Welch's t statistic alone (nullopt when se = 0). Spec: stats.welch. Pre: as welch.
[[nodiscard]] std::optional<double> welch_t(std::span<const double> a, std::span<const double> b);

// ---------------------------------------------------------------------------------------------
// Judging a claim
// ---------------------------------------------------------------------------------------------

/// The verdict on one claim (spec stats.compare, stats.equivalence).
enum class Verdict {
  holds,            ///< the claim is true on pathref's runs by the rule stated for it
  fails,            ///< "does not hold": significantly against the claim (direction stated)
  not_significant,  ///< a comparison whose difference is not significant at alpha
  inconclusive,     ///< a value claim whose interval crosses an edge of the margin band
  untestable,       ///< it cannot be tested here (reason stated beside it)
};
/// "holds" | "does not hold" | "not significant" | "inconclusive" | "cannot be tested".
[[nodiscard]] std::string_view to_string(Verdict v) noexcept;

/// Which way the evidence points. Value claims: pathref's value against the paper's
/// (`pathref_better`, `pathref_worse`, `none` = holds or an interval wider than the margin band).
/// Comparisons: pathref's observed difference against the claimed one (`as_claimed`, `opposite`,
/// `equal`).
enum class Direction { none, pathref_better, pathref_worse, as_claimed, opposite, equal };
/// "none" | "pathref better" | "pathref worse" | "as claimed" | "opposite" | "equal".
[[nodiscard]] std::string_view to_string(Direction d) noexcept;

/// A verdict with its direction, as the reports print it: "holds"; "does not hold — pathref
/// better"; "does not hold — pathref worse"; "does not hold — the opposite is significant";
/// "not significant — difference as claimed" / "— difference opposite" / "— no difference";
/// "inconclusive — pathref better" / "— pathref worse" / "— interval wider than the margin";
/// "cannot be tested". Spec: stats.equivalence, stats.compare.
[[nodiscard]] std::string verdict_text(Verdict v, Direction d);

/// Which way a quantity is better: lengths, turns, iterations, times are lower_is_better;
/// reductions and success rates higher_is_better.
enum class Sense { lower_is_better, higher_is_better };

/// The kinds of claimed quantity, each with the equivalence margin of stats.margin.
enum class Quantity {
  length,      ///< a path length (m or cells): +- 1 % of the paper's value
  turns,       ///< a number of turns: +- 1 turn
  iterations,  ///< iterations / generations to converge: +- max(1, 10 % of the paper's value)
  time,        ///< a time in seconds (simulated or physical): +- 5 % of the paper's value
  percent,     ///< a percentage (a reduction, a rate): +- 5 percentage points
};
/// "length" | "turns" | "iterations" | "time" | "percent".
[[nodiscard]] std::string_view to_string(Quantity q) noexcept;
/// The inverse of to_string (UsageError naming the valid values otherwise).
[[nodiscard]] Quantity parse_quantity(std::string_view name);

/// The equivalence margin m >= 0 of a claimed value of this kind (the table of stats.margin,
/// fixed before any run). Spec: stats.margin. Pre: paper value finite (DomainError).
[[nodiscard]] double equivalence_margin(Quantity q, double paper_value);

/// Verdict and direction of a judgement.
struct Judgement {
  Verdict verdict = Verdict::untestable;
  Direction direction = Direction::none;
};

/// Judges a claimed value by an interval (stats.equivalence): holds iff
/// paper - margin <= lo and hi <= paper + margin; fails iff hi < paper - margin (pathref lower)
/// or lo > paper + margin (pathref higher), the direction better/worse by `sense`; otherwise
/// inconclusive, the direction that of the side the interval crosses (none when it crosses both).
/// Spec: stats.equivalence. Pre: lo <= hi, all finite, margin >= 0 (DomainError).
[[nodiscard]] Judgement judge_equivalence(Interval ci, double paper, double margin, Sense sense);

/// The claimed order of a comparison of a against b: a_less ("A is shorter / fewer / faster
/// than B"), a_greater.
enum class Claimed { a_less, a_greater };

/// Judges a comparison from a two-sided p value and the observed order (stats.compare):
/// `observed` is Direction::as_claimed, opposite or equal (the caller's test statistic says which);
/// holds iff p < alpha and observed = as_claimed; fails (direction opposite) iff p < alpha and
/// observed = opposite; otherwise not_significant with the observed direction.
/// Spec: stats.compare. Pre: 0 <= p <= 1, 0 < alpha < 1, observed one of the three (DomainError).
[[nodiscard]] Judgement judge_comparison(double p, double alpha, Direction observed);

/// Judges a comparison from a bootstrap interval of a - b (mean_difference, sd_difference):
/// a_less: holds iff hi < 0, fails (opposite) iff lo > 0; a_greater mirrored; otherwise
/// not_significant, the direction that of the interval's midpoint (equal when 0).
/// Spec: stats.compare. Pre: lo <= hi, finite (DomainError).
[[nodiscard]] Judgement judge_interval_comparison(Interval ci, Claimed claim);

/// Everything a report prints for a claimed value.
struct ValueAssessment {
  Summary summary;        ///< of the runs
  BootStatistic statistic = BootStatistic::mean;
  Interval ci;            ///< the bootstrap interval of the statistic ([x, x] when exact)
  double paper = 0.0;
  Quantity quantity = Quantity::length;
  double margin = 0.0;    ///< equivalence_margin(quantity, paper)
  Judgement judgement;
};
/// A claimed value of a stochastic planner: bootstrap_ci(runs, statistic, options), the margin of
/// `quantity`, judge_equivalence. Spec: stats.equivalence.
/// Pre: as bootstrap_ci (n >= 2), paper finite (DomainError).
[[nodiscard]] ValueAssessment assess_value(std::span<const double> runs, double paper, Quantity quantity,
                                           Sense sense, const BootstrapOptions& options,
                                           BootStatistic statistic = BootStatistic::mean);
/// A claimed value that pathref computes exactly (a deterministic planner, one run): the
/// interval [x, x]. Spec: stats.equivalence. Pre: x, paper finite (DomainError).
[[nodiscard]] ValueAssessment assess_exact_value(double x, double paper, Quantity quantity, Sense sense);

/// Everything a report prints for a comparison of two samples.
struct ComparisonAssessment {
  Summary a;
  Summary b;
  Claimed claim = Claimed::a_less;
  double alpha = 0.05;
  MannWhitney mann_whitney;     ///< the deciding test
  std::optional<Welch> welch;   ///< reported beside it (nullopt when n_a or n_b < 2)
  Judgement judgement;
};
/// "A < B" (a_less) or "A > B" judged by the two-sided Mann-Whitney U test at alpha: the observed
/// order is as_claimed iff u_a < n_a n_b / 2 (a_less; > for a_greater), opposite iff the reverse,
/// equal iff u_a = n_a n_b / 2; then judge_comparison(p, alpha, observed). Welch's t is computed
/// and reported, never deciding. Spec: stats.compare.
/// Pre: as mann_whitney; 0 < alpha < 1 (DomainError).
[[nodiscard]] ComparisonAssessment compare_samples(std::span<const double> a, std::span<const double> b,
                                                   Claimed claim, double alpha = 0.05);

// ---------------------------------------------------------------------------------------------
// Printed numbers (used to show a value with the paper's decimals)
// ---------------------------------------------------------------------------------------------

/// Reduction of `to` against `from` in percent: 100 (from - to) / from (negative: an increase).
/// Spec: reproduce.judge. Pre: from > 0 and finite, to finite (DomainError).
[[nodiscard]] double reduction_percent(double from, double to);

/// Number of digits after the decimal point of a printed decimal ("29.8" -> 1, "26" -> 0).
/// Spec: reproduce.judge. Pre: text is an optional '-', digits, optionally '.' and digits (DomainError).
[[nodiscard]] int printed_decimals(std::string_view printed);

/// `value` printed with `decimals` digits after the point (fixed notation, correctly rounded,
/// ties to even on the exact binary value, as Python's format(v, '.Nf')). Spec: reproduce.judge.
/// Pre: value finite, 0 <= decimals <= 17 (DomainError).
[[nodiscard]] std::string fixed(double value, int decimals);

/// True iff `value` rounded to the printed number's decimals equals the printed number:
/// fixed(value, printed_decimals(printed)) == printed (e.g. 29.79899 vs "29.8": holds).
/// Spec: reproduce.judge. Pre: as printed_decimals and fixed.
[[nodiscard]] bool matches_printed(double value, std::string_view printed);

/// The printed-digits rule for a value pathref computes exactly (no sampling noise): holds iff
/// matches_printed(value, printed); otherwise fails, the direction pathref_better or pathref_worse
/// by the sign of value - printed and `sense`. Used for pathref's checks of exact optima and for a
/// deterministic computation on the paper's own data and folds (cin2021-ml's tenfold numbers).
/// Spec: reproduce.judge. Pre: as matches_printed (DomainError).
[[nodiscard]] Judgement judge_printed(double value, std::string_view printed, Sense sense);

/// RETIRED (issue 11): the +-10-point tolerance of "about P %" claims. Kept only until the Shi
/// report moves to assess_value(..., Quantity::percent, ...); new code must not use it.
inline constexpr double about_percent_tolerance = 10.0;
/// RETIRED (see about_percent_tolerance): holds iff |ours - claimed| <= 10.
[[nodiscard]] Verdict judge_about_percent(double ours, double claimed);

}  // namespace pathref::reproduce
