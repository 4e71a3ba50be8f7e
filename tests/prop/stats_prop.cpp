// spec: stats.mean, stats.sd, stats.quantile, stats.bootstrap_ci, stats.betainc,
// stats.mann_whitney, stats.welch, stats.equivalence, stats.compare (spec/stats.md)
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "pathref/reproduce/stats.hpp"

using namespace pathref::reproduce;
using V = std::vector<double>;

namespace {
/// Samples of exactly representable values k/4, k in [-400, 400], of size [lo, hi].
rc::Gen<V> gen_sample(int lo, int hi) {
  return rc::gen::mapcat(rc::gen::inRange(lo, hi + 1), [](int n) {
    return rc::gen::container<V>(static_cast<std::size_t>(n),
                                 rc::gen::map(rc::gen::inRange(-400, 401), [](int k) { return k / 4.0; }));
  });
}
}  // namespace

TEST_CASE("prop_stats_mean_within_range", "[stats][prop]") {
  rc::prop("min <= mean <= max", [] {
    const V x = *gen_sample(1, 40);
    const double m = mean(x);
    RC_ASSERT(minimum(x) <= m);
    RC_ASSERT(m <= maximum(x));
  });
}

TEST_CASE("prop_stats_sd_shift_invariant", "[stats][prop]") {
  rc::prop("sd(x + c) == sd(x) for exact shifts; sd >= 0", [] {
    const V x = *gen_sample(2, 40);
    const double c = *rc::gen::inRange(-64, 65) * 1.0;
    V y = x;
    for (double& v : y) v += c;
    RC_ASSERT(sample_std(x) >= 0.0);
    RC_ASSERT(std::fabs(sample_std(y) - sample_std(x)) <= 1e-12 * (1.0 + sample_std(x)));
  });
}

TEST_CASE("prop_stats_quantile_monotone_and_bounded", "[stats][prop]") {
  rc::prop("quantile is non-decreasing in p, within [min, max], exact at the ends", [] {
    const V x = *gen_sample(1, 30);
    const double p = *rc::gen::inRange(0, 1001) / 1000.0;
    const double q = *rc::gen::inRange(0, 1001) / 1000.0;
    const double lo = std::min(p, q), hi = std::max(p, q);
    RC_ASSERT(quantile(x, lo) <= quantile(x, hi));
    RC_ASSERT(quantile(x, lo) >= minimum(x));
    RC_ASSERT(quantile(x, hi) <= maximum(x));
    RC_ASSERT(quantile(x, 0.0) == minimum(x));
    RC_ASSERT(quantile(x, 1.0) == maximum(x));
  });
}

TEST_CASE("prop_stats_bootstrap_within_sample_range", "[stats][prop]") {
  rc::prop("mean and minimum intervals lie within [min a, max a], lo <= hi", [] {
    const V a = *gen_sample(2, 20);
    const auto seed = *rc::gen::inRange<std::uint32_t>(0, 1000);
    for (const auto s : {BootStatistic::mean, BootStatistic::minimum}) {
      const Interval ci = bootstrap_ci(a, s, {seed, 200, 0.95});
      RC_ASSERT(ci.lo <= ci.hi);
      RC_ASSERT(ci.lo >= minimum(a));
      RC_ASSERT(ci.hi <= maximum(a));
    }
  });
}

TEST_CASE("prop_stats_bootstrap_deterministic_in_seed", "[stats][prop]") {
  rc::prop("the same seed gives the same interval; a wider level never gives a narrower one", [] {
    const V a = *gen_sample(2, 20);
    const V b = *gen_sample(2, 20);
    const auto seed = *rc::gen::inRange<std::uint32_t>(0, 1000);
    const Interval x = bootstrap_two_sample_ci(a, b, BootStatistic::mean_difference, {seed, 200, 0.9});
    const Interval y = bootstrap_two_sample_ci(a, b, BootStatistic::mean_difference, {seed, 200, 0.9});
    RC_ASSERT(x.lo == y.lo);
    RC_ASSERT(x.hi == y.hi);
    const Interval w = bootstrap_two_sample_ci(a, b, BootStatistic::mean_difference, {seed, 200, 0.99});
    RC_ASSERT(w.lo <= x.lo);
    RC_ASSERT(w.hi >= x.hi);
  });
}

TEST_CASE("prop_stats_bootstrap_paired_identical_arms_zero", "[stats][prop]") {
  rc::prop("paired: identical arms give [0, 0]; a constant shift c gives [c, c] up to rounding; lo <= hi", [] {
    const V a = *gen_sample(2, 20);
    const auto seed = *rc::gen::inRange<std::uint32_t>(0, 1000);
    const Interval z = bootstrap_paired_ci(a, a, BootStatistic::mean_difference, {seed, 100, 0.95});
    RC_ASSERT(z.lo == 0.0);
    RC_ASSERT(z.hi == 0.0);
    const double c = *rc::gen::inRange(-50, 51) / 4.0;
    V b;
    for (const double x : a) b.push_back(x - c);
    const Interval s = bootstrap_paired_ci(a, b, BootStatistic::mean_difference, {seed, 100, 0.95});
    RC_ASSERT(s.lo <= s.hi);
    RC_ASSERT(std::fabs(s.lo - c) <= 1e-9 * (1.0 + std::fabs(c) + maximum(a) - minimum(a) + 1e3));
    RC_ASSERT(std::fabs(s.hi - c) <= 1e-9 * (1.0 + std::fabs(c) + maximum(a) - minimum(a) + 1e3));
  });
}

