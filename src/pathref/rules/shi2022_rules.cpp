// JSON adapters for the shi2022.* rules (spec/shi2022.md). Each adapter only converts JSON to the
// arguments of the functions in equations/ and grid/, and their results back to JSON.
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/aco.hpp"
#include "pathref/equations/ga.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/equations/proportional.hpp"
#include "pathref/equations/shi2022.hpp"
#include "pathref/grid/coords.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {

Json numbers(const std::vector<double>& v) {
  Json out = Json::array();
  for (const double x : v) out.push_back(number(x));
  return out;
}

grid::Cell cell_arg(const Json& in, const char* key) { return grid::cell_from_json(arg(in, key)); }

std::vector<grid::Cell> path_arg(const Json& in, const char* key) {
  return grid::path_from_json(arg(in, key));
}

double opt_number(const Json& in, const char* key, double fallback) {
  return (in.is_object() && in.contains(key)) ? arg_number(in, key) : fallback;
}

const char* band_name(ga::TurnBand b) {
  switch (b) {
    case ga::TurnBand::straight:
      return "straight";
    case ga::TurnBand::up_to_45:
      return "up_to_45";
    case ga::TurnBand::up_to_90:
      return "up_to_90";
    case ga::TurnBand::above_90:
      return "above_90";
  }
  return "?";
}

