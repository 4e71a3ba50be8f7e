#include "pathref/equations/bspline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::bspline {

namespace {

bool finite(Vec2 p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

void check_degree(int degree) {
  require(degree >= 1 && degree <= max_degree,
          "bspline: degree must be in [1, " + std::to_string(max_degree) + "]");
}

void check_count(std::size_t m, int degree) {
  check_degree(degree);
  require(m <= max_control_points, "bspline: more than max_control_points control points");
  require(m >= static_cast<std::size_t>(degree) + 1,
          "bspline: a curve of degree p needs at least p + 1 control points");
}

void check_knots(const std::vector<double>& knots, int degree, std::size_t m) {
  check_count(m, degree);
  const auto p = static_cast<std::size_t>(degree);
  require(knots.size() == m + p + 1, "bspline: the knot vector must hold m + p + 1 values");
  for (std::size_t j = 0; j < knots.size(); ++j) {
    require(std::isfinite(knots[j]), "bspline: knots must be finite");
    if (j > 0) require(knots[j - 1] <= knots[j], "bspline: knots must be non-decreasing");
  }
  require(knots[p] < knots[m], "bspline: the domain [u_p, u_m] must not be empty");
}

void check_t(double t) {
  require(t >= 0.0 && t <= 1.0, "bspline: the segment parameter t must be in [0, 1]");
}

/// N_{k-p..k, p}(u) on span k (local Cox–de Boor table, same formula and order as the full
/// recursion: the entries outside [k - q, k] are exactly 0 and contribute exact zeros).
std::vector<double> local_basis(const std::vector<double>& U, std::size_t p, std::size_t k,
                                double u) {
  // n[r] holds N_{k-q+r, q} for r = 0..q during step q.
  std::vector<double> n(p + 1, 0.0);
  n[0] = 1.0;  // N_{k,0}
  for (std::size_t q = 1; q <= p; ++q) {
    std::vector<double> next(p + 1, 0.0);
    for (std::size_t r = 0; r <= q; ++r) {
      const std::size_t i = k - q + r;
      // N_{i,q-1} is n[r-1] (index i - (k - (q-1)) = r - 1) when 1 <= r, and N_{i+1,q-1} is
      // n[r] when r <= q - 1.
      const double left_n = (r >= 1) ? n[r - 1] : 0.0;
      const double right_n = (r <= q - 1) ? n[r] : 0.0;
      const double dl = U[i + q] - U[i];
      const double dr = U[i + q + 1] - U[i + 1];
      const double a = (dl == 0.0) ? 0.0 : ((u - U[i]) / dl) * left_n;
      const double b = (dr == 0.0) ? 0.0 : ((U[i + q + 1] - u) / dr) * right_n;
      next[r] = a + b;
    }
    n = std::move(next);
  }
  return n;
}

double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * static_cast<double>(n - k + i) / static_cast<double>(i);
  return r;
}

double factorial(int n) {
  double r = 1.0;
  for (int i = 2; i <= n; ++i) r *= static_cast<double>(i);
  return r;
}

}  // namespace

EndHandling parse_end_handling(std::string_view name) {
  if (name == "clamped") return EndHandling::clamped;
  if (name == "repeated") return EndHandling::repeated;
  if (name == "none") return EndHandling::none;
  throw UsageError("end handling must be clamped, repeated or none, not '" + std::string(name) +
                   "'");
}

std::string_view to_string(EndHandling e) noexcept {
  switch (e) {
    case EndHandling::clamped: return "clamped";
    case EndHandling::repeated: return "repeated";
    case EndHandling::none: return "none";
  }
  return "none";
}

std::vector<double> uniform_knots(std::size_t control_count, int degree) {
  check_count(control_count, degree);
  const std::size_t n = control_count + static_cast<std::size_t>(degree) + 1;
  std::vector<double> u(n);
  for (std::size_t j = 0; j < n; ++j) u[j] = static_cast<double>(j);
  return u;
}

std::vector<double> clamped_knots(std::size_t control_count, int degree) {
  check_count(control_count, degree);
  const auto p = static_cast<std::size_t>(degree);
  const std::size_t m = control_count;
  std::vector<double> u(m + p + 1);
  for (std::size_t j = 0; j < u.size(); ++j) {
    if (j <= p) {
      u[j] = 0.0;
    } else if (j >= m) {
      u[j] = static_cast<double>(m - p);
    } else {
      u[j] = static_cast<double>(j - p);
    }
  }
  return u;
}

