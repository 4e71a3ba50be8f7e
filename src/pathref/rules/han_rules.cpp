// JSON adapters for the han.* rules (spec/han.md). Each adapter only converts JSON to the
// arguments of the functions in equations/, and their results back to JSON.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "pathref/core/error.hpp"
#include "pathref/equations/aco.hpp"
#include "pathref/equations/aco_adaptive.hpp"
#include "pathref/equations/corner.hpp"
#include "pathref/equations/han.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/pseudo_random.hpp"
#include "pathref/equations/rls.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {

Json numbers(const std::vector<double>& v) {
  Json out = Json::array();
  for (const double x : v) out.push_back(number(x));
  return out;
}

Json vec2(const Eigen::Vector2d& v) { return Json::array({number(v(0)), number(v(1))}); }

Json mat2(const Eigen::Matrix2d& m) {
  return Json::array({Json::array({number(m(0, 0)), number(m(0, 1))}),
                      Json::array({number(m(1, 0)), number(m(1, 1))})});
}

Eigen::Vector2d vec2_arg(const Json& in, const char* key) {
  const auto v = arg_numbers(in, key);
  if (v.size() != 2) throw UsageError(std::string(key) + " must be a pair [p0, p1]");
  return Eigen::Vector2d(v[0], v[1]);
}

grid::Cell cell_arg(const Json& in, const char* key) { return grid::cell_from_json(arg(in, key)); }

bool bool_arg(const Json& in, const char* key) {
  const Json& v = arg(in, key);
  if (!v.is_boolean()) throw UsageError(std::string(key) + " must be true or false");
  return v.get<bool>();
}

