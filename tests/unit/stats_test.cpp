// spec: stats.mean, stats.sd, stats.quantile, stats.bootstrap_ci, stats.betainc, stats.student_t,
// stats.mann_whitney, stats.welch, stats.margin, stats.equivalence, stats.compare (spec/stats.md)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/reproduce/report.hpp"
#include "pathref/reproduce/stats.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"

using namespace pathref;
using namespace pathref::reproduce;
using V = std::vector<double>;

TEST_CASE("stats.mean: hand values and domain", "[stats]") {
  CHECK(mean(V{1, 2, 3, 4}) == 2.5);
  CHECK(mean(V{1e16, 1.0, -1e16}) == 0.0);  // left to right: 1e16 + 1 rounds to 1e16
  CHECK(mean(V{1e16, -1e16, 1.0}) == 1.0 / 3.0);
  CHECK_THROWS_AS(mean(V{}), DomainError);
  CHECK_THROWS_AS(mean(V{1.0, std::nan("")}), DomainError);
}

TEST_CASE("stats.sd: hand values and domain", "[stats]") {
  CHECK(sample_std(V{2, 4, 4, 4, 5, 5, 7, 9}) == std::sqrt(32.0 / 7.0));
  CHECK(sample_std(V{1, 1}) == 0.0);
  CHECK_THROWS_AS(sample_std(V{1}), DomainError);
}

TEST_CASE("stats.quantile: type 7 hand values", "[stats]") {
  CHECK(quantile(V{3, 1, 2, 4}, 0.5) == 2.5);
  CHECK(quantile(V{3, 1, 2, 4}, 0.25) == 1.75);
  CHECK(quantile(V{5, -1, 3}, 0.0) == -1.0);
  CHECK(quantile(V{5, -1, 3}, 1.0) == 5.0);
  CHECK(quantile(V{7.25}, 0.3) == 7.25);
  CHECK_THROWS_AS(quantile(V{1, 2}, 1.5), DomainError);
  CHECK_THROWS_AS(quantile_sorted(V{2, 1}, 0.5), DomainError);
  CHECK_THROWS_AS(quantile(V{}, 0.5), DomainError);
}

TEST_CASE("stats.bootstrap_ci: draw order replayed by hand", "[stats]") {
  // Replay the spec's draw order with the stream and rng.index directly.
  const V a{29.8, 30.4, 31.2, 29.8, 32.6};
  const V b{31.2, 32.0, 33.5, 31.8};
  const BootstrapOptions o{7, 100, 0.9};
  rng::Stream s(7);
  V means, diffs;
  for (int r = 0; r < 100; ++r) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += a[rng::uniform_index(s.next_double(), a.size())];
    means.push_back(sum / 5.0);
  }
  std::sort(means.begin(), means.end());
  const Interval ci = bootstrap_ci(a, BootStatistic::mean, o);
  const double alpha = 1.0 - 0.9;
  CHECK(ci.lo == quantile_sorted(means, alpha / 2.0));
  CHECK(ci.hi == quantile_sorted(means, 1.0 - alpha / 2.0));
  // Two samples: all of a's draws first, then b's, per replicate.
  rng::Stream s2(7);
  for (int r = 0; r < 100; ++r) {
    double sa = 0.0, sb = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sa += a[rng::uniform_index(s2.next_double(), a.size())];
    for (std::size_t i = 0; i < b.size(); ++i) sb += b[rng::uniform_index(s2.next_double(), b.size())];
    diffs.push_back(sa / 5.0 - sb / 4.0);
  }
  std::sort(diffs.begin(), diffs.end());
  const Interval d = bootstrap_two_sample_ci(a, b, BootStatistic::mean_difference, o);
  CHECK(d.lo == quantile_sorted(diffs, alpha / 2.0));
  CHECK(d.hi == quantile_sorted(diffs, 1.0 - alpha / 2.0));
  CHECK(d.hi < 0.0);
  const Interval c = bootstrap_ci(V{2, 2, 2}, BootStatistic::mean, {});
  CHECK(c.lo == 2.0);
  CHECK(c.hi == 2.0);
  CHECK_THROWS_AS(bootstrap_ci(V{1}, BootStatistic::mean, {}), DomainError);
  CHECK_THROWS_AS(bootstrap_ci(a, BootStatistic::mean_difference, {}), DomainError);
  CHECK_THROWS_AS(bootstrap_two_sample_ci(a, V{0, 1}, BootStatistic::reduction_percent, {}), DomainError);
  CHECK_THROWS_AS(bootstrap_ci(a, BootStatistic::mean, {1, 0, 0.95}), DomainError);
  CHECK_THROWS_AS(bootstrap_ci(a, BootStatistic::mean, {1, 10, 1.0}), DomainError);
  CHECK(parse_boot_statistic("sd_difference") == BootStatistic::sd_difference);
  CHECK_THROWS_AS(parse_boot_statistic("median"), UsageError);
}

