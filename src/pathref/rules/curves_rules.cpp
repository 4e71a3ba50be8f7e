// JSON adapters for the curves.* rules (spec/curves.md) and the B-spline rules of sensors2023
// (spec/sensors2023.md eq6, eq7, eq8, a1, a2, a3). Points are [x, y] arrays of numbers.
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/bspline.hpp"
#include "pathref/geometry/clearance.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/curves_rules.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

geometry::Vec2 point_from_json(const Json& v, const char* what) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
    throw UsageError(std::string("'") + what + "' must hold points [x, y] of two numbers");
  return geometry::Vec2{v[0].get<double>(), v[1].get<double>()};
}

std::vector<geometry::Vec2> points_arg(const Json& in, const char* key) {
  const Json& a = arg(in, key);
  if (!a.is_array()) throw UsageError(std::string("input '") + key + "' must be an array of [x, y]");
  std::vector<geometry::Vec2> out;
  out.reserve(a.size());
  for (const Json& p : a) out.push_back(point_from_json(p, key));
  return out;
}

Json point_json(geometry::Vec2 p) { return Json::array({number(p.x), number(p.y)}); }

Json points_json(std::span<const geometry::Vec2> pts) {
  Json a = Json::array();
  for (const auto& p : pts) a.push_back(point_json(p));
  return a;
}

namespace {

int degree_arg(const Json& in) {
  const long long p = arg_integer(in, "degree");
  if (p < -1000 || p > 1000) throw DomainError("bspline: degree out of range");
  return static_cast<int>(p);
}

/// A curve from {degree, knots, control} (explicit) or {degree, points, end} (built).
bspline::Curve curve_arg(const Json& in) {
  bspline::Curve c;
  c.degree = degree_arg(in);
  if (in.contains("knots")) {
    c.knots = arg_numbers(in, "knots");
    c.control = points_arg(in, "control");
    return c;
  }
  const auto pts = points_arg(in, "points");
  return bspline::make_curve(pts, c.degree,
                             bspline::parse_end_handling(opt_string(in, "end", "repeated")));
}

std::size_t count_arg(const Json& in, const char* key) {
  const long long n = arg_integer(in, key);
  if (n < 0) throw DomainError(std::string(key) + " must be >= 0");
  return static_cast<std::size_t>(n);
}

}  // namespace

