/// \file aco_planners.cpp
/// The registered ant-colony planners (aco, iaco-shi, iaco-shi-nomin, iaco-han) and astar-han:
/// each is a preset of ant_colony::Config (resp. search::astar with the Chebyshev heuristic),
/// parameters merged with planners::merge_params, one rng::Stream seeded with the request's seed.
/// Spec: spec/shi2022-aco.md, spec/han-iaco.md
#include <string>
#include <utility>

#include "pathref/core/error.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/planners/ant_colony.hpp"
#include "pathref/planners/search.hpp"

namespace pathref::planners {

namespace {

Planner colony_planner(std::string name, std::string description, ant_colony::Config (*preset)()) {
  Planner p;
  p.name = std::move(name);
  p.description = std::move(description);
  p.defaults = ant_colony::to_params(preset());
  p.bytes_per_cell = ant_colony::bytes_per_cell;
  p.run = [defaults = p.defaults, preset](const Request& req) {
    if (req.grid == nullptr) throw UsageError("plan request without a grid");
    const Json params = merge_params(defaults, req.params);
    const ant_colony::Config cfg = ant_colony::from_params(preset(), params);
    rng::Stream stream(req.seed);
    stream.set_trace(req.trace);
    ant_colony::Run r = ant_colony::run(req, cfg, stream);
    r.result.extra["seed"] = req.seed;
    return std::move(r.result);
  };
  return p;
}

}  // namespace

Planner make_aco_planner() {
  return colony_planner(
      "aco",
      "Ant System (Shi et al. 2022 Sec. 4.1, Eq. 2-7, eta = 1/d; Table 1), spec/shi2022-aco.md",
      &ant_colony::shi_aco);
}

Planner make_iaco_shi_planner() {
  return colony_planner(
      "iaco-shi",
      "improved ACO (Shi et al. 2022 Sec. 4.4.1: Eq. 12 eta, Eq. 13 adaptive rho with rho_min), "
      "spec/shi2022-aco.md",
      &ant_colony::shi_iaco);
}

Planner make_iaco_shi_nomin_planner() {
  return colony_planner(
      "iaco-shi-nomin",
      "IACO* (Shi et al. 2022 Sec. 5.1: iaco-shi without rho_min), spec/shi2022-aco.md",
      &ant_colony::shi_iaco_nomin);
}

Planner make_aco_classic_planner() {
  return colony_planner(
      "aco-classic",
      "the classic MATLAB ant-colony grid script (eta = 1/d(j, goal), tau0 8, rho 0.3, beta 7, "
      "100 x 50 ants, deposit both ways; corner policy always by default), spec/classic.md",
      &ant_colony::classic_aco);
}

Planner make_aco_cin_planner() {
  return colony_planner(
      "aco-cin",
      "optimised ACO of cin2021 Sec. 5.5 (Eq. 29-35: iteration-best/global-best deposits with "
      "weights N-t, t; dead-angle table), spec/cin2021-hga-aco.md",
      &ant_colony::cin_aco);
}

Planner make_iaco_han_planner() {
  return colony_planner(
      "iaco-han",
      "improved ACO of Han (IJACSA) Eq. 1-7: corner heuristic, pseudo-random rule with adaptive "
      "q0, elite deposit, stepped rho; spec/han-iaco.md",
      &ant_colony::han_iaco);
}

Planner make_astar_han_planner() {
  Planner p;
  p.name = "astar-han";
  p.description =
      "8-direction A* with the Chebyshev heuristic (Han (IJACSA) Sec. III.B, Eq. 8), "
      "spec/han-iaco.md";
  p.defaults = Json{{"h_form", "chebyshev"}};
  p.bytes_per_cell = search::bytes_per_cell;
  p.run = [defaults = p.defaults](const Request& req) {
    if (req.grid == nullptr) throw UsageError("plan request without a grid");
    Json params = merge_params(defaults, req.params);
    const std::string form = params.at("h_form").get<std::string>();
    if (form != "chebyshev" && form != "octile")
      throw UsageError("h_form must be chebyshev or octile, not '" + form + "'");
    const auto h = heuristics::parse_heuristic(form);
    search::require_memory(req, *req.grid, "astar-han");
    search::Outcome o = search::astar(*req.grid, req.start, req.goal, req.policy, h);
    Result r;
    r.found = o.found;
    r.path = std::move(o.path);
    r.length = o.length;
    r.expansions = o.expansions;
    r.params_used = std::move(params);
    r.extra = Json{{"heuristic", form},
                   {"admissible", heuristics::admissible(h, req.policy)},
                   {"consistent", heuristics::consistent(h, req.policy)}};
    return r;
  };
  return p;
}

}  // namespace pathref::planners