void register_aco(Registry& r) {
  r.add(Rule{
      "shi2022.eq2",
      "Transition probabilities P_ij = tau^alpha eta^beta / sum over allowed_k (Shi Eq. 2)",
      "pathref::aco::transition_weights, pathref::aco::transition_probabilities, "
      "pathref::equations::proportional_probabilities",
      {{"tau", "number[]", "pheromone tau_is of each allowed candidate s, canonical order"},
       {"eta", "number[]", "heuristic eta_is of each allowed candidate (Eq. 3 or Eq. 12)"},
       {"alpha", "number", "pheromone exponent (Table 1: 1)"},
       {"beta", "number", "heuristic exponent (Table 1: 7)"}},
      {{"weights", "number[]", "tau^alpha eta^beta per candidate (what rng::roulette draws on)"},
       {"p", "number[]", "the probabilities, weights / their left-to-right sum"}},
      [](const Json& in) {
        const auto tau = arg_numbers(in, "tau");
        const auto eta = arg_numbers(in, "eta");
        const double alpha = arg_number(in, "alpha");
        const double beta = arg_number(in, "beta");
        const auto w = aco::transition_weights(tau, eta, alpha, beta);
        const auto p = equations::proportional_probabilities(w);
        return Json{{"weights", numbers(w)}, {"p", numbers(p)}};
      }});
  r.add(Rule{
      "shi2022.eq3",
      "Distance heuristic eta_ij = 1/d_ij between cell centres (Shi Eq. 3)",
      "pathref::aco::eta_inverse_distance",
      {{"i", "cell", "current cell [x, y]"}, {"j", "cell", "next (candidate) cell [x, y], != i"}},
      {{"eta", "number", "1 / d_ij"}},
      [](const Json& in) {
        return Json{{"eta", number(aco::eta_inverse_distance(cell_arg(in, "i"), cell_arg(in, "j")))}};
      }});
  r.add(Rule{
      "shi2022.eq4",
      "Euclidean distance d_ij between the centres of two cells (Shi Eq. 4)",
      "pathref::metrics::centre_distance",
      {{"i", "cell", "a cell [x, y]"}, {"j", "cell", "a cell [x, y]"}},
      {{"d", "number", "sqrt((x_i - x_j)^2 + (y_i - y_j)^2)"}},
      [](const Json& in) {
        return Json{{"d", number(metrics::centre_distance(cell_arg(in, "i"), cell_arg(in, "j")))}};
      }});
  r.add(Rule{
      "shi2022.eq5",
      "Pheromone update tau(t+1) = (1 - rho) tau(t) + delta tau (Shi Eq. 5)",
      "pathref::aco::pheromone_update",
      {{"tau", "number", "tau_ij(t) >= 0"},
       {"rho", "number", "evaporation rate in (0, 1)"},
       {"delta", "number", "delta tau_ij(t) >= 0 (Eq. 6)"}},
      {{"tau_next", "number", "((1 - rho) * tau) + delta"}},
      [](const Json& in) {
        return Json{{"tau_next", number(aco::pheromone_update(arg_number(in, "tau"),
                                                              arg_number(in, "rho"),
                                                              arg_number(in, "delta")))}};
      }});
  r.add(Rule{
      "shi2022.eq6",
      "Total deposit on an edge: sum over ants of delta tau^k, left to right (Shi Eq. 6)",
      "pathref::aco::total_deposit",
      {{"deposits", "number[]", "delta tau_ij^k for k = 1..m, in ant order (may be empty)"}},
      {{"delta", "number", "their left-to-right sum"}},
      [](const Json& in) {
        return Json{{"delta", number(aco::total_deposit(arg_numbers(in, "deposits")))}};
      }});
  r.add(Rule{
      "shi2022.eq7",
      "Ant-cycle deposit Q/L_k on an edge the ant's path goes by, else 0 (Shi Eq. 7)",
      "pathref::aco::edge_deposit, pathref::aco::ant_cycle_deposit",
      {{"Q", "number", "pheromone intensity > 0 (Table 1: 1)"},
       {"path", "path", "ant k's path, >= 2 nodes, no consecutive repeats"},
       {"from", "cell", "the edge's first cell i"},
       {"to", "cell", "the edge's second cell j"},
       {"edge_sense", "string", "directed (default) | undirected"},
       {"edge_repeats", "string", "once (default) | per_traversal"}},
      {{"deposit", "number", "delta tau_ij^k"}, {"L", "number", "L_k = metrics.length of the path"}},
      [](const Json& in) {
        const auto path = path_arg(in, "path");
        const auto sense = aco::parse_edge_sense(opt_string(in, "edge_sense", "directed"));
        const auto repeats = aco::parse_edge_repeats(opt_string(in, "edge_repeats", "once"));
        const double d = aco::edge_deposit(path, cell_arg(in, "from"), cell_arg(in, "to"),
                                           arg_number(in, "Q"), sense, repeats);
        return Json{{"deposit", number(d)}, {"L", number(metrics::path_length(path))}};
      }});
  r.add(Rule{
      "shi2022.eq12",
      "Goal-directed heuristic eta_ij = 1/(d_ij + d_jE) (Shi Eq. 12)",
      "pathref::aco::eta_goal_directed",
      {{"i", "cell", "current cell"}, {"j", "cell", "next (candidate) cell, != i"},
       {"goal", "cell", "target cell E"}},
      {{"eta", "number", "1 / (d_ij + d_jE)"}},
      [](const Json& in) {
        return Json{{"eta", number(aco::eta_goal_directed(cell_arg(in, "i"), cell_arg(in, "j"),
                                                          cell_arg(in, "goal")))}};
      }});
  r.add(Rule{
      "shi2022.eq13",
      "Adaptive evaporation factor rho(t+1) from rho(t), with floor rho_min (Shi Eq. 13)",
      "pathref::aco::adaptive_rho",
      {{"rho", "number", "rho(t) in (0, 1)"},
       {"t", "integer", "current iteration, 0 <= t <= T"},
       {"T", "integer", "total number of iterations (Table 1: 100)"},
       {"rho_min", "number", "floor in [0, 1) (Table 1: 0.1; 0 = IACO*, no floor)"},
       {"steps", "integer", "optional: apply the update this many times (t, t+1, ...)"},
       {"rho_reading", "string", "factor (default) | condition | clamp"}},
      {{"rho_next", "number", "rho(t+1)"},
       {"sequence", "number[]", "with steps: rho(t+1), ..., rho(t+steps)"}},
      [](const Json& in) {
        const auto reading = aco::parse_rho_reading(opt_string(in, "rho_reading", "factor"));
        double rho = arg_number(in, "rho");
        const long long t = arg_integer(in, "t");
        const long long T = arg_integer(in, "T");
        const double rho_min = arg_number(in, "rho_min");
        Json out = Json::object();
        out["rho_next"] = number(aco::adaptive_rho(rho, t, T, rho_min, reading));
        if (in.contains("steps")) {
          const long long steps = arg_integer(in, "steps");
          require(steps >= 1 && t + steps - 1 <= T, "steps must lie in [1, T - t + 1]");
          Json seq = Json::array();
          for (long long s = 0; s < steps; ++s) {
            rho = aco::adaptive_rho(rho, t + s, T, rho_min, reading);
            seq.push_back(number(rho));
          }
          out["sequence"] = seq;
        }
        return out;
      }});
}