TEST_CASE("prop_stats_betainc_symmetry", "[stats][prop]") {
  rc::prop("I_x(a, b) + I_{1-x}(b, a) = 1, in [0, 1], non-decreasing in x", [] {
    const double a = *rc::gen::inRange(1, 400) / 8.0;
    const double b = *rc::gen::inRange(1, 400) / 8.0;
    const double x = *rc::gen::inRange(0, 1025) / 1024.0;  // 1 - x exact
    const double v = betainc(a, b, x);
    RC_ASSERT(v >= 0.0);
    RC_ASSERT(v <= 1.0);
    RC_ASSERT(std::fabs(v + betainc(b, a, 1.0 - x) - 1.0) <= 1e-12);
    if (x <= 1.0 - 1.0 / 1024.0) RC_ASSERT(betainc(a, b, x + 1.0 / 1024.0) >= v - 1e-14);
  });
}

TEST_CASE("prop_stats_mann_whitney_swap_symmetry", "[stats][prop]") {
  rc::prop("swapping the samples swaps U_a and U_b and keeps p; p in [0, 1]", [] {
    const V a = *gen_sample(1, 15);
    const V b = *gen_sample(1, 15);
    const MannWhitney x = mann_whitney(a, b);
    const MannWhitney y = mann_whitney(b, a);
    RC_ASSERT(x.u_a == y.u_b);
    RC_ASSERT(x.u_a + x.u_b == static_cast<double>(a.size() * b.size()));
    RC_ASSERT(x.exact == y.exact);
    RC_ASSERT(std::fabs(x.p - y.p) <= 1e-15);
    RC_ASSERT(x.p >= 0.0);
    RC_ASSERT(x.p <= 1.0);
  });
}

TEST_CASE("prop_stats_welch_antisymmetric", "[stats][prop]") {
  rc::prop("welch(b, a) = -t, same df and p", [] {
    const V a = *gen_sample(2, 20);
    const V b = *gen_sample(2, 20);
    const Welch x = welch(a, b);
    const Welch y = welch(b, a);
    RC_ASSERT(x.t == -y.t);
    RC_ASSERT(x.df.has_value() == y.df.has_value());
    RC_ASSERT(std::fabs(x.p - y.p) <= 1e-15);
    RC_ASSERT(x.p >= 0.0);
    RC_ASSERT(x.p <= 1.0);
  });
}

TEST_CASE("prop_stats_equivalence_narrower_interval_never_flips", "[stats][prop]") {
  rc::prop("an interval inside another never reverses a decided verdict or its direction", [] {
    const double paper = *rc::gen::inRange(-200, 201) / 4.0;
    const double margin = *rc::gen::inRange(0, 40) / 4.0;
    int v[4] = {*rc::gen::inRange(-400, 401), *rc::gen::inRange(-400, 401), *rc::gen::inRange(-400, 401),
                *rc::gen::inRange(-400, 401)};
    std::sort(v, v + 4);
    const Interval outer{v[0] / 4.0, v[3] / 4.0};
    const Interval inner{v[1] / 4.0, v[2] / 4.0};
    const Sense s = *rc::gen::element(Sense::lower_is_better, Sense::higher_is_better);
    const Judgement o = judge_equivalence(outer, paper, margin, s);
    const Judgement i = judge_equivalence(inner, paper, margin, s);
    if (o.verdict == Verdict::holds || o.verdict == Verdict::fails) {
      RC_ASSERT(i.verdict == o.verdict);
      RC_ASSERT(i.direction == o.direction);
    }
    if (o.verdict == Verdict::inconclusive && o.direction != Direction::none)
      RC_ASSERT(i.direction == o.direction || i.direction == Direction::none);
  });
}

TEST_CASE("prop_stats_compare_far_apart_samples_hold", "[stats][prop]") {
  rc::prop("when every a is below every b (n >= 4 each) 'a < b' holds and 'a > b' fails", [] {
    V a = *gen_sample(4, 20);
    V b = *gen_sample(4, 20);
    const double shift = maximum(a) - minimum(b) + 1.0;
    for (double& x : b) x += shift;
    RC_ASSERT(compare_samples(a, b, Claimed::a_less).judgement.verdict == Verdict::holds);
    const Judgement g = compare_samples(a, b, Claimed::a_greater).judgement;
    RC_ASSERT(g.verdict == Verdict::fails);
    RC_ASSERT(g.direction == Direction::opposite);
  });
}