std::vector<Vec2> control_polygon(std::span<const Vec2> points, int degree, EndHandling end) {
  check_degree(degree);
  require(!points.empty(), "bspline: no points");
  require(points.size() <= max_control_points, "bspline: more than max_control_points points");
  for (const Vec2& p : points) require(finite(p), "bspline: points must be finite");
  std::vector<Vec2> out;
  if (end != EndHandling::repeated) {
    out.assign(points.begin(), points.end());
    return out;
  }
  const auto extra = static_cast<std::size_t>(degree - 1);
  require(points.size() + 2 * extra <= max_control_points,
          "bspline: more than max_control_points control points after repeating the ends");
  out.reserve(points.size() + 2 * extra);
  out.insert(out.end(), extra, points.front());
  out.insert(out.end(), points.begin(), points.end());
  out.insert(out.end(), extra, points.back());
  return out;
}

KnotSpacing parse_knot_spacing(std::string_view name) {
  if (name == "uniform") return KnotSpacing::uniform;
  if (name == "chord") return KnotSpacing::chord;
  throw UsageError("knots must be uniform or chord, not '" + std::string(name) + "'");
}

std::string_view to_string(KnotSpacing k) noexcept {
  return k == KnotSpacing::chord ? "chord" : "uniform";
}

std::vector<double> clamped_chord_knots(std::span<const Vec2> control, int degree) {
  const std::size_t m = control.size();
  check_count(m, degree);
  for (const Vec2& q : control) require(finite(q), "bspline: control points must be finite");
  const auto p = static_cast<std::size_t>(degree);
  std::vector<double> t(m, 0.0);
  for (std::size_t i = 1; i < m; ++i) {
    const double dx = control[i].x - control[i - 1].x;
    const double dy = control[i].y - control[i - 1].y;
    t[i] = t[i - 1] + std::sqrt((dx * dx) + (dy * dy));
  }
  const double L = t[m - 1];
  std::vector<double> u = clamped_knots(m, degree);
  if (!(L > 0.0)) return u;
  const auto top = static_cast<double>(m - p);
  const double den = static_cast<double>(p) * L;
  for (std::size_t j = 1; j + p < m; ++j) {
    double s = 0.0;
    for (std::size_t i = j; i < j + p; ++i) s = s + t[i];
    u[p + j] = std::min(top, (top * s) / den);
  }
  return u;
}

Curve make_curve(std::span<const Vec2> points, int degree, EndHandling end, KnotSpacing spacing) {
  if (spacing == KnotSpacing::uniform) return make_curve(points, degree, end);
  require(end == EndHandling::clamped, "bspline: chord-length knots need end handling clamped");
  Curve c;
  c.degree = degree;
  c.control = control_polygon(points, degree, end);
  c.knots = clamped_chord_knots(c.control, degree);
  return c;
}

Curve make_curve(std::span<const Vec2> points, int degree, EndHandling end) {
  Curve c;
  c.degree = degree;
  c.control = control_polygon(points, degree, end);
  c.knots = (end == EndHandling::clamped) ? clamped_knots(c.control.size(), degree)
                                          : uniform_knots(c.control.size(), degree);
  return c;
}

int degree_for(std::size_t point_count, int requested, EndHandling end) {
  check_degree(requested);
  require(point_count >= 1, "bspline: no points");
  for (int p = requested; p >= 1; --p) {
    const std::size_t m = (end == EndHandling::repeated)
                              ? point_count + 2 * static_cast<std::size_t>(p - 1)
                              : point_count;
    if (m >= static_cast<std::size_t>(p) + 1) return p;
  }
  throw DomainError("bspline: no degree <= the requested one can be built from these points");
}

void check_curve(const Curve& c) {
  check_knots(c.knots, c.degree, c.control.size());
  for (const Vec2& p : c.control) require(finite(p), "bspline: control points must be finite");
}

std::array<double, 2> domain(const Curve& c) {
  check_curve(c);
  return {c.knots[static_cast<std::size_t>(c.degree)], c.knots[c.control.size()]};
}

std::size_t span_index(const std::vector<double>& knots, int degree, std::size_t control_count,
                       double u) {
  check_knots(knots, degree, control_count);
  const auto p = static_cast<std::size_t>(degree);
  const std::size_t m = control_count;
  require(u >= knots[p] && u <= knots[m], "bspline: u outside the domain [u_p, u_m]");
  if (u == knots[m]) {
    std::size_t k = m - 1;
    while (!(knots[k] < knots[k + 1])) --k;  // terminates: knots[p] < knots[m]
    return k;
  }
  // the k in [p, m-1] with u_k <= u < u_{k+1}: last knot among u_p..u_{m-1} that is <= u
  const auto first = knots.begin() + static_cast<std::ptrdiff_t>(p);
  const auto last = knots.begin() + static_cast<std::ptrdiff_t>(m);
  const auto it = std::upper_bound(first, last, u);  // first knot > u in [u_p, u_m)
  return static_cast<std::size_t>(it - knots.begin()) - 1;
}

