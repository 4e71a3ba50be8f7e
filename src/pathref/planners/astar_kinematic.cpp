#include "pathref/planners/astar_kinematic.hpp"
#include "pathref/planners/search.hpp"

#include <cmath>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/metrics.hpp"

namespace pathref::sensors2023 {

namespace {

void check_options(const KinematicOptions& o) {
  require(o.directions == 5 || o.directions == 8, "astar-kinematic: directions must be 5 or 8");
  require(o.radius >= 1 && o.radius <= 64, "astar-kinematic: radius must be in 1..64");
  require(o.k >= 1 && o.k <= 1024, "astar-kinematic: k must be in 1..1024");
  require(std::isfinite(o.ds) && o.ds >= 0.0 && o.ds <= 64.0,
          "astar-kinematic: ds must be in [0, 64]");
  require(o.degree >= 1 && o.degree <= bspline::max_degree,
          "astar-kinematic: degree must be in 1..20");
  require(std::isfinite(o.spacing) && o.spacing > 0.0,
          "astar-kinematic: spacing must be finite and > 0");
  require(std::isfinite(o.inflation) && o.inflation >= 0.0,
          "astar-kinematic: inflation must be finite and >= 0");
}

geometry::Vec2 centre(grid::Cell c) {
  return geometry::Vec2{static_cast<double>(c.x) + 0.5, static_cast<double>(c.y) + 0.5};
}

double polyline_length(const std::vector<geometry::Vec2>& p) {
  double s = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const double dx = p[i].x - p[i - 1].x;
    const double dy = p[i].y - p[i - 1].y;
    s = s + std::sqrt((dx * dx) + (dy * dy));
  }
  return s;
}

}  // namespace

Redundancy parse_redundancy(std::string_view name) {
  if (name == "secondary") return Redundancy::secondary;
  if (name == "ordinary") return Redundancy::ordinary;
  if (name == "none") return Redundancy::none;
  throw UsageError("redundancy must be secondary, ordinary or none, not '" + std::string(name) +
                   "'");
}

std::string_view to_string(Redundancy r) noexcept {
  switch (r) {
    case Redundancy::secondary: return "secondary";
    case Redundancy::ordinary: return "ordinary";
    case Redundancy::none: return "none";
  }
  return "none";
}

KinematicResult plan_kinematic(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                               grid::CornerPolicy policy, const KinematicOptions& o) {
  check_options(o);
  require(g.in_bounds(start), "search: start cell outside the grid");
  require(g.in_bounds(goal), "search: goal cell outside the grid");
  KinematicResult out;
  const double R = heuristics::euclidean(start, goal);
  out.start_goal_distance = R;

  // Eq. 1-4 on the one best-first core.
  const auto run = [&](int directions) {
    search::ExpansionRule rule;
    if (directions == 5)
      rule.moves = [&](grid::Cell c) { return child_moves(g, c, goal, o.radius); };
    rule.h = [&](grid::Cell n) { return heuristics::euclidean(n, goal); };  // Eq. 2
    rule.f = [&](double gv, double hv, grid::Cell) {  // Eq. 3 / 4, r = h(n)
      return f_weighted(gv, hv, hv, R, o.weight);
    };
    return search::best_first(g, start, goal, policy, rule);
  };
  out.search = run(o.directions);
  if (!out.search.found && o.directions == 5 && o.fallback) {
    search::Outcome full = run(8);
    full.expansions += out.search.expansions;
    full.generated += out.search.generated;
    full.child_nodes += out.search.child_nodes;
    out.search = std::move(full);
    out.fallback_used = true;
  }
  if (!out.search.found) return out;

  // Eq. 5: the ordinary pass (collision test) and the secondary pass (collision + safety test).
  const std::vector<grid::Cell>& raw = out.search.path;
  const auto collision_free = [&](grid::Cell a, grid::Cell b) {
    return !segment_blocked(g, a, b);
  };
  const auto safe = [&](grid::Cell a, grid::Cell b) {
    return !segment_blocked(g, a, b) && safety_test(g, a, b, o.k, o.ds, o.safety).safe;
  };
  out.ordinary = greedy_removal(std::span<const grid::Cell>(raw), collision_free);
  out.secondary = greedy_removal(
      std::span<const grid::Cell>(o.secondary_on_raw ? raw : out.ordinary), safe);
  switch (o.redundancy) {
    case Redundancy::secondary: out.key_nodes = out.secondary; break;
    case Redundancy::ordinary: out.key_nodes = out.ordinary; break;
    case Redundancy::none: out.key_nodes = raw; break;
  }
  out.turns_raw = metrics::turn_count(raw);
  out.turns_ordinary = metrics::turn_count(out.ordinary);
  out.turns_secondary = metrics::turn_count(out.secondary);
  out.turns_key = metrics::turn_count(out.key_nodes);
  out.key_length = metrics::path_length(out.key_nodes);
  std::vector<geometry::Vec2> key_points;
  key_points.reserve(out.key_nodes.size());
  for (const grid::Cell& c : out.key_nodes) key_points.push_back(centre(c));
  out.key_clearance = geometry::clearance(g, key_points, {o.inflation, 0.0, true});

  // Eq. 6-8: the B-spline of the key nodes, sampled, and its clearance.
  bool fits = true;
  try {
    out.degree_used = bspline::degree_for(key_points.size(), o.degree, o.end);
  } catch (const DomainError&) {
    fits = false;  // one key node with clamped / none: no curve
  }
  if (fits) {
    const bspline::Curve curve = bspline::make_curve(key_points, out.degree_used, o.end);
    out.curve = bspline::sample(curve, o.spacing);
    out.curve_length = polyline_length(out.curve.points);
    out.clearance =
        geometry::clearance(g, out.curve.points, {o.inflation, out.curve.chord / 2.0, true});
    out.has_curve = true;
  }
  return out;
}

