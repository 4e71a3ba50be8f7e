// spec: rng.stream, rng.index, rng.roulette, rng.bernoulli, rng.res53
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cmath>
#include <random>
#include <vector>

#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"
#include "support/reach.hpp"

using namespace pathref;

namespace {
/// A double in [0, 1) that is a multiple of 2^-53, as res53 produces.
rc::Gen<double> unit_draw() {
  return rc::gen::map(rc::gen::inRange<std::uint64_t>(0, std::uint64_t{1} << 53),
                      [](std::uint64_t k) { return static_cast<double>(k) * 0x1p-53; });
}
}  // namespace

TEST_CASE("prop_res53_in_unit_interval", "[rng][prop]") {
  rc::prop("res53 lies in [0,1)", [](std::uint32_t a, std::uint32_t b) {
    const double u = rng::res53(a, b);
    RC_ASSERT(u >= 0.0);
    RC_ASSERT(u < 1.0);
  });
}

TEST_CASE("prop_stream_is_deterministic", "[rng][prop]") {
  rc::prop("two streams with one seed agree", [](std::uint32_t seed) {
    rng::Stream a(seed), b(seed);
    for (int i = 0; i < 16; ++i) RC_ASSERT(a.next_double() == b.next_double());
  });
}

TEST_CASE("prop_stream_is_std_mt19937", "[rng][prop]") {
  // rng::Stream runs Mt19937 (32-bit words); [rand.predef]'s std::mt19937 (uint_fast32_t words)
  // is the oracle: the same outputs for every seed, across several state refills (624 words).
  rc::prop("Stream(seed) == std::mt19937(seed), output for output", [](std::uint32_t seed) {
    const auto skip = *rc::gen::inRange(0, 3000);
    rng::Stream s(seed);
    std::mt19937 oracle(seed);
    for (int i = 0; i < skip + 1300; ++i) RC_ASSERT(s.next_u32() == static_cast<std::uint32_t>(oracle()));
  });
}

TEST_CASE("prop_index_in_range_and_monotone", "[rng][prop]") {
  rc::prop("floor(u*n) in [0,n), monotone in u", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 1000000);
    const double u1 = *unit_draw();
    const double u2 = *unit_draw();
    const auto k1 = rng::uniform_index(u1, n);
    const auto k2 = rng::uniform_index(u2, n);
    RC_ASSERT(k1 < n);
    if (u1 <= u2) RC_ASSERT(k1 <= k2);
  });
}

TEST_CASE("prop_roulette_picks_positive_weight_at_the_cumsum_crossing", "[rng][prop]") {
  rc::prop("choice is the first crossing of u*sum", [] {
    const auto w = *rc::gen::nonEmpty(rc::gen::container<std::vector<double>>(
        rc::gen::map(rc::gen::inRange(0, 5), [](int k) { return static_cast<double>(k) * 0.25; })));
    double total = 0.0;
    for (double x : w) total += x;
    RC_PRE(total > 0.0);
    const double u = *unit_draw();
    const auto k = rng::roulette(w, u);
    RC_ASSERT(k < w.size());
    RC_ASSERT(w[k] > 0.0);
    double before = 0.0;
    for (std::size_t i = 0; i < k; ++i) before += w[i];
    RC_ASSERT(before + w[k] >= u * total);
    // No earlier positive weight already reaches the target.
    double c = 0.0;
    for (std::size_t i = 0; i < k; ++i) {
      c += w[i];
      if (w[i] > 0.0) RC_ASSERT(c < u * total);
    }
  });
}

TEST_CASE("prop_roulette_exact_cumulative_sum_ties", "[rng][prop]") {
  // Uniform u over 2^53 values almost never makes u * total equal a cumulative sum, the only place
  // where ">=" and ">" differ (issue 17). Here the weights are integers padded to a power-of-two
  // total 2^e, and u = c / 2^e for c a cumulative sum at a positive weight, so u * total == c
  // exactly. Oracle (written out, spec rng.roulette): the first index with w > 0 and cumsum >= c.
  pathref::testing::Reach ties;
  rc::prop("u * total equal to a cumulative sum picks the piece that completes it", [&ties] {
    auto w = *rc::gen::nonEmpty(rc::gen::container<std::vector<double>>(
        rc::gen::map(rc::gen::inRange(0, 5), [](int k) { return static_cast<double>(k); })));
    double sum = 0.0;
    for (double x : w) sum += x;
    double total = 1.0;
    while (total < sum || total == 0.0) total *= 2.0;
    if (total > sum) w.push_back(total - sum);  // the pad: total is a power of two
    std::vector<double> cums;                   // cumulative sums at the positive weights
    double c = 0.0;
    for (double x : w) {
      c += x;
      if (x > 0.0) cums.push_back(c);
    }
    const double target = *rc::gen::elementOf(cums);
    const double u = target / total;  // exact: total is a power of two
    const bool tie = target < total;  // u = 1 is out of range: the last cumulative sum is not drawn
    RC_PRE(tie);
    ties.hit(u * total == target);
    std::size_t want = w.size();
    c = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      c += w[i];
      if (w[i] > 0.0 && c >= target) {
        want = i;
        break;
      }
    }
    RC_ASSERT(rng::roulette(w, u) == want);
  });
  pathref::testing::require_reach(ties, 1.0, "exact ties u * total == a cumulative sum");
}

TEST_CASE("prop_bernoulli_at_u_equal_p_is_false", "[rng][prop]") {
  rc::prop("bernoulli(u, u) is false: the spec's u < p is strict", [] {
    const double u = *unit_draw();
    RC_ASSERT(!rng::bernoulli(u, u));
    RC_ASSERT(rng::bernoulli(u, std::nextafter(u, 2.0)));
  });
}

TEST_CASE("prop_roulette_frequencies_follow_weights", "[rng][prop]") {
  // Statistical oracle with a fixed stream: 200000 draws over weights 1:2:3:4. The chi-square
  // statistic with 3 degrees of freedom stays under 16.27 (p = 0.001) for a correct roulette.
  const std::vector<double> w{1.0, 2.0, 3.0, 4.0};
  std::vector<double> counts(4, 0.0);
  rng::Stream s(2024);
  const int n = 200000;
  for (int i = 0; i < n; ++i) counts[rng::roulette(w, s.next_double())] += 1.0;
  double chi2 = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    const double e = n * w[k] / 10.0;
    chi2 += (counts[k] - e) * (counts[k] - e) / e;
  }
  CHECK(chi2 < 16.27);
}

TEST_CASE("prop_bernoulli_is_u_below_p", "[rng][prop]") {
  rc::prop("bernoulli(u, p) == (u < p); p = 0 never, p = 1 always", [] {
    const double u = *unit_draw();
    const double p = *rc::gen::map(rc::gen::inRange<std::uint64_t>(0, (std::uint64_t{1} << 53) + 1),
                                   [](std::uint64_t k) { return static_cast<double>(k) * 0x1p-53; });
    RC_ASSERT(rng::bernoulli(u, p) == (u < p));
    RC_ASSERT(!rng::bernoulli(u, 0.0));
    RC_ASSERT(rng::bernoulli(u, 1.0));
  });
}
