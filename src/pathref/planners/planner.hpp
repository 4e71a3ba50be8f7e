#pragma once
/// \file planner.hpp
/// The common shape of every planner: a request (map, start, goal, corner policy, seed, named
/// parameters) and a result (path, metrics, per-iteration curves, extra planner-specific data).
/// Planners are registered by name; `pathref plan --algo NAME` looks them up here.
/// Spec: spec/cli.md#plan, each planner's own spec file for its parameters and draw order.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/core/memory.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::search {
class Workspace;  // search.hpp
}  // namespace pathref::search

namespace pathref::rng {
class Trace;  // rng/trace.hpp
}  // namespace pathref::rng

namespace pathref::planners {

using Json = nlohmann::json;

/// Asked at iteration boundaries: true = stop now (Request::interrupted).
using Interrupt = std::function<bool()>;

/// Throws pathref::Interrupted when `interrupted` is set and returns true (planner.cpp).
void stop_if_interrupted(const Interrupt& interrupted);

struct Request {
  const grid::Grid* grid = nullptr;
  grid::Cell start;
  grid::Cell goal;
  grid::CornerPolicy policy = grid::CornerPolicy::strict;
  std::uint32_t seed = 1;
  /// Parameter overrides by name (from --set key=value); every planner validates its own and
  /// throws UsageError naming an unknown key.
  Json params = Json::object();
  /// Optional reusable search state (not owned; one per thread) for the grid search planners
  /// astar and dijkstra: with it they allocate nothing per call once it has grown to the grid;
  /// results are the same with or without it (spec/search.md "Reusing the search state").
  /// Other planners ignore it.
  search::Workspace* workspace = nullptr;
  /// Optional draw trace (not owned): the planner's stream records every draw in it with its
  /// purpose (spec/rng.md#draw-traces; `pathref plan --trace`). Results are the same with or
  /// without it. Deterministic planners draw nothing.
  rng::Trace* trace = nullptr;
  /// Optional: asked at every iteration / generation boundary of the iterative planners; when it
  /// returns true the run stops by throwing pathref::Interrupted (the Python module's Ctrl-C).
  /// Empty: never asked. Asking draws nothing and changes no result.
  Interrupt interrupted;
  /// The memory limit of the run in bytes (spec/cli.md#memory; `--max-memory`): a planner
  /// estimates its need from the grid before allocating, counts its stored paths as they grow,
  /// and throws UsageError naming the estimate and this limit when it would exceed it. The
  /// limit changes no result of a run that stays within it.
  std::uint64_t max_memory = memory::default_limit;
};

struct Result {
  bool found = false;
  std::vector<grid::Cell> path;  ///< start ... goal, empty when !found
  double length = 0.0;           ///< sum of step costs (metrics.length)
  std::int64_t expansions = 0;   ///< nodes expanded (search planners); 0 otherwise
  std::int64_t iterations = 0;   ///< iterations run (iterative planners); 0 otherwise
  std::vector<double> best_per_iteration;  ///< best-so-far length after each iteration
  std::vector<double> mean_per_iteration;  ///< mean length of the iteration's solutions
  Json params_used = Json::object();       ///< every parameter value used, defaults included
  Json extra = Json::object();             ///< planner-specific output (e.g. winning phase)
};

struct Planner {
  std::string name;         ///< --algo value, e.g. "astar"
  std::string description;  ///< one line, with the paper it follows
  Json defaults;            ///< parameter name -> default value
  std::function<Result(const Request&)> run;
  /// Bytes per grid cell a run needs before its paths, the grid included (spec/cli.md#memory,
  /// each planner's "Memory"): `plan` and `scen` give it to the map reader, which refuses a map
  /// whose W x H x bytes_per_cell exceeds --max-memory before allocating its grid.
  std::uint64_t bytes_per_cell = 1;
};

/// Every registered planner, sorted by name.
[[nodiscard]] const std::vector<Planner>& planners();
/// nullptr if unknown.
[[nodiscard]] const Planner* find_planner(std::string_view name);

/// The registered planners' names, comma-separated, for messages ("known: ...").
[[nodiscard]] std::string planner_names();

/// The first key of `params` (an object) that `p` cannot take — an unknown key, or a value of
/// another JSON type than its default (merge_params' checks, one key at a time) — with
/// merge_params' message; nullopt when every key can be taken. For readers that report the key
/// at its place in a file (simulation scenarios: /planner/params/KEY).
[[nodiscard]] std::optional<std::pair<std::string, std::string>> first_bad_param(const Planner& p, const Json& params);

/// defaults overlaid with request.params; UsageError for a key not in defaults or a value of
/// another JSON type than its default.
[[nodiscard]] Json merge_params(const Json& defaults, const Json& overrides);

}  // namespace pathref::planners