TEST_CASE("stats.bootstrap_paired_ci: draw order replayed by hand", "[stats]") {
  // One index per pair and replicate; a*_i = a[k], b*_i = b[k] (spec stats.bootstrap_ci, paired).
  const V a{40, 35, 52, 47, 38, 44};  // e.g. child nodes of the 5-direction search
  const V b{43, 36, 57, 50, 41, 47};  // the 8-direction search on the same maps
  const BootstrapOptions o{9, 200, 0.95};
  rng::Stream s(9);
  V diffs, reds;
  for (int r = 0; r < 200; ++r) {
    double sa = 0.0, sb = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::size_t k = rng::uniform_index(s.next_double(), a.size());
      sa += a[k];
      sb += b[k];
    }
    diffs.push_back(sa / 6.0 - sb / 6.0);
    reds.push_back(100.0 * (sb / 6.0 - sa / 6.0) / (sb / 6.0));
  }
  std::sort(diffs.begin(), diffs.end());
  std::sort(reds.begin(), reds.end());
  const double alpha = 1.0 - 0.95;
  const Interval d = bootstrap_paired_ci(a, b, BootStatistic::mean_difference, o);
  CHECK(d.lo == quantile_sorted(diffs, alpha / 2.0));
  CHECK(d.hi == quantile_sorted(diffs, 1.0 - alpha / 2.0));
  CHECK(d.hi < 0.0);  // every pair has a < b: every replicate is negative
  const Interval red = bootstrap_paired_ci(a, b, BootStatistic::reduction_percent, o);
  CHECK(red.lo == quantile_sorted(reds, alpha / 2.0));
  CHECK(red.hi == quantile_sorted(reds, 1.0 - alpha / 2.0));
  CHECK(red.lo > 0.0);
  // The unpaired interval of the same data is wider (the map-to-map spread does not cancel).
  const Interval u = bootstrap_two_sample_ci(a, b, BootStatistic::mean_difference, o);
  CHECK(u.hi - u.lo > d.hi - d.lo);
  CHECK_THROWS_AS(bootstrap_paired_ci(a, V{1, 2, 3}, BootStatistic::mean_difference, {}), DomainError);
  CHECK_THROWS_AS(bootstrap_paired_ci(V{1}, V{2}, BootStatistic::mean_difference, {}), DomainError);
  CHECK_THROWS_AS(bootstrap_paired_ci(a, b, BootStatistic::sd_difference, {}), DomainError);
  CHECK_THROWS_AS(bootstrap_paired_ci(a, b, BootStatistic::mean, {}), DomainError);
  CHECK_THROWS_AS(bootstrap_paired_ci(V{1, 2}, V{0, 3}, BootStatistic::reduction_percent, {}), DomainError);
  CHECK_THROWS_AS(bootstrap_paired_ci(V{1, 2}, V{1, 3}, BootStatistic::mean_difference, {1, 0, 0.95}), DomainError);
}

