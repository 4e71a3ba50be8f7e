// JSON adapters for the cin2021 S-RRT rules (spec/cin2021-srrt.md). They live in pathref_geometry
// because they need the exact collision test (ObstacleMap); they reach the registry through
// rules::add_extension_module (install_srrt_rules). No CGAL header here.
#include <cmath>
#include <string>
#include <vector>

#include "pathref/io/scene_json.hpp"
#include "pathref/continuous/kdtree.hpp"
#include "pathref/continuous/rrt.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/clearance.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::geometry {

namespace {

using rules::Json;
using continuous::Vec2;

Vec2 point_arg(const Json& in, const char* key) {
  const Json& v = rules::arg(in, key);
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
    throw UsageError(std::string("input '") + key + "' must be [x, y] (two numbers)");
  return Vec2{v[0].get<double>(), v[1].get<double>()};
}

std::vector<Vec2> points_arg(const Json& in, const char* key) {
  const Json& v = rules::arg(in, key);
  if (!v.is_array()) throw UsageError(std::string("input '") + key + "' must be [[x, y], ...]");
  std::vector<Vec2> out;
  for (const Json& p : v) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      throw UsageError(std::string("input '") + key + "' must be [[x, y], ...]");
    out.push_back(Vec2{p[0].get<double>(), p[1].get<double>()});
  }
  return out;
}

Json point_json(Vec2 p) { return Json::array({rules::number(p.x), rules::number(p.y)}); }
Json points_json(const std::vector<Vec2>& v) {
  Json a = Json::array();
  for (const Vec2& p : v) a.push_back(point_json(p));
  return a;
}

/// The scene part of a rule input (its geometry keys only: the other inputs of a rule, such as
/// `start` in world coordinates, are not the scene's).
ObstacleMap obstacles_of(const Json& in) {
  Json geo = Json::object();
  for (const char* k : {"origin", "width", "height", "cell_size", "radius", "margin", "polygons"})
    if (in.contains(k)) geo[k] = in.at(k);
  return ObstacleMap::from_scene(io::scene_from_json(geo, "<input>", io::SceneKeys::geometry));
}

const std::vector<rules::Field> scene_fields = {
    {"origin", "number[2]", "world lower-left corner [x, y] (exact decimals)"},
    {"width", "integer", "W: the world is [ox, ox + W s] x [oy, oy + H s]"},
    {"height", "integer", "H"},
    {"cell_size", "number", "s > 0"},
    {"radius", "number", "robot radius >= 0"},
    {"margin", "number", "safety margin >= 0; r = radius + margin"},
    {"polygons", "object[]", "[{\"vertices\": [[x, y], ...]}, ...] simple polygons (exact decimals)"},
};

std::vector<rules::Field> with(std::vector<rules::Field> base, std::initializer_list<rules::Field> more) {
  base.insert(base.end(), more);
  return base;
}

/// Algorithm 1's parameters from a rule input: the planner defaults overlaid with the input's
/// numeric keys and the interpretation options (bias, near, variant, sample, steer).
continuous::RrtParams params_of(const Json& in) {
  Json m = continuous::continuous_defaults("rrt");
  for (const char* k : {"delta", "goal_probability"})
    if (in.contains(k)) m[k] = rules::arg_number(in, k);
  for (const char* k : {"max_iterations", "max_rejections"})
    if (in.contains(k)) m[k] = rules::arg_integer(in, k);
  for (const char* k : {"bias", "near", "variant", "sample", "steer"})
    m[k] = rules::opt_string(in, k, m[k].get<std::string>().c_str());
  return continuous::rrt_params(m);
}

