// OMPL as the peer of pathref's continuous planners (issue 14; spec/cin2021-srrt.md "OMPL peer"):
// on the scenes of `pathref reproduce cin2021-srrt` (A, B, C), OMPL's geometric::RRT with goal
// bias P_g = 0.6 and range delta = 1.7, then its PathSimplifier, against pathref's `rrt` (Algorithm
// 1, and OMPL's ordering `variant=ompl`) and `s-rrt` — success rate, path length, path nodes,
// planning time, over N seeds (default 100). Both sides use pathref's exact collision test
// (ObstacleMap::point_free / segment_free as OMPL's state validity checker and motion validator),
// so the comparison is of the planners, not of the collision checkers.
//
// Opt-in, never in CI: tools/deps-ompl.sh installs libompl-dev and prints the configure line
// (-DPATHREF_BENCHMARKS=ON -DPATHREF_OMPL_PEER=ON). The library never depends on OMPL.
// Usage: srrt_ompl_peer [N] [first_seed]    (prints markdown tables; results: docs/performance.md)
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "pathref/io/scene_json.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/reproduce/cin2021_srrt.hpp"
#include "pathref/reproduce/stats.hpp"

namespace ob = ompl::base;
namespace og = ompl::geometric;
using pathref::continuous::Vec2;

namespace {

Vec2 xy(const ob::State* s) {
  const auto* r = s->as<ob::RealVectorStateSpace::StateType>();
  return Vec2{r->values[0], r->values[1]};
}

/// OMPL motion validator that asks pathref's exact segment test (no sampling at a resolution).
class ExactMotionValidator final : public ob::MotionValidator {
 public:
  ExactMotionValidator(const ob::SpaceInformationPtr& si, const pathref::geometry::ObstacleMap& map)
      : ob::MotionValidator(si), map_(map) {}
  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const bool ok = map_.segment_free(xy(s1), xy(s2));
    (ok ? valid_ : invalid_)++;
    return ok;
  }
  bool checkMotion(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>& last) const override {
    if (checkMotion(s1, s2)) return true;
    if (last.first != nullptr) si_->copyState(last.first, s1);
    last.second = 0.0;
    return false;
  }

 private:
  const pathref::geometry::ObstacleMap& map_;
};

double length(const std::vector<Vec2>& p) { return pathref::continuous::polyline_length(p); }

std::vector<Vec2> points(const og::PathGeometric& path) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < path.getStateCount(); ++i) out.push_back(xy(path.getState(static_cast<unsigned int>(i))));
  return out;
}

bool all_free(const pathref::geometry::ObstacleMap& map, const std::vector<Vec2>& p) {
  for (std::size_t i = 1; i < p.size(); ++i)
    if (!map.segment_free(p[i - 1], p[i])) return false;
  return true;
}

/// Per series: successes, and length / nodes / time of the successful runs.
struct Acc {
  int runs = 0, found = 0, invalid = 0;
  std::vector<double> length, nodes, time_ms;
};