TEST_CASE("stats.betainc: closed forms", "[stats]") {
  CHECK(betainc(1, 1, 0.3) == Approx(0.3).epsilon(1e-14));
  CHECK(betainc(3, 1, 0.5) == Approx(0.125).epsilon(1e-14));
  CHECK(betainc(1, 2, 0.5) == Approx(0.75).epsilon(1e-14));
  CHECK(betainc(7.5, 7.5, 0.5) == Approx(0.5).epsilon(1e-13));
  CHECK(betainc(2, 3, 0.0) == 0.0);
  CHECK(betainc(2, 3, 1.0) == 1.0);
  // I_x(2, 2) = 3x^2 - 2x^3
  for (const double x : {0.1, 0.25, 0.6, 0.9}) CHECK(betainc(2, 2, x) == Approx(3 * x * x - 2 * x * x * x).epsilon(1e-13));
  CHECK_THROWS_AS(betainc(0, 1, 0.5), DomainError);
  CHECK_THROWS_AS(betainc(1, 1, 1.5), DomainError);
}

TEST_CASE("stats.student_t: closed forms for df 1 and 2", "[stats]") {
  for (const double t : {0.1, 1.0, 3.0, 25.0}) {
    CHECK(student_t_two_sided_p(t, 1) == Approx(1 - 2 * std::atan(t) / std::numbers::pi).epsilon(1e-12));
    CHECK(student_t_two_sided_p(-t, 2) == Approx(1 - t / std::sqrt(2 + t * t)).epsilon(1e-12));
  }
  CHECK(student_t_two_sided_p(0, 5) == 1.0);
  CHECK(student_t_two_sided_p(INFINITY, 5) == 0.0);
  CHECK(student_t_two_sided_p(1e200, 5) == 0.0);
  // Large df tends to the normal: t = 1.959963984540054 gives 0.05.
  CHECK(student_t_two_sided_p(1.959963984540054, 1e7) == Approx(0.05).epsilon(1e-5));
  CHECK_THROWS_AS(student_t_two_sided_p(1, 0), DomainError);
}

namespace {
/// P(U >= u) by enumerating every subset of ranks for a (no ties).
double enumerate_tail(std::size_t na, std::size_t nb, double u) {
  const std::size_t n = na + nb;
  std::size_t count = 0, total = 0;
  for (std::uint32_t mask = 0; mask < (1U << n); ++mask) {
    if (static_cast<std::size_t>(__builtin_popcount(mask)) != na) continue;
    ++total;
    double ua = 0.0;  // pairs (a, b) with a above b: for each a at position i, the b's below it
    for (std::size_t i = 0; i < n; ++i) {
      if (!(mask & (1U << i))) continue;
      for (std::size_t j = 0; j < i; ++j)
        if (!(mask & (1U << j))) ua += 1.0;
    }
    if (ua >= u) ++count;
  }
  return static_cast<double>(count) / static_cast<double>(total);
}
}  // namespace

TEST_CASE("stats.mann_whitney: exact distribution against enumeration", "[stats]") {
  for (std::size_t na = 1; na <= 5; ++na)
    for (std::size_t nb = 1; nb <= 6; ++nb) {
      // a takes ranks spread out, b the rest: values are distinct integers
      V a, b;
      for (std::size_t i = 0; i < na + nb; ++i) ((i * 7 + na) % 3 == 0 && a.size() < na ? a : b).push_back(static_cast<double>(i));
      while (a.size() < na) { a.push_back(b.back()); b.pop_back(); }
      while (b.size() < nb) b.push_back(100.0 + static_cast<double>(b.size()));
      if (a.size() != na || b.size() != nb) continue;
      const MannWhitney m = mann_whitney(a, b);
      REQUIRE(m.exact);
      CHECK(m.u_a + m.u_b == static_cast<double>(na * nb));
      const double u = std::max(m.u_a, m.u_b);
      CHECK(m.p == Approx(std::min(1.0, 2 * enumerate_tail(na, nb, u))).epsilon(1e-14));
      CHECK_FALSE(m.z.has_value());
    }
  const MannWhitney h = mann_whitney(V{1, 2}, V{3, 4});
  CHECK(h.u_a == 0.0);
  CHECK(h.p == Approx(1.0 / 3.0).epsilon(1e-15));
}

