// `pathref plan --algo rrt | s-rrt`: continuous planners on polygon scenes (exact, not inflated
// into cells) and on grid maps (blocked cells as squares). World coordinates in, continuous paths
// out (plan JSON format version 2). Spec: spec/cli.md#plan-continuous, spec/cin2021-srrt.md.
#include <fmt/core.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "commands.hpp"
#include "pathref/io/scene_json.hpp"
#include "pathref/core/version.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/decimal.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/io/builtin_maps.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/io/svg_continuous.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/trace.hpp"

namespace pathref::cli {

namespace {

using continuous::Vec2;
using Json = nlohmann::json;

double to_double(const geometry::Decimal& d) { return std::strtod(geometry::to_string(d).c_str(), nullptr); }

/// "X,Y" with X and Y JSON numbers (decimal, optional sign, fraction, exponent) -> the nearest
/// doubles. UsageError naming the option otherwise.
Vec2 parse_xy(const std::string& text, const char* option) {
  const auto bad = [&] {
    return UsageError(fmt::format("{} expects X,Y (two decimal numbers, world coordinates), got '{}'", option, text));
  };
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw bad();
  const auto number = [&](const std::string& s) {
    if (!geometry::parse_decimal(s)) throw bad();
    const double v = std::strtod(s.c_str(), nullptr);
    if (!std::isfinite(v)) throw bad();
    return v;
  };
  return Vec2{number(text.substr(0, comma)), number(text.substr(comma + 1))};
}

/// The obstacles, the default endpoints (cell centres) and a description of the map.
struct ContinuousMap {
  std::optional<geometry::ObstacleMap> obstacles;
  std::optional<Vec2> start, goal;
  Json map_json;
  std::string description;
  /// The cell (x, y)'s centre in world coordinates.
  double ox = 0.0, oy = 0.0, s = 1.0;
  [[nodiscard]] Vec2 centre(grid::Cell c) const {
    return Vec2{ox + (static_cast<double>(c.x) + 0.5) * s, oy + (static_cast<double>(c.y) + 0.5) * s};
  }
};

ContinuousMap load_continuous_map(const ContinuousPlanArgs& o) {
  if (o.map_file.empty() == o.builtin.empty())
    throw UsageError("give exactly one of --map FILE or --builtin NAME (see pathref maps)");
  ContinuousMap cm;
  io::MapFormat format = io::parse_map_format(o.read.format);
  if (!o.map_file.empty() && format == io::MapFormat::automatic)
    format = io::detect_map_format(o.map_file, "");
  if (!o.map_file.empty() && format == io::MapFormat::scene) {
    const geometry::Scene sc = io::read_scene_file(o.map_file);
    try {
      cm.obstacles = geometry::ObstacleMap::from_scene(sc);
    } catch (const DomainError& e) {
      throw DomainError(o.map_file + ": " + e.what());
    }
    cm.ox = to_double(sc.origin.x);
    cm.oy = to_double(sc.origin.y);
    cm.s = to_double(sc.cell_size);
    if (sc.start) cm.start = cm.centre(*sc.start);
    if (sc.goal) cm.goal = cm.centre(*sc.goal);
    cm.map_json = Json{{"source", "file"},
                       {"kind", "scene"},
                       {"name", sc.name.empty() ? o.map_file : sc.name},
                       {"file", o.map_file},
                       {"polygons", sc.polygons.size()},
                       {"radius", geometry::to_string(sc.radius)},
                       {"margin", geometry::to_string(sc.margin)}};
    cm.description = fmt::format("{} (scene {}, {} polygons, r = {} + {})", sc.name.empty() ? o.map_file : sc.name,
                                 o.map_file, sc.polygons.size(), geometry::to_string(sc.radius),
                                 geometry::to_string(sc.margin));
  } else {
    Json src;
    const io::MapFile m = [&] {
      if (!o.builtin.empty()) {
        const io::BuiltinMap* b = io::find_builtin_map(o.builtin);
        if (b == nullptr)
          throw UsageError(fmt::format("unknown built-in map '{}' (known: {})", o.builtin, io::builtin_map_names()));
        src = Json{{"source", "builtin"}, {"name", std::string(b->name)}, {"file", nullptr}};
        return io::load_builtin_map(*b);
      }
      io::MapFile f = io::load_map_file(o.map_file, map_read_options(o.read)).map;
      src = Json{{"source", "file"}, {"name", f.name.empty() ? o.map_file : f.name}, {"file", o.map_file}};
      return f;
    }();
    cm.obstacles = geometry::ObstacleMap::from_grid(m.grid, geometry::decimal_from_integer(0));
    if (m.start) cm.start = cm.centre(*m.start);
    if (m.goal) cm.goal = cm.centre(*m.goal);
    src["kind"] = "grid";
    src["width"] = m.grid.width();
    src["height"] = m.grid.height();
    src["rows"] = m.grid.to_rows_top_first();
    src["radius"] = "0";
    cm.description = fmt::format("{} (grid {}x{}, {} blocked cells as unit squares, r = 0)",
                                 src["name"].get<std::string>(), m.grid.width(), m.grid.height(),
                                 m.grid.blocked_count());
    cm.map_json = std::move(src);
  }
  return cm;
}

Vec2 endpoint(const std::optional<std::string>& cell_text, const std::optional<std::string>& xy_text,
              const std::optional<Vec2>& from_map, const ContinuousMap& cm, const char* which) {
  if (cell_text && xy_text)
    throw UsageError(fmt::format("give at most one of --{0} X,Y (a cell: its centre) and --{0}-xy X,Y (world coordinates)", which));
  if (xy_text) return parse_xy(*xy_text, which == std::string("start") ? "--start-xy" : "--goal-xy");
  if (cell_text) return cm.centre(parse_cell_arg(*cell_text, which == std::string("start") ? "--start" : "--goal"));
  if (from_map) return *from_map;
  throw UsageError(fmt::format("the map defines no {0}: give --{0}-xy X,Y or --{0} X,Y", which));
}

Json points_json(const std::vector<Vec2>& pts) {
  Json a = Json::array();
  for (const Vec2& p : pts) a.push_back(Json::array({p.x, p.y}));
  return a;
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json metrics_json(const continuous::PathMetrics& m) {
  return Json{{"length", m.length}, {"nodes", m.nodes}, {"clearance", number_or_null(m.clearance)}};
}

Json numbers_json(const std::vector<double>& v) {
  Json a = Json::array();
  for (const double x : v) a.push_back(x);
  return a;
}

/// The smoothed curve of s-rrt (spec/cli.md#plan-continuous, spec/cin2021-srrt.md
/// r[cin2021.srrt.curve]).
Json curve_json(const continuous::CurveResult& c, double inflation, double ms) {
  return Json{{"degree", c.degree},
              {"end", "clamped"},
              {"knots", numbers_json(c.curve.knots)},
              {"control", points_json(c.curve.control)},
              {"kept", c.kept},
              {"samples", points_json(c.samples.points)},
              {"params", numbers_json(c.samples.params)},
              {"chord", c.samples.chord},
              {"length", c.length},
              {"max_curvature", number_or_null(c.max_curvature)},
              {"clearance", Json{{"distance", number_or_null(c.clearance.distance)},
                                 {"lower", number_or_null(c.clearance.lower)},
                                 {"upper", number_or_null(c.clearance.upper)},
                                 {"inflation", inflation},
                                 {"verdict", std::string(geometry::to_string(c.clearance.verdict))}}},
              {"repair", c.repair},
              {"inserted", c.inserted},
              {"time_ms", ms}};
}

std::string fmt_pt(Vec2 p) { return fmt::format("({}, {})", p.x, p.y); }

}  // namespace

int run_continuous_plan(const ContinuousPlanArgs& o) {
  if (o.policy_given)
    throw UsageError(fmt::format("--policy is a grid notion (diagonal moves between cells); {} plans in the continuous plane", o.algo));
  const std::uint32_t seed = o.seed;
  const Json defaults = continuous::continuous_defaults(o.algo);
  const Json merged = planners::merge_params(defaults, o.overrides);
  (void)continuous::rrt_params(merged);  // option names checked before the map is read
  if (o.algo == "s-rrt") (void)continuous::curve_params(merged);
  const ContinuousMap cm = load_continuous_map(o);
  const Vec2 start = endpoint(o.start, o.start_xy, cm.start, cm, "start");
  const Vec2 goal = endpoint(o.goal, o.goal_xy, cm.goal, cm, "goal");
  const geometry::ObstacleMap& om = *cm.obstacles;
  if (!om.point_free(start))
    throw UsageError(fmt::format("start {} is not free (outside the world or within r of an obstacle)", fmt_pt(start)));
  if (!om.point_free(goal))
    throw UsageError(fmt::format("goal {} is not free (outside the world or within r of an obstacle)", fmt_pt(goal)));
  if (start == goal) throw UsageError(fmt::format("start and goal are the same point {}: there is nothing to plan", fmt_pt(start)));

  rng::Trace trace;
  const continuous::ContinuousRun run =
      continuous::run_continuous(o.algo, om, start, goal, merged, seed, o.trace.empty() ? nullptr : &trace);
  if (!o.trace.empty()) write_trace_file(o.trace, trace, seed, o.algo, run.params_used);
  Json j{{"format", "pathref-plan"},
         {"format_version", 2},
         {"space", "continuous"},
         {"algo", o.algo},
         {"seed", seed},
         {"params", run.params_used},
         {"map", cm.map_json},
         {"world", Json{{"lower", Json::array({om.lower().x, om.lower().y})},
                        {"upper", Json::array({om.upper().x, om.upper().y})}}},
         {"start_xy", Json::array({start.x, start.y})},
         {"goal_xy", Json::array({goal.x, goal.y})},
         {"found", run.tree.found},
         {"iterations", run.tree.iterations},
         {"samples", run.tree.iterations},
         {"tree_size", run.tree.nodes.size()},
         {"rejected_edges", run.tree.rejected_edges},
         {"draws", run.tree.draws},
         {"time_ms", run.time_ms},
         {"tree", Json{{"nodes", points_json(run.tree.nodes)}, {"parent", run.tree.parent}}},
         {"raw_path", points_json(run.raw)},
         {"raw", run.tree.found ? metrics_json(run.raw_metrics) : Json(nullptr)}};
  stamp_version(j);
  if (o.algo == "s-rrt") {
    j["shortcut_path"] = points_json(run.shortcut_path);
    j["shortcut_kept"] = run.kept;
    j["shortcut"] = run.tree.found && !run.shortcut_path.empty() ? metrics_json(run.shortcut_metrics) : Json(nullptr);
    j["curve"] = run.curve ? curve_json(*run.curve, om.inflation(), run.curve_ms) : Json(nullptr);
  }
  const std::string title = fmt::format("{}: {}, seed {}", cm.map_json.value("name", std::string()), o.algo, seed);
  if (!o.json_out.empty()) write_output_file(o.json_out, j.dump(2) + "\n");
  if (!o.svg.empty()) write_figure(o.svg, io::svg_continuous(io::ContinuousScene{om.polygons(), om.radius(), om.lower(), om.upper()}, run, start, goal, title));
  if (o.json) {
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("pathref {} plan\n", std::string(pathref::version()));
    fmt::print("  map         {}\n", cm.description);
    fmt::print("  world       [{}, {}] x [{}, {}]\n", om.lower().x, om.upper().x, om.lower().y, om.upper().y);
    fmt::print("  algo        {} (continuous plane, exact collision checks)\n", o.algo);
    fmt::print("  seed        {}\n", seed);
    std::string params;
    for (const auto& [k, v] : run.params_used.items())
      params += (params.empty() ? "" : " ") + k + "=" + (v.is_string() ? v.get<std::string>() : v.dump());
    fmt::print("  params      {}\n", params);
    fmt::print("  start       {}\n", fmt_pt(start));
    fmt::print("  goal        {}\n", fmt_pt(goal));
    fmt::print("result\n");
    fmt::print("  found       {}\n", run.tree.found ? "yes" : "no (no path within max_iterations)");
    fmt::print("  iterations  {}\n", run.tree.iterations);
    fmt::print("  tree        {} nodes, {} rejected edges, {} draws\n", run.tree.nodes.size(), run.tree.rejected_edges,
               run.tree.draws);
    if (run.tree.found) {
      fmt::print("  raw path    length {}, {} nodes, clearance {}\n", run.raw_metrics.length, run.raw_metrics.nodes,
                 run.raw_metrics.clearance);
      if (!run.shortcut_path.empty())
        fmt::print("  shortcut    length {}, {} nodes, clearance {}\n", run.shortcut_metrics.length,
                   run.shortcut_metrics.nodes, run.shortcut_metrics.clearance);
      if (run.curve) {
        const auto& c = *run.curve;
        fmt::print("  curve       degree {}, {} control points, {} samples (chord <= {:.4g}), length {}\n", c.degree,
                   c.curve.control.size(), c.samples.points.size(), c.samples.chord, c.length);
        fmt::print("              clearance in [{}, {}] (r = {}): {}, max curvature {}\n", c.clearance.lower,
                   c.clearance.upper, om.inflation(), geometry::to_string(c.clearance.verdict), c.max_curvature);
        fmt::print("              repair {}{}\n", c.repair,
                   c.inserted.empty() ? std::string() : fmt::format(" ({} node(s) re-inserted)", c.inserted.size()));
      }
    }
    fmt::print("  time        {:.3f} ms\n", run.time_ms);
    if (!o.json_out.empty()) fmt::print("wrote {}\n", o.json_out);
    if (!o.svg.empty()) fmt::print("wrote {}\n", o.svg);
    if (!o.trace.empty()) fmt::print("wrote {} ({} draws)\n", o.trace, trace.draws().size());
  }
  return run.tree.found ? 0 : 1;
}

}  // namespace pathref::cli