KinematicOptions options_from_json(const planners::Json& p) {
  KinematicOptions o;
  const auto integer = [&](const char* key) {
    const auto& v = p.at(key);
    if (!v.is_number_integer()) throw UsageError(std::string(key) + " must be an integer");
    const auto x = v.get<long long>();
    if (x < -100000 || x > 100000) throw DomainError(std::string(key) + " out of range");
    return static_cast<int>(x);
  };
  const auto real = [&](const char* key) {
    const auto& v = p.at(key);
    if (!v.is_number()) throw UsageError(std::string(key) + " must be a number");
    return v.get<double>();
  };
  const auto text = [&](const char* key) {
    const auto& v = p.at(key);
    if (!v.is_string()) throw UsageError(std::string(key) + " must be a string");
    return v.get<std::string>();
  };
  o.directions = integer("directions");
  o.radius = integer("radius");
  const std::string fb = text("fallback");
  if (fb != "full" && fb != "none") throw UsageError("fallback must be full or none");
  o.fallback = fb == "full";
  o.weight = parse_weight_form(text("weight"));
  o.redundancy = parse_redundancy(text("redundancy"));
  const std::string si = text("secondary_input");
  if (si != "raw" && si != "ordinary") throw UsageError("secondary_input must be raw or ordinary");
  o.secondary_on_raw = si == "raw";
  o.k = integer("k");
  o.ds = real("ds");
  o.safety = parse_safety_compare(text("safety"));
  o.degree = integer("degree");
  o.end = bspline::parse_end_handling(text("end"));
  o.spacing = real("spacing");
  o.inflation = real("inflation");
  check_options(o);
  return o;
}

planners::Json result_to_json(const KinematicResult& r, const KinematicOptions& o) {
  using planners::Json;
  const auto cells = [](const std::vector<grid::Cell>& v) {
    Json a = Json::array();
    for (const auto& c : v) a.push_back(Json::array({c.x, c.y}));
    return a;
  };
  const auto num = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  const auto clear = [&](const geometry::Clearance& c) {
    return Json{{"distance", num(c.distance)},
                {"lower", num(c.lower)},
                {"upper", num(c.upper)},
                {"verdict", std::string(geometry::to_string(c.verdict))},
                {"inflation", o.inflation}};
  };
  Json j = {{"fallback_used", r.fallback_used},
            {"start_goal_distance", r.start_goal_distance},
            {"expansions", r.search.expansions},
            {"generated", r.search.generated},
            {"child_nodes", r.search.child_nodes}};
  if (!r.search.found) return j;
  j["turns_raw"] = r.turns_raw;
  j["ordinary_nodes"] = cells(r.ordinary);
  j["turns_ordinary"] = r.turns_ordinary;
  j["secondary_nodes"] = cells(r.secondary);
  j["turns_secondary"] = r.turns_secondary;
  j["key_nodes"] = cells(r.key_nodes);
  j["turns_key"] = r.turns_key;
  j["key_length"] = r.key_length;
  j["key_clearance"] = clear(r.key_clearance);
  if (r.has_curve) {
    Json pts = Json::array();
    for (const auto& p : r.curve.points) pts.push_back(Json::array({p.x, p.y}));
    j["curve"] = Json{{"degree", r.degree_used},
                      {"end", std::string(bspline::to_string(o.end))},
                      {"spacing", o.spacing},
                      {"chord", r.curve.chord},
                      {"samples", r.curve.points.size()},
                      {"length", r.curve_length},
                      {"clearance", clear(r.clearance)},
                      {"points", pts}};
  }
  return j;
}

}  // namespace pathref::sensors2023

namespace pathref::planners {

Planner make_astar_kinematic_planner() {
  Planner p;
  p.name = "astar-kinematic";
  p.description =
      "kinematic-constraint A* (Sensors 2023 Eq. 1-8: 5 child directions, weighted Euclidean "
      "heuristic, secondary redundancy removal, cubic B-spline), spec/sensors2023.md";
  p.defaults = Json{{"directions", 5},       {"radius", 1},         {"fallback", "full"},
                    {"weight", "linear"},    {"redundancy", "secondary"},
                    {"secondary_input", "raw"}, {"k", 4},            {"ds", 1.0},
                    {"safety", "ge"},        {"degree", 3},         {"end", "repeated"},
                    {"spacing", 0.1},        {"inflation", 0.0}};
  p.bytes_per_cell = search::bytes_per_cell;
  p.run = [defaults = p.defaults](const Request& req) {
    if (req.grid == nullptr) throw UsageError("plan request without a grid");
    Json params = merge_params(defaults, req.params);
    const sensors2023::KinematicOptions o = sensors2023::options_from_json(params);
    search::require_memory(req, *req.grid, "astar-kinematic");
    const sensors2023::KinematicResult k =
        sensors2023::plan_kinematic(*req.grid, req.start, req.goal, req.policy, o);
    Result r;
    r.found = k.search.found;
    r.path = k.search.path;
    r.length = k.search.length;
    r.expansions = k.search.expansions;
    r.params_used = std::move(params);
    r.extra = sensors2023::result_to_json(k, o);
    return r;
  };
  return p;
}

}  // namespace pathref::planners
