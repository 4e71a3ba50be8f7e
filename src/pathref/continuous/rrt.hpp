#pragma once
/// \file rrt.hpp
/// The improved (goal-biased) RRT of Cin et al. 2021, Algorithm 1, and its greedy reverse
/// shortcut, Algorithm 2 ("S-RRT", Computational Intelligence and Neuroscience 2021, article
/// 8025730, Sec. 4, doi:10.1155/2021/8025730), in the continuous plane. The listings' symbols are
/// lost; the reconstruction, its open readings and the draw order are in spec/cin2021-srrt.md.
/// CGAL-free: collision checks go through the CollisionChecker interface; the exact checker on
/// polygons and grid cells is geometry::ObstacleMap (pathref/geometry/obstacles.hpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/continuous/kdtree.hpp"
#include "pathref/geometry/collision.hpp"

namespace pathref::rng {
class Stream;
}

namespace pathref::continuous {

/// What a continuous planner asks of the map (geometry/collision.hpp).
using CollisionChecker = geometry::CollisionChecker;

/// Steer(x_near, x_target, delta): the point delta away from x_near towards x_target.
/// With dx = t.x - n.x, dy = t.y - n.y, d = sqrt(dx*dx + dy*dy) and s = delta / d:
/// clip (default): d <= delta gives x_target itself, else (n.x + s*dx, n.y + s*dy);
/// fixed: always (n.x + s*dx, n.y + s*dy) (may overshoot x_target).
/// d == 0 gives x_near. Source: Algorithm 1 line 10 ("fixed step"), Sec. 4.3 delta = 1.7.
/// Spec: cin2021.srrt.steer. Pre: delta > 0 and finite (DomainError).
[[nodiscard]] Vec2 steer(Vec2 near, Vec2 target, double delta, bool clip = true);

/// Reading of Algorithm 1's goal-bias branch (spec r[cin2021.alg1], param `bias`).
enum class BiasBranch { lt, gt };
/// Which node grows (param `near`): nearest to the random sample (the listing's line 4) or
/// nearest to the chosen target.
enum class NearTo { sample, target };
/// Named variants (param `variant`): the paper's listing, plain RRT (no goal bias, no p draw),
/// OMPL's RRT ordering (p first, then either the goal or a sample, nearest to that target).
enum class RrtVariant { paper, plain, ompl };
/// Sampling region (param `sample`): the world rectangle, or rejection until a free point.
enum class SampleMode { rect, free };

/// Parameters of Algorithm 1 (defaults: Sec. 4.3 where it gives them; spec table otherwise).
struct RrtParams {
  double delta = 1.7;                  ///< fixed step (Sec. 4.3)
  double goal_probability = 0.6;       ///< P_g (Sec. 4.3)
  std::int64_t max_iterations = 20000; ///< N of "for i = 1 to N"
  BiasBranch bias = BiasBranch::lt;
  NearTo near = NearTo::sample;
  RrtVariant variant = RrtVariant::paper;
  SampleMode sample = SampleMode::rect;
  bool clip = true;                    ///< steer reading (clip | fixed)
  std::int64_t max_rejections = 1000;  ///< sample=free: draws per sample before giving up (DomainError)
};

/// Parses `bias`, `near`, `variant`, `sample`, `steer` option names ("lt"/"gt", ...);
/// UsageError naming the key and the allowed values otherwise.
[[nodiscard]] BiasBranch parse_bias(std::string_view s);
[[nodiscard]] NearTo parse_near(std::string_view s);
[[nodiscard]] RrtVariant parse_variant(std::string_view s);
[[nodiscard]] SampleMode parse_sample(std::string_view s);
[[nodiscard]] std::string_view to_string(BiasBranch b) noexcept;
[[nodiscard]] std::string_view to_string(NearTo n) noexcept;
[[nodiscard]] std::string_view to_string(RrtVariant v) noexcept;
[[nodiscard]] std::string_view to_string(SampleMode m) noexcept;

/// The tree and the outcome of one run of Algorithm 1.
struct RrtResult {
  bool found = false;
  std::vector<Vec2> nodes;              ///< node 0 = start; the goal, if reached, is the last node
  std::vector<std::int64_t> parent;     ///< parent[0] = -1
  std::int64_t iterations = 0;          ///< loop iterations run (samples drawn, rejections excluded)
  std::int64_t rejected_edges = 0;      ///< iterations whose new edge was not free
  std::uint64_t draws = 0;              ///< doubles drawn from the stream
  std::vector<std::size_t> path;        ///< node indices start ... goal ("denoise"), empty if !found
};

/// Algorithm 1 (improved RRT) from `start` to `goal` on `map`, drawing from `stream` in the order
/// of spec r[cin2021.alg1]. The goal test (after each added node, and once for the start): the
/// node is within delta of the goal (squared_distance <= delta^2) and the edge to the goal is
/// free; then the goal is added as its child. Source: Cin et al. 2021 Algorithm 1, Sec. 4.2.
/// Spec: cin2021.alg1. Pre: delta > 0, 0 <= P_g <= 1, max_iterations >= 0, start and goal free
/// and distinct (DomainError).
[[nodiscard]] RrtResult rrt(const CollisionChecker& map, Vec2 start, Vec2 goal, const RrtParams& params,
                            rng::Stream& stream);

/// The start-to-goal branch of a tree ("denoise", Algorithm 2 line 2): node indices from the root
/// to `leaf`, following parent links. Spec: cin2021.alg2. Pre: a valid parent array with
/// parent[0] = -1 and leaf < size (DomainError).
[[nodiscard]] std::vector<std::size_t> branch(const std::vector<std::int64_t>& parent, std::size_t leaf);

/// Algorithm 2's greedy reverse shortcut of a path p_0 ... p_m whose consecutive segments are
/// free: s = 0, out = [0]; while s != m: c = m; while not segment_free(p_s, p_c): c = c - 1;
/// append c, s = c. Returns the kept indices (0 first, m last). Never longer than the input
/// (triangle inequality), every output segment free (checked).
/// Source: Cin et al. 2021 Algorithm 2, Sec. 4.2 ("reverse retrospective mechanism").
/// Spec: cin2021.alg2. Pre: path non-empty (DomainError); a consecutive segment that is not free
/// is a DomainError (the input is not a valid tree branch).
[[nodiscard]] std::vector<std::size_t> shortcut(const CollisionChecker& map, const std::vector<Vec2>& path);

/// Polyline length sum_i |p_{i+1} - p_i| (sqrt of squared_distance), summed left to right.
/// Spec: cin2021.srrt.metrics.
[[nodiscard]] double polyline_length(const std::vector<Vec2>& points);

}  // namespace pathref::continuous
