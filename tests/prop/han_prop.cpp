// spec: han.eq1, han.eq2, han.eq3, han.eq4, han.eq5, han.eq7, han.eq8, han.eq9, han.eq15
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/QR>

#include "pathref/core/error.hpp"
#include "pathref/equations/aco.hpp"
#include "pathref/equations/aco_adaptive.hpp"
#include "pathref/equations/corner.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/pseudo_random.hpp"
#include "pathref/equations/rls.hpp"

using namespace pathref;
using grid::Cell;

namespace {

constexpr std::int64_t dxs[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr std::int64_t dys[8] = {-1, -1, -1, 0, 0, 1, 1, 1};

/// Strictly increasing times: t_0 = 0, steps k/4 with k in [1, 8] (exact binary fractions).
rc::Gen<std::vector<double>> gen_times(std::size_t n) {
  return rc::gen::map(rc::gen::container<std::vector<int>>(n, rc::gen::inRange(1, 9)),
                      [](const std::vector<int>& steps) {
                        std::vector<double> t;
                        double acc = 0.0;
                        for (std::size_t l = 0; l < steps.size(); ++l) {
                          t.push_back(acc);
                          acc += static_cast<double>(steps[l]) / 4.0;
                        }
                        return t;
                      });
}

/// Observations in [-100, 100], multiples of 1/16.
rc::Gen<std::vector<double>> gen_obs(std::size_t n) {
  return rc::gen::container<std::vector<double>>(
      n, rc::gen::map(rc::gen::inRange(-1600, 1601), [](int k) { return static_cast<double>(k) / 16.0; }));
}

/// Weighted batch least squares with Eigen (column-pivoting Householder QR on sqrt(w)-scaled rows).
Eigen::Vector2d batch(const std::vector<double>& t, const std::vector<double>& z,
                      const std::vector<double>& w) {
  const auto n = static_cast<Eigen::Index>(t.size());
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index l = 0; l < n; ++l) {
    const auto k = static_cast<std::size_t>(l);
    const double s = std::sqrt(w[k]);
    A(l, 0) = s * t[k];
    A(l, 1) = s;
    b(l) = s * z[k];
  }
  return A.colPivHouseholderQr().solve(b);
}

}  // namespace

TEST_CASE("prop_han_transition_probabilities_sum_to_one", "[han][prop]") {
  rc::prop("Eq. 1 with omega from Eq. 2-3: p >= 0 and |sum p - 1| <= 2 n 2^-53", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 9);
    const auto tau = *rc::gen::container<std::vector<double>>(
        n, rc::gen::map(rc::gen::inRange(1, 65), [](int k) { return static_cast<double>(k) / 16.0; }));
    std::vector<double> eta;
    std::vector<Cell> cand;
    const Cell cur{10, 10};
    for (std::size_t r = 0; r < n; ++r) {
      const auto d = static_cast<std::size_t>(*rc::gen::inRange(0, 8));
      cand.push_back(Cell{cur.x + dxs[d], cur.y + dys[d]});
      eta.push_back(aco::eta_inverse_distance(cur, cand.back()));
    }
    const auto dp = static_cast<std::size_t>(*rc::gen::inRange(0, 8));
    const Cell prev{cur.x - dxs[dp], cur.y - dys[dp]};
    const auto omega = corner::corner_factors(prev, cur, cand, 0.5);
    const double gamma = *rc::gen::element(0.0, 1.0, 2.0);
    const auto p = aco::transition_probabilities(tau, eta, 4.0, 8.0, aco::CornerFactor{omega, gamma});
    double s = 0.0;
    for (const double x : p) {
      RC_ASSERT(x >= 0.0);
      RC_ASSERT(x <= 1.0);
      s += x;
    }
    // Bound of shi2022.eq2: S has relative error <= (n-1) 2^-53, each quotient 2^-53, and the
    // check's own sum another (n-1) 2^-53; no underflow (weights >= 2^-40 here).
    RC_ASSERT(std::fabs(s - 1.0) <= 2.0 * static_cast<double>(n) * 0x1p-53);
  });
}