TEST_CASE("stats.mann_whitney: ties, normal approximation, all tied", "[stats]") {
  // SciPy 1.10: mannwhitneyu([1..9, 10.5], [3..13]) = (32.5, 0.12048854088778624)
  const MannWhitney m = mann_whitney(V{1, 2, 3, 4, 5, 6, 7, 8, 9, 10.5}, V{3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13});
  CHECK_FALSE(m.exact);
  CHECK(m.u_a == 32.5);
  CHECK(m.p == Approx(0.12048854088778624).epsilon(1e-12));
  const MannWhitney t = mann_whitney(V{2, 2, 2}, V{2, 2});
  CHECK(t.p == 1.0);
  CHECK_FALSE(t.z.has_value());
  // both samples larger than 8 and no ties: normal, with z reported
  V a(9), b(9);
  std::iota(a.begin(), a.end(), 0.0);
  for (std::size_t i = 0; i < 9; ++i) b[i] = static_cast<double>(i) + 0.25;
  const MannWhitney n = mann_whitney(a, b);
  CHECK_FALSE(n.exact);
  REQUIRE(n.z.has_value());
  CHECK_THROWS_AS(mann_whitney(V{}, V{1}), DomainError);
  CHECK(normal_two_sided_p(-1.0) == 1.0);
  CHECK(normal_two_sided_p(1.959963984540054) == Approx(0.05).epsilon(1e-12));
}

TEST_CASE("stats.welch: constant samples and hand value", "[stats]") {
  const Welch w = welch(V{1, 2, 3, 4, 5, 6, 7, 8, 9, 10.5}, V{3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13});
  // SciPy 1.10 ttest_ind(equal_var=False): t = -1.7459220366141293, p = 0.0969963722442601
  CHECK(w.t == Approx(-1.7459220366141293).epsilon(1e-14));
  CHECK(w.p == Approx(0.0969963722442601).epsilon(1e-10));
  REQUIRE(w.df.has_value());
  CHECK(*w.df == Approx(18.973989728038049).epsilon(1e-13));
  const Welch c = welch(V{1, 1}, V{1, 1, 1});
  CHECK(c.t == 0.0);
  CHECK(c.p == 1.0);
  CHECK_FALSE(c.df.has_value());
  const Welch d = welch(V{1, 1}, V{2, 2});
  CHECK(std::isinf(d.t));
  CHECK(d.t < 0);
  CHECK(d.p == 0.0);
  CHECK_FALSE(welch_t(V{1, 1}, V{2, 2}).has_value());
  CHECK_THROWS_AS(welch(V{1}, V{1, 2}), DomainError);
}

TEST_CASE("stats.margin: the table", "[stats]") {
  CHECK(equivalence_margin(Quantity::length, 29.8) == 0.01 * 29.8);
  CHECK(equivalence_margin(Quantity::turns, 6.4) == 1.0);
  CHECK(equivalence_margin(Quantity::iterations, 24) == 0.1 * 24.0);
  CHECK(equivalence_margin(Quantity::iterations, 8) == 1.0);
  CHECK(equivalence_margin(Quantity::time, 142) == 0.05 * 142.0);
  CHECK(equivalence_margin(Quantity::percent, 46) == 5.0);
  CHECK(parse_quantity("time") == Quantity::time);
  CHECK_THROWS_AS(parse_quantity("speed"), UsageError);
  CHECK_THROWS_AS(equivalence_margin(Quantity::length, INFINITY), DomainError);
}