std::vector<double> basis_functions(const std::vector<double>& knots, int degree,
                                    std::size_t control_count, double u) {
  const std::size_t k = span_index(knots, degree, control_count, u);
  const auto p = static_cast<std::size_t>(degree);
  const std::vector<double> local = local_basis(knots, p, k, u);
  std::vector<double> all(control_count, 0.0);
  for (std::size_t r = 0; r <= p; ++r) all[k - p + r] = local[r];
  return all;
}

namespace {
/// Eq. 6 on span k of an already checked curve.
Vec2 evaluate_on_span(const Curve& c, std::size_t k, double u) {
  const auto p = static_cast<std::size_t>(c.degree);
  const std::vector<double> n = local_basis(c.knots, p, k, u);
  // The sum over every i in order: the terms before k - p and after k are exact zeros.
  Vec2 out{0.0, 0.0};
  for (std::size_t r = 0; r <= p; ++r) {
    const Vec2& q = c.control[k - p + r];
    out.x = out.x + n[r] * q.x;
    out.y = out.y + n[r] * q.y;
  }
  return out;
}
}  // namespace

Vec2 evaluate(const Curve& c, double u) {
  check_curve(c);
  return evaluate_on_span(c, span_index(c.knots, c.degree, c.control.size(), u), u);
}

double uniform_basis(int j, int n, double t) {
  check_degree(n);
  require(j >= 0 && j <= n, "bspline: uniform_basis needs 0 <= j <= n");
  check_t(t);
  double sum = 0.0;
  for (int q = 0; q <= n - j; ++q) {
    const double sign = (q % 2 == 0) ? 1.0 : -1.0;
    const double base = t + static_cast<double>(n - j - q);
    double power = 1.0;
    for (int e = 0; e < n; ++e) power *= base;
    sum = sum + sign * binomial(n + 1, q) * power;
  }
  return sum / factorial(n);
}