TEST_CASE("prop_corner_equivalent_readings_give_equal_probabilities", "[han][prop]") {
  rc::prop("multiply+two == divide+one and multiply+one == divide+two (Eq. 2-3)", [] {
    const Cell cur{0, 0};
    const auto dp = static_cast<std::size_t>(*rc::gen::inRange(0, 8));
    const Cell prev{-dxs[dp], -dys[dp]};
    std::vector<Cell> cand;
    for (std::size_t d = 0; d < 8; ++d) cand.push_back(Cell{dxs[d], dys[d]});
    const std::vector<double> tau(8, 1.0), eta(8, 1.0);
    using corner::At90;
    using corner::OmegaForm;
    const auto probs = [&](OmegaForm f, At90 a) {
      const auto w = corner::corner_factors(prev, cur, cand, 0.5, f, a);
      return aco::transition_probabilities(tau, eta, 4.0, 8.0, aco::CornerFactor{w, 1.0});
    };
    RC_ASSERT(probs(OmegaForm::multiply, At90::two) == probs(OmegaForm::divide, At90::one));
    RC_ASSERT(probs(OmegaForm::multiply, At90::one) == probs(OmegaForm::divide, At90::two));
  });
}

TEST_CASE("prop_pseudo_random_choice_is_max_or_positive", "[han][prop]") {
  rc::prop("argmax is the first maximum; roulette picks a positive weight", [] {
    auto w = *rc::gen::nonEmpty(rc::gen::container<std::vector<double>>(
        rc::gen::map(rc::gen::inRange(0, 5), [](int k) { return static_cast<double>(k); })));
    w.push_back(1.0);  // at least one positive weight
    const double q = *rc::gen::map(rc::gen::inRange(0, 1024), [](int k) { return k / 1024.0; });
    const double q0 = *rc::gen::map(rc::gen::inRange(0, 1025), [](int k) { return k / 1024.0; });
    const double u = *rc::gen::map(rc::gen::inRange(0, 1024), [](int k) { return k / 1024.0; });
    const auto c = aco::pseudo_random_choice(w, q, q0, u);
    RC_ASSERT(w[c.index] > 0.0);
    RC_ASSERT((c.mode == aco::ChoiceMode::argmax) == (q <= q0));
    if (c.mode == aco::ChoiceMode::argmax) {
      for (std::size_t k = 0; k < w.size(); ++k) {
        RC_ASSERT(w[k] <= w[c.index]);
        if (k < c.index) RC_ASSERT(w[k] < w[c.index]);
      }
    }
  });
}

TEST_CASE("prop_q0_bounds_and_monotone", "[han][prop]") {
  rc::prop("fl(0.2 eps) <= q0 <= fl(0.9 eps), non-increasing in N_c", [] {
    const auto n_max = *rc::gen::inRange<std::int64_t>(1, 1000);
    const auto n_c = *rc::gen::inRange<std::int64_t>(0, n_max + 1);
    const double eps = *rc::gen::element(1.0, 0.5, 0.75, 1.1, 0.1, 1e-3);
    const double q0 = aco::adaptive_q0(eps, n_c, n_max);
    RC_ASSERT(q0 >= eps * 0.2);
    RC_ASSERT(q0 <= eps * 0.9);
    if (n_c < n_max) RC_ASSERT(aco::adaptive_q0(eps, n_c + 1, n_max) <= q0);
  });
}

