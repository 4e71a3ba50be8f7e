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
  if (algo == "s-rrt") {
    const CurveParams c;
    j["shortcut"] = true;
    j["smooth"] = true;
    j["degree"] = c.degree;
    j["knots"] = std::string(bspline::to_string(c.knots));
    j["spacing"] = c.spacing;
    j["repair"] = c.repair;
  }
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

CurveParams curve_params(const Json& m) {
  CurveParams c;
  const auto get_bool = [&](const char* key, bool def) {
    if (!m.contains(key)) return def;
    if (!m.at(key).is_boolean()) throw UsageError(std::string(key) + " must be true or false");
    return m.at(key).get<bool>();
  };
  if (m.contains("degree")) {
    const Json& d = m.at("degree");
    if (!d.is_number_integer()) throw UsageError("degree must be an integer");
    const auto v = d.get<std::int64_t>();
    if (v < 1 || v > bspline::max_degree)
      throw DomainError("degree must be in [1, " + std::to_string(bspline::max_degree) + "]");
    c.degree = static_cast<int>(v);
  }
  if (m.contains("knots")) {
    if (!m.at("knots").is_string()) throw UsageError("knots must be uniform or chord");
    c.knots = bspline::parse_knot_spacing(m.at("knots").get<std::string>());
  }
  if (m.contains("spacing")) {
    if (!m.at("spacing").is_number()) throw UsageError("spacing must be a number");
    c.spacing = m.at("spacing").get<double>();
    if (!(std::isfinite(c.spacing) && c.spacing > 0.0)) throw DomainError("spacing must be finite and > 0");
  }
  c.repair = get_bool("repair", c.repair);
  return c;
}

namespace {

/// One curve over raw[kept] with its samples, clearance and curvature (no repair).
CurveResult build_curve(const CollisionChecker& map, const std::vector<Vec2>& raw,
                        const std::vector<std::size_t>& kept, const CurveParams& params) {
  CurveResult r;
  r.kept = kept;
  std::vector<Vec2> pts;
  pts.reserve(kept.size());
  for (const std::size_t k : kept) pts.push_back(raw[k]);
  r.degree = bspline::degree_for(pts.size(), params.degree, bspline::EndHandling::clamped);
  r.curve = bspline::make_curve(pts, r.degree, bspline::EndHandling::clamped, params.knots);
  r.samples = bspline::sample(r.curve, params.spacing);
  geometry::ClearanceOptions o;
  o.inflation = map.inflation();
  o.tolerance = r.samples.chord / 2.0;
  o.border = false;
  r.clearance = geometry::clearance(map, r.samples.points, o);
  r.length = polyline_length(r.samples.points);
  r.max_curvature = 0.0;
  for (const double u : r.samples.params)
    r.max_curvature = std::max(r.max_curvature, std::abs(bspline::curvature(r.curve, u)));
  return r;
}

}  // namespace

CurveResult smooth_path(const CollisionChecker& map, const std::vector<Vec2>& raw,
                        const std::vector<std::size_t>& kept, const CurveParams& params) {
  require(raw.size() >= 2, "smooth_path: the raw path needs >= 2 points");
  require(kept.size() >= 2 && kept.front() == 0 && kept.back() == raw.size() - 1,
          "smooth_path: kept must start at 0 and end at the last raw index");
  for (std::size_t i = 1; i < kept.size(); ++i)
    require(kept[i - 1] < kept[i], "smooth_path: kept must be strictly increasing");
  CurveResult r = build_curve(map, raw, kept, params);
  if (!params.repair) return r;
  std::vector<std::size_t> inserted;
  while (r.clearance.verdict != geometry::ClearanceVerdict::clear) {
    const auto s = static_cast<std::size_t>(r.clearance.segment);
    const double u = r.samples.params[s];
    const Vec2 at = r.samples.points[s];
    const std::size_t k = bspline::span_index(r.curve.knots, r.degree, r.curve.control.size(), u);
    const std::size_t lo = r.kept[k - static_cast<std::size_t>(r.degree)];
    const std::size_t hi = r.kept[k];
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = lo + 1; i < hi; ++i) {  // every i strictly between two kept neighbours is not kept
      if (std::binary_search(r.kept.begin(), r.kept.end(), i)) continue;
      const double d = squared_distance(raw[i], at);
      if (d < best_d) {
        best_d = d;
        best = i;
      }
    }
    if (!(best_d < std::numeric_limits<double>::infinity())) {
      r.inserted = inserted;
      r.repair = "stuck";
      return r;
    }
    std::vector<std::size_t> next = r.kept;
    next.insert(std::upper_bound(next.begin(), next.end(), best), best);
    inserted.push_back(best);
    r = build_curve(map, raw, next, params);
  }
  r.inserted = inserted;
  r.repair = "clear";
  return r;
}

ContinuousRun run_continuous(std::string_view algo, const CollisionChecker& map, Vec2 start, Vec2 goal,
                             const Json& merged, std::uint32_t seed, rng::Trace* trace) {
  if (!is_continuous_planner(algo)) throw UsageError("not a continuous planner: '" + std::string(algo) + "'");
  const RrtParams params = rrt_params(merged);
  const bool do_shortcut = algo == "s-rrt" && merged.value("shortcut", true);
  const bool do_smooth = algo == "s-rrt" && merged.value("smooth", true);
  const CurveParams cparams = algo == "s-rrt" ? curve_params(merged) : CurveParams{};
  ContinuousRun run;
  run.params_used = merged;
  const auto t0 = std::chrono::steady_clock::now();
  rng::Stream stream(seed);
  stream.set_trace(trace);
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
    if (do_smooth) {
      // The curve's control points: the kept nodes (all raw nodes when shortcut=false).
      std::vector<std::size_t> kept = run.kept;
      if (!do_shortcut)
        for (std::size_t i = 0; i < run.raw.size(); ++i) kept.push_back(i);
      if (run.raw.size() >= 2) {
        const auto c0 = std::chrono::steady_clock::now();
        run.curve = smooth_path(map, run.raw, kept, cparams);
        run.curve_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - c0).count();
      }
    }
  }
  return run;
}

}  // namespace pathref::continuous