TEST_CASE("stats.equivalence: every outcome", "[stats]") {
  const auto j = [](double lo, double hi, Sense s = Sense::lower_is_better) {
    return judge_equivalence({lo, hi}, 29.8, 0.298, s);
  };
  CHECK(j(29.7, 29.9).verdict == Verdict::holds);
  CHECK(j(27, 28).verdict == Verdict::fails);
  CHECK(j(27, 28).direction == Direction::pathref_better);
  CHECK(j(31, 32).direction == Direction::pathref_worse);
  CHECK(j(27, 28, Sense::higher_is_better).direction == Direction::pathref_worse);
  CHECK(j(29, 29.9).verdict == Verdict::inconclusive);
  CHECK(j(29, 29.9).direction == Direction::pathref_better);
  CHECK(j(28, 31).direction == Direction::none);
  CHECK(verdict_text(Verdict::fails, Direction::pathref_better) == "does not hold — pathref better");
  CHECK(verdict_text(Verdict::inconclusive, Direction::none) == "inconclusive — interval wider than the margin");
  CHECK_THROWS_AS(judge_equivalence({2, 1}, 1.5, 0.1, Sense::lower_is_better), DomainError);
  // assess_value / assess_exact_value
  const V runs{29.79899, 29.79899, 29.79899, 29.79899};
  const ValueAssessment v = assess_value(runs, 29.8, Quantity::length, Sense::lower_is_better, {});
  CHECK(v.judgement.verdict == Verdict::holds);
  CHECK(v.margin == 0.01 * 29.8);
  const ValueAssessment e = assess_exact_value(31.56, 29.8, Quantity::length, Sense::lower_is_better);
  CHECK(e.judgement.verdict == Verdict::fails);
  CHECK(e.judgement.direction == Direction::pathref_worse);
  const Json js = value_json(v, {});
  CHECK(js["judgement"]["text"] == "holds");
  CHECK(js["ci"].size() == 2);
}

TEST_CASE("stats.compare: every outcome", "[stats]") {
  CHECK(judge_comparison(0.01, 0.05, Direction::as_claimed).verdict == Verdict::holds);
  CHECK(judge_comparison(0.01, 0.05, Direction::opposite).verdict == Verdict::fails);
  CHECK(judge_comparison(0.05, 0.05, Direction::as_claimed).verdict == Verdict::not_significant);
  CHECK(judge_comparison(0.5, 0.05, Direction::equal).direction == Direction::equal);
  CHECK_THROWS_AS(judge_comparison(0.5, 0.05, Direction::pathref_better), DomainError);
  CHECK(judge_interval_comparison({-0.5, -0.1}, Claimed::a_less).verdict == Verdict::holds);
  CHECK(judge_interval_comparison({0.1, 0.5}, Claimed::a_less).verdict == Verdict::fails);
  CHECK(judge_interval_comparison({0.1, 0.5}, Claimed::a_greater).verdict == Verdict::holds);
  CHECK(judge_interval_comparison({-0.25, 0.25}, Claimed::a_less).direction == Direction::equal);
  const V a{1, 2, 3, 4, 5, 6, 7, 8}, b{11, 12, 13, 14, 15, 16, 17, 18};
  const ComparisonAssessment c = compare_samples(a, b, Claimed::a_less);
  CHECK(c.judgement.verdict == Verdict::holds);
  CHECK(c.mann_whitney.p == Approx(2.0 / 12870.0).epsilon(1e-14));
  REQUIRE(c.welch.has_value());
  CHECK(c.welch->t < 0);
  CHECK(compare_samples(a, b, Claimed::a_greater).judgement.verdict == Verdict::fails);
  CHECK(compare_samples(V{1, 3}, V{2, 4}, Claimed::a_less).judgement.verdict == Verdict::not_significant);
  const Json js = comparison_json(c);
  CHECK(js["test"] == "Mann-Whitney U (two-sided)");
  CHECK(js["judgement"]["verdict"] == "holds");
}