TEST_CASE("prop_stepped_rho_bounds", "[han][prop]") {
  rc::prop("rho_min <= rho(t) <= max(0.9 rho(t-1), rho_min), non-decreasing in the spread", [] {
    const double rho = *rc::gen::map(rc::gen::inRange(1, 1024), [](int k) { return k / 1024.0; });
    const double rho_min = *rc::gen::element(0.0, 0.1, 0.3);
    const double Ln = *rc::gen::map(rc::gen::inRange(1, 400), [](int k) { return k / 4.0; });
    const double d1 = *rc::gen::map(rc::gen::inRange(0, 40), [](int k) { return k / 4.0; });
    const double d2 = *rc::gen::map(rc::gen::inRange(0, 40), [](int k) { return k / 4.0; });
    const double lo = std::min(d1, d2), hi = std::max(d1, d2);
    const double r_lo = aco::stepped_rho(rho, Ln + lo, Ln, 1.0, 5.0, rho_min);
    const double r_hi = aco::stepped_rho(rho, Ln + hi, Ln, 1.0, 5.0, rho_min);
    RC_ASSERT(r_lo >= rho_min);
    RC_ASSERT(r_hi <= std::max(0.9 * rho, rho_min));
    RC_ASSERT(r_lo <= r_hi);
  });
}

TEST_CASE("prop_chebyshev_consistent_and_below_octile", "[han][prop]") {
  rc::prop("h <= octile (free-space optimum) and h(n) <= c(n, n') + h(n') for 8 neighbours", [] {
    const Cell n{*rc::gen::inRange<std::int64_t>(-50, 50), *rc::gen::inRange<std::int64_t>(-50, 50)};
    const Cell g{*rc::gen::inRange<std::int64_t>(-50, 50), *rc::gen::inRange<std::int64_t>(-50, 50)};
    const double h = heuristics::chebyshev(n, g);
    RC_ASSERT(h <= heuristics::octile(n, g));
    for (std::size_t d = 0; d < 8; ++d) {
      const Cell m{n.x + dxs[d], n.y + dys[d]};
      const double c = (dxs[d] != 0 && dys[d] != 0) ? std::sqrt(2.0) : 1.0;
      RC_ASSERT(h <= c + heuristics::chebyshev(m, g));
    }
  });
}

TEST_CASE("prop_rls_equals_weighted_batch_least_squares", "[han][prop]") {
  // Tolerance: both sides solve the same 2x2 weighted least-squares problem in binary64. With
  // these data (times <= 60 in quarter steps, |z| <= 100, n <= 30, lambda >= 0.8) the RLS result
  // was measured against the exact rational solution: max error 2.1e-14 * max(1, |z|) over 1500
  // random cases (Python replay of the spec, bit-identical to the C++); Eigen's QR is of the same
  // order. 1e-10 * max(1, |z|) leaves a margin of ~5000 for both sides and other libms, and still
  // catches a wrong weighting (a wrong power of lambda moves theta by > 1e-3 on such data).
  rc::prop("weighted init: RLS == exponentially weighted batch (Eigen QR), lambda = 1: OLS", [] {
    const auto n = *rc::gen::inRange<std::size_t>(2, 31);
    const auto t = *gen_times(n);
    const auto x = *gen_obs(n);
    const auto y = *gen_obs(n);
    const double lambda = *rc::gen::element(1.0, 0.99, 0.95, 0.9, 0.8);
    const auto m = *rc::gen::inRange<std::size_t>(2, n + 1);
    const auto e = rls::rls_estimate(t, x, y, lambda, m, rls::InitWeights::weighted);
    std::vector<double> w(n, 1.0);
    for (std::size_t l = n - 1; l-- > 0;) w[l] = w[l + 1] * lambda;
    const Eigen::Vector2d bx = batch(t, x, w), by = batch(t, y, w);
    double scale = 1.0;
    for (std::size_t l = 0; l < n; ++l) scale = std::max({scale, std::fabs(x[l]), std::fabs(y[l])});
    const double tol = 1e-10 * scale;
    for (Eigen::Index i = 0; i < 2; ++i) {
      RC_ASSERT(std::fabs(e.A(i) - bx(i)) <= tol);
      RC_ASSERT(std::fabs(e.B(i) - by(i)) <= tol);
    }
  });
  rc::prop("unweighted init: RLS == batch with weights lambda^(n - max(l, m))", [] {
    const auto n = *rc::gen::inRange<std::size_t>(2, 31);
    const auto t = *gen_times(n);
    const auto x = *gen_obs(n);
    const auto y = *gen_obs(n);
    const double lambda = *rc::gen::element(1.0, 0.95, 0.9, 0.8);
    const auto m = *rc::gen::inRange<std::size_t>(2, n + 1);
    const auto e = rls::rls_estimate(t, x, y, lambda, m, rls::InitWeights::unweighted);
    std::vector<double> w(n, 1.0);
    for (std::size_t l = n - 1; l-- > 0;) w[l] = (l + 1 >= m) ? w[l + 1] * lambda : w[l + 1];
    const Eigen::Vector2d bx = batch(t, x, w);
    double scale = 1.0;
    for (std::size_t l = 0; l < n; ++l) scale = std::max(scale, std::fabs(x[l]));
    for (Eigen::Index i = 0; i < 2; ++i) RC_ASSERT(std::fabs(e.A(i) - bx(i)) <= 1e-10 * scale);
  });
}