void register_srrt_rules(rules::Registry& r) {
  r.add(rules::Rule{
      "cin2021.srrt.collision",
      "Exact test: segment [a, b] free iff inside the world and dist^2 > r^2 to every closed obstacle polygon",
      "pathref::geometry::ObstacleMap::segment_free",
      with(scene_fields, {{"a", "number[2]", "segment start (binary64, exact)"}, {"b", "number[2]", "segment end (a == b: a point)"}}),
      {{"free", "bool", "segment_free(a, b)"},
       {"signs", "integer[]", "per polygon: sign of dist^2 - r^2 (-1, 0, +1)"}},
      [](const Json& in) {
        const ObstacleMap m = obstacles_of(in);
        const Vec2 a = point_arg(in, "a"), b = point_arg(in, "b");
        Json signs = Json::array();
        for (std::size_t k = 0; k < m.polygon_count(); ++k) signs.push_back(m.compare_segment(k, a, b));
        return Json{{"free", m.segment_free(a, b)}, {"signs", signs}};
      }});
  r.add(rules::Rule{
      "cin2021.srrt.nearest",
      "Nearest tree node to q: smallest (dx*dx + dy*dy, index), the oldest of equally near nodes",
      "pathref::continuous::KdTree::nearest",
      {{"points", "number[2][]", "the tree's nodes in insertion order"}, {"q", "number[2]", "the query point"}},
      {{"index", "integer", "index of the nearest node"}},
      [](const Json& in) {
        const auto pts = points_arg(in, "points");
        continuous::KdTree t;
        for (const Vec2& p : pts) t.insert(p);
        const std::size_t k = t.nearest(point_arg(in, "q"));
        if (k != continuous::nearest_brute_force(pts, point_arg(in, "q")))
          throw DomainError("internal: k-d tree and brute force disagree");
        return Json{{"index", k}};
      }});
  r.add(rules::Rule{
      "cin2021.srrt.steer",
      "Steer(x_near, x_target, delta): the point delta away towards the target (clip: the target when d <= delta)",
      "pathref::continuous::steer",
      {{"near", "number[2]", "x_near"}, {"target", "number[2]", "x_target"}, {"delta", "number", "step > 0"},
       {"steer", "string", "reading: clip (default) | fixed"}},
      {{"new", "number[2]", "x_new"}},
      [](const Json& in) {
        const std::string mode = rules::opt_string(in, "steer", "clip");
        if (mode != "clip" && mode != "fixed") throw UsageError("steer must be clip or fixed");
        return Json{{"new", point_json(continuous::steer(point_arg(in, "near"), point_arg(in, "target"),
                                                          rules::arg_number(in, "delta"), mode == "clip"))}};
      }});
  r.add(rules::Rule{
      "cin2021.alg1",
      "Algorithm 1 (goal-biased RRT) on a scene from start to goal with a seed: the tree and the path",
      "pathref::continuous::rrt",
      with(scene_fields,
           {{"start", "number[2]", "x_init (world, binary64)"},
            {"goal", "number[2]", "x_goal"},
            {"seed", "integer", "rng::Stream seed"},
            {"delta", "number", "fixed step (default 1.7)"},
            {"goal_probability", "number", "P_g (default 0.6)"},
            {"max_iterations", "integer", "N (default 20000)"},
            {"max_rejections", "integer", "sample=free: cap (default 1000)"},
            {"bias", "string", "reading: lt (default) | gt"},
            {"near", "string", "reading: sample (default) | target"},
            {"variant", "string", "paper (default) | plain | ompl"},
            {"sample", "string", "rect (default) | free"},
            {"steer", "string", "clip (default) | fixed"}}),
      {{"found", "bool", "the goal was reached"},
       {"path", "number[2][]", "root ... goal"},
       {"tree_size", "integer", "nodes in the tree (goal included)"},
       {"iterations", "integer", "loop iterations"},
       {"rejected_edges", "integer", "iterations whose edge was not free"},
       {"draws", "integer", "doubles drawn"}},
      [](const Json& in) {
        const ObstacleMap m = obstacles_of(in);
        const auto seed = rules::arg_integer(in, "seed");
        if (seed < 0 || seed > 4294967295LL) throw UsageError("seed must be in [0, 2^32 - 1]");
        rng::Stream s(static_cast<std::uint32_t>(seed));
        const auto res = continuous::rrt(m, point_arg(in, "start"), point_arg(in, "goal"), params_of(in), s);
        std::vector<Vec2> path;
        for (const auto k : res.path) path.push_back(res.nodes[k]);
        return Json{{"found", res.found},
                    {"path", points_json(path)},
                    {"tree_size", res.nodes.size()},
                    {"iterations", res.iterations},
                    {"rejected_edges", res.rejected_edges},
                    {"draws", res.draws}};
      }});
  r.add(rules::Rule{
      "cin2021.alg2",
      "Algorithm 2: greedy reverse shortcut of a free path (kept indices, lengths before and after)",
      "pathref::continuous::shortcut",
      with(scene_fields, {{"path", "number[2][]", "p_0 ... p_m with free consecutive segments"}}),
      {{"kept", "integer[]", "indices kept (0 first, m last)"},
       {"length_before", "number", "polyline length of the input"},
       {"length_after", "number", "polyline length of the kept nodes"}},
      [](const Json& in) {
        const ObstacleMap m = obstacles_of(in);
        const auto path = points_arg(in, "path");
        const auto kept = continuous::shortcut(m, path);
        std::vector<Vec2> out;
        for (const auto k : kept) out.push_back(path[k]);
        return Json{{"kept", kept},
                    {"length_before", continuous::polyline_length(path)},
                    {"length_after", continuous::polyline_length(out)}};
      }});
  r.add(rules::Rule{
      "cin2021.srrt.metrics",
      "Table 2 metrics of a polyline: length (left-to-right sum), nodes, clearance (exact distance, without r)",
      "pathref::continuous::path_metrics",
      with(scene_fields, {{"path", "number[2][]", "p_0 ... p_m (m >= 0)"}}),
      {{"length", "number", "sum of sqrt(dx*dx + dy*dy)"},
       {"nodes", "integer", "m + 1"},
       {"clearance", "number", "min segment-obstacle distance (\"inf\" without obstacles)"},
       {"turning", "number", "sum of |heading changes| atan2(|cross|, dot), radians"}},
      [](const Json& in) {
        const ObstacleMap m = obstacles_of(in);
        const auto pm = continuous::path_metrics(m, points_arg(in, "path"));
        return Json{{"length", pm.length},
                    {"nodes", pm.nodes},
                    {"clearance", rules::number(pm.clearance)},
                    {"turning", pm.turning}};
      }});
  r.add(rules::Rule{
      "curves.polygon-clearance",
      "Distance of a polyline (or sampled curve) to a scene's closed polygons and world border; bounds and verdict",
      "pathref::geometry::clearance",
      with(scene_fields,
           {{"points", "number[2][]", "the polyline [[x, y], ...]"},
            {"inflation", "number", "r >= 0 for the verdict (default 0; independent of the scene's radius)"},
            {"tolerance", "number", "tau >= 0: vertices are curve samples within tau (default 0)"},
            {"border", "bool", "the outside of the world rectangle is an obstacle (default true)"}}),
      {{"distance", "number", "distance of the polyline ('inf' without obstacles)"},
       {"lower", "number", "lower bound of the path's clearance"},
       {"upper", "number", "upper bound"},
       {"verdict", "string", "clear | enters | undetermined"},
       {"segment", "integer", "first segment attaining the distance (-1 if inf)"}},
      [](const Json& in) {
        const ObstacleMap m = obstacles_of(in);
        ClearanceOptions o;
        if (in.contains("inflation")) o.inflation = rules::arg_number(in, "inflation");
        if (in.contains("tolerance")) o.tolerance = rules::arg_number(in, "tolerance");
        if (in.contains("border")) {
          if (!in.at("border").is_boolean()) throw UsageError("input 'border' must be a bool");
          o.border = in.at("border").get<bool>();
        }
        const auto c = clearance(m, points_arg(in, "points"), o);
        return Json{{"distance", rules::number(c.distance)},
                    {"lower", rules::number(c.lower)},
                    {"upper", rules::number(c.upper)},
                    {"verdict", std::string(to_string(c.verdict))},
                    {"segment", c.segment}};
      }});
  r.add(rules::Rule{
      "cin2021.srrt.curve",
      "S-RRT's clamped B-spline over the kept nodes: samples, clearance against r, curvature, optional repair",
      "pathref::continuous::smooth_path",
      with(scene_fields,
           {{"raw", "number[2][]", "the raw path p_0 ... p_n (Algorithm 1's branch)"},
            {"kept", "integer[]", "indices kept by Algorithm 2 (0 first, n last)"},
            {"degree", "integer", "requested degree (default 3)"},
            {"knots", "string", "uniform (default) | chord"},
            {"spacing", "number", "sample spacing > 0 (default 0.05)"},
            {"repair", "bool", "re-insert and re-smooth (default false)"}}),
      {{"degree", "integer", "degree used"},
       {"kept", "integer[]", "control points as raw indices (after repair)"},
       {"inserted", "integer[]", "raw indices re-inserted, in order"},
       {"samples", "integer", "number of samples"},
       {"chord", "number", "the sampler's chord bound"},
       {"length", "number", "polyline length of the samples"},
       {"max_curvature", "number", "max |curvature| at the samples ('inf' where no tangent)"},
       {"lower", "number", "clearance lower bound"},
       {"upper", "number", "clearance upper bound"},
       {"verdict", "string", "clear | enters | undetermined (against the scene's r)"},
       {"repair", "string", "off | clear | stuck"}},
      [](const Json& in) {
        const ObstacleMap m = obstacles_of(in);
        Json params = Json::object();
        if (in.contains("degree")) params["degree"] = in.at("degree");
        if (in.contains("knots")) params["knots"] = in.at("knots");
        if (in.contains("spacing")) params["spacing"] = in.at("spacing");
        if (in.contains("repair")) params["repair"] = in.at("repair");
        const auto cp = continuous::curve_params(params);
        const Json& kj = rules::arg(in, "kept");
        if (!kj.is_array()) throw UsageError("input 'kept' must be an array of indices");
        std::vector<std::size_t> kept;
        for (const Json& v : kj) {
          if (!v.is_number_integer() || v.get<std::int64_t>() < 0) throw UsageError("input 'kept' must hold indices >= 0");
          kept.push_back(v.get<std::size_t>());
        }
        const auto raw = points_arg(in, "raw");
        require(kept.empty() || kept.back() < raw.size(), "kept: index out of range");
        const auto c = continuous::smooth_path(m, raw, kept, cp);
        return Json{{"degree", c.degree},
                    {"kept", c.kept},
                    {"inserted", c.inserted},
                    {"samples", c.samples.points.size()},
                    {"chord", rules::number(c.samples.chord)},
                    {"length", rules::number(c.length)},
                    {"max_curvature", rules::number(c.max_curvature)},
                    {"lower", rules::number(c.clearance.lower)},
                    {"upper", rules::number(c.clearance.upper)},
                    {"verdict", std::string(to_string(c.clearance.verdict))},
                    {"repair", c.repair}};
      }});
}

}  // namespace

void install_srrt_rules() { rules::add_extension_module(&register_srrt_rules); }

}  // namespace pathref::geometry
