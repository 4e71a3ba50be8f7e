#pragma once
/// \file reach.hpp
/// Property vacuity (issue 17): a property that returns early on some generated cases must say
/// what share of its cases reached the assertion, and fail when that share falls under a named
/// threshold. Count in the property (`reach.hit(bool)`), then call `require_reach` after rc::prop.
/// The thresholds are far below the shares measured (docs/testing.md lists both), so a pass is
/// not luck: with RapidCheck's 100 cases, a binomial tail under the threshold is < 1e-6.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

namespace pathref::testing {

struct Reach {
  std::int64_t cases = 0;
  std::int64_t reached = 0;
  /// Counts one case; returns `reached_assertion` so that `if (!reach.hit(ok)) return;` reads.
  bool hit(bool reached_assertion) {
    ++cases;
    if (reached_assertion) ++reached;
    return reached_assertion;
  }
  [[nodiscard]] double share() const { return cases == 0 ? 0.0 : static_cast<double>(reached) / static_cast<double>(cases); }
};

/// Fails the test case unless at least `min_share` of the counted cases reached the assertion.
inline void require_reach(const Reach& r, double min_share, const std::string& what) {
  INFO(what << ": " << r.reached << " of " << r.cases << " cases reached the assertion (threshold "
            << min_share << ")");
  CHECK(r.cases > 0);
  CHECK(r.share() >= min_share);
}

}  // namespace pathref::testing