std::array<double, 4> uniform_cubic_basis(double t) {
  check_t(t);
  const double s = 1.0 - t;
  const double t2 = t * t;
  const double t3 = t2 * t;
  return {s * s * s / 6.0, (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0,
          (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0, t3 / 6.0};
}

Vec2 uniform_segment(std::span<const Vec2> points, double t) {
  require(points.size() >= 2 && points.size() <= static_cast<std::size_t>(max_degree) + 1,
          "bspline: a uniform segment of degree n takes n + 1 points, 1 <= n <= max_degree");
  for (const Vec2& p : points) require(finite(p), "bspline: points must be finite");
  check_t(t);
  const int n = static_cast<int>(points.size()) - 1;
  Vec2 out{0.0, 0.0};
  for (int j = 0; j <= n; ++j) {
    const double f = uniform_basis(j, n, t);
    out.x = out.x + f * points[static_cast<std::size_t>(j)].x;
    out.y = out.y + f * points[static_cast<std::size_t>(j)].y;
  }
  return out;
}

Vec2 cubic_matrix_segment(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, double t) {
  for (const Vec2& p : {p0, p1, p2, p3}) require(finite(p), "bspline: points must be finite");
  check_t(t);
  static constexpr double M[4][4] = {
      {-1.0, 3.0, -3.0, 1.0}, {3.0, -6.0, 3.0, 0.0}, {-3.0, 0.0, 3.0, 0.0}, {1.0, 4.0, 1.0, 0.0}};
  const double row[4] = {t * t * t, t * t, t, 1.0};
  double w[4];
  for (int j = 0; j < 4; ++j) {
    double s = 0.0;
    for (int r = 0; r < 4; ++r) s = s + row[r] * M[r][j];
    w[j] = s;
  }
  const Vec2 P[4] = {p0, p1, p2, p3};
  Vec2 out{0.0, 0.0};
  for (int j = 0; j < 4; ++j) {
    out.x = out.x + w[j] * P[j].x;
    out.y = out.y + w[j] * P[j].y;
  }
  return Vec2{out.x / 6.0, out.y / 6.0};
}

Samples sample(const Curve& c, double spacing) {
  check_curve(c);
  require(std::isfinite(spacing) && spacing > 0.0, "bspline: spacing must be finite and > 0");
  const auto p = static_cast<std::size_t>(c.degree);
  const std::size_t m = c.control.size();
  const std::vector<double>& U = c.knots;
  Samples s;
  // First pass: the step counts, checked against max_samples before allocating.
  std::vector<std::size_t> steps(m, 0);
  std::vector<double> bound(m, 0.0);
  std::size_t total = 1;
  for (std::size_t k = p; k < m; ++k) {
    const double width = U[k + 1] - U[k];
    if (!(width > 0.0)) continue;
    double d = 0.0;
    for (std::size_t i = k - p + 1; i <= k; ++i) {
      const double den = U[i + p] - U[i];
      if (den == 0.0) continue;
      const double dx = c.control[i].x - c.control[i - 1].x;
      const double dy = c.control[i].y - c.control[i - 1].y;
      d = std::max(d, static_cast<double>(p) * std::sqrt((dx * dx) + (dy * dy)) / den);
    }
    const double want = std::ceil(d * width / spacing);
    require(std::isfinite(want) && want < static_cast<double>(max_samples),
            "bspline: more than max_samples samples");
    steps[k] = std::max<std::size_t>(1, static_cast<std::size_t>(want));
    bound[k] = d * width / static_cast<double>(steps[k]);
    total += steps[k];
    require(total <= max_samples, "bspline: more than max_samples samples");
  }
  s.points.reserve(total);
  s.params.reserve(total);
  for (std::size_t k = p; k < m; ++k) {
    if (steps[k] == 0) continue;
    const double width = U[k + 1] - U[k];
    for (std::size_t j = 0; j < steps[k]; ++j) {
      const double u = U[k] + static_cast<double>(j) * width / static_cast<double>(steps[k]);
      s.params.push_back(u);
      s.points.push_back(evaluate_on_span(c, k, u));
    }
    s.chord = std::max(s.chord, bound[k]);
  }
  s.params.push_back(U[m]);
  s.points.push_back(evaluate(c, U[m]));  // the closed right end (span_index)
  return s;
}

Derivatives derivatives(const Curve& c, double u) {
  check_curve(c);
  const std::size_t k = span_index(c.knots, c.degree, c.control.size(), u);
  const auto p = static_cast<std::size_t>(c.degree);
  const std::vector<double>& U = c.knots;
  Derivatives d;
  d.point = evaluate_on_span(c, k, u);
  // Q_j for j = k - p + 1 .. k (index j - (k - p + 1)); zero denominators give 0.
  std::vector<Vec2> q(p, Vec2{0.0, 0.0});
  for (std::size_t r = 0; r < p; ++r) {
    const std::size_t j = k - p + 1 + r;
    const double den = U[j + p] - U[j];
    if (den == 0.0) continue;
    q[r] = Vec2{(static_cast<double>(p) * (c.control[j].x - c.control[j - 1].x)) / den,
                (static_cast<double>(p) * (c.control[j].y - c.control[j - 1].y)) / den};
  }
  const std::vector<double> n1 = local_basis(U, p - 1, k, u);  // N_{k-p+1..k, p-1}
  for (std::size_t r = 0; r < p; ++r) {
    d.first.x = d.first.x + n1[r] * q[r].x;
    d.first.y = d.first.y + n1[r] * q[r].y;
  }
  if (p >= 2) {
    const std::vector<double> n2 = local_basis(U, p - 2, k, u);  // N_{k-p+2..k, p-2}
    for (std::size_t r = 0; r + 1 < p; ++r) {
      const std::size_t j = k - p + 2 + r;
      const double den = U[j + p - 1] - U[j];
      if (den == 0.0) continue;
      const double rx = (static_cast<double>(p - 1) * (q[r + 1].x - q[r].x)) / den;
      const double ry = (static_cast<double>(p - 1) * (q[r + 1].y - q[r].y)) / den;
      d.second.x = d.second.x + n2[r] * rx;
      d.second.y = d.second.y + n2[r] * ry;
    }
  }
  return d;
}

double curvature(const Curve& c, double u) {
  const Derivatives d = derivatives(c, u);
  const double s2 = (d.first.x * d.first.x) + (d.first.y * d.first.y);
  if (s2 == 0.0) return std::numeric_limits<double>::infinity();
  const double cross = (d.first.x * d.second.y) - (d.first.y * d.second.x);
  return cross / (s2 * std::sqrt(s2));
}

}  // namespace pathref::bspline
