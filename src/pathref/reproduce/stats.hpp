#pragma once
/// \file stats.hpp
/// The statistics and claim judgements of `pathref reproduce` as small pure functions: mean,
/// sample standard deviation, minimum, reductions in percent, Welch's t, and the rules that
/// decide whether a paper's printed number or comparative claim holds.
/// Spec: spec/reproduce.md (sections "Statistics" and "Judging a claim")
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace pathref::reproduce {

/// Arithmetic mean: (x_0 + x_1 + ... + x_{n-1}) / n, summed left to right in binary64.
/// Spec: reproduce.stats. Pre: n >= 1, every value finite (DomainError).
[[nodiscard]] double mean(std::span<const double> values);

/// Sample standard deviation (Bessel's n - 1): sqrt(sum_i (x_i - m)^2 / (n - 1)), m = mean(x),
/// two passes, sums left to right. Spec: reproduce.stats. Pre: n >= 2, every value finite
/// (DomainError). Post: >= 0; 0 iff all values are equal.
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

/// Reduction of `to` against `from` in percent: 100 (from - to) / from (negative: an increase).
/// Spec: reproduce.judge. Pre: from > 0 and finite, to finite (DomainError).
[[nodiscard]] double reduction_percent(double from, double to);

/// Welch's t statistic of two samples: (mean(a) - mean(b)) / sqrt(s_a^2/n_a + s_b^2/n_b);
/// nullopt when the denominator is 0 (both samples constant). Spec: reproduce.judge.
/// Pre: n_a >= 2, n_b >= 2, finite values (DomainError).
[[nodiscard]] std::optional<double> welch_t(std::span<const double> a, std::span<const double> b);

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

/// The verdict on one claim.
enum class Verdict {
  holds,         ///< the claim is true on pathref's runs by the rule stated for it
  fails,         ///< it is false ("does not hold")
  untestable,    ///< it cannot be tested here (reason stated beside it)
};
/// "holds" | "does not hold" | "cannot be tested".
[[nodiscard]] std::string_view to_string(Verdict v) noexcept;

/// Tolerance of "about P %" claims, in percentage points (spec reproduce.judge).
inline constexpr double about_percent_tolerance = 10.0;

/// Verdict on "X reduces Q by about `claimed` % against Y": holds iff our reduction r (percent)
/// satisfies |r - claimed| <= about_percent_tolerance. Spec: reproduce.judge.
/// Pre: r and claimed finite (DomainError).
[[nodiscard]] Verdict judge_about_percent(double ours, double claimed);

}  // namespace pathref::reproduce
