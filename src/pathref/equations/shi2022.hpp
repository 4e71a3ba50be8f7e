#pragma once
/// \file shi2022.hpp
/// Shi et al. 2022 (doi:10.3389/fbioe.2022.905983) as a paper: its Table 1 parameters, and where
/// each of its equations lives. pathref organises code by concept, so the equations are spread
/// over grid/, equations/metrics.hpp, equations/aco.hpp, equations/ga.hpp and
/// equations/proportional.hpp; this header is the map from the paper to them.
/// Spec: spec/shi2022.md
///
/// | Shi 2022 | function |
/// |---|---|
/// | Eq. (1) cell centre | grid::cell_centre (src/pathref/grid/coords.hpp), Eq1Form |
/// | Eq. (2) transition probability | aco::transition_weights, aco::transition_probabilities, equations::proportional_probabilities |
/// | Eq. (3) eta = 1/d_ij | aco::eta_inverse_distance |
/// | Eq. (4) d_ij | metrics::centre_distance (src/pathref/equations/metrics.hpp) |
/// | Eq. (5) pheromone update | aco::pheromone_update |
/// | Eq. (6) total deposit | aco::total_deposit |
/// | Eq. (7) ant-cycle deposit | aco::ant_cycle_deposit, aco::edge_deposit |
/// | Eq. (8) continuity | ga::continuity_delta, ga::is_continuous (via heuristics::chebyshev) |
/// | Eq. (9) mid-point insertion | ga::insertion_cell, ga::insertion_number |
/// | Eq. (10), (15) 1/length | ga::inverse_length |
/// | Eq. (11) roulette probability | equations::proportional_probabilities (draw: rng::roulette) |
/// | Eq. (12) eta = 1/(d_ij + d_jE) | aco::eta_goal_directed |
/// | Eq. (13) adaptive rho | aco::adaptive_rho |
/// | Eq. (14) weighted fitness | ga::weighted_fitness |
/// | Eq. (16) smoothness factor | ga::smoothness_factor |
/// | Eq. (17) turning angle | metrics::turning_angles, ga::turn_band |
/// | Eq. (18) safety factor | ga::safety_factor (via metrics::safety_counts) |
/// | Eq. (19), (20) adaptive P_c, P_m | ga::adaptive_pc, ga::adaptive_pm |
#include <cstdint>

namespace pathref::shi2022 {

/// Eq. (1), grid coordinates: implemented by grid::cell_centre (rule grid.coord), whose Eq1Form
/// selects the corrected form (default) or the printed one under either numbering.
/// Source: Shi et al. 2022, Eq. (1), Sec. 3, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq1 (adapter over grid::cell_centre). Golden: golden/shi2022/shi2022.eq1.json

/// Eq. (4), the Euclidean distance between cell centres: implemented by metrics::centre_distance
/// (rule metrics.length), exact integer differences and one correctly rounded square root.
/// Source: Shi et al. 2022, Eq. (4), Sec. 4.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq4 (adapter over metrics::centre_distance). Golden: golden/shi2022/shi2022.eq4.json

/// Eq. (17), the turning angle: implemented by metrics::turning_angles (rule metrics.turn-angle,
/// atan2 of the exact cross and dot products), and its penalty band by ga::turn_band.
/// Source: Shi et al. 2022, Eq. (17), Sec. 4.4.2, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq17 (adapter over metrics::turning_angles and ga::turn_band).
/// Golden: golden/shi2022/shi2022.eq17.json

/// Table 1 of Shi et al. 2022, "Simulation experiment initial parameter table". The printed table
/// merges the "Other parameters" cells of its two rows into one; the first line (alpha .. rho_min)
/// belongs to the ant colony row, the second (a .. P_m_max) to the genetic algorithm row.
/// Source: Shi et al. 2022, Table 1, Sec. 5.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.table1. Golden: golden/shi2022/shi2022.table1.json
struct Table1 {
  std::int64_t ants = 50;              ///< ant colony: initial quantity (number of ants m)
  std::int64_t aco_iterations = 100;   ///< ant colony: maximum number of iterations T (Eq. 13)
  double alpha = 1.0;                  ///< Eq. (2)
  double beta = 7.0;                   ///< Eq. (2)
  double Q = 1.0;                      ///< Eq. (7)
  double rho_initial = 0.9;            ///< Eq. (13): rho(0)
  double rho_min = 0.1;                ///< Eq. (13)
  std::int64_t ga_population = 200;    ///< genetic algorithm: initial population size
  std::int64_t ga_generations = 50;    ///< genetic algorithm: maximum iterations M_g (Eq. 19-20)
  double a = 5.0;                      ///< Eq. (14)
  double b = 4.0;                      ///< Eq. (14)
  double c = 1.0;                      ///< Eq. (14)
  double pc = 0.8;                     ///< fixed P_c of the non-adaptive GA (spec shi2022.eq19)
  double pm = 0.1;                     ///< fixed P_m of the non-adaptive GA (spec shi2022.eq20)
  double pm_max = 0.3;                 ///< Eq. (20)
};

/// The values of Table 1. Spec: shi2022.table1.
inline constexpr Table1 table1{};

}  // namespace pathref::shi2022
