#include "pathref/equations/rls.hpp"

#include <cmath>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::rls {

namespace {

bool all_finite(std::span<const double> v) {
  for (const double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

bool finite2(const Eigen::Vector2d& v) { return std::isfinite(v(0)) && std::isfinite(v(1)); }

bool finite22(const Eigen::Matrix2d& m) {
  return std::isfinite(m(0, 0)) && std::isfinite(m(0, 1)) && std::isfinite(m(1, 0)) &&
         std::isfinite(m(1, 1));
}

void check_lambda(double lambda) {
  require(std::isfinite(lambda) && lambda > 0.0 && lambda <= 1.0, "lambda must lie in (0, 1]");
}

double line(const Eigen::Vector2d& theta, double t) { return (t * theta(0)) + theta(1); }

}  // namespace

Position position(const LinearMotion& m, double t) {
  require(std::isfinite(m.a) && std::isfinite(m.b) && std::isfinite(m.c) && std::isfinite(m.d) &&
              std::isfinite(t),
          "the motion parameters and t must be finite");
  const Position p{(m.a * t) + m.b, (m.c * t) + m.d};
  require(std::isfinite(p.x) && std::isfinite(p.y), "the position overflows");
  return p;
}

Eigen::Matrix<double, Eigen::Dynamic, 2> regressor_matrix(std::span<const double> t) {
  require(!t.empty(), "T_n needs at least one time");
  require(all_finite(t), "times must be finite");
  Eigen::Matrix<double, Eigen::Dynamic, 2> T(static_cast<Eigen::Index>(t.size()), 2);
  for (std::size_t l = 0; l < t.size(); ++l) {
    T(static_cast<Eigen::Index>(l), 0) = t[l];
    T(static_cast<Eigen::Index>(l), 1) = 1.0;
  }
  return T;
}

std::vector<double> stacked(std::span<const double> t, const Eigen::Vector2d& theta) {
  require(!t.empty(), "need at least one time");
  require(all_finite(t) && finite2(theta), "times and parameters must be finite");
  std::vector<double> out;
  out.reserve(t.size());
  for (const double tl : t) {
    const double v = line(theta, tl);
    require(std::isfinite(v), "a model value overflows");
    out.push_back(v);
  }
  return out;
}

std::vector<double> residuals(std::span<const double> t, std::span<const double> z,
                              const Eigen::Vector2d& theta) {
  require(!t.empty(), "need at least one sample");
  require(t.size() == z.size(), "one observation per time");
  require(all_finite(t) && all_finite(z) && finite2(theta), "samples and parameters must be finite");
  std::vector<double> e;
  e.reserve(t.size());
  for (std::size_t l = 0; l < t.size(); ++l) {
    const double v = z[l] - line(theta, t[l]);
    require(std::isfinite(v), "a residual overflows");
    e.push_back(v);
  }
  return e;
}

double weighted_cost(std::span<const double> e, double lambda) {
  require(!e.empty(), "J_n needs at least one residual");
  require(all_finite(e), "residuals must be finite");
  check_lambda(lambda);
  double J = e[0] * e[0];
  for (std::size_t l = 1; l < e.size(); ++l) J = (lambda * J) + (e[l] * e[l]);
  require(std::isfinite(J), "J_n overflows");
  return J;
}

InitWeights parse_init_weights(std::string_view name) {
  if (name == "weighted") return InitWeights::weighted;
  if (name == "unweighted") return InitWeights::unweighted;
  throw UsageError("unknown RLS initialisation '" + std::string(name) +
                   "' (expected weighted or unweighted)");
}

Estimate rls_init(std::span<const double> t, std::span<const double> x, std::span<const double> y,
                  double lambda, InitWeights w) {
  const std::size_t m = t.size();
  require(m >= 2, "the initialisation needs at least 2 samples");
  require(x.size() == m && y.size() == m, "one x and one y per time");
  require(all_finite(t) && all_finite(x) && all_finite(y), "samples must be finite");
  for (std::size_t l = 1; l < m; ++l) require(t[l - 1] < t[l], "times must be strictly increasing");
  check_lambda(lambda);
  // weights w_l = lambda^(m-l): w_m = 1, w_l = w_{l+1} * lambda (descending); or all 1.
  std::vector<double> wl(m, 1.0);
  if (w == InitWeights::weighted)
    for (std::size_t l = m - 1; l-- > 0;) wl[l] = wl[l + 1] * lambda;
  double s_tt = 0.0, s_t = 0.0, s_1 = 0.0, r_x = 0.0, r_x1 = 0.0, r_y = 0.0, r_y1 = 0.0;
  for (std::size_t l = 0; l < m; ++l) {
    const double wt = wl[l] * t[l];
    s_tt += wl[l] * (t[l] * t[l]);
    s_t += wt;
    s_1 += wl[l];
    r_x += wt * x[l];
    r_x1 += wl[l] * x[l];
    r_y += wt * y[l];
    r_y1 += wl[l] * y[l];
  }
  const double det = (s_tt * s_1) - (s_t * s_t);
  require(std::isfinite(det) && det > 0.0, "T^T W T is singular or overflows in binary64");
  Estimate e;
  e.P(0, 0) = s_1 / det;
  e.P(0, 1) = -s_t / det;
  e.P(1, 0) = -s_t / det;
  e.P(1, 1) = s_tt / det;
  e.A(0) = (e.P(0, 0) * r_x) + (e.P(0, 1) * r_x1);
  e.A(1) = (e.P(1, 0) * r_x) + (e.P(1, 1) * r_x1);
  e.B(0) = (e.P(0, 0) * r_y) + (e.P(0, 1) * r_y1);
  e.B(1) = (e.P(1, 0) * r_y) + (e.P(1, 1) * r_y1);
  require(finite22(e.P) && finite2(e.A) && finite2(e.B), "the initial estimate overflows");
  return e;
}

Eigen::Matrix2d scaled_covariance(const Eigen::Matrix2d& P, double lambda) {
  require(finite22(P), "P must be finite");
  check_lambda(lambda);
  Eigen::Matrix2d Ps;
  for (Eigen::Index i = 0; i < 2; ++i)
    for (Eigen::Index j = 0; j < 2; ++j) Ps(i, j) = P(i, j) / lambda;
  require(finite22(Ps), "P / lambda overflows");
  return Ps;
}

Eigen::Vector2d rls_gain(const Eigen::Matrix2d& P_scaled, double t) {
  require(finite22(P_scaled) && std::isfinite(t), "P and t must be finite");
  const double g0 = (P_scaled(0, 0) * t) + P_scaled(0, 1);
  const double g1 = (P_scaled(1, 0) * t) + P_scaled(1, 1);
  const double s = (t * g0) + g1;
  const double den = 1.0 + s;
  require(std::isfinite(den) && den > 0.0, "1 + phi^T P phi must be positive and finite");
  const Eigen::Vector2d K(g0 / den, g1 / den);
  require(finite2(K), "the gain overflows");
  return K;
}

Eigen::Vector2d rls_parameter_update(const Eigen::Vector2d& theta, const Eigen::Vector2d& K,
                                     double t, double z) {
  require(finite2(theta) && finite2(K) && std::isfinite(t) && std::isfinite(z),
          "the update needs finite values");
  const double err = z - line(theta, t);
  const Eigen::Vector2d next(theta(0) + (K(0) * err), theta(1) + (K(1) * err));
  require(finite2(next), "the parameter update overflows");
  return next;
}

Eigen::Matrix2d rls_covariance_update(const Eigen::Matrix2d& P_scaled, const Eigen::Vector2d& K,
                                      double t) {
  require(finite22(P_scaled) && finite2(K) && std::isfinite(t), "the update needs finite values");
  const double h0 = (t * P_scaled(0, 0)) + P_scaled(1, 0);
  const double h1 = (t * P_scaled(0, 1)) + P_scaled(1, 1);
  Eigen::Matrix2d P;
  P(0, 0) = P_scaled(0, 0) - (K(0) * h0);
  P(0, 1) = P_scaled(0, 1) - (K(0) * h1);
  P(1, 0) = P_scaled(1, 0) - (K(1) * h0);
  P(1, 1) = P_scaled(1, 1) - (K(1) * h1);
  require(finite22(P), "the covariance update overflows");
  return P;
}

Estimate rls_step(const Estimate& prev, double t, double x, double y, double lambda) {
  const Eigen::Matrix2d Ps = scaled_covariance(prev.P, lambda);
  const Eigen::Vector2d K = rls_gain(Ps, t);
  Estimate next;
  next.A = rls_parameter_update(prev.A, K, t, x);
  next.B = rls_parameter_update(prev.B, K, t, y);
  next.P = rls_covariance_update(Ps, K, t);
  return next;
}

Estimate rls_estimate(std::span<const double> t, std::span<const double> x,
                      std::span<const double> y, double lambda, std::size_t m, InitWeights w) {
  const std::size_t n = t.size();
  require(x.size() == n && y.size() == n, "one x and one y per time");
  require(m >= 2 && m <= n, "need 2 <= m <= n");
  require(all_finite(t) && all_finite(x) && all_finite(y), "samples must be finite");
  for (std::size_t l = 1; l < n; ++l) require(t[l - 1] < t[l], "times must be strictly increasing");
  Estimate e = rls_init(t.first(m), x.first(m), y.first(m), lambda, w);
  for (std::size_t l = m; l < n; ++l) e = rls_step(e, t[l], x[l], y[l], lambda);
  return e;
}

}  // namespace pathref::rls
