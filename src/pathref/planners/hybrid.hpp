#pragma once
/// \file hybrid.hpp
/// The two GA-ACO hybrids of Shi et al. 2022: the traditional hybrid (`hybrid-ga-aco`, Sec. 4.3,
/// Figure 5, after Bao et al. 2021 as Shi describes it) and the improved hybrid (`iha`, Sec. 4.4.3
/// steps 1-9). Each composes one run of the ant-colony engine (planners/ant_colony.hpp) and the GA
/// engine (planners/genetic.hpp) on ONE random stream: the colony's draws first, then the GA's.
/// Source: Shi et al. 2022, doi:10.3389/fbioe.2022.905983, Sec. 4.3, 4.4.3.
/// Spec: spec/shi2022-ga.md (shi2022.plan.hybrid, shi2022.plan.iha)
#include <cstdint>
#include <string_view>

#include "pathref/planners/ant_colony.hpp"
#include "pathref/planners/genetic.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::hybrid {

using planners::Json;

/// Traditional hybrid: how the GA population is completed when the colony found fewer distinct
/// paths than the population size (option `fill`).
enum class Fill {
  repeat,  ///< the sorted distinct ant paths again, cyclically (default)
  random,  ///< random chains of Sec. 4.2 (genetic::initial_paths)
};
/// IHA: which paths the deletion operator is applied to (option `deletion_scope`).
enum class DeletionScope {
  initial,  ///< the random initial population only (step 4, default)
  merged,   ///< also the injected ant paths
};
[[nodiscard]] Fill parse_fill(std::string_view name);
[[nodiscard]] std::string_view to_string(Fill v) noexcept;
[[nodiscard]] DeletionScope parse_deletion_scope(std::string_view name);
[[nodiscard]] std::string_view to_string(DeletionScope v) noexcept;

/// Settings of `hybrid-ga-aco`: Ant System (ant_colony::shi_aco) then the single GA (genetic::shi_ga).
struct TraditionalConfig {
  ant_colony::Config aco = ant_colony::shi_aco();
  genetic::Config ga = genetic::shi_ga();
  Fill fill = Fill::repeat;
};
/// Settings of `iha`: IACO (ant_colony::shi_iaco) then the improved GA with deletion, injection
/// and elite retention.
struct ImprovedConfig {
  ant_colony::Config aco = ant_colony::shi_iaco();
  genetic::Config ga = [] {
    genetic::Config c = genetic::shi_iga();
    c.elitist = true;
    return c;
  }();
  std::int64_t inject = 10;  ///< number of ant paths injected (the shortest distinct ones), >= 0
  DeletionScope deletion_scope = DeletionScope::initial;
};

/// Settings of `hga-aco-cin` (cin2021 Sec. 5.2-5.5): the optimised GA (genetic::cin_ga), the
/// conversion of Eq. 28 and the optimised ACO (ant_colony::cin_aco).
struct CinConfig {
  genetic::Config ga = genetic::cin_ga();
  ant_colony::Config aco = ant_colony::cin_aco();
  cin::ConversionForm conversion_form = cin::ConversionForm::q_over_l;
  ant_colony::InitialMode conversion = ant_colony::InitialMode::add;
  double elite_share = 0.2;  ///< share of the last generation converted, (0, 1]
};

/// Parameters: the colony's (ant_colony::to_params) with the prefix "aco_", the GA's
/// (genetic::to_params), and the hybrid's own (`fill`; `inject`, `deletion_scope`,
/// `elite_fraction`). Spec: shi2022.plan.hybrid, shi2022.plan.iha ("Parameters").
[[nodiscard]] Json to_params(const TraditionalConfig& c);
[[nodiscard]] Json to_params(const ImprovedConfig& c);
[[nodiscard]] TraditionalConfig from_params(const TraditionalConfig& base, const Json& params);
[[nodiscard]] ImprovedConfig from_params(const ImprovedConfig& base, const Json& params);
/// hga-aco-cin: the GA's parameters unprefixed, the colony's with "aco_", and `conversion_form`,
/// `conversion`, `elite_share`. Spec: cin2021.plan.hga-aco ("Parameters").
[[nodiscard]] Json to_params(const CinConfig& c);
[[nodiscard]] CinConfig from_params(const CinConfig& base, const Json& params);

/// The traditional hybrid (spec shi2022.plan.hybrid): Ant System, then the single GA whose
/// initial population is the colony's distinct paths, shortest first. Result: the GA's best;
/// curves = the colony's T iterations then the GA's M_g generations; extra.phase = "aco" | "ga".
/// Spec: shi2022.plan.hybrid
/// Pre: req.grid set (UsageError); start, goal in bounds and free (DomainError).
/// Post: found => path valid under req.policy.
[[nodiscard]] planners::Result run_traditional(const planners::Request& req,
                                               const TraditionalConfig& c, rng::Stream& stream);

/// The improved hybrid (spec shi2022.plan.iha, Shi Sec. 4.4.3 steps 1-9). extra.phase = "aco" |
/// "ga" (which phase produced the final best), extra.best_origin, extra.best_generation.
/// Spec: shi2022.plan.iha
/// Pre: as run_traditional. Post: found => path valid under req.policy.
[[nodiscard]] planners::Result run_improved(const planners::Request& req, const ImprovedConfig& c,
                                            rng::Stream& stream);

/// HGA-ACO (spec cin2021.plan.hga-aco): the whole ga-cin run, the Eq. 28 conversion of the top
/// ceil(elite_share M) of its last generation (by fitness, stable) into the initial pheromone,
/// then the whole aco-cin run from it, on one stream. Result: the ACO phase's best; curves = the
/// GA's generations then the colony's iterations; extra: phase_lengths {ga, aco}, ga_best_length,
/// best_iteration (ACO phase), converted_rows, converted_edges, dead_angle_table, draws.
/// Source: cin2021 Sec. 5.2, 5.4, Figure 7, doi:10.1155/2021/8025730.
/// Spec: cin2021.plan.hga-aco
/// Pre: req.grid set (UsageError); start, goal in bounds and free (DomainError).
/// Post: found => path valid under req.policy.
[[nodiscard]] planners::Result run_cin(const planners::Request& req, const CinConfig& c,
                                       rng::Stream& stream);

}  // namespace pathref::hybrid

namespace pathref::planners {

/// Planner "hybrid-ga-aco". Spec: shi2022.plan.hybrid
[[nodiscard]] Planner make_hybrid_ga_aco_planner();
/// Planner "iha". Spec: shi2022.plan.iha
[[nodiscard]] Planner make_iha_planner();
/// Planner "hga-aco-cin": cin2021 HGA-ACO. Spec: cin2021.plan.hga-aco
[[nodiscard]] Planner make_hga_aco_cin_planner();

}  // namespace pathref::planners
