#pragma once
/// \file bspline.hpp
/// The project's one B-spline module: a planar B-spline of any degree p >= 1 over any
/// non-decreasing knot vector, with the end handling (clamped knots / repeated end points / none)
/// as a parameter; Cox–de Boor basis and evaluation, the uniform (matrix) form for uniform knots
/// only, and sampling at a selectable spacing with a proven chord bound.
///
/// Used by: sensors2023 (Eq. 6–8, A1–A3: cubic B-spline of the key nodes after redundancy
/// removal, default end handling `repeated`) and cin2021 (S-RRT, clamped cubic B-spline,
/// Eq. 12–15: end handling `clamped`). One function serves every rule; spec/index/*.json says
/// which.
///
/// Conventions (spec/curves.md r[curves.knots]):
/// - m control points P_0..P_{m-1}, degree p, knots u_0..u_{m+p} (m + p + 1 values).
/// - The curve's domain is [u_p, u_m]; every evaluation outside it is a DomainError.
/// - N_{i,0}(u) = 1 on the half-open [u_i, u_{i+1}), except at the domain's right end u = u_m,
///   where the last non-empty span [u_k, u_{k+1}] with u_{k+1} = u_m is taken closed (so the
///   basis sums to 1 on the whole closed domain); 0/0 := 0 in the recursion.
/// - Uniform knots are u_j = j; clamped knots are p + 1 zeros, 1 .. m - p - 1, p + 1 times m - p.
///
/// Source: de Boor (1972), doi:10.1016/0021-9045(72)90080-9; Cox (1972),
/// doi:10.1093/imamat/10.2.134; Piegl & Tiller, The NURBS Book (1997) A2.1–A2.2;
/// Sensors 2023, 23(8), 4102, doi:10.3390/s23084102, Eq. (6)–(8), (A1)–(A3).
/// Spec: spec/curves.md (curves.knots, curves.sample, curves.curvature), spec/sensors2023.md
/// (sensors2023.eq6, eq7, eq8, a1, a2, a3), spec/cin2021-srrt.md (cin2021.eq12, cin2021.eq13,
/// cin2021.eq14, cin2021.eq15: the same functions)
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/geometry/vec2.hpp"