TEST_CASE("prop_rls_exact_on_noise_free_lines", "[han][prop]") {
  rc::prop("first times 0 and 1, dyadic lambda: theta == (alpha, beta) bit for bit", [] {
    // The initial batch is exact (det = lambda, P = [[(1+lambda)/lambda, -1/lambda], ...] with
    // lambda in {1, 1/2, 1/4}); every later innovation z - ((t alpha) + beta) is exactly 0 for
    // these small integers and quarter times, so theta never moves, whatever K is.
    const auto n = *rc::gen::inRange<std::size_t>(2, 30);
    auto t = *gen_times(n);
    t[1] = 1.0;
    for (std::size_t l = 2; l < n; ++l) t[l] = std::max(t[l], t[l - 1] + 0.25);
    const double alpha = *rc::gen::inRange(-50, 51), beta = *rc::gen::inRange(-50, 51);
    const double gamma = *rc::gen::inRange(-50, 51), delta = *rc::gen::inRange(-50, 51);
    std::vector<double> x, y;
    for (const double tl : t) {
      x.push_back((tl * alpha) + beta);
      y.push_back((tl * gamma) + delta);
    }
    const double lambda = *rc::gen::element(1.0, 0.5, 0.25);
    const auto e = rls::rls_estimate(t, x, y, lambda);
    RC_ASSERT(e.A == Eigen::Vector2d(alpha, beta));
    RC_ASSERT(e.B == Eigen::Vector2d(gamma, delta));
    const double future = t.back() + 3.0;
    const rls::Position p = rls::position(rls::LinearMotion{e.A(0), e.A(1), e.B(0), e.B(1)}, future);
    RC_ASSERT(p.x == (future * alpha) + beta);
    RC_ASSERT(p.y == (future * gamma) + delta);
  });
  rc::prop("any times and lambda in [0.8, 1]: theta within 1e-9 (1 + |alpha| + |beta|)", [] {
    // In exact arithmetic theta is exactly the line (the data lie in the model, T has full rank);
    // the binary64 error is the initial batch's, ~cond(T^T W T) * 2^-53 <= 1e-10 relative here,
    // and later innovations only shrink it.
    const auto n = *rc::gen::inRange<std::size_t>(2, 30);
    const auto t = *gen_times(n);
    const double alpha = *rc::gen::inRange(-50, 51) / 8.0, beta = *rc::gen::inRange(-50, 51) / 8.0;
    std::vector<double> x;
    for (const double tl : t) x.push_back((tl * alpha) + beta);
    const double lambda = *rc::gen::element(1.0, 0.99, 0.95, 0.9, 0.8);
    const auto e = rls::rls_estimate(t, x, x, lambda);
    const double tol = 1e-9 * (1.0 + std::fabs(alpha) + std::fabs(beta));
    RC_ASSERT(std::fabs(e.A(0) - alpha) <= tol);
    RC_ASSERT(std::fabs(e.A(1) - beta) <= tol);
  });
}
