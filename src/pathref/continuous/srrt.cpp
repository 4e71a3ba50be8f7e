#include "pathref/continuous/srrt.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::continuous {

const std::vector<std::string_view>& continuous_planner_names() {
  static const std::vector<std::string_view> names{"rrt", "s-rrt"};
  return names;
}

bool is_continuous_planner(std::string_view algo) {
  for (const auto n : continuous_planner_names())
    if (n == algo) return true;
  return false;
}

Json continuous_defaults(std::string_view algo) {
  if (!is_continuous_planner(algo)) throw UsageError("not a continuous planner: '" + std::string(algo) + "'");
  const RrtParams d;
  Json j{{"delta", d.delta},
         {"goal_probability", d.goal_probability},
         {"max_iterations", d.max_iterations},
         {"max_rejections", d.max_rejections},
         {"bias", std::string(to_string(d.bias))},
         {"near", std::string(to_string(d.near))},
         {"variant", std::string(to_string(d.variant))},
         {"sample", std::string(to_string(d.sample))},
         {"steer", "clip"}};
  if (algo == "s-rrt") j["shortcut"] = true;
  return j;
}

RrtParams rrt_params(const Json& m) {
  RrtParams p;
  p.delta = m.at("delta").get<double>();
  p.goal_probability = m.at("goal_probability").get<double>();
  p.max_iterations = m.at("max_iterations").get<std::int64_t>();
  p.max_rejections = m.at("max_rejections").get<std::int64_t>();
  p.bias = parse_bias(m.at("bias").get<std::string>());
  p.near = parse_near(m.at("near").get<std::string>());
  p.variant = parse_variant(m.at("variant").get<std::string>());
  p.sample = parse_sample(m.at("sample").get<std::string>());
  const std::string steer_name = m.at("steer").get<std::string>();
  if (steer_name != "clip" && steer_name != "fixed")
    throw UsageError("steer must be one of clip, fixed, got '" + steer_name + "'");
  p.clip = steer_name == "clip";
  return p;
}

double total_turning(const std::vector<Vec2>& points) {
  double sum = 0.0;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const double ux = points[i].x - points[i - 1].x, uy = points[i].y - points[i - 1].y;
    const double vx = points[i + 1].x - points[i].x, vy = points[i + 1].y - points[i].y;
    const double cross = ux * vy - uy * vx;
    const double dot = ux * vx + uy * vy;
    if ((ux == 0.0 && uy == 0.0) || (vx == 0.0 && vy == 0.0)) continue;
    sum += std::atan2(std::abs(cross), dot);
  }
  return sum;
}

PathMetrics path_metrics(const CollisionChecker& map, const std::vector<Vec2>& points) {
  require(!points.empty(), "path_metrics: empty path");
  PathMetrics m;
  m.length = polyline_length(points);
  m.nodes = static_cast<std::int64_t>(points.size());
  m.clearance = points.size() == 1 ? map.segment_clearance(points[0], points[0])
                                   : std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < points.size(); ++i)
    m.clearance = std::min(m.clearance, map.segment_clearance(points[i - 1], points[i]));
  m.turning = total_turning(points);
  return m;
}

ContinuousRun run_continuous(std::string_view algo, const CollisionChecker& map, Vec2 start, Vec2 goal,
                             const Json& merged, std::uint32_t seed) {
  if (!is_continuous_planner(algo)) throw UsageError("not a continuous planner: '" + std::string(algo) + "'");
  const RrtParams params = rrt_params(merged);
  const bool do_shortcut = algo == "s-rrt" && merged.value("shortcut", true);
  ContinuousRun run;
  run.params_used = merged;
  const auto t0 = std::chrono::steady_clock::now();
  rng::Stream stream(seed);
  run.tree = rrt(map, start, goal, params, stream);
  if (run.tree.found) {
    for (const std::size_t k : run.tree.path) run.raw.push_back(run.tree.nodes[k]);
    if (do_shortcut) {
      run.kept = shortcut(map, run.raw);
      for (const std::size_t k : run.kept) run.shortcut_path.push_back(run.raw[k]);
    }
  }
  const auto t1 = std::chrono::steady_clock::now();
  run.time_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  if (run.tree.found) {
    run.raw_metrics = path_metrics(map, run.raw);
    if (do_shortcut) run.shortcut_metrics = path_metrics(map, run.shortcut_path);
  }
  return run;
}

}  // namespace pathref::continuous