void register_aco_part(Registry& r) {
  r.add(Rule{
      "han.eq1",
      "Transition probabilities with the corner heuristic, tau^alpha eta^beta omega^gamma / sum (Han Eq. 1)",
      "pathref::aco::transition_weights, pathref::aco::transition_probabilities",
      {{"tau", "number[]", "pheromone of each allowed candidate, canonical order"},
       {"eta", "number[]", "heuristic of each allowed candidate"},
       {"omega", "number[]", "corner heuristic of each allowed candidate (Eq. 2)"},
       {"alpha", "number", "pheromone exponent (paper: 4)"},
       {"beta", "number", "heuristic exponent (paper: 8)"},
       {"gamma", "number", "corner exponent (pathref's choice: 1)"}},
      {{"weights", "number[]", "(tau^alpha eta^beta) omega^gamma per candidate"},
       {"p", "number[]", "weights / their left-to-right sum"}},
      [](const Json& in) {
        const auto tau = arg_numbers(in, "tau");
        const auto eta = arg_numbers(in, "eta");
        const auto omega = arg_numbers(in, "omega");
        const aco::CornerFactor cf{omega, arg_number(in, "gamma")};
        const double alpha = arg_number(in, "alpha");
        const double beta = arg_number(in, "beta");
        const auto w = aco::transition_weights(tau, eta, alpha, beta, cf);
        const auto p = aco::transition_probabilities(tau, eta, alpha, beta, cf);
        return Json{{"weights", numbers(w)}, {"p", numbers(p)}};
      }});
  r.add(Rule{
      "han.eq2",
      "Corner heuristic omega_ij = omega_i T (reading multiply) or omega_i / T (divide) (Han Eq. 2)",
      "pathref::corner::corner_heuristic",
      {{"omega_i", "number", "adjustable parameter in (0, 1)"},
       {"T", "integer", "turning cost of Eq. 3, 1 or 2"},
       {"omega_form", "string", "multiply (default) | divide"}},
      {{"omega", "number", "omega_ij"}},
      [](const Json& in) {
        const auto form = corner::parse_omega_form(opt_string(in, "omega_form", "multiply"));
        const long long T = arg_integer(in, "T");
        require(T == 1 || T == 2, "the turning cost T must be 1 or 2");
        return Json{{"omega", number(corner::corner_heuristic(arg_number(in, "omega_i"),
                                                              static_cast<int>(T), form))}};
      }});
  r.add(Rule{
      "han.eq3",
      "Turning cost T = 2 for theta <= 90 deg, 1 above, of the move cur -> next (Han Eq. 3)",
      "pathref::corner::turning_cost",
      {{"prev", "cell", "optional: the cell the ant came from (absent or null: first move)"},
       {"cur", "cell", "current cell"},
       {"next", "cell", "candidate cell"},
       {"omega_form", "string", "multiply (default: theta = heading change) | divide (interior angle)"},
       {"at90", "string", "two (default) | one: the T of theta = 90 deg"}},
      {{"T", "integer", "1 or 2"}},
      [](const Json& in) {
        const auto form = corner::parse_omega_form(opt_string(in, "omega_form", "multiply"));
        const auto at90 = corner::parse_at90(opt_string(in, "at90", "two"));
        std::optional<grid::Cell> prev;
        if (in.contains("prev") && !in.at("prev").is_null()) prev = cell_arg(in, "prev");
        return Json{{"T", corner::turning_cost(prev, cell_arg(in, "cur"), cell_arg(in, "next"),
                                               form, at90)}};
      }});
  r.add(Rule{
      "han.eq4",
      "Pseudo-random proportional choice: argmax if q <= q0, else roulette with draw u (Han Eq. 4)",
      "pathref::aco::pseudo_random_choice, pathref::aco::argmax_weight",
      {{"weights", "number[]", "Eq. 1 weights of the allowed candidates, canonical order"},
       {"q", "number", "draw in [0, 1)"},
       {"q0", "number", "threshold in [0, 1] (Eq. 5)"},
       {"u", "number", "roulette draw in [0, 1), used only when q > q0"}},
      {{"index", "integer", "position of the chosen candidate"},
       {"mode", "string", "argmax | roulette"}},
      [](const Json& in) {
        const auto c = aco::pseudo_random_choice(arg_numbers(in, "weights"), arg_number(in, "q"),
                                                 arg_number(in, "q0"), arg_number(in, "u"));
        return Json{{"index", c.index},
                    {"mode", c.mode == aco::ChoiceMode::argmax ? "argmax" : "roulette"}};
      }});
  r.add(Rule{
      "han.eq5",
      "Adaptive threshold q0 = epsilon (0.2 + 0.7 (N_max - N_c)/N_max) (Han Eq. 5)",
      "pathref::aco::adaptive_q0",
      {{"epsilon", "number", "adjustment coefficient > 0 (pathref's choice: 1)"},
       {"N_c", "integer", "current iteration, 0 <= N_c <= N_max"},
       {"N_max", "integer", "maximum number of iterations (paper: 50)"}},
      {{"q0", "number", "epsilon * (0.2 + (r * 0.7)), r = (N_max - N_c) / N_max"}},
      [](const Json& in) {
        return Json{{"q0", number(aco::adaptive_q0(arg_number(in, "epsilon"), arg_integer(in, "N_c"),
                                                   arg_integer(in, "N_max")))}};
      }});
  r.add(Rule{
      "han.eq6",
      "Pheromone update with elite term h (L_a - L_n)/L_n on the best path's edges, floored (Han Eq. 6)",
      "pathref::aco::pheromone_update_elite, pathref::aco::elite_bonus",
      {{"tau", "number", "tau_ij(t) >= 0"},
       {"rho", "number", "evaporation factor in (0, 1) (Eq. 7)"},
       {"delta", "number", "ant-cycle deposit sum >= 0 (Shi Eq. 6-7)"},
       {"h", "number", "elite coefficient >= 0 (pathref's choice: 1)"},
       {"L_a", "number", "best length before this iteration > 0"},
       {"L_n", "number", "best length of this iteration > 0"},
       {"tau_min", "number", "floor > 0 (pathref's choice: 0.01)"},
       {"on_best_path", "bool", "whether (i, j) is an edge of this iteration's best path"},
       {"bonus_edges", "string", "best_path (default) | all_edges"}},
      {{"bonus", "number", "the elite term applied to this edge (0 off the best path)"},
       {"tau_next", "number", "max(((1 - rho) tau + delta) + bonus, tau_min)"}},
      [](const Json& in) {
        const std::string edges = opt_string(in, "bonus_edges", "best_path");
        if (edges != "best_path" && edges != "all_edges")
          throw UsageError("bonus_edges must be best_path or all_edges");
        const double full = aco::elite_bonus(arg_number(in, "h"), arg_number(in, "L_a"),
                                             arg_number(in, "L_n"));
        const bool on = bool_arg(in, "on_best_path") || edges == "all_edges";
        const double bonus = on ? full : 0.0;
        const double next = aco::pheromone_update_elite(
            arg_number(in, "tau"), arg_number(in, "rho"), arg_number(in, "delta"), bonus,
            arg_number(in, "tau_min"));
        return Json{{"bonus", number(bonus)}, {"tau_next", number(next)}};
      }});
  r.add(Rule{
      "han.eq7",
      "Stepped evaporation rho(t) = 0.9/0.8/0.7 rho(t-1) by the spread L_A - L_n, floored (Han Eq. 7)",
      "pathref::aco::stepped_rho",
      {{"rho", "number", "rho(t-1) in (0, 1) (paper: rho(0) = 0.7)"},
       {"L_ref", "number", "L_A, this iteration's worst length (or L_a under history_best)"},
       {"L_n", "number", "this iteration's best length"},
       {"a", "number", "lower threshold >= 0 (pathref's choice: 1)"},
       {"b", "number", "upper threshold > a (pathref's choice: 5)"},
       {"rho_min", "number", "floor in [0, 1) (pathref's choice: 0.1)"},
       {"spread_reference", "string", "iteration_worst (default) | history_best"}},
      {{"rho_next", "number", "rho(t)"}},
      [](const Json& in) {
        const auto ref =
            aco::parse_spread_reference(opt_string(in, "spread_reference", "iteration_worst"));
        return Json{{"rho_next", number(aco::stepped_rho(
                                     arg_number(in, "rho"), arg_number(in, "L_ref"),
                                     arg_number(in, "L_n"), arg_number(in, "a"),
                                     arg_number(in, "b"), arg_number(in, "rho_min"), ref))}};
      }});
  r.add(Rule{
      "han.eq8",
      "A* heuristic h(n) = max(|n_x - g_x|, |n_y - g_y|) (Han Eq. 8; octile selectable)",
      "pathref::heuristics::chebyshev, pathref::heuristics::octile",
      {{"n", "cell", "current node"},
       {"g", "cell", "goal node"},
       {"h_form", "string", "chebyshev (default, as printed) | octile"}},
      {{"h", "number", "h(n)"}},
      [](const Json& in) {
        const std::string form = opt_string(in, "h_form", "chebyshev");
        if (form != "chebyshev" && form != "octile")
          throw UsageError("h_form must be chebyshev or octile");
        const auto n = cell_arg(in, "n");
        const auto g = cell_arg(in, "g");
        return Json{{"h", number(form == "chebyshev" ? heuristics::chebyshev(n, g)
                                                     : heuristics::octile(n, g))}};
      }});
}

