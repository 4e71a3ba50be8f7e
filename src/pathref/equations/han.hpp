#pragma once
/// \file han.hpp
/// Han (IJACSA), "Application of Improved Ant Colony Algorithm Integrating Adaptive Parameter
/// Configuration in Robot Mobile Path Design", as a paper: its parameters (printed and chosen),
/// and where each of its equations lives. pathref organises code by concept, so the equations
/// are spread over equations/aco.hpp, corner.hpp, pseudo_random.hpp, aco_adaptive.hpp,
/// heuristics.hpp and rls.hpp; this header is the map from the paper to them.
/// Spec: spec/han.md
///
/// | Han | function |
/// |---|---|
/// | Eq. (1) transition probability with omega^gamma | aco::transition_weights, aco::transition_probabilities with aco::CornerFactor |
/// | Eq. (2) corner heuristic omega | corner::corner_heuristic, corner::corner_factors |
/// | Eq. (3) turning cost T | corner::turning_cost |
/// | Eq. (4) pseudo-random proportional rule | aco::pseudo_random_choice, aco::argmax_weight (roulette: rng::roulette) |
/// | Eq. (5) adaptive q0 | aco::adaptive_q0 |
/// | Eq. (6) pheromone update with elite term | aco::pheromone_update_elite, aco::elite_bonus (with aco::pheromone_update) |
/// | Eq. (7) stepped rho | aco::stepped_rho |
/// | Eq. (8) A* heuristic | heuristics::chebyshev (src/pathref/equations/heuristics.hpp) |
/// | Eq. (9) linear motion | rls::position |
/// | Eq. (10)-(11) stacked model, T_n | rls::stacked, rls::regressor_matrix |
/// | Eq. (12)-(13) residuals | rls::residuals |
/// | Eq. (14) weighted cost | rls::weighted_cost |
/// | Eq. (15) RLS with forgetting factor | rls::rls_init, rls::scaled_covariance, rls::rls_gain, rls::rls_parameter_update, rls::rls_covariance_update, rls::rls_step, rls::rls_estimate |
#include <cstdint>

namespace pathref::han {

/// Eq. (1), transition probability with the corner heuristic: implemented by
/// aco::transition_weights / aco::transition_probabilities (Shi Eq. 2) with the optional
/// aco::CornerFactor{omega, gamma}, weights (pow(tau, alpha) * pow(eta, beta)) * pow(omega, gamma).
/// Source: Han (IJACSA), Eq. (1), Sec. III.A.
/// Spec: han.eq1 (adapter over aco::transition_weights and aco::transition_probabilities).
/// Golden: golden/han/han.eq1.json

/// Eq. (8), the A* heuristic h(n) = max(|n_x - g_x|, |n_y - g_y|): implemented by
/// heuristics::chebyshev (rule search.h.chebyshev); the octile form is the reading `octile`.
/// Source: Han (IJACSA), Eq. (8), Sec. III.B.
/// Spec: han.eq8 (adapter over heuristics::chebyshev and heuristics::octile).
/// Golden: golden/han/han.eq8.json

/// The parameters of Han (IJACSA): the values printed in Sec. IV (`printed`) and the values
/// pathref chooses for the ones the paper does not give (`choice`, spec han.params).
/// Source: Han (IJACSA), Sec. IV ("the maximum number of cycles was 50, alpha = 4, beta = 8,
/// rho = 0.7, and the total quantity of ants was 50").
/// Spec: han.params. Golden: golden/han/han.params.json
struct Params {
  std::int64_t ants = 50;               ///< printed: number of ants
  std::int64_t max_cycles = 50;         ///< printed: N_max of Eq. (5)
  double alpha = 4.0;                   ///< printed: Eq. (1), (4)
  double beta = 8.0;                    ///< printed: Eq. (1), (4)
  double rho_initial = 0.7;             ///< printed: rho(0) of Eq. (6)-(7)
  double gamma = 1.0;                   ///< choice: exponent of omega in Eq. (1), (4)
  double omega_i = 0.5;                 ///< choice: omega_i of Eq. (2), in (0, 1)
  double epsilon = 1.0;                 ///< choice: epsilon of Eq. (5) (q0 from 0.9 to 0.2)
  double h = 1.0;                       ///< choice: elite coefficient h of Eq. (6)
  double Q = 1.0;                       ///< choice: ant-cycle deposit Q / L_k in Eq. (6)
  double tau_initial = 1.0;             ///< choice: initial pheromone
  double tau_min = 0.01;                ///< choice: pheromone floor of Eq. (6)
  double a = 1.0;                       ///< choice: lower spread threshold of Eq. (7), cell sides
  double b = 5.0;                       ///< choice: upper spread threshold of Eq. (7), cell sides
  double rho_min = 0.1;                 ///< choice: floor of Eq. (7)
  double lambda = 0.95;                 ///< choice: forgetting factor of Eq. (14)-(15)
  std::int64_t rls_init_samples = 2;    ///< choice: m, samples of the initial batch (Eq. 15)
};

/// The parameter set pathref uses for Han's planners. Spec: han.params.
inline constexpr Params params{};

}  // namespace pathref::han
