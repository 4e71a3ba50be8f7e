#include "pathref/planners/ant_colony.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "pathref/core/error.hpp"
#include "pathref/core/memory.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/equations/pseudo_random.hpp"
#include "pathref/rng/draws.hpp"

namespace pathref::ant_colony {

// ---- option names ---------------------------------------------------------------------------

Eta parse_eta(std::string_view name) {
  if (name == "inverse_distance") return Eta::inverse_distance;
  if (name == "goal_directed") return Eta::goal_directed;
  if (name == "goal_inverse") return Eta::goal_inverse;
  throw UsageError("eta must be inverse_distance, goal_directed or goal_inverse, not '" +
                   std::string(name) + "'");
}
std::string_view to_string(Eta v) noexcept {
  switch (v) {
    case Eta::inverse_distance: return "inverse_distance";
    case Eta::goal_directed: return "goal_directed";
    case Eta::goal_inverse: return "goal_inverse";
  }
  return "inverse_distance";
}
DeadEnd parse_dead_end(std::string_view name) {
  if (name == "die") return DeadEnd::die;
  if (name == "backtrack") return DeadEnd::backtrack;
  if (name == "dead_angle") return DeadEnd::dead_angle;
  throw UsageError("dead_end must be die, backtrack or dead_angle, not '" + std::string(name) + "'");
}
std::string_view to_string(DeadEnd v) noexcept {
  switch (v) {
    case DeadEnd::die: return "die";
    case DeadEnd::backtrack: return "backtrack";
    case DeadEnd::dead_angle: return "dead_angle";
  }
  return "die";
}
DeadAngleRecord parse_dead_angle_record(std::string_view name) {
  if (name == "cul_de_sac") return DeadAngleRecord::cul_de_sac;
  if (name == "any_stuck") return DeadAngleRecord::any_stuck;
  throw UsageError("dead_angle_record must be cul_de_sac or any_stuck, not '" + std::string(name) + "'");
}
std::string_view to_string(DeadAngleRecord v) noexcept {
  return v == DeadAngleRecord::cul_de_sac ? "cul_de_sac" : "any_stuck";
}
DeadAngle parse_dead_angle(std::string_view name) {
  if (name == "exclude") return DeadAngle::exclude;
  if (name == "penalise_only") return DeadAngle::penalise_only;
  throw UsageError("dead_angle must be exclude or penalise_only, not '" + std::string(name) + "'");
}
std::string_view to_string(DeadAngle v) noexcept {
  return v == DeadAngle::exclude ? "exclude" : "penalise_only";
}
InitialMode parse_initial_mode(std::string_view name) {
  if (name == "add") return InitialMode::add;
  if (name == "replace") return InitialMode::replace;
  throw UsageError("conversion must be add or replace, not '" + std::string(name) + "'");
}
std::string_view to_string(InitialMode v) noexcept { return v == InitialMode::add ? "add" : "replace"; }
DrawU parse_draw_u(std::string_view name) {
  if (name == "lazy") return DrawU::lazy;
  if (name == "always") return DrawU::always;
  throw UsageError("draw_u must be lazy or always, not '" + std::string(name) + "'");
}
std::string_view to_string(DrawU v) noexcept { return v == DrawU::lazy ? "lazy" : "always"; }
BonusEdges parse_bonus_edges(std::string_view name) {
  if (name == "best_path") return BonusEdges::best_path;
  if (name == "all_edges") return BonusEdges::all_edges;
  throw UsageError("bonus_edges must be best_path or all_edges, not '" + std::string(name) + "'");
}
std::string_view to_string(BonusEdges v) noexcept {
  return v == BonusEdges::best_path ? "best_path" : "all_edges";
}
RhoTiming parse_rho_timing(std::string_view name) {
  if (name == "next") return RhoTiming::next;
  if (name == "current") return RhoTiming::current;
  throw UsageError("rho_timing must be next or current, not '" + std::string(name) + "'");
}
std::string_view to_string(RhoTiming v) noexcept {
  return v == RhoTiming::next ? "next" : "current";
}

namespace {

std::string_view name_of(aco::EdgeSense v) {
  return v == aco::EdgeSense::directed ? "directed" : "undirected";
}
std::string_view name_of(aco::RhoReading v) {
  switch (v) {
    case aco::RhoReading::factor: return "factor";
    case aco::RhoReading::condition: return "condition";
    case aco::RhoReading::clamp: return "clamp";
  }
  return "factor";
}
std::string_view name_of(aco::SpreadReference v) {
  return v == aco::SpreadReference::iteration_worst ? "iteration_worst" : "history_best";
}
std::string_view name_of(corner::OmegaForm v) {
  return v == corner::OmegaForm::multiply ? "multiply" : "divide";
}
std::string_view name_of(corner::At90 v) { return v == corner::At90::two ? "two" : "one"; }

constexpr std::int64_t max_ants = 1000000;
constexpr std::int64_t max_iterations = 1000000;

void validate(const Config& c) {
  require(c.ants >= 1 && c.ants <= max_ants, "ant colony: ants must be in [1, 10^6]");
  require(c.iterations >= 1 && c.iterations <= max_iterations,
          "ant colony: iterations must be in [1, 10^6]");
  require(std::isfinite(c.alpha) && c.alpha >= 0.0, "ant colony: alpha must be finite and >= 0");
  require(std::isfinite(c.beta) && c.beta >= 0.0, "ant colony: beta must be finite and >= 0");
  require(std::isfinite(c.Q) && c.Q > 0.0, "ant colony: Q must be finite and > 0");
  require(std::isfinite(c.tau0) && c.tau0 > 0.0, "ant colony: tau0 must be finite and > 0");
  require(std::isfinite(c.eta_goal) && c.eta_goal > 0.0, "ant colony: eta_goal must be finite and > 0");
  require(c.rho > 0.0 && c.rho < 1.0, "ant colony: rho (rho_initial) must be in (0, 1)");
  if (c.evaporation != Evaporation::constant)
    require(c.rho_min >= 0.0 && c.rho_min < 1.0, "ant colony: rho_min must be in [0, 1)");
  if (c.evaporation == Evaporation::shi_adaptive)
    require(c.rho_t_origin == 0 || c.rho_t_origin == 1, "ant colony: rho_t_origin must be 0 or 1");
  if (c.evaporation == Evaporation::han_stepped)
    require(std::isfinite(c.a) && std::isfinite(c.b) && c.a >= 0.0 && c.a < c.b,
            "ant colony: Eq. 7 constants need 0 <= a < b");
  if (c.corner == Corner::han) {
    require(std::isfinite(c.gamma) && c.gamma >= 0.0, "ant colony: gamma must be finite and >= 0");
    require(c.omega_i > 0.0 && c.omega_i < 1.0, "ant colony: omega_i must be in (0, 1)");
  }
  if (c.selection == Selection::pseudo_random) {
    require(c.q0_origin == 0 || c.q0_origin == 1, "ant colony: q0_origin must be 0 or 1");
    // Eq. 5's domain (epsilon > 0, q0 <= 1) at its largest value, N_c = 0.
    static_cast<void>(aco::adaptive_q0(c.epsilon, 0, c.iterations));
  }
  if (c.deposit == Deposit::han_elite) {
    require(std::isfinite(c.h) && c.h >= 0.0, "ant colony: h must be finite and >= 0");
    require(std::isfinite(c.tau_min) && c.tau_min > 0.0, "ant colony: tau_min must be finite and > 0");
  }
  if (c.deposit == Deposit::weighted_best && c.tau_bounds)
    require(std::isfinite(c.tau_lower) && std::isfinite(c.tau_upper) && c.tau_lower > 0.0 &&
                c.tau_lower < c.tau_upper,
            "ant colony: tau bounds need 0 < tau_lower < tau_upper, finite");
  if (c.dead_end == DeadEnd::dead_angle)
    static_cast<void>(cin::dead_angle_penalty(1.0, c.lambda, c.lambda_form));  // 0 < lambda < 1
}

/// Direction slot of the step (dx, dy) in grid.neighbour-order: 0..7. The reverse step is 7 - k.
int direction(std::int64_t dx, std::int64_t dy) {
  const auto k = static_cast<int>((dy + 1) * 3 + (dx + 1));
  return k > 4 ? k - 1 : k;
}

/// The step (dx, dy) of direction slot k (the inverse of direction()).
constexpr std::int64_t slot_dx[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr std::int64_t slot_dy[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
/// Whether direction slot k is a diagonal step.
constexpr bool slot_diagonal[8] = {true, false, true, false, false, true, false, true};

/// The allowed moves of every free cell as one byte (spec shi2022.plan.aco, "Memory"): bit k is
/// set iff the step in direction slot k is allowed (grid::step_allowed under `policy`), so the
/// moves of cell i in ascending bit order are grid::neighbours(g, cell i) in canonical order
/// (grid.neighbour-order: rows bottom to top, columns left to right = ascending slot). 1 byte
/// per cell, where a list of (target, slot) arcs took up to 8 x 16 bytes and its growth twice that.
std::vector<std::uint8_t> move_masks(const grid::Grid& g, grid::CornerPolicy policy) {
  std::vector<std::uint8_t> masks(static_cast<std::size_t>(g.cell_count()), 0);
  for (std::int64_t y = 0; y < g.height(); ++y)
    for (std::int64_t x = 0; x < g.width(); ++x) {
      const grid::Cell c{x, y};
      if (!g.free(c)) continue;
      std::uint8_t m = 0;
      for (int k = 0; k < 8; ++k)
        if (grid::step_allowed(g, c, grid::Cell{x + slot_dx[k], y + slot_dy[k]}, policy))
          m = static_cast<std::uint8_t>(m | (1U << k));
      masks[static_cast<std::size_t>(y * g.width() + x)] = m;
    }
  return masks;
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

/// Bytes one stored distinct path of n cells takes: its cells in AntPath (16 B each), its key in
/// the `seen` map (8 B per cell index) and about 160 B of vector and map-node overhead.
std::uint64_t distinct_path_bytes(std::size_t n) {
  return memory::plus(memory::times(n, 24), 160);
}

}  // namespace

std::uint64_t memory_estimate(std::int64_t cells) noexcept {
  return memory::times(static_cast<std::uint64_t>(cells < 0 ? 0 : cells), bytes_per_cell);
}

// ---- presets and parameters -----------------------------------------------------------------

Config shi_aco() { return Config{}; }

Config classic_aco() {
  Config c;  // Ant System: proportional selection, constant rho, ant-cycle deposit, dead ants die
  c.eta = Eta::goal_inverse;
  c.eta_goal = 100.0;
  c.ants = 50;
  c.iterations = 100;
  c.alpha = 1.0;
  c.beta = 7.0;
  c.Q = 1.0;
  c.tau0 = 8.0;
  c.rho = 0.3;
  c.edge_sense = aco::EdgeSense::undirected;
  c.dead_end = DeadEnd::die;
  return c;
}

Config shi_iaco() {
  Config c;
  c.eta = Eta::goal_directed;
  c.evaporation = Evaporation::shi_adaptive;
  c.rho = 0.9;
  c.rho_min = 0.1;
  return c;
}

Config shi_iaco_nomin() {
  Config c = shi_iaco();
  c.rho_min = 0.0;
  return c;
}

Config han_iaco() {
  Config c;
  // spec han.plan.iaco, Reading "eta" and "dead_end": the goal-directed eta and backtracking
  // ants are the readings the paper's text supports best (inverse_distance and die remain
  // selectable).
  c.eta = Eta::goal_directed;
  c.dead_end = DeadEnd::backtrack;
  c.selection = Selection::pseudo_random;
  c.corner = Corner::han;
  c.evaporation = Evaporation::han_stepped;
  c.deposit = Deposit::han_elite;
  c.ants = 50;
  c.iterations = 50;
  c.alpha = 4.0;
  c.beta = 8.0;
  c.rho = 0.7;
  c.rho_min = 0.1;
  c.Q = 1.0;
  c.tau0 = 1.0;
  c.a = 1.0;
  c.b = 5.0;
  c.gamma = 1.0;
  c.omega_i = 0.5;
  c.epsilon = 1.0;
  c.h = 1.0;
  c.tau_min = 0.01;
  return c;
}

Config cin_aco() {
  Config c;
  c.eta = Eta::inverse_distance;
  c.deposit = Deposit::weighted_best;
  c.dead_end = DeadEnd::dead_angle;
  c.ants = 30;
  c.iterations = 50;
  c.alpha = 1.0;
  c.beta = 2.0;
  c.rho = 0.3;
  c.Q = 1.0;
  c.tau0 = 0.1;
  c.lambda = 0.5;
  c.eta_goal = 2.0;  // eta = goal_inverse (Eq. 30's alternative): d_GG := 1/2
  return c;
}

Json to_params(const Config& c) {
  Json p = Json::object();
  p["ants"] = c.ants;
  p["iterations"] = c.iterations;
  p["alpha"] = c.alpha;
  p["beta"] = c.beta;
  p["Q"] = c.Q;
  p["tau0"] = c.tau0;
  p["eta"] = std::string(to_string(c.eta));
  if (c.eta == Eta::goal_inverse) p["eta_goal"] = c.eta_goal;
  p["edge_sense"] = std::string(name_of(c.edge_sense));
  p["dead_end"] = std::string(to_string(c.dead_end));
  switch (c.evaporation) {
    case Evaporation::constant:
      p["rho"] = c.rho;
      break;
    case Evaporation::shi_adaptive:
      p["rho_initial"] = c.rho;
      p["rho_min"] = c.rho_min;
      p["rho_reading"] = std::string(name_of(c.rho_reading));
      p["rho_t_origin"] = c.rho_t_origin;
      break;
    case Evaporation::han_stepped:
      p["rho"] = c.rho;
      p["rho_min"] = c.rho_min;
      p["a"] = c.a;
      p["b"] = c.b;
      p["spread_reference"] = std::string(name_of(c.spread_reference));
      p["rho_timing"] = std::string(to_string(c.rho_timing));
      break;
  }
  if (c.corner == Corner::han) {
    p["gamma"] = c.gamma;
    p["omega_i"] = c.omega_i;
    p["omega_form"] = std::string(name_of(c.omega_form));
    p["at90"] = std::string(name_of(c.at90));
  }
  if (c.selection == Selection::pseudo_random) {
    p["epsilon"] = c.epsilon;
    p["q0_origin"] = c.q0_origin;
    p["draw_u"] = std::string(to_string(c.draw_u));
  }
  if (c.deposit == Deposit::han_elite) {
    p["h"] = c.h;
    p["tau_min"] = c.tau_min;
    p["bonus_edges"] = std::string(to_string(c.bonus_edges));
  }
  if (c.deposit == Deposit::weighted_best) {
    p["weight_norm"] = std::string(cin::to_string(c.weight_norm));
    p["tau_bounds"] = c.tau_bounds ? "on" : "off";
    p["tau_lower"] = c.tau_lower;
    p["tau_upper"] = c.tau_upper;
  }
  if (c.dead_end == DeadEnd::dead_angle) {
    p["lambda"] = c.lambda;
    p["lambda_form"] = std::string(cin::to_string(c.lambda_form));
    p["dead_angle"] = std::string(to_string(c.dead_angle));
    p["dead_angle_record"] = std::string(to_string(c.dead_angle_record));
  }
  return p;
}

Config from_params(const Config& base, const Json& params) {
  Config c = base;
  const Json allowed = to_params(base);
  for (const auto& item : params.items()) {
    // not a structured binding: clang 14 cannot capture one in the lambdas below
    const std::string& k = item.key();
    const Json& v = item.value();
    if (!allowed.contains(k)) throw UsageError("unknown ant-colony parameter '" + k + "'");
    const bool want_int = allowed.at(k).is_number_integer();
    const bool want_num = allowed.at(k).is_number();
    const bool want_str = allowed.at(k).is_string();
    if ((want_int && !v.is_number_integer()) || (want_num && !v.is_number()) ||
        (want_str && !v.is_string()))
      throw UsageError("parameter '" + k + "' must be of the same type as its default " +
                       allowed.at(k).dump());
    const auto num = [&] {
      const double d = v.get<double>();
      require(std::isfinite(d), "parameter '" + k + "' must be finite");
      return d;
    };
    const auto integer = [&] { return v.get<std::int64_t>(); };
    const auto str = [&] { return v.get<std::string>(); };
    if (k == "ants") c.ants = integer();
    else if (k == "iterations") c.iterations = integer();
    else if (k == "alpha") c.alpha = num();
    else if (k == "beta") c.beta = num();
    else if (k == "Q") c.Q = num();
    else if (k == "tau0") c.tau0 = num();
    else if (k == "eta") c.eta = parse_eta(str());
    else if (k == "eta_goal") c.eta_goal = num();
    else if (k == "edge_sense") c.edge_sense = aco::parse_edge_sense(str());
    else if (k == "dead_end") c.dead_end = parse_dead_end(str());
    else if (k == "rho" || k == "rho_initial") c.rho = num();
    else if (k == "rho_min") c.rho_min = num();
    else if (k == "rho_reading") c.rho_reading = aco::parse_rho_reading(str());
    else if (k == "rho_t_origin") {
      const std::int64_t o = integer();
      require(o == 0 || o == 1, "rho_t_origin must be 0 or 1");
      c.rho_t_origin = static_cast<int>(o);
    } else if (k == "a") c.a = num();
    else if (k == "b") c.b = num();
    else if (k == "spread_reference") c.spread_reference = aco::parse_spread_reference(str());
    else if (k == "rho_timing") c.rho_timing = parse_rho_timing(str());
    else if (k == "gamma") c.gamma = num();
    else if (k == "omega_i") c.omega_i = num();
    else if (k == "omega_form") c.omega_form = corner::parse_omega_form(str());
    else if (k == "at90") c.at90 = corner::parse_at90(str());
    else if (k == "epsilon") c.epsilon = num();
    else if (k == "q0_origin") {
      const std::int64_t o = integer();
      require(o == 0 || o == 1, "q0_origin must be 0 or 1");
      c.q0_origin = static_cast<int>(o);
    } else if (k == "draw_u") c.draw_u = parse_draw_u(str());
    else if (k == "h") c.h = num();
    else if (k == "tau_min") c.tau_min = num();
    else if (k == "bonus_edges") c.bonus_edges = parse_bonus_edges(str());
    else if (k == "weight_norm") c.weight_norm = cin::parse_weight_norm(str());
    else if (k == "tau_bounds") {
      const std::string b = str();
      if (b != "on" && b != "off") throw UsageError("tau_bounds must be on or off");
      c.tau_bounds = b == "on";
    } else if (k == "tau_lower") c.tau_lower = num();
    else if (k == "tau_upper") c.tau_upper = num();
    else if (k == "lambda") c.lambda = num();
    else if (k == "lambda_form") c.lambda_form = cin::parse_lambda_form(str());
    else if (k == "dead_angle") c.dead_angle = parse_dead_angle(str());
    else if (k == "dead_angle_record") c.dead_angle_record = parse_dead_angle_record(str());
    else throw UsageError("unknown ant-colony parameter '" + k + "'");
  }
  validate(c);
  return c;
}

// ---- the run --------------------------------------------------------------------------------

Run run(const planners::Request& req, const Config& cfg, rng::Stream& stream) {
  return run(req, cfg, stream, {}, InitialMode::add);
}

Run run(const planners::Request& req, const Config& cfg, rng::Stream& stream,
        std::span<const cin::EdgePheromone> initial, InitialMode initial_mode) {
  if (req.grid == nullptr) throw UsageError("plan request without a grid");
  const grid::Grid& g = *req.grid;
  require(g.in_bounds(req.start), "ant colony: start cell outside the grid");
  require(g.in_bounds(req.goal), "ant colony: goal cell outside the grid");
  require(g.free(req.start), "ant colony: start cell is blocked");
  require(g.free(req.goal), "ant colony: goal cell is blocked");
  validate(cfg);

  Run out;
  planners::Result& res = out.result;
  res.params_used = to_params(cfg);
  const std::uint64_t draws_before = stream.doubles_drawn();

  if (req.start == req.goal) {  // spec: the one-cell path, no iteration, no draw
    res.found = true;
    res.path = {req.start};
    res.length = 0.0;
    res.extra = Json{{"best_iteration", nullptr}, {"best_ant", nullptr}, {"draws", 0},
                     {"distinct_paths", 0}};
    return out;
  }

  const std::int64_t cells = g.cell_count();
  const auto ucells = static_cast<std::size_t>(cells);
  // spec shi2022.plan.aco "Memory": the per-cell state is estimated before it is allocated.
  const std::uint64_t fixed = memory_estimate(cells);
  const std::string what = fmt::format("the ant colony on a {}x{} grid ({} bytes per cell)", g.width(),
                                       g.height(), bytes_per_cell);
  memory::require_within(fixed, req.max_memory, what);
  const std::vector<std::uint8_t> moves = move_masks(g, req.policy);
  const std::int64_t W = g.width();
  const std::int64_t start = g.index(req.start);
  const std::int64_t goal = g.index(req.goal);
  const grid::Cell goal_cell = req.goal;
  const auto m = static_cast<std::size_t>(cfg.ants);
  const std::int64_t N = cfg.iterations;

  // Pheromone on every ordered pair (cell, direction slot): tau[8 i + k].
  std::vector<double> tau(ucells * 8U, cfg.tau0);
  for (const cin::EdgePheromone& e : initial) {
    require(g.in_bounds(e.from) && g.in_bounds(e.to), "initial pheromone: edge outside the grid");
    const std::int64_t dx = e.to.x - e.from.x;
    const std::int64_t dy = e.to.y - e.from.y;
    require(std::llabs(dx) <= 1 && std::llabs(dy) <= 1 && (dx != 0 || dy != 0),
            "initial pheromone: an edge joins two 8-neighbours");
    require(std::isfinite(e.tau) && e.tau > 0.0, "initial pheromone: values must be finite and > 0");
    const std::size_t slot = static_cast<std::size_t>(g.index(e.from)) * 8U +
                             static_cast<std::size_t>(direction(dx, dy));
    tau[slot] = initial_mode == InitialMode::add ? cfg.tau0 + e.tau : e.tau;
  }
  // cin2021 dead-angle table (DeadEnd::dead_angle): kept for the whole run.
  std::vector<std::uint8_t> dead_table(ucells, 0);
  Json dead_table_cells = Json::array();
  std::int64_t deadlocks = 0;
  const bool exclude_table = cfg.dead_end == DeadEnd::dead_angle && cfg.dead_angle == DeadAngle::exclude;

  std::vector<std::uint8_t> tabu(ucells, 0);
  std::vector<std::int64_t> touched;
  std::vector<std::vector<std::int64_t>> paths(m);  // cell indices per ant
  std::vector<bool> alive(m, false);
  std::vector<double> lengths(m, 0.0);
  std::vector<grid::Cell> cell_path;

  // pow(eta_ij, beta) of every move, computed on first use (-1: not yet): eta depends only on the
  // move and the goal, so this is transition_weights' pow(eta, beta) evaluated once instead of per
  // step (the same doubles; spec shi2022.eq2, aco::transition_weights_into). Every eta form is a
  // function of the target cell j and of d_ij alone (1 for a straight step, sqrt 2 for a diagonal
  // one: metrics::centre_distance of (dx, dy)), so the cache holds two values per target cell,
  // eta_pow[2 j + diagonal], not eight per (cell, direction slot).
  std::vector<double> eta_pow(ucells * 2U, -1.0);

  // per-move scratch
  std::vector<double> w_tau;
  std::vector<double> w_eta;
  std::vector<double> weights;
  // per-iteration scratch of the deposit grouping
  std::vector<double> grouped;
  std::vector<grid::Cell> cand_cells;
  std::vector<std::int64_t> cand_index;

  double best_len = std::numeric_limits<double>::infinity();
  std::vector<std::int64_t> best_path;
  std::int64_t best_iteration = 0;
  std::int64_t best_ant = 0;

  double rho_state = cfg.rho;  // shi_adaptive: rho of the current iteration; han: rho(t-1)
  Json rho_used = Json::array();
  Json q0_used = Json::array();
  Json dead_per_iteration = Json::array();
  Json it_best = Json::array();
  Json it_worst = Json::array();
  std::map<std::vector<std::int64_t>, std::size_t> seen;
  // What grows during the run (spec shi2022.plan.aco "Memory"): the ants' walks, the distinct
  // paths and the best path, counted as they grow against req.max_memory.
  std::uint64_t distinct_bytes = 0;
  const auto check_growth = [&] {
    std::uint64_t grown = memory::times(touched.capacity(), 8);
    for (const auto& p : paths) grown = memory::plus(grown, memory::times(p.capacity(), 8));
    grown = memory::plus(grown, memory::times(best_path.capacity(), 8));
    grown = memory::plus(grown, distinct_bytes);
    memory::require_within(memory::plus(fixed, grown), req.max_memory, what + " and its stored paths so far");
  };

  const auto to_cells = [&](const std::vector<std::int64_t>& idx) {
    std::vector<grid::Cell> v;
    v.reserve(idx.size());
    for (const std::int64_t i : idx) v.push_back(g.cell(i));
    return v;
  };

  for (std::int64_t t = 1; t <= N; ++t) {
    planners::stop_if_interrupted(req.interrupted);
    double q0 = 0.0;
    if (cfg.selection == Selection::pseudo_random) {
      const std::int64_t Nc = cfg.q0_origin == 1 ? t : t - 1;
      q0 = aco::adaptive_q0(cfg.epsilon, Nc, N);
      q0_used.push_back(q0);
    }

    // ---- tour construction, ants in ascending order ----
    for (std::size_t a = 0; a < m; ++a) {
      std::vector<std::int64_t>& path = paths[a];
      path.clear();
      for (const std::int64_t i : touched) tabu[static_cast<std::size_t>(i)] = 0;
      touched.clear();
      path.push_back(start);
      tabu[static_cast<std::size_t>(start)] = 1;
      touched.push_back(start);
      bool dead = false;
      while (path.back() != goal) {
        const std::int64_t cur = path.back();
        const grid::Cell cur_cell = g.cell(cur);
        const unsigned mask = moves[static_cast<std::size_t>(cur)];
        const auto target = [&](int k) { return cur + slot_dy[k] * W + slot_dx[k]; };
        w_tau.clear();
        w_eta.clear();
        cand_cells.clear();
        cand_index.clear();
        for (int k = 0; k < 8; ++k) {
          if ((mask & (1U << k)) == 0) continue;
          const std::int64_t to_index = target(k);
          if (tabu[static_cast<std::size_t>(to_index)] != 0) continue;
          if (exclude_table && dead_table[static_cast<std::size_t>(to_index)] != 0) continue;
          const grid::Cell to = g.cell(to_index);
          cand_index.push_back(to_index);
          cand_cells.push_back(to);
          const std::size_t slot = static_cast<std::size_t>(cur) * 8U + static_cast<std::size_t>(k);
          w_tau.push_back(tau[slot]);
          const std::size_t eslot = static_cast<std::size_t>(to_index) * 2U + (slot_diagonal[k] ? 1U : 0U);
          if (eta_pow[eslot] < 0.0) {
            const double eta =
                cfg.eta == Eta::inverse_distance ? aco::eta_inverse_distance(cur_cell, to)
                : cfg.eta == Eta::goal_directed  ? aco::eta_goal_directed(cur_cell, to, goal_cell)
                                                 : aco::eta_goal_inverse(to, goal_cell, cfg.eta_goal);
            require(std::isfinite(eta) && eta >= 0.0, "eta must be finite and >= 0");
            eta_pow[eslot] = std::pow(eta, cfg.beta);
          }
          w_eta.push_back(eta_pow[eslot]);
        }
        if (cand_index.empty()) {  // dead end
          if (cfg.dead_end == DeadEnd::die) {
            dead = true;
            break;
          }
          bool record = cfg.dead_end == DeadEnd::dead_angle && path.size() >= 2;
          if (record && cfg.dead_angle_record == DeadAngleRecord::cul_de_sac) {
            std::size_t open = 0;  // allowed moves into cells outside the table (tabu ignored)
            for (int k = 0; k < 8; ++k)
              if ((mask & (1U << k)) != 0) open += dead_table[static_cast<std::size_t>(target(k))] == 0 ? 1U : 0U;
            record = open <= 1;
          }
          if (record) {
            // cin2021 Sec. 5.5.2: record cur, penalise every allowed move into it (Eq. 35)
            ++deadlocks;
            const auto ucur = static_cast<std::size_t>(cur);
            if (dead_table[ucur] == 0) {
              dead_table[ucur] = 1;
              dead_table_cells.push_back(Json::array({cur_cell.x, cur_cell.y}));
            }
            for (int k = 0; k < 8; ++k) {
              if ((mask & (1U << k)) == 0) continue;
              const std::size_t in_slot = static_cast<std::size_t>(target(k)) * 8U +
                                          static_cast<std::size_t>(7 - k);
              tau[in_slot] = cin::dead_angle_penalty(tau[in_slot], cfg.lambda, cfg.lambda_form);
            }
          }
          path.pop_back();  // backtrack; the dead end stays tabu
          if (path.empty()) {
            dead = true;
            break;
          }
          continue;
        }
        if (cfg.corner == Corner::han) {
          std::optional<grid::Cell> prev;
          if (path.size() >= 2) prev = g.cell(path[path.size() - 2]);
          const std::vector<double> omega = corner::corner_factors(
              prev, cur_cell, cand_cells, cfg.omega_i, cfg.omega_form, cfg.at90);
          aco::transition_weights_into(w_tau, w_eta, cfg.alpha, aco::CornerFactor{omega, cfg.gamma}, weights);
        } else {
          aco::transition_weights_into(w_tau, w_eta, cfg.alpha, std::nullopt, weights);
        }
        std::size_t k = 0;
        if (stream.tracing())
          stream.set_context(fmt::format("iteration {} ant {} step {}", t, a, path.size() - 1));
        if (cfg.selection == Selection::proportional) {
          const double u = stream.next_double("aco.transition roulette (rng.roulette)");
          k = rng::roulette(weights, u);
        } else {
          const double q = stream.next_double("aco.transition q0 test (pseudo-random proportional)");
          double u = 0.0;
          if (cfg.draw_u == DrawU::always || q > q0) u = stream.next_double("aco.transition roulette (rng.roulette)");
          k = aco::pseudo_random_choice(weights, q, q0, u).index;
        }
        const std::int64_t next = cand_index[k];
        const std::size_t grown_from = path.capacity() + touched.capacity();
        path.push_back(next);
        tabu[static_cast<std::size_t>(next)] = 1;
        touched.push_back(next);
        if (path.capacity() + touched.capacity() != grown_from) check_growth();
      }
      alive[a] = !dead;
      if (!dead) {
        cell_path = to_cells(path);
        lengths[a] = metrics::path_length(cell_path);
      }
    }

    // ---- iteration statistics ----
    std::int64_t dead_count = 0;
    std::size_t survivors = 0;
    double sum = 0.0;
    double L_n = std::numeric_limits<double>::infinity();
    double L_A = -std::numeric_limits<double>::infinity();
    std::size_t n_ant = 0;
    for (std::size_t a = 0; a < m; ++a) {
      if (!alive[a]) {
        ++dead_count;
        continue;
      }
      ++survivors;
      sum += lengths[a];
      if (lengths[a] < L_n) {
        L_n = lengths[a];
        n_ant = a;
      }
      if (lengths[a] > L_A) L_A = lengths[a];
      auto [pos, inserted] = seen.try_emplace(paths[a], out.distinct_paths.size());
      if (inserted) {
        distinct_bytes = memory::plus(distinct_bytes, distinct_path_bytes(paths[a].size()));
        check_growth();
        AntPath ap;
        ap.path = to_cells(paths[a]);
        ap.length = lengths[a];
        ap.first_iteration = t;
        ap.first_ant = static_cast<std::int64_t>(a);
        out.distinct_paths.push_back(std::move(ap));
      }
      AntPath& ap = out.distinct_paths[pos->second];
      ap.last_iteration = t;
      ++ap.count;
    }
    dead_per_iteration.push_back(dead_count);
    it_best.push_back(number_or_null(L_n));
    it_worst.push_back(number_or_null(L_A));
    res.mean_per_iteration.push_back(survivors > 0 ? sum / static_cast<double>(survivors)
                                                   : std::numeric_limits<double>::quiet_NaN());
    const double L_a = std::isfinite(best_len) ? best_len : L_n;  // best before this iteration

    // ---- rho of this iteration's update ----
    double rho = cfg.rho;
    switch (cfg.evaporation) {
      case Evaporation::constant:
        break;
      case Evaporation::shi_adaptive:
        rho = rho_state;
        break;
      case Evaporation::han_stepped: {
        double rho_t = rho_state;
        if (survivors > 0) {
          const double L_ref = cfg.spread_reference == aco::SpreadReference::iteration_worst ? L_A : L_a;
          rho_t = aco::stepped_rho(rho_state, L_ref, L_n, cfg.a, cfg.b, cfg.rho_min,
                                   cfg.spread_reference);
        }
        rho = cfg.rho_timing == RhoTiming::next ? rho_state : rho_t;
        rho_state = rho_t;
        break;
      }
    }
    rho_used.push_back(rho);

    if (cfg.deposit == Deposit::weighted_best) {
      // cin2021 Eq. 31-34: the global best is updated first (strict improvement), then every
      // edge evaporates and the edges of pi_ib and pi_gb get the weighted deposits of Eq. 32-33.
      const std::vector<std::int64_t>* gb = best_path.empty() ? nullptr : &best_path;
      double L_gb = best_len;
      if (survivors > 0 && L_n < best_len) {
        gb = &paths[n_ant];
        L_gb = L_n;
      }
      const cin::BestWeights w = cin::best_path_weights(t - 1, N, cfg.weight_norm);
      // The marked edges as (slot, bits) sorted by slot, bits OR-ed per slot (bit 1: on pi_ib,
      // bit 2: on pi_gb): O(path length), not a byte per edge of the grid.
      std::vector<std::pair<std::size_t, std::uint8_t>> on;
      const auto mark = [&](const std::vector<std::int64_t>& p, std::uint8_t bit) {
        for (std::size_t s = 1; s < p.size(); ++s) {
          const grid::Cell from = g.cell(p[s - 1]);
          const grid::Cell to = g.cell(p[s]);
          const int k = direction(to.x - from.x, to.y - from.y);
          on.emplace_back(static_cast<std::size_t>(p[s - 1]) * 8U + static_cast<std::size_t>(k), bit);
          if (cfg.edge_sense == aco::EdgeSense::undirected)
            on.emplace_back(static_cast<std::size_t>(p[s]) * 8U + static_cast<std::size_t>(7 - k), bit);
        }
      };
      if (survivors > 0) mark(paths[n_ant], 1);
      if (gb != nullptr) mark(*gb, 2);
      std::sort(on.begin(), on.end());
      std::size_t next_on = 0;
      for (std::size_t e = 0; e < tau.size(); ++e) {
        std::uint8_t bits = 0;
        while (next_on < on.size() && on[next_on].first == e) bits = static_cast<std::uint8_t>(bits | on[next_on++].second);
        const double d = bits == 0 ? 0.0
                                   : cin::weighted_best_deposit((bits & 1U) != 0, w.ib, L_n,
                                                                (bits & 2U) != 0, w.gb, L_gb, cfg.Q);
        double v = aco::pheromone_update(tau[e], rho, d);
        if (cfg.tau_bounds) v = std::clamp(v, cfg.tau_lower, cfg.tau_upper);
        tau[e] = v;
      }
    } else {
    // ---- deposits: (slot, value) in ant order, then grouped per slot (stable) ----
    std::vector<std::pair<std::size_t, double>> deposits;
    for (std::size_t a = 0; a < m; ++a) {
      if (!alive[a]) continue;
      const double d = aco::ant_cycle_deposit(cfg.Q, lengths[a]);
      const auto& p = paths[a];
      for (std::size_t s = 1; s < p.size(); ++s) {
        const grid::Cell from = g.cell(p[s - 1]);
        const grid::Cell to = g.cell(p[s]);
        const int k = direction(to.x - from.x, to.y - from.y);
        deposits.emplace_back(static_cast<std::size_t>(p[s - 1]) * 8U + static_cast<std::size_t>(k), d);
        if (cfg.edge_sense == aco::EdgeSense::undirected)
          deposits.emplace_back(static_cast<std::size_t>(p[s]) * 8U + static_cast<std::size_t>(7 - k), d);
      }
    }
    // Eq. (5) per slot: aco::total_deposit of the slot's deposits in ant order. The deposits are
    // sorted by slot keeping that order (a stable sort), so each slot's group is the same
    // sequence as before and total_deposit sums it left to right from 0. Only the slots with
    // deposits are held (O(path length), not a delta per edge of the grid: spec "Memory").
    std::stable_sort(deposits.begin(), deposits.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    grouped.resize(deposits.size());
    for (std::size_t i = 0; i < deposits.size(); ++i) grouped[i] = deposits[i].second;
    std::size_t next_dep = 0;
    // delta of slot e (0 without deposits); called for e ascending.
    const auto delta_of = [&](std::size_t e) {
      if (next_dep >= deposits.size() || deposits[next_dep].first != e) return 0.0;
      const std::size_t from = next_dep;
      while (next_dep < deposits.size() && deposits[next_dep].first == e) ++next_dep;
      return aco::total_deposit(std::span<const double>(grouped).subspan(from, next_dep - from));
    };

    if (cfg.deposit == Deposit::ant_cycle) {
      for (std::size_t e = 0; e < tau.size(); ++e) tau[e] = aco::pheromone_update(tau[e], rho, delta_of(e));
    } else {
      std::vector<std::size_t> on_best;  // the best path's slots, sorted, unique
      bool all_best = false;
      double bonus = 0.0;
      if (survivors > 0) {
        bonus = aco::elite_bonus(cfg.h, L_a, L_n);
        if (cfg.bonus_edges == BonusEdges::all_edges) {
          all_best = true;
        } else {
          const auto& p = paths[n_ant];
          for (std::size_t s = 1; s < p.size(); ++s) {
            const grid::Cell from = g.cell(p[s - 1]);
            const grid::Cell to = g.cell(p[s]);
            const int k = direction(to.x - from.x, to.y - from.y);
            on_best.push_back(static_cast<std::size_t>(p[s - 1]) * 8U + static_cast<std::size_t>(k));
            if (cfg.edge_sense == aco::EdgeSense::undirected)
              on_best.push_back(static_cast<std::size_t>(p[s]) * 8U + static_cast<std::size_t>(7 - k));
          }
          std::sort(on_best.begin(), on_best.end());
          on_best.erase(std::unique(on_best.begin(), on_best.end()), on_best.end());
        }
      }
      std::size_t next_best = 0;
      for (std::size_t e = 0; e < tau.size(); ++e) {
        bool best_edge = all_best;
        if (next_best < on_best.size() && on_best[next_best] == e) {
          best_edge = true;
          ++next_best;
        }
        tau[e] = aco::pheromone_update_elite(tau[e], rho, delta_of(e), best_edge ? bonus : 0.0, cfg.tau_min);
      }
    }
    }  // deposit modes other than weighted_best

    // ---- best so far (strict improvement: the earliest best is kept) ----
    if (survivors > 0 && L_n < best_len) {
      best_len = L_n;
      best_path = paths[n_ant];
      check_growth();
      best_iteration = t;
      best_ant = static_cast<std::int64_t>(n_ant);
    }
    res.best_per_iteration.push_back(best_len);

    // ---- Shi Eq. 13: rho of the next iteration ----
    if (cfg.evaporation == Evaporation::shi_adaptive && t < N)
      rho_state = aco::adaptive_rho(rho_state, t - 1 + cfg.rho_t_origin, N, cfg.rho_min,
                                    cfg.rho_reading);
  }

  res.iterations = N;
  res.found = !best_path.empty();
  if (res.found) {
    res.path = to_cells(best_path);
    res.length = best_len;
  }
  Json extra = Json::object();
  extra["best_iteration"] = res.found ? Json(best_iteration) : Json(nullptr);
  extra["best_ant"] = res.found ? Json(best_ant) : Json(nullptr);
  extra["dead_ants_per_iteration"] = std::move(dead_per_iteration);
  extra["iteration_best"] = std::move(it_best);
  extra["iteration_worst"] = std::move(it_worst);
  extra["rho_per_iteration"] = std::move(rho_used);
  if (cfg.selection == Selection::pseudo_random) extra["q0_per_iteration"] = std::move(q0_used);
  extra["distinct_paths"] = out.distinct_paths.size();
  if (cfg.dead_end == DeadEnd::dead_angle) {
    extra["dead_angle_table"] = std::move(dead_table_cells);
    extra["deadlocks"] = deadlocks;
  }
  extra["draws"] = stream.doubles_drawn() - draws_before;
  res.extra = std::move(extra);
  return out;
}

}  // namespace pathref::ant_colony