void register_rls_part(Registry& r) {
  r.add(Rule{
      "han.eq9",
      "Linear motion of a dynamic obstacle x = a t + b, y = c t + d (Han Eq. 9)",
      "pathref::rls::position",
      {{"a", "number", ""}, {"b", "number", ""}, {"c", "number", ""}, {"d", "number", ""},
       {"t", "number", "time"}},
      {{"x", "number", "(a * t) + b"}, {"y", "number", "(c * t) + d"}},
      [](const Json& in) {
        const rls::LinearMotion m{arg_number(in, "a"), arg_number(in, "b"), arg_number(in, "c"),
                                  arg_number(in, "d")};
        const rls::Position p = rls::position(m, arg_number(in, "t"));
        return Json{{"x", number(p.x)}, {"y", number(p.y)}};
      }});
  r.add(Rule{
      "han.eq10",
      "Stacked observations X_n = T_n A_m, Y_n = T_n B_m (Han Eq. 10, '+' read as product)",
      "pathref::rls::stacked",
      {{"t", "number[]", "times t_1..t_n"},
       {"A", "number[]", "[a, b]"},
       {"B", "number[]", "[c, d]"}},
      {{"X", "number[]", "(t_l * a) + b"}, {"Y", "number[]", "(t_l * c) + d"}},
      [](const Json& in) {
        const auto t = arg_numbers(in, "t");
        return Json{{"X", numbers(rls::stacked(t, vec2_arg(in, "A")))},
                    {"Y", numbers(rls::stacked(t, vec2_arg(in, "B")))}};
      }});
  r.add(Rule{
      "han.eq11",
      "Regressor matrix T_n with rows [t_l, 1] (Han Eq. 11)",
      "pathref::rls::regressor_matrix",
      {{"t", "number[]", "times t_1..t_n"}},
      {{"T", "number[][]", "n rows [t_l, 1]"}},
      [](const Json& in) {
        const auto T = rls::regressor_matrix(arg_numbers(in, "t"));
        Json rows = Json::array();
        for (Eigen::Index l = 0; l < T.rows(); ++l)
          rows.push_back(Json::array({number(T(l, 0)), number(T(l, 1))}));
        return Json{{"T", rows}};
      }});
  r.add(Rule{
      "han.eq12",
      "Error vector E_n = [e_1..e_n] of the samples against an estimate (Han Eq. 12)",
      "pathref::rls::residuals",
      {{"t", "number[]", "times"}, {"x", "number[]", "observed x_l"},
       {"A", "number[]", "estimate [a, b]"}},
      {{"E", "number[]", "e_l = x_l - ((t_l * a) + b)"}},
      [](const Json& in) {
        return Json{{"E", numbers(rls::residuals(arg_numbers(in, "t"), arg_numbers(in, "x"),
                                                 vec2_arg(in, "A")))}};
      }});
  r.add(Rule{
      "han.eq13",
      "Residuals E_n = X_n - T_n A_n and Y_n - T_n B_n (Han Eq. 13)",
      "pathref::rls::residuals",
      {{"t", "number[]", "times"}, {"x", "number[]", "observed x_l"}, {"y", "number[]", "observed y_l"},
       {"A", "number[]", "estimate A_n = [a, b]"}, {"B", "number[]", "estimate B_n = [c, d]"}},
      {{"E_x", "number[]", "x_l - ((t_l * a) + b)"}, {"E_y", "number[]", "y_l - ((t_l * c) + d)"}},
      [](const Json& in) {
        const auto t = arg_numbers(in, "t");
        return Json{{"E_x", numbers(rls::residuals(t, arg_numbers(in, "x"), vec2_arg(in, "A")))},
                    {"E_y", numbers(rls::residuals(t, arg_numbers(in, "y"), vec2_arg(in, "B")))}};
      }});
  r.add(Rule{
      "han.eq14",
      "Exponentially weighted cost J_n = sum lambda^(n-l) e_l^2 (Han Eq. 14)",
      "pathref::rls::weighted_cost",
      {{"e", "number[]", "residuals e_1..e_n"}, {"lambda", "number", "forgetting factor in (0, 1]"}},
      {{"J", "number", "J_1 = e_1^2, J_l = (lambda J_{l-1}) + e_l^2"}},
      [](const Json& in) {
        return Json{{"J", number(rls::weighted_cost(arg_numbers(in, "e"), arg_number(in, "lambda")))}};
      }});
  r.add(Rule{
      "han.eq15",
      "Recursive least squares with forgetting factor: init P_m, then gain, update, P/lambda (Han Eq. 15)",
      "pathref::rls::rls_estimate, pathref::rls::rls_init, pathref::rls::rls_step",
      {{"t", "number[]", "times, strictly increasing"},
       {"x", "number[]", "observed x_l"},
       {"y", "number[]", "observed y_l"},
       {"lambda", "number", "forgetting factor in (0, 1] (pathref's choice: 0.95)"},
       {"m", "integer", "optional: samples of the initial batch, 2 <= m <= n (default 2)"},
       {"init_weights", "string", "weighted (default) | unweighted"}},
      {{"A", "number[]", "A_n = [a, b]"},
       {"B", "number[]", "B_n = [c, d]"},
       {"P", "number[][]", "P_n, 2x2, rows"}},
      [](const Json& in) {
        const auto w = rls::parse_init_weights(opt_string(in, "init_weights", "weighted"));
        const long long m = in.contains("m") ? arg_integer(in, "m") : 2;
        require(m >= 2, "m must be >= 2");
        const auto e = rls::rls_estimate(arg_numbers(in, "t"), arg_numbers(in, "x"),
                                         arg_numbers(in, "y"), arg_number(in, "lambda"),
                                         static_cast<std::size_t>(m), w);
        return Json{{"A", vec2(e.A)}, {"B", vec2(e.B)}, {"P", mat2(e.P)}};
      }});
}

}  // namespace