void register_ga(Registry& r) {
  r.add(Rule{
      "shi2022.eq8",
      "Continuity Delta = max(|dx|, |dy|) of two genes; continuous iff Delta = 1 (Shi Eq. 8)",
      "pathref::ga::continuity_delta, pathref::ga::is_continuous",
      {{"a", "cell", "gene (x_i, y_i)"}, {"b", "cell", "gene (x_{i+1}, y_{i+1})"}},
      {{"delta", "integer", "Delta"}, {"continuous", "bool", "Delta == 1"}},
      [](const Json& in) {
        const auto a = cell_arg(in, "a");
        const auto b = cell_arg(in, "b");
        return Json{{"delta", ga::continuity_delta(a, b)}, {"continuous", ga::is_continuous(a, b)}};
      }});
  r.add(Rule{
      "shi2022.eq9",
      "Mid-point insertion x' = int[(x_i + x_{i+1})/2], y' likewise, and its number P' (Shi Eq. 9)",
      "pathref::ga::insertion_cell, pathref::ga::insertion_number",
      {{"a", "cell", "gene (x_i, y_i), inside the grid"},
       {"b", "cell", "gene (x_{i+1}, y_{i+1}), inside the grid"},
       {"width", "integer", "grid width W"},
       {"height", "integer", "grid height H"},
       {"mid_rounding", "string", "floor (default) | ceil | half_even"},
       {"mid_number", "string", "row_major (default) | printed_sum"}},
      {{"cell", "cell", "(x', y')"}, {"number", "integer", "P'"}},
      [](const Json& in) {
        const auto a = cell_arg(in, "a");
        const auto b = cell_arg(in, "b");
        const auto rounding = ga::parse_mid_rounding(opt_string(in, "mid_rounding", "floor"));
        const auto form = ga::parse_mid_number(opt_string(in, "mid_number", "row_major"));
        const auto n = ga::insertion_number(a, b, arg_integer(in, "width"), arg_integer(in, "height"),
                                            rounding, form);
        return Json{{"cell", grid::cell_to_json(ga::insertion_cell(a, b, rounding))},
                    {"number", n}};
      }});
  r.add(Rule{
      "shi2022.eq10",
      "Traditional GA fitness fit = 1/length (Shi Eq. 10)",
      "pathref::ga::inverse_length",
      {{"length", "number", "path length > 0 (metrics.length)"}},
      {{"fit", "number", "1 / length"}},
      [](const Json& in) {
        return Json{{"fit", number(ga::inverse_length(arg_number(in, "length")))}};
      }});
  r.add(Rule{
      "shi2022.eq11",
      "Roulette selection probability p_i = F_i / sum F (Shi Eq. 11)",
      "pathref::equations::proportional_probabilities",
      {{"fitness", "number[]", "F_1..F_n, finite, >= 0, positive sum"}},
      {{"p", "number[]", "F_i / (left-to-right sum of F)"}},
      [](const Json& in) {
        return Json{{"p", numbers(equations::proportional_probabilities(arg_numbers(in, "fitness")))}};
      }});
  r.add(Rule{
      "shi2022.eq14",
      "Weighted fitness a fit_1 + b fit_2 + c fit_3 (Shi Eq. 14)",
      "pathref::ga::weighted_fitness",
      {{"fit1", "number", "length factor (Eq. 15)"},
       {"fit2", "number", "smoothness factor (Eq. 16)"},
       {"fit3", "number", "safety factor (Eq. 18)"},
       {"a", "number", "optional, default 5 (Table 1)"},
       {"b", "number", "optional, default 4 (Table 1)"},
       {"c", "number", "optional, default 1 (Table 1)"}},
      {{"fit", "number", "((a*fit1) + (b*fit2)) + (c*fit3)"}},
      [](const Json& in) {
        const ga::FitnessWeights w{opt_number(in, "a", shi2022::table1.a),
                                   opt_number(in, "b", shi2022::table1.b),
                                   opt_number(in, "c", shi2022::table1.c)};
        return Json{{"fit", number(ga::weighted_fitness(arg_number(in, "fit1"), arg_number(in, "fit2"),
                                                        arg_number(in, "fit3"), w))}};
      }});
  r.add(Rule{
      "shi2022.eq15",
      "Length factor fit_1 = 1/length (Shi Eq. 15)",
      "pathref::ga::inverse_length",
      {{"length", "number", "path length > 0 (metrics.length)"}},
      {{"fit1", "number", "1 / length"}},
      [](const Json& in) {
        return Json{{"fit1", number(ga::inverse_length(arg_number(in, "length")))}};
      }});
  r.add(Rule{
      "shi2022.eq16",
      "Smoothness factor fit_2 from the turning bands with penalties 5/100/1000 (Shi Eq. 16)",
      "pathref::ga::smoothness_factor",
      {{"path", "path", "the path (metrics path domain)"},
       {"penalties", "number[]", "optional [P_45, P_90, P_180], default [5, 100, 1000]"},
       {"smoothness", "string",
        "inverse_total_plus_one (default) | per_node | per_turn | angle_times_penalty | inverse_total"}},
      {{"fit2", "number", "the smoothness factor"}},
      [](const Json& in) {
        ga::TurnPenalties p{};
        if (in.contains("penalties")) {
          const auto v = arg_numbers(in, "penalties");
          if (v.size() != 3) throw UsageError("penalties must be [P_45, P_90, P_180]");
          p = ga::TurnPenalties{v[0], v[1], v[2]};
        }
        const auto reading = ga::parse_smoothness_reading(opt_string(in, "smoothness", "inverse_total_plus_one"));
        return Json{{"fit2", number(ga::smoothness_factor(path_arg(in, "path"), reading, p))}};
      }});
  r.add(Rule{
      "shi2022.eq17",
      "Turning angle theta at each interior node and its penalty band (Shi Eq. 17)",
      "pathref::metrics::turning_angles, pathref::ga::turn_band",
      {{"path", "path", "the path (metrics path domain)"}},
      {{"theta", "number[]", "turning angle (radians) at nodes 1..n-2"},
       {"band", "string[]", "straight | up_to_45 | up_to_90 | above_90 per interior node"}},
      [](const Json& in) {
        const auto path = path_arg(in, "path");
        const auto theta = metrics::turning_angles(path);
        Json bands = Json::array();
        for (std::size_t k = 1; k + 1 < path.size(); ++k)
          bands.push_back(band_name(ga::turn_band(path[k - 1], path[k], path[k + 1])));
        return Json{{"theta", numbers(theta)}, {"band", bands}};
      }});
  r.add(Rule{
      "shi2022.eq18",
      "Safety factor fit_3 from obstacles among the 8 neighbours (Shi Eq. 18): 1/(1 + total) by default",
      "pathref::ga::safety_factor",
      {{"grid", "grid", "rows top first"},
       {"path", "path", "the path, every node inside the grid"},
       {"safety_aggregate", "string", "inverse_total_plus_one (default) | per_node (as printed) | mean"},
       {"safety_count", "string", "count (default) | indicator"},
       {"safe_node", "string", "one (default) | skip (per_node and mean only)"},
       {"safety_nodes", "string", "all_but_goal (default) | all | interior"},
       {"outside", "string", "free (default) | blocked (metrics.safety)"}},
      {{"fit3", "number", "the safety factor"}},
      [](const Json& in) {
        const ga::SafetyOptions o{
            ga::parse_safety_aggregate(opt_string(in, "safety_aggregate", "inverse_total_plus_one")),
            ga::parse_safety_count(opt_string(in, "safety_count", "count")),
            ga::parse_safe_node(opt_string(in, "safe_node", "one")),
            ga::parse_safety_nodes(opt_string(in, "safety_nodes", "all_but_goal")),
            metrics::parse_outside_cells(opt_string(in, "outside", "free"))};
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        return Json{{"fit3", number(ga::safety_factor(g, path_arg(in, "path"), o))}};
      }});
  r.add(Rule{
      "shi2022.eq19",
      "Adaptive crossover probability P_c(i) = cos(pi/2 * i/(M_g + i)) (Shi Eq. 19)",
      "pathref::ga::adaptive_pc",
      {{"i", "integer", "current generation, 0 <= i <= M_g"},
       {"M_g", "integer", "maximum number of generations (Table 1: 50)"},
       {"pc_reading", "string", "printed (default) | scaled (times Table 1's P_c = 0.8)"}},
      {{"pc", "number", "P_c(i)"}},
      [](const Json& in) {
        const std::string reading = opt_string(in, "pc_reading", "printed");
        if (reading != "printed" && reading != "scaled")
          throw UsageError("pc_reading must be printed or scaled");
        const double scale = reading == "scaled" ? shi2022::table1.pc : 1.0;
        return Json{{"pc", number(ga::adaptive_pc(arg_integer(in, "i"), arg_integer(in, "M_g"), scale))}};
      }});
  r.add(Rule{
      "shi2022.eq20",
      "Adaptive mutation probability P_m(i) = cos(pi/2 (M_g - i)/(M_g + i)) capped at P_m_max (Shi Eq. 20)",
      "pathref::ga::adaptive_pm",
      {{"i", "integer", "current generation, 0 <= i <= M_g"},
       {"M_g", "integer", "maximum number of generations (Table 1: 50)"},
       {"pm_max", "number", "cap P_m_max in (0, 1] (Table 1: 0.3)"},
       {"pm_reading", "string", "printed (default) | scaled (times Table 1's P_m = 0.1)"},
       {"pm_at_zero", "string", "binary64 (default) | exact_zero"}},
      {{"pm", "number", "P_m(i)"}},
      [](const Json& in) {
        const std::string reading = opt_string(in, "pm_reading", "printed");
        if (reading != "printed" && reading != "scaled")
          throw UsageError("pm_reading must be printed or scaled");
        const double scale = reading == "scaled" ? shi2022::table1.pm : 1.0;
        const auto at_zero = ga::parse_pm_at_zero(opt_string(in, "pm_at_zero", "binary64"));
        return Json{{"pm", number(ga::adaptive_pm(arg_integer(in, "i"), arg_integer(in, "M_g"),
                                                  arg_number(in, "pm_max"), scale, at_zero))}};
      }});
}

}  // namespace

