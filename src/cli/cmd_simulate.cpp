// `pathref simulate SCENARIO [--planner NAME] [--json] [--full] [--svg FILE]`: Han's dynamic-
// obstacle simulation (IACO-A*, Fig. 5, 6, 8) of a pathref-sim 1 scenario file.
// Spec: spec/han-sim.md (han.sim.run, section "CLI"), spec/cli.md#simulate.
#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/svg_fused.hpp"
#include "pathref/io/svg_sim.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/sim/fused.hpp"
#include "pathref/sim/simulate.hpp"

namespace pathref::cli {

namespace {

struct SimulateOptions {
  std::string scenario;
  std::string planner;
  std::string svg_file;
  bool json = false;
  bool full = false;
};

/// A "pathref-sim 2" scenario: the fused system of sensors2023 (spec/sensors2023-dwa.md).
int run_fused(const SimulateOptions& o, const std::string& text, const std::string& base) {
  dwa::FusedScenario s = dwa::parse_fused_scenario(text, o.scenario, base);
  if (!o.planner.empty()) {
    s.planner = o.planner;
    s.planner_params = dwa::Json::object();
    s.path.clear();
  }
  const dwa::FusedResult r = dwa::simulate_fused(s);
  if (o.json) {
    dwa::Json j = dwa::to_json(r, o.full);
    j["params"] = dwa::params_json(s);
    stamp_version(j);
    fmt::print("{}\n", j.dump());
  } else {
    fmt::print("scenario: {} (pathref-sim 2: sensors2023 global path + following DWA)\n", o.scenario);
    fmt::print("parameters: {}\n", dwa::params_json(s).dump());
    if (!r.global_found) {
      fmt::print("global path: none ({})\n", s.path.empty() ? s.planner : std::string("given path"));
    } else {
      fmt::print("global path: {} cells, {} key nodes ({})\n", r.global_path.size(), r.key_nodes.size(),
                 s.path.empty() ? s.planner : std::string("given path"));
    }
    fmt::print("outcome: {}\n", dwa::to_string(r.outcome));
    fmt::print("time: {:.6f} s\n", r.time);
    fmt::print("length: {:.6f} m\n", r.length);
    fmt::print("turns: {}\n", r.turns);
    fmt::print("min clearance: {:.6f} m\n", r.min_clearance);
    fmt::print("steps: {} ({} braked)\n", r.steps, r.braked_steps);
    for (const dwa::Skip& k : r.skips)
      fmt::print("skip: t = {:.6f} s key node {} ({})\n", k.t, k.key, dwa::to_string(k.reason));
  }
  if (!o.svg_file.empty()) {
    write_figure(o.svg_file, io::svg_fused(s, r));
    if (!o.json) fmt::print("wrote {}\n", o.svg_file);
  }
  return r.outcome == dwa::Outcome::reached ? 0 : 1;
}

/// `--planner NAME`: a registered planner (checked before the scenario is read).
void check_planner_option(const std::string& name) {
  if (!name.empty() && planners::find_planner(name) == nullptr)
    throw UsageError("--planner expects a planner name (" + planners::planner_names() + "), got '" +
                     io::printable(name) + "'");
}

int run_simulate(const SimulateOptions& o) {
  check_planner_option(o.planner);
  const std::string text = io::read_text_file(o.scenario, "scenario file");
  const std::string base = std::filesystem::path(o.scenario).parent_path().string();
  if (dwa::scenario_format(text) == "pathref-sim 2") return run_fused(o, text, base);
  sim::Scenario s = sim::parse_scenario(text, o.scenario, base);
  if (!o.planner.empty()) {
    s.planner = o.planner;
    s.planner_params = sim::Json::object();
    s.path.clear();
  }
  const sim::SimResult r = sim::simulate(s);
  if (o.json) {
    sim::Json j = sim::to_json(r, o.full);
    stamp_version(j);
    fmt::print("{}\n", j.dump());
  } else {
    if (!r.global_found) {
      fmt::print("global path: none ({})\n", s.path.empty() ? s.planner : std::string("given path"));
    } else {
      fmt::print("global path: {} cells, {:.6f} m ({})\n", r.global_path.size(), r.global_length,
                 s.path.empty() ? s.planner : std::string("given path"));
    }
    fmt::print("reached goal: {}\n", r.reached_goal ? "yes" : "no");
    std::size_t outside = 0;
    for (const auto& c : r.collisions) outside += c.outside_guarantee.empty() ? 0U : 1U;
    fmt::print("collisions: {} ({} outside the guarantee)\n", r.collisions.size(), outside);
    for (const auto& c : r.collisions)
      fmt::print("collision: t = {:.6f} s with O{} at {:.6f} m ({})\n", c.t, c.obstacle + 1, c.distance,
                 c.outside_guarantee.empty() ? std::string("inside the guarantee: a defect of the rules")
                                             : "outside the guarantee: " + c.outside_guarantee);
    for (const auto& w : r.waits)
      fmt::print("wait: {:.6f} s to {:.6f} s ({:.6f} s)\n", w.start, w.end, w.end - w.start);
    for (const auto& p : r.replans)
      fmt::print("replan: t = {:.6f} s from ({}, {}) to local target ({}, {}), {} cells\n", p.t, p.from.x,
                 p.from.y, p.target.x, p.target.y, p.detour.size());
    for (const auto& e : r.evasions)
      fmt::print("evade: t = {:.6f} s from ({}, {}) to refuge ({}, {}), {} cells, rejoin at ({}, {})\n", e.t,
                 e.from.x, e.from.y, e.refuge.x, e.refuge.y, e.path.size(), e.target.x, e.target.y);
    for (const auto& u : r.unavoidable) {
      std::string ids;
      for (const auto id : u.obstacles) ids += (ids.empty() ? "O" : ", O") + std::to_string(id + 1);
      fmt::print("unavoidable: t = {:.6f} s with {} ({})\n", u.t, ids, u.reason);
    }
    fmt::print("waits: {} ({:.6f} s)\n", r.waits.size(), r.wait_time);
    fmt::print("replans: {}\n", r.replans.size());
    fmt::print("evasions: {}\n", r.evasions.size());
    fmt::print("distance: {:.6f} m\n", r.distance);
    fmt::print("time: {:.6f} s\n", r.time);
  }
  if (!o.svg_file.empty()) {
    write_figure(o.svg_file, io::svg_simulation(s, r));
    if (!o.json) fmt::print("wrote {}\n", o.svg_file);
  }
  return (r.reached_goal && r.collisions.empty()) ? 0 : 1;
}

}  // namespace

void add_simulate_command(CLI::App& app, Action& run) {
  auto* cmd = app.add_subcommand(
      "simulate",
      "Dynamic-obstacle simulation of a scenario file: \"pathref-sim 1\" is Han's (IACO-A*, Fig. 5-6, 8: RLS "
      "prediction, side waits, frontal A* detours; spec/han-sim.md); \"pathref-sim 2\" is sensors2023's fused "
      "global path + following DWA among moving and temporary obstacles (spec/sensors2023-dwa.md). Exit 1 if "
      "the goal is not reached or a collision happened");
  static SimulateOptions o;
  cmd->add_option("scenario", o.scenario, "scenario file (JSON, format \"pathref-sim 1\" or \"pathref-sim 2\")")
      ->required()
      ->type_name("FILE");
  cmd->add_option("--planner", o.planner,
                  "global planner by name (overrides the scenario's planner and path; e.g. iaco-han, astar-han, astar)")
      ->type_name("NAME");
  cmd->add_option("--svg", o.svg_file, "draw the run (Fig. 8 style) to FILE")->type_name("FILE");
  cmd->add_flag("--json", o.json, "print one JSON object (format pathref-sim-result) instead of the report");
  cmd->add_flag("--full", o.full, "with --json: add the trajectory and the obstacle tracks");
  cmd->callback([&run] { run = [] { return run_simulate(o); }; });
}

}  // namespace pathref::cli