void register_han_rules(Registry& r) {
  r.add(Rule{
      "han.params",
      "Parameters of Han (IJACSA): printed (ants, cycles, alpha, beta, rho) and pathref's choices",
      "pathref::han::params",
      {},
      {{"ants", "integer", "printed"}, {"max_cycles", "integer", "printed, N_max"},
       {"alpha", "number", "printed"}, {"beta", "number", "printed"},
       {"rho_initial", "number", "printed"}, {"gamma", "number", "choice"},
       {"omega_i", "number", "choice"}, {"epsilon", "number", "choice"}, {"h", "number", "choice"},
       {"Q", "number", "choice"}, {"tau_initial", "number", "choice"},
       {"tau_min", "number", "choice"}, {"a", "number", "choice"}, {"b", "number", "choice"},
       {"rho_min", "number", "choice"}, {"lambda", "number", "choice"},
       {"rls_init_samples", "integer", "choice"}},
      [](const Json&) {
        const auto& p = han::params;
        return Json{{"ants", p.ants},          {"max_cycles", p.max_cycles},
                    {"alpha", p.alpha},        {"beta", p.beta},
                    {"rho_initial", p.rho_initial}, {"gamma", p.gamma},
                    {"omega_i", p.omega_i},    {"epsilon", p.epsilon},
                    {"h", p.h},                {"Q", p.Q},
                    {"tau_initial", p.tau_initial}, {"tau_min", p.tau_min},
                    {"a", p.a},                {"b", p.b},
                    {"rho_min", p.rho_min},    {"lambda", p.lambda},
                    {"rls_init_samples", p.rls_init_samples}};
      }});
  register_aco_part(r);
  register_rls_part(r);
}

}  // namespace pathref::rules