std::string cell(const std::vector<double>& v, int d) {
  if (v.empty()) return "—";
  const auto s = pathref::reproduce::summarize(v);
  return fmt::format("{:.{}f} ± {:.{}f}", *s.mean, d, s.std ? *s.std : 0.0, d);
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 100;
  const auto first = static_cast<std::uint32_t>(argc > 2 ? std::atol(argv[2]) : 1);
  if (n < 2 || n > 100000) {
    fmt::print(stderr, "usage: srrt_ompl_peer [N >= 2] [first_seed]\n");
    return 2;
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
  ompl::RNG::setSeed(first);  // once, before any OMPL generator exists: the OMPL runs are one seeded sequence
  const double delta = 1.7, pg = 0.6, time_limit_s = 5.0;
  fmt::print("OMPL {}.{}.{} RRT (goal bias {}, range {}, time limit {} s) vs pathref, {} runs per series, seeds {}..{}\n\n",
             OMPL_MAJOR_VERSION, OMPL_MINOR_VERSION, OMPL_PATCH_VERSION, pg, delta, time_limit_s, n, first, first + static_cast<std::uint32_t>(n) - 1);
  for (const auto& sc : pathref::reproduce::cin2021_srrt_scenes()) {
    const auto scene = pathref::io::parse_scene_json(sc.scene_json, sc.id);
    const auto map = pathref::geometry::ObstacleMap::from_scene(scene);
    std::map<std::string, Acc> acc;
    std::vector<std::string> order;
    const auto add = [&](const std::string& key, bool found, bool valid, const std::vector<Vec2>& path, double ms) {
      if (acc.find(key) == acc.end()) order.push_back(key);
      Acc& a = acc[key];
      ++a.runs;
      if (!found) return;
      ++a.found;
      if (!valid) ++a.invalid;
      a.length.push_back(length(path));
      a.nodes.push_back(static_cast<double>(path.size()));
      a.time_ms.push_back(ms);
    };
    // pathref
    for (const auto& [key, algo, over] :
         std::vector<std::tuple<std::string, std::string, pathref::continuous::Json>>{
             {"pathref rrt (Algorithm 1)", "rrt", pathref::continuous::Json::object()},
             {"pathref rrt variant=ompl", "rrt", pathref::continuous::Json{{"variant", "ompl"}}},
             {"pathref s-rrt (kept nodes)", "s-rrt", pathref::continuous::Json{{"smooth", false}}}}) {
      const auto merged = pathref::planners::merge_params(pathref::continuous::continuous_defaults(algo), over);
      for (int i = 0; i < n; ++i) {
        const auto r = pathref::continuous::run_continuous(algo, map, sc.start, sc.goal, merged,
                                                           first + static_cast<std::uint32_t>(i));
        const auto& p = algo == "s-rrt" ? r.shortcut_path : r.raw;
        add(key, r.tree.found, r.tree.found && all_free(map, p), p, r.time_ms);
      }
    }
    // OMPL
    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0, map.lower().x), bounds.setHigh(0, map.upper().x);
    bounds.setLow(1, map.lower().y), bounds.setHigh(1, map.upper().y);
    space->setBounds(bounds);
    for (int i = 0; i < n; ++i) {
      og::SimpleSetup ss(space);
      const auto si = ss.getSpaceInformation();
      ss.setStateValidityChecker([&map](const ob::State* s) { return map.point_free(xy(s)); });
      si->setMotionValidator(std::make_shared<ExactMotionValidator>(si, map));
      ob::ScopedState<> start(space), goal(space);
      start[0] = sc.start.x, start[1] = sc.start.y;
      goal[0] = sc.goal.x, goal[1] = sc.goal.y;
      ss.setStartAndGoalStates(start, goal);
      auto rrt = std::make_shared<og::RRT>(si);
      rrt->setGoalBias(pg);
      rrt->setRange(delta);
      ss.setPlanner(rrt);
      ss.setup();
      const auto t0 = std::chrono::steady_clock::now();
      const ob::PlannerStatus status = ss.solve(time_limit_s);
      const double plan_ms = ms_since(t0);
      const bool found = status == ob::PlannerStatus::EXACT_SOLUTION;
      if (!found) {
        add("OMPL RRT (raw)", false, false, {}, 0);
        add("OMPL RRT + reduceVertices/shortcutPath", false, false, {}, 0);
        add("OMPL RRT + reduceVertices/shortcutPath + smoothBSpline", false, false, {}, 0);
        add("OMPL RRT + simplifyMax (incl. smoothBSpline)", false, false, {}, 0);
        continue;
      }
      const og::PathGeometric raw = ss.getSolutionPath();
      add("OMPL RRT (raw)", true, all_free(map, points(raw)), points(raw), plan_ms);
      og::PathSimplifier ps(si, ss.getProblemDefinition()->getGoal());
      og::PathGeometric shortcut = raw;
      const auto t1 = std::chrono::steady_clock::now();
      ps.reduceVertices(shortcut);
      ps.shortcutPath(shortcut);
      const double shortcut_ms = ms_since(t1);
      add("OMPL RRT + reduceVertices/shortcutPath", true, all_free(map, points(shortcut)), points(shortcut),
          plan_ms + shortcut_ms);
      og::PathGeometric smoothed = shortcut;  // smoothBSpline alone (defaults: 5 steps, minChange = epsilon)
      const auto t3 = std::chrono::steady_clock::now();
      ps.smoothBSpline(smoothed);
      const double smooth_ms = ms_since(t3);
      add("OMPL RRT + reduceVertices/shortcutPath + smoothBSpline", true, all_free(map, points(smoothed)),
          points(smoothed), plan_ms + shortcut_ms + smooth_ms);
      og::PathGeometric full = raw;
      const auto t2 = std::chrono::steady_clock::now();
      ps.simplifyMax(full);
      const double full_ms = ms_since(t2);
      add("OMPL RRT + simplifyMax (incl. smoothBSpline)", true, all_free(map, points(full)), points(full),
          plan_ms + full_ms);
    }
    fmt::print("Scene {} ({}):\n\n", sc.id, sc.description);
    fmt::print("| series | success | invalid | length | nodes | time (ms) |\n|---|---|---|---|---|---|\n");
    for (const auto& key : order) {
      const Acc& a = acc[key];
      fmt::print("| {} | {}/{} | {} | {} | {} | {} |\n", key, a.found, a.runs, a.invalid, cell(a.length, 3),
                 cell(a.nodes, 1), cell(a.time_ms, 3));
    }
    fmt::print("\n");
  }
  return 0;
}
