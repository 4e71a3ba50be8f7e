#include "pathref/reproduce/stats.hpp"

#include <fmt/core.h>

#include <cmath>

#include "pathref/core/error.hpp"

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

double reduction_percent(double from, double to) {
  require(std::isfinite(from) && from > 0.0, "reduction_percent: 'from' must be finite and > 0");
  require(std::isfinite(to), "reduction_percent: 'to' must be finite");
  return 100.0 * (from - to) / from;
}

std::optional<double> welch_t(std::span<const double> a, std::span<const double> b) {
  require(a.size() >= 2 && b.size() >= 2, "welch_t: each sample needs at least two values");
  const double sa = sample_std(a);
  const double sb = sample_std(b);
  const double se2 = sa * sa / static_cast<double>(a.size()) + sb * sb / static_cast<double>(b.size());
  if (se2 == 0.0) return std::nullopt;
  return (mean(a) - mean(b)) / std::sqrt(se2);
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

std::string_view to_string(Verdict v) noexcept {
  switch (v) {
    case Verdict::holds:
      return "holds";
    case Verdict::fails:
      return "does not hold";
    case Verdict::untestable:
      return "cannot be tested";
  }
  return "cannot be tested";
}

Verdict judge_about_percent(double ours, double claimed) {
  require(std::isfinite(ours) && std::isfinite(claimed), "judge_about_percent: values must be finite");
  return std::fabs(ours - claimed) <= about_percent_tolerance ? Verdict::holds : Verdict::fails;
}

}  // namespace pathref::reproduce
