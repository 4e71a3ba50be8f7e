#pragma once
/// \file rls.hpp
/// Linear motion of a dynamic obstacle and its recursive least-squares (RLS) estimate with a
/// forgetting factor, Han (IJACSA) Eq. (9)-(15). The model is x = a t + b, y = c t + d; each
/// coordinate is a scalar regression on phi(t) = [t, 1]^T with parameters A = [a, b]^T and
/// B = [c, d]^T, sharing the regressor and hence the covariance P and the gain K.
/// Every operation is written out on scalars in a fixed order (spec han.eq15), so the results
/// are bit-reproducible; Eigen types are the containers.
/// Spec: spec/han.md (han.eq9, han.eq10, han.eq11, han.eq12, han.eq13, han.eq14, han.eq15)
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace pathref::rls {

/// The parameters of Eq. (9): x = a t + b, y = c t + d.
struct LinearMotion {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  double d = 0.0;
};

/// A position (x, y) in the map's length unit.
struct Position {
  double x = 0.0;
  double y = 0.0;
};

/// Eq. (9): the obstacle's position at time t, x = (a * t) + b, y = (c * t) + d.
/// Source: Han (IJACSA), Eq. (9), Sec. III.B.
/// Spec: han.eq9
/// Pre: a, b, c, d, t finite; the result finite (DomainError).
/// Golden: golden/han/han.eq9.json
[[nodiscard]] Position position(const LinearMotion& m, double t);

/// Eq. (11): the n x 2 regressor matrix T_n with rows [t_l, 1], l = 1..n.
/// Source: Han (IJACSA), Eq. (11), Sec. III.B.
/// Spec: han.eq11
/// Pre: t non-empty, every t_l finite (DomainError).
/// Post: rows() == t.size(); T(l, 0) == t_l, T(l, 1) == 1.
/// Golden: golden/han/han.eq11.json
[[nodiscard]] Eigen::Matrix<double, Eigen::Dynamic, 2> regressor_matrix(std::span<const double> t);

/// Eq. (10): the stacked model values T_n theta, row l evaluated (t_l * theta_0) + theta_1
/// (X_n = T_n A_m with theta = A_m, Y_n = T_n B_m with theta = B_m).
/// Source: Han (IJACSA), Eq. (10) (printed "T_n + A_m", read as the product), Sec. III.B.
/// Spec: han.eq10
/// Pre: t non-empty; t and theta finite; the results finite (DomainError).
/// Post: one value per time, equal to position(...) of Eq. (9) at t_l.
/// Golden: golden/han/han.eq10.json
[[nodiscard]] std::vector<double> stacked(std::span<const double> t, const Eigen::Vector2d& theta);

/// Eq. (12)-(13): the residual vector E_n = Z_n - T_n theta, e_l = z_l - ((t_l * theta_0) +
/// theta_1), for an estimate theta (A_n for Z = X, B_n for Z = Y).
/// Source: Han (IJACSA), Eq. (12)-(13), Sec. III.B.
/// Spec: han.eq12, han.eq13
/// Pre: t and z non-empty, of equal size, finite; theta finite; results finite (DomainError).
/// Post: e.size() == t.size(); e == 0 wherever the sample lies on the line theta exactly.
/// Golden: golden/han/han.eq12.json, golden/han/han.eq13.json
[[nodiscard]] std::vector<double> residuals(std::span<const double> t, std::span<const double> z,
                                            const Eigen::Vector2d& theta);

/// Eq. (14): J_n = sum_{l=1..n} lambda^(n-l) e_l^2, evaluated by the recursion J_1 = e_1 * e_1,
/// J_l = (lambda * J_{l-1}) + (e_l * e_l) (no pow).
/// Source: Han (IJACSA), Eq. (14), Sec. III.B.
/// Spec: han.eq14
/// Pre: e non-empty, finite; 0 < lambda <= 1; result finite (DomainError).
/// Post: J >= 0; with lambda == 1 the left-to-right sum of squares.
/// Golden: golden/han/han.eq14.json
[[nodiscard]] double weighted_cost(std::span<const double> e, double lambda);

/// How the first m samples are weighted in the initialisation (spec han.eq15, "Reading").
enum class InitWeights {
  weighted,    ///< P_m = (T_m^T Lambda_m T_m)^-1, Lambda_m = diag(lambda^(m-1), ..., 1) (default)
  unweighted,  ///< P_m = (T_m^T T_m)^-1 as printed in Eq. (15)
};
/// "weighted" | "unweighted" -> InitWeights; UsageError otherwise. Spec: han.eq15.
[[nodiscard]] InitWeights parse_init_weights(std::string_view name);

/// An RLS estimate after n samples: A_n (x), B_n (y) and the covariance P_n.
struct Estimate {
  Eigen::Vector2d A = Eigen::Vector2d::Zero();
  Eigen::Vector2d B = Eigen::Vector2d::Zero();
  Eigen::Matrix2d P = Eigen::Matrix2d::Zero();
};

/// Eq. (15), initialisation: the (weighted) batch least-squares solution of the given samples
/// (the first m), P_m = (T_m^T W T_m)^-1, A_m = P_m T_m^T W X_m, B_m = P_m T_m^T W Y_m, with W the
/// identity (unweighted) or diag(lambda^(m-l)) (weighted). Operation order in spec han.eq15.
/// Source: Han (IJACSA), Eq. (15) "P_{n-1} = (T_{n-1}^T T_{n-1})^-1 / lambda", Sec. III.B.
/// Spec: han.eq15
/// Pre: m = t.size() >= 2 equal to x.size(), y.size(); t strictly increasing, all finite;
/// 0 < lambda <= 1; det(T^T W T) > 0 and the results finite (DomainError).
/// Post: A, B interpolate exactly (in exact arithmetic) when m == 2.
/// Golden: golden/han/han.eq15.json
[[nodiscard]] Estimate rls_init(std::span<const double> t, std::span<const double> x,
                                std::span<const double> y, double lambda,
                                InitWeights w = InitWeights::weighted);

/// Eq. (15) as printed: the scaled covariance P_{n-1} / lambda (each entry divided by lambda).
/// Spec: han.eq15. Pre: P finite; 0 < lambda <= 1 (DomainError). Golden: golden/han/han.eq15.json
[[nodiscard]] Eigen::Matrix2d scaled_covariance(const Eigen::Matrix2d& P, double lambda);

/// RLS gain K_n = Ps phi / (1 + phi^T Ps phi), Ps = P_{n-1} / lambda, phi = [t, 1]^T; evaluated
/// g_i = (Ps(i,0) * t) + Ps(i,1), s = (t * g_0) + g_1, K_i = g_i / (1 + s).
/// Spec: han.eq15. Pre: Ps and t finite; 1 + s > 0; K finite (DomainError).
/// Golden: golden/han/han.eq15.json
[[nodiscard]] Eigen::Vector2d rls_gain(const Eigen::Matrix2d& P_scaled, double t);

/// RLS parameter update theta_n = theta_{n-1} + K_n (z_n - phi^T theta_{n-1}); evaluated
/// err = z - ((t * theta_0) + theta_1), theta_i + (K_i * err).
/// Spec: han.eq15. Pre: all finite; result finite (DomainError). Golden: golden/han/han.eq15.json
[[nodiscard]] Eigen::Vector2d rls_parameter_update(const Eigen::Vector2d& theta,
                                                   const Eigen::Vector2d& K, double t, double z);

/// RLS covariance update P_n = Ps - K_n (phi^T Ps); evaluated h_j = (t * Ps(0,j)) + Ps(1,j),
/// P_n(i,j) = Ps(i,j) - (K_i * h_j). Spec: han.eq15. Pre: all finite; result finite
/// (DomainError). Golden: golden/han/han.eq15.json
[[nodiscard]] Eigen::Matrix2d rls_covariance_update(const Eigen::Matrix2d& P_scaled,
                                                    const Eigen::Vector2d& K, double t);

/// One RLS step with the sample (t, x, y): Ps = scaled_covariance(P, lambda),
/// K = rls_gain(Ps, t), A and B by rls_parameter_update, P by rls_covariance_update.
/// Source: Han (IJACSA), Eq. (13)-(15), Sec. III.B (the recursion the paper leaves out is the
/// standard RLS with forgetting factor; spec han.eq15).
/// Spec: han.eq15
/// Pre: as the parts; 0 < lambda <= 1 (DomainError). Time ordering is the caller's (rls_estimate
/// checks it).
/// Golden: golden/han/han.eq15.json
[[nodiscard]] Estimate rls_step(const Estimate& prev, double t, double x, double y, double lambda);

/// The whole recursion: rls_init on samples 1..m, then rls_step for samples m+1..n.
/// In exact arithmetic the result minimises J_n of Eq. (14) for x and for y (weighted), i.e.
/// equals the exponentially weighted batch least-squares solution; with lambda = 1 the ordinary
/// batch solution; with unweighted initialisation the batch solution with weights
/// lambda^(n - max(l, m)).
/// Source: Han (IJACSA), Eq. (9)-(15), Sec. III.B.
/// Spec: han.eq15
/// Pre: t, x, y of equal size n >= m >= 2; t strictly increasing; all finite; 0 < lambda <= 1
/// (DomainError).
/// Interpretation: InitWeights (default weighted).
/// Golden: golden/han/han.eq15.json
[[nodiscard]] Estimate rls_estimate(std::span<const double> t, std::span<const double> x,
                                    std::span<const double> y, double lambda, std::size_t m = 2,
                                    InitWeights w = InitWeights::weighted);

}  // namespace pathref::rls