namespace pathref::bspline {

using geometry::Vec2;

/// How the ends of the curve are treated (spec curves.knots).
enum class EndHandling {
  clamped,   ///< open knot vector: p + 1 equal knots at each end; the curve starts at P_0 and
             ///< ends at P_{m-1} (cin2021 Eq. 15)
  repeated,  ///< uniform knots, each end point repeated so that it appears p times: the curve
             ///< starts and ends at the first and last given point (sensors2023 default)
  none,      ///< uniform knots, points as given: the curve starts near, not at, the end points
};
/// "clamped" | "repeated" | "none" -> handling; UsageError otherwise. Spec: curves.knots.
[[nodiscard]] EndHandling parse_end_handling(std::string_view name);
[[nodiscard]] std::string_view to_string(EndHandling e) noexcept;

/// Limits checked before allocating (DomainError): degree in [1, max_degree], at most
/// max_control_points control points, at most max_samples samples.
inline constexpr int max_degree = 20;
inline constexpr std::size_t max_control_points = std::size_t{1} << 20;
inline constexpr std::size_t max_samples = std::size_t{1} << 24;

/// A B-spline curve: degree p, knots (m + p + 1 values, non-decreasing) and m control points.
struct Curve {
  int degree = 3;
  std::vector<double> knots;
  std::vector<Vec2> control;
};

/// Uniform knot vector u_j = j, j = 0 .. m + p. Source: Sensors 2023 Eq. (8) (uniform cubic).
/// Spec: curves.knots. Pre: 1 <= p <= max_degree, p + 1 <= m <= max_control_points (DomainError).
/// Golden: golden/curves/curves.knots.json
[[nodiscard]] std::vector<double> uniform_knots(std::size_t control_count, int degree);

/// Clamped (open uniform) knot vector: u_0 = .. = u_p = 0, u_{p+j} = j for j = 1 .. m - p - 1,
/// u_m = .. = u_{m+p} = m - p. Source: cin2021 Eq. (15) (the paper's [0, 1] is the affine image
/// u / (m - p): the same curve); Piegl & Tiller (1997) Sec. 2.2.
/// Spec: curves.knots, cin2021.eq15. Pre: as uniform_knots.
/// Golden: golden/curves/curves.knots.json, golden/cin2021-srrt/cin2021.eq15.json
[[nodiscard]] std::vector<double> clamped_knots(std::size_t control_count, int degree);

/// How the interior knots of a clamped knot vector are spaced (spec cin2021.eq15, param
/// `knots`): uniform (clamped_knots, default) or by chord length (clamped_chord_knots).
enum class KnotSpacing { uniform, chord };
/// "uniform" | "chord" -> spacing; UsageError otherwise. Spec: cin2021.eq15.
[[nodiscard]] KnotSpacing parse_knot_spacing(std::string_view name);
[[nodiscard]] std::string_view to_string(KnotSpacing k) noexcept;

/// Clamped knot vector with chord-length interior knots over the control points P_0 .. P_{m-1}:
/// t_0 = 0, t_i = t_{i-1} + |P_i - P_{i-1}| (|v| = sqrt(vx*vx + vy*vy), i = 1 .. m - 1, left to
/// right), L = t_{m-1}; u_0 = .. = u_p = 0, u_m = .. = u_{m+p} = m - p and, for
/// j = 1 .. m - p - 1, with s_j = t_j + .. + t_{j+p-1} (left to right),
/// u_{p+j} = min(m - p, ((m - p) * s_j) / (p * L)) (the averaging technique of Piegl & Tiller
/// (1997) Eq. (9.8) on chord-length parameters, scaled to the domain of clamped_knots).
/// L = 0 (all points equal) gives clamped_knots. Non-decreasing (rounding is monotone).
/// Source: cin2021 Eq. (15) leaves the interior knots open; Piegl & Tiller (1997) Sec. 9.2.1.
/// Spec: cin2021.eq15. Pre: control finite, 1 <= p <= max_degree, p + 1 <= m <=
/// max_control_points (DomainError). Golden: golden/cin2021-srrt/cin2021.eq15.json
[[nodiscard]] std::vector<double> clamped_chord_knots(std::span<const Vec2> control, int degree);

/// The control polygon of an end handling: `repeated` prepends p - 1 copies of the first point
/// and appends p - 1 copies of the last (each end point then appears p times); `clamped` and
/// `none` return the points unchanged. Spec: curves.knots.
/// Pre: points non-empty, finite, 1 <= p <= max_degree (DomainError).
[[nodiscard]] std::vector<Vec2> control_polygon(std::span<const Vec2> points, int degree,
                                                EndHandling end);

/// The curve of `points` under an end handling: control_polygon + (clamped_knots if clamped,
/// else uniform_knots). Spec: curves.knots, sensors2023.eq6.
/// Pre: p + 1 <= (control polygon size) <= max_control_points, 1 <= p <= max_degree, finite
/// points (DomainError; lower the degree with degree_for for few points).
/// Golden: golden/curves/curves.knots.json
[[nodiscard]] Curve make_curve(std::span<const Vec2> points, int degree, EndHandling end);

/// make_curve with the interior knots of a clamped curve spaced by `spacing` (uniform:
/// clamped_knots; chord: clamped_chord_knots). Spec: cin2021.eq15.
/// Pre: as make_curve; KnotSpacing::chord only with EndHandling::clamped (DomainError).
/// Golden: golden/cin2021-srrt/cin2021.eq15.json
[[nodiscard]] Curve make_curve(std::span<const Vec2> points, int degree, EndHandling end,
                               KnotSpacing spacing);

/// The degree to use for `point_count` points when `requested` is asked for: the largest
/// p <= requested for which make_curve accepts the points (clamped / none: p <= m - 1;
/// repeated: any p when m >= 2, p >= 2 when m = 1). Lets a caller lower the degree for few
/// points (cin2021's S-RRT with 2 or 3 nodes). Spec: curves.knots.
/// Pre: 1 <= requested <= max_degree; some p works (m >= 2, or m = 1 with repeated and
/// requested >= 2) (DomainError).
[[nodiscard]] int degree_for(std::size_t point_count, int requested, EndHandling end);

/// The curve's parameter domain [u_p, u_m]. Spec: curves.knots.
/// Pre: the curve is valid (check_curve).
[[nodiscard]] std::array<double, 2> domain(const Curve& c);

/// Checks a curve: 1 <= p <= max_degree, m >= p + 1, knots.size() == m + p + 1, knots finite
/// and non-decreasing, u_p < u_m (non-empty domain), control points finite (DomainError naming
/// which). Spec: curves.knots.
void check_curve(const Curve& c);

/// The knot span k of u: the k in [p, m - 1] with u_k <= u < u_{k+1}, or, for u = u_m, the
/// largest k with u_k < u_{k+1} = u_m: N_{k,0}(u) = 1 and every other N_{i,0}(u) = 0.
/// Spec: sensors2023.eq7 (the closed right end), cin2021.eq13.
/// Pre: u in domain(c) (DomainError), c valid.
[[nodiscard]] std::size_t span_index(const std::vector<double>& knots, int degree,
                                     std::size_t control_count, double u);

/// Every basis function N_{i,p}(u), i = 0 .. m - 1, by the Cox–de Boor recursion (Eq. 7):
/// N_{i,0} from span_index, then for q = 1 .. p
/// N_{i,q} = ((u - u_i) / (u_{i+q} - u_i)) N_{i,q-1} + ((u_{i+q+1} - u) / (u_{i+q+1} - u_{i+1}))
/// N_{i+1,q-1}, each quotient with 0/0 := 0 (a zero denominator makes its term 0), the two terms
/// added left to right. Source: Sensors 2023 Eq. (7); cin2021 Eq. (13)-(14); Cox (1972);
/// de Boor (1972).
/// Spec: sensors2023.eq7, cin2021.eq14 (with cin2021.eq13 as N_{i,0}). Pre: knots valid for
/// (m, p) as in check_curve; u in [u_p, u_m] (DomainError). Post: values in [0, 1], at most
/// p + 1 non-zero, sum 1 up to rounding.
/// Golden: golden/sensors2023/sensors2023.eq7.json, golden/cin2021-srrt/cin2021.eq14.json
[[nodiscard]] std::vector<double> basis_functions(const std::vector<double>& knots, int degree,
                                                  std::size_t control_count, double u);

/// The curve point P(u) = sum_i P_i N_{i,p}(u) (Eq. 6), the sum taken over i = 0 .. m - 1 in
/// order, x and y separately, with the basis of basis_functions.
/// Source: Sensors 2023 Eq. (6); cin2021 Eq. (12). Spec: sensors2023.eq6, cin2021.eq12.
/// Pre: check_curve(c); u in domain(c) (DomainError). Post: in the convex hull of the p + 1
/// control points P_{k-p} .. P_k of u's span k. Golden: golden/sensors2023/sensors2023.eq6.json
[[nodiscard]] Vec2 evaluate(const Curve& c, double u);

/// The uniform B-spline basis of degree n (A2):
/// F_{j,n}(t) = (1 / n!) sum_{q=0}^{n-j} (-1)^q C(n+1, q) (t + n - j - q)^n, summed over q in
/// increasing order. Source: Sensors 2023 Eq. (A2). Spec: sensors2023.a2.
/// Pre: 1 <= n <= max_degree, 0 <= j <= n, t in [0, 1] (DomainError).
/// Golden: golden/sensors2023/sensors2023.a2.json
[[nodiscard]] double uniform_basis(int j, int n, double t);

/// The four uniform cubic basis polynomials (A3), each in the printed Horner-free form:
/// F0 = (1 - t)^3 / 6, F1 = (3t^3 - 6t^2 + 4) / 6, F2 = (-3t^3 + 3t^2 + 3t + 1) / 6, F3 = t^3 / 6.
/// Source: Sensors 2023 Eq. (A3). Spec: sensors2023.a3. Pre: t in [0, 1] (DomainError).
/// Golden: golden/sensors2023/sensors2023.a3.json
[[nodiscard]] std::array<double, 4> uniform_cubic_basis(double t);

/// One segment of the uniform B-spline of degree n = points.size() - 1 (A1):
/// P(t) = sum_{j=0}^{n} P_j F_{j,n}(t), in order of j, with F from uniform_basis.
/// Source: Sensors 2023 Eq. (A1). Spec: sensors2023.a1.
/// Pre: 2 <= points.size() <= max_degree + 1, finite, t in [0, 1] (DomainError).
/// Post: equals evaluate(Curve{n, uniform_knots, points}, n + t) up to rounding.
/// Golden: golden/sensors2023/sensors2023.a1.json
[[nodiscard]] Vec2 uniform_segment(std::span<const Vec2> points, double t);

/// One uniform cubic segment in matrix form (Eq. 8): P(t) = (1/6) [t^3 t^2 t 1] M [P0 P1 P2 P3]^T
/// with M = [[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 0, 3, 0], [1, 4, 1, 0]]: first the row vector
/// w = [t^3 t^2 t 1] M (each entry summed over the four rows in order), then sum_j w_j P_j in
/// order of j, then divided by 6. Holds for uniform knots only.
/// Source: Sensors 2023 Eq. (8). Spec: sensors2023.eq8. Pre: finite points, t in [0, 1]
/// (DomainError). Golden: golden/sensors2023/sensors2023.eq8.json
[[nodiscard]] Vec2 cubic_matrix_segment(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, double t);

/// Samples of a curve at a selectable spacing.
struct Samples {
  std::vector<Vec2> points;    ///< P(u) at the parameters below, start to end
  std::vector<double> params;  ///< increasing, first u_p, last u_m
  /// The proven bound of the method: every two consecutive samples are at most `chord` apart,
  /// and every curve point lies within chord / 2 of a sample (chord <= spacing).
  double chord = 0.0;
};

/// Samples a curve so that consecutive samples are at most `spacing` apart. On each non-empty
/// span [u_k, u_{k+1}] the speed bound D_k = max_{i=k-p+1..k} p |P_i - P_{i-1}| /
/// (u_{i+p} - u_i), |v| = sqrt(vx^2 + vy^2), (terms with a zero denominator are 0) holds for |P'(u)| (convex hull of the
/// derivative's control points); the span is cut into s_k = max(1, ceil(D_k (u_{k+1} - u_k) /
/// spacing)) equal parameter steps, u = u_k + j (u_{k+1} - u_k) / s_k, j = 0 .. s_k - 1; the
/// domain's end u_m closes the list. `chord` = max_k D_k (u_{k+1} - u_k) / s_k.
/// Source: pathref (sampling is not in either paper). Spec: curves.sample.
/// Pre: check_curve(c); spacing finite and > 0; the sample count <= max_samples (DomainError).
/// Post: params strictly increasing; |points[i+1] - points[i]| <= chord (1 + 1e-12) + 1e-12;
/// chord <= spacing. Golden: golden/curves/curves.sample.json
[[nodiscard]] Samples sample(const Curve& c, double spacing);

/// P(u), P'(u) and P''(u) of a curve, on the span of span_index (one-sided at knots: the
/// derivative from the right, at u_m from the left).
struct Derivatives {
  Vec2 point;
  Vec2 first;
  Vec2 second;
};

/// The curve point and its first two derivatives at u (spec curves.curvature), on span k:
/// P'(u) = sum_{j=k-p+1..k} Q_j N_{j,p-1}(u) with Q_j = (p (P_j - P_{j-1})) / (u_{j+p} - u_j);
/// P''(u) = sum_{j=k-p+2..k} ((p - 1) (Q_j - Q_{j-1})) / (u_{j+p-1} - u_j) N_{j,p-2}(u) (p >= 2;
/// 0 for p = 1); a term with a zero denominator is 0; the bases N_{.,p-1}, N_{.,p-2} are the
/// Cox–de Boor values on the same knot vector (degree 0 = the indicator of span k); sums in
/// increasing j, x and y separately. Source: de Boor (1972); Piegl & Tiller (1997) Eq. (3.3)-(3.4).
/// Spec: curves.curvature. Pre: check_curve(c); u in domain(c) (DomainError).
/// Golden: golden/curves/curves.curvature.json
[[nodiscard]] Derivatives derivatives(const Curve& c, double u);

/// Signed curvature kappa(u) = cross / (s2 * sqrt(s2)) with cross = (x' y'') - (y' x''),
/// s2 = (x' x') + (y' y') from derivatives(); +inf where P'(u) = 0 (no tangent: the curve may
/// have a cusp there, so a maximum over samples flags it). Positive = turning left.
/// Source: pathref (cin2021 issue: "curvature of the smoothed curve"; neither paper defines it).
/// Spec: curves.curvature. Pre: as derivatives. Golden: golden/curves/curves.curvature.json
[[nodiscard]] double curvature(const Curve& c, double u);

}  // namespace pathref::bspline