void register_shi2022_rules(Registry& r) {
  r.add(Rule{
      "shi2022.table1",
      "Table 1 parameters of Shi et al. 2022 (ACO and GA parts)",
      "pathref::shi2022::table1",
      {},
      {{"ants", "integer", "m"}, {"aco_iterations", "integer", "T"}, {"alpha", "number", ""},
       {"beta", "number", ""}, {"Q", "number", ""}, {"rho_initial", "number", ""},
       {"rho_min", "number", ""}, {"ga_population", "integer", ""},
       {"ga_generations", "integer", "M_g"}, {"a", "number", ""}, {"b", "number", ""},
       {"c", "number", ""}, {"pc", "number", ""}, {"pm", "number", ""}, {"pm_max", "number", ""}},
      [](const Json&) {
        const auto& t = shi2022::table1;
        return Json{{"ants", t.ants},
                    {"aco_iterations", t.aco_iterations},
                    {"alpha", t.alpha},
                    {"beta", t.beta},
                    {"Q", t.Q},
                    {"rho_initial", t.rho_initial},
                    {"rho_min", t.rho_min},
                    {"ga_population", t.ga_population},
                    {"ga_generations", t.ga_generations},
                    {"a", t.a},
                    {"b", t.b},
                    {"c", t.c},
                    {"pc", t.pc},
                    {"pm", t.pm},
                    {"pm_max", t.pm_max}};
      }});
  r.add(Rule{
      "shi2022.eq1",
      "Grid coordinates of cell number i (Shi Eq. 1, corrected; printed forms selectable)",
      "pathref::grid::cell_centre",
      {{"i", "integer", "0-based cell number (S = 0)"},
       {"width", "integer", "W (the paper's N)"},
       {"height", "integer", "H"},
       {"form", "string", "corrected (default) | printed0 | printed1"}},
      {{"x", "number", "centre x"}, {"y", "number", "centre y"}},
      [](const Json& in) {
        const auto form = grid::parse_eq1_form(opt_string(in, "form", "corrected"));
        const grid::Point p = grid::cell_centre(arg_integer(in, "i"), arg_integer(in, "width"),
                                                arg_integer(in, "height"), form);
        return Json{{"x", number(p.x)}, {"y", number(p.y)}};
      }});
  register_aco(r);
  register_ga(r);
}

}  // namespace pathref::rules