void register_curves_rules(Registry& r) {
  r.add(Rule{
      "curves.knots",
      "Knot vectors (uniform, clamped) and the control polygon of an end handling",
      "pathref::bspline::make_curve",
      {{"points", "point[]", "the given points [[x, y], ...]"},
       {"degree", "integer", "p >= 1"},
       {"end", "string", "clamped | repeated (default) | none"}},
      {{"knots", "number[]", "u_0 .. u_{m+p}"},
       {"control", "point[]", "the control polygon"},
       {"domain", "number[]", "[u_p, u_m]"},
       {"degree_for", "integer", "the largest degree <= p that the end handling accepts"}},
      [](const Json& in) {
        const auto pts = points_arg(in, "points");
        const int p = degree_arg(in);
        const auto end = bspline::parse_end_handling(opt_string(in, "end", "repeated"));
        const bspline::Curve c = bspline::make_curve(pts, p, end);
        Json knots = Json::array();
        for (double u : c.knots) knots.push_back(number(u));
        const auto d = bspline::domain(c);
        return Json{{"knots", knots},
                    {"control", points_json(c.control)},
                    {"domain", Json::array({number(d[0]), number(d[1])})},
                    {"degree_for", bspline::degree_for(pts.size(), p, end)}};
      }});
  r.add(Rule{
      "curves.sample",
      "Samples of a B-spline with consecutive samples at most `spacing` apart",
      "pathref::bspline::sample",
      {{"degree", "integer", "p"},
       {"points", "point[]", "given points (with end), or knots + control"},
       {"end", "string", "clamped | repeated (default) | none"},
       {"knots", "number[]", "optional explicit knot vector (then control is required)"},
       {"control", "point[]", "explicit control points"},
       {"spacing", "number", "delta > 0"}},
      {{"params", "number[]", "the sample parameters"},
       {"points", "point[]", "P(u) at them"},
       {"chord", "number", "the proven chord bound <= spacing"}},
      [](const Json& in) {
        const auto s = bspline::sample(curve_arg(in), arg_number(in, "spacing"));
        Json params = Json::array();
        for (double u : s.params) params.push_back(number(u));
        return Json{{"params", params}, {"points", points_json(s.points)}, {"chord", number(s.chord)}};
      }});
  r.add(Rule{
      "curves.clearance",
      "Exact distance of a polyline (or sampled curve) to the blocked cells (unit squares) and border",
      "pathref::geometry::clearance",
      {{"grid", "grid", "rows top first"},
       {"points", "point[]", "the polyline [[x, y], ...]"},
       {"inflation", "number", "r >= 0 (default 0)"},
       {"tolerance", "number", "tau >= 0: vertices are curve samples within tau (default 0)"},
       {"border", "bool", "the outside of the map is an obstacle (default true)"}},
      {{"distance", "number", "exact distance of the polyline ('inf' if no obstacle)"},
       {"lower", "number", "lower bound of the path's clearance"},
       {"upper", "number", "upper bound of the path's clearance"},
       {"verdict", "string", "clear | enters | undetermined"},
       {"segment", "integer", "first segment attaining the distance (-1 if inf)"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        geometry::ClearanceOptions o;
        if (in.contains("inflation")) o.inflation = arg_number(in, "inflation");
        if (in.contains("tolerance")) o.tolerance = arg_number(in, "tolerance");
        if (in.contains("border")) {
          if (!in.at("border").is_boolean()) throw UsageError("input 'border' must be a bool");
          o.border = in.at("border").get<bool>();
        }
        const auto c = geometry::clearance(g, points_arg(in, "points"), o);
        return Json{{"distance", number(c.distance)},
                    {"lower", number(c.lower)},
                    {"upper", number(c.upper)},
                    {"verdict", std::string(geometry::to_string(c.verdict))},
                    {"segment", c.segment}};
      }});

  r.add(Rule{
      "curves.curvature",
      "P(u), P'(u), P''(u) and the signed curvature of a B-spline (+inf where P'(u) = 0)",
      "pathref::bspline::curvature",
      {{"degree", "integer", "p"},
       {"points", "point[]", "given points (with end), or knots + control"},
       {"end", "string", "clamped | repeated (default) | none"},
       {"knots", "number[]", "optional explicit knot vector (then control is required)"},
       {"control", "point[]", "explicit control points"},
       {"u", "number", "in [u_p, u_m]"}},
      {{"point", "point", "P(u)"},
       {"first", "point", "P'(u) (one-sided at knots, on span_index's span)"},
       {"second", "point", "P''(u)"},
       {"curvature", "number", "(x'y'' - y'x'') / |P'|^3; 'inf' where P'(u) = 0"}},
      [](const Json& in) {
        const bspline::Curve c = curve_arg(in);
        const double u = arg_number(in, "u");
        const auto d = bspline::derivatives(c, u);
        return Json{{"point", point_json(d.point)},
                    {"first", point_json(d.first)},
                    {"second", point_json(d.second)},
                    {"curvature", number(bspline::curvature(c, u))}};
      }});

  // One adapter for bspline::basis_functions, which serves cin2021.eq14 and sensors2023.eq7.
  const std::vector<Field> basis_inputs = {{"knots", "number[]", "u_0 .. u_{m+p}"},
                                           {"degree", "integer", "p"},
                                           {"count", "integer", "m, the number of control points"},
                                           {"u", "number", "in [u_p, u_m]"}};
  const std::vector<Field> basis_outputs = {{"n", "number[]", "N_{0,p}(u) .. N_{m-1,p}(u)"},
                                            {"span", "integer", "the knot span k"}};
  const auto basis_eval = [](const Json& in) {
    const auto knots = arg_numbers(in, "knots");
    const int p = degree_arg(in);
    const std::size_t m = count_arg(in, "count");
    const double u = arg_number(in, "u");
    const auto n = bspline::basis_functions(knots, p, m, u);
    Json a = Json::array();
    for (double v : n) a.push_back(number(v));
    return Json{{"n", a}, {"span", bspline::span_index(knots, p, m, u)}};
  };

  // ---- cin2021 S-RRT Eq. 12-15: the same B-spline functions, clamped knots ----
  const auto clamped_curve = [](const Json& in) {
    const auto pts = points_arg(in, "points");
    const int p = bspline::degree_for(pts.size(), degree_arg(in), bspline::EndHandling::clamped);
    const auto spacing = bspline::parse_knot_spacing(opt_string(in, "knots", "uniform"));
    return bspline::make_curve(pts, p, bspline::EndHandling::clamped, spacing);
  };
  const std::vector<Field> clamped_inputs = {
      {"points", "point[]", "the control points d_0 .. d_n (S-RRT's kept nodes)"},
      {"degree", "integer", "requested degree k (lowered by degree_for for few points)"},
      {"knots", "string", "interior knots: uniform (default) | chord"}};
  r.add(Rule{
      "cin2021.eq12",
      "Clamped B-spline point P(u) = sum_i d_i N_{i,k}(u) over S-RRT's nodes (cin2021 Eq. 12)",
      "pathref::bspline::evaluate",
      [&] {
        auto f = clamped_inputs;
        f.push_back({"u", "number", "in [u_k, u_{n+1}] = [0, n + 1 - k]"});
        return f;
      }(),
      {{"point", "point", "P(u)"}, {"degree", "integer", "the degree used"}},
      [clamped_curve](const Json& in) {
        const bspline::Curve c = clamped_curve(in);
        return Json{{"point", point_json(bspline::evaluate(c, arg_number(in, "u")))},
                    {"degree", c.degree}};
      }});
  r.add(Rule{
      "cin2021.eq13",
      "Degree-0 basis N_{i,0}(u) = 1 on [u_i, u_{i+1}) (closed at the domain's right end) (cin2021 Eq. 13)",
      "pathref::bspline::span_index",
      {{"knots", "number[]", "u_0 .. u_{m+p}"},
       {"degree", "integer", "p (fixes the domain [u_p, u_m])"},
       {"count", "integer", "m"},
       {"u", "number", "in [u_p, u_m]"}},
      {{"n0", "number[]", "N_{0,0}(u) .. N_{m+p-1,0}(u)"}, {"span", "integer", "the i with N_{i,0}(u) = 1"}},
      [](const Json& in) {
        const auto knots = arg_numbers(in, "knots");
        const std::size_t k =
            bspline::span_index(knots, degree_arg(in), count_arg(in, "count"), arg_number(in, "u"));
        Json a = Json::array();
        for (std::size_t i = 0; i + 1 < knots.size(); ++i) a.push_back(i == k ? 1 : 0);
        return Json{{"n0", a}, {"span", k}};
      }});
  r.add(Rule{
      "cin2021.eq14",
      "Cox-de Boor recursion N_{i,k}(u) with 0/0 := 0 on clamped knots (cin2021 Eq. 14)",
      "pathref::bspline::basis_functions",
      basis_inputs, basis_outputs, basis_eval});
  r.add(Rule{
      "cin2021.eq15",
      "Clamped knot vector (end knots repeated k + 1 times; interior uniform or chord-length) (cin2021 Eq. 15)",
      "pathref::bspline::make_curve",
      clamped_inputs,
      {{"degree", "integer", "the degree used (degree_for)"},
       {"knots", "number[]", "u_0 .. u_{m+k}"},
       {"domain", "number[]", "[u_k, u_m]"}},
      [clamped_curve](const Json& in) {
        const bspline::Curve c = clamped_curve(in);
        Json knots = Json::array();
        for (double u : c.knots) knots.push_back(number(u));
        const auto d = bspline::domain(c);
        return Json{{"degree", c.degree}, {"knots", knots}, {"domain", Json::array({number(d[0]), number(d[1])})}};
      }});

  // ---- sensors2023 B-spline rules (the same functions serve cin2021's S-RRT) ----
  r.add(Rule{
      "sensors2023.eq6",
      "B-spline curve point P(u) = sum_i P_i N_{i,p}(u) (Sensors 2023 Eq. 6)",
      "pathref::bspline::evaluate",
      {{"degree", "integer", "p"},
       {"knots", "number[]", "u_0 .. u_{m+p} (or points + end)"},
       {"control", "point[]", "P_0 .. P_{m-1}"},
       {"points", "point[]", "alternative: given points, built with end"},
       {"end", "string", "clamped | repeated (default) | none"},
       {"u", "number", "in [u_p, u_m]"}},
      {{"point", "point", "P(u)"}},
      [](const Json& in) {
        return Json{{"point", point_json(bspline::evaluate(curve_arg(in), arg_number(in, "u")))}};
      }});
  r.add(Rule{
      "sensors2023.eq7",
      "Cox-de Boor basis functions N_{i,p}(u), i = 0..m-1 (Sensors 2023 Eq. 7)",
      "pathref::bspline::basis_functions",
      basis_inputs, basis_outputs, basis_eval});
  r.add(Rule{
      "sensors2023.eq8",
      "Uniform cubic B-spline segment in matrix form (Sensors 2023 Eq. 8)",
      "pathref::bspline::cubic_matrix_segment",
      {{"control", "point[]", "P0, P1, P2, P3"}, {"t", "number", "in [0, 1]"}},
      {{"point", "point", "P(t)"}},
      [](const Json& in) {
        const auto c = points_arg(in, "control");
        if (c.size() != 4) throw UsageError("input 'control' must hold 4 points");
        return Json{{"point", point_json(bspline::cubic_matrix_segment(c[0], c[1], c[2], c[3],
                                                                        arg_number(in, "t")))}};
      }});
  r.add(Rule{
      "sensors2023.a1",
      "Uniform B-spline segment of degree n = points - 1 (Sensors 2023 Eq. A1)",
      "pathref::bspline::uniform_segment",
      {{"control", "point[]", "P_i .. P_{i+n}"}, {"t", "number", "in [0, 1]"}},
      {{"point", "point", "P_{i,n}(t)"}},
      [](const Json& in) {
        return Json{{"point", point_json(bspline::uniform_segment(points_arg(in, "control"),
                                                                  arg_number(in, "t")))}};
      }});
  r.add(Rule{
      "sensors2023.a2",
      "Uniform B-spline basis F_{j,n}(t) (Sensors 2023 Eq. A2)",
      "pathref::bspline::uniform_basis",
      {{"j", "integer", "0..n"}, {"n", "integer", "degree 1..20"}, {"t", "number", "in [0, 1]"}},
      {{"f", "number", "F_{j,n}(t)"}},
      [](const Json& in) {
        const long long j = arg_integer(in, "j");
        const long long n = arg_integer(in, "n");
        if (j < -1000 || j > 1000 || n < -1000 || n > 1000)
          throw DomainError("bspline: uniform_basis needs 0 <= j <= n <= max_degree");
        return Json{{"f", number(bspline::uniform_basis(static_cast<int>(j), static_cast<int>(n),
                                                        arg_number(in, "t")))}};
      }});
  r.add(Rule{
      "sensors2023.a3",
      "Uniform cubic basis polynomials F_{0..3,3}(t) (Sensors 2023 Eq. A3)",
      "pathref::bspline::uniform_cubic_basis",
      {{"t", "number", "in [0, 1]"}},
      {{"f", "number[]", "[F0, F1, F2, F3]"}},
      [](const Json& in) {
        const auto f = bspline::uniform_cubic_basis(arg_number(in, "t"));
        return Json{{"f", Json::array({number(f[0]), number(f[1]), number(f[2]), number(f[3])})}};
      }});
}

}  // namespace pathref::rules
