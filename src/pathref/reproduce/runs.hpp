#pragma once
/// \file runs.hpp
/// Repeated planner runs for `pathref reproduce`: one run of a registered planner with its
/// measurements (length, turns, iterations to converge, validity, drive time, wall-clock time),
/// the planners looked up by name at run time, the --quick parameter overrides, and the JSON of
/// runs and their summaries. Spec: spec/reproduce.md (reproduce.run, reproduce.quick,
/// reproduce.stats, reproduce.curves)
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/reproduce/report.hpp"

namespace pathref::reproduce {

using Json = nlohmann::json;

/// One run of one planner with everything reproduce measures.
struct RunRecord {
  std::uint32_t seed = 0;
  bool found = false;
  bool valid = false;               ///< metrics.valid-path re-check of the returned path
  std::string validation;           ///< its reason code, or "not_found"
  double length = 0.0;              ///< metrics.length of the path (found only)
  std::int64_t turns = 0;           ///< metrics.turns (found only)
  /// metrics.converge of the curve's last phase (reproduce.converge): for a hybrid whose extra
  /// has phase_iterations.ga = M_g, the last M_g values (its GA generations); else the whole curve
  std::optional<std::int64_t> converged_at;
  std::optional<std::int64_t> converged_at_whole;  ///< metrics.converge of the whole curve
  std::int64_t phase_offset = 0;    ///< index of the curve's first GA-phase value (0: whole curve)
  std::int64_t iterations = 0;      ///< the planner's iteration count
  std::optional<double> drive_time; ///< drive.path-time, Mecanum, 1 m cells, defaults (found only)
  double wall_ms = 0.0;             ///< wall-clock time of planner.run, ms (a measurement)
  std::vector<grid::Cell> path;
  std::vector<double> best_per_iteration;
  std::vector<double> mean_per_iteration;
  Json params_used;
  Json extra;
};

/// How run_series executes its runs (spec reproduce.execution): `run` runs them here on `jobs`
/// threads (results identical to one thread except the measured wall times); `emit` runs nothing
/// and appends one self-contained job (job_json) per run to `emitted`, the series then holding
/// placeholder runs that found nothing; `merge` runs nothing and takes each run's record from
/// `merged` (job key -> record_to_json_full), a missing one being a UsageError.
struct Execution {
  enum class Mode { run, emit, merge };
  Mode mode = Mode::run;
  int jobs = 1;
  std::vector<Json>* emitted = nullptr;
  const std::map<std::string, Json>* merged = nullptr;
  std::string merged_from;  ///< the --merge directory, for messages
};
/// The execution context in force (default: run on one thread). Spec: reproduce.execution.
[[nodiscard]] const Execution& current_execution();
/// Installs `e` as the execution context until the scope ends (then restores the previous one).
/// Not for concurrent reproductions: one reproduction at a time per process.
class ExecutionScope {
 public:
  explicit ExecutionScope(Execution e);
  ~ExecutionScope();
  ExecutionScope(const ExecutionScope&) = delete;
  ExecutionScope& operator=(const ExecutionScope&) = delete;

 private:
  Execution previous_;
};

/// Calls fn(0), ..., fn(n - 1), on current_execution().jobs threads in run mode (each index
/// exactly once, in any order; the caller writes results by index, so the outcome does not depend
/// on the schedule). The first exception by index is rethrown after all have finished.
void parallel_for(std::size_t n, const std::function<void(std::size_t)>& fn);

/// The identity of one run: context, planner, requested parameters, seed and a 64-bit FNV-1a
/// fingerprint of the map, endpoints and policy. Spec: reproduce.execution.
[[nodiscard]] std::string job_key(const std::string& context, const std::string& name, const Json& requested,
                                  const grid::Grid& g, grid::Cell start, grid::Cell goal,
                                  grid::CornerPolicy policy, std::uint32_t seed);

/// The self-contained job of one run: {"key", "context", "planner", "params", "seed", "policy",
/// "start", "goal", "rows"} (rows top first, spec/grid.md). Spec: reproduce.execution.
[[nodiscard]] Json job_json(const std::string& context, const std::string& name, const Json& requested,
                            const grid::Grid& g, grid::Cell start, grid::Cell goal, grid::CornerPolicy policy,
                            std::uint32_t seed);

/// Runs one job (job_json) and returns {"format": "pathref-reproduce-run", "format_version": 1,
/// "key", "record": record_to_json_full}. UsageError for a malformed job or an unknown planner.
/// Spec: reproduce.execution.
[[nodiscard]] Json run_job(const Json& job);

/// Every field of a RunRecord, losslessly (non-finite doubles as "inf", "-inf", "nan").
[[nodiscard]] Json record_to_json_full(const RunRecord& r);
/// The inverse of record_to_json_full (UsageError naming the field on malformed input).
[[nodiscard]] RunRecord record_from_json_full(const Json& j);

/// The planner registered as `name`, or nullptr (the caller reports "not available in this
/// build"). Spec: reproduce.run.
[[nodiscard]] const planners::Planner* available(const std::string& name);

/// Runs `planner` once (planner.run on a Request with these fields) and measures the result:
/// length = metrics.length of the returned path, turns = metrics.turns, converged_at =
/// metrics.converge of the GA phase of best_per_iteration for hybrids and of the whole curve
/// otherwise (reproduce.converge; nullopt when empty or without a finite value),
/// valid = metrics.valid-path, drive_time = drive.path-time (Mecanum base, cell 1 m, defaults)
/// when the path is an 8-neighbour chain, wall_ms = steady clock around planner.run.
/// Spec: reproduce.run. Pre: start/goal in bounds and free (the planner's own errors propagate).
[[nodiscard]] RunRecord run_once(const planners::Planner& planner, const grid::Grid& g,
                                 grid::Cell start, grid::Cell goal, grid::CornerPolicy policy,
                                 std::uint32_t seed, const Json& params);

/// The --quick overrides for a planner with these defaults: every integer parameter named
/// (after an optional "aco_" prefix) ants -> 8, iterations -> 10, generations -> 10,
/// population -> 20, when the default is larger; nothing else. Spec: reproduce.quick.
[[nodiscard]] Json quick_overrides(const Json& defaults);

/// The JSON of one run (no path and no curves: those are reproducible with `pathref plan`).
/// Spec: reproduce.json.
[[nodiscard]] Json run_to_json(const RunRecord& r);

/// Summary JSON of a planner's runs: {"runs", "found", "valid", "length", "turns",
/// "converged_at", "iterations", "drive_time_s", "wall_ms"}, each statistic an object
/// {"n", "mean", "std", "min", "max"} over the runs that found a path (null where undefined).
/// Spec: reproduce.stats.
[[nodiscard]] Json summary_json(const std::vector<RunRecord>& runs);

/// Pointwise mean of the curves (left-to-right sums over runs in run order) up to the longest
/// curve; a point is +inf (drawn as a gap) unless every curve has a finite value there.
/// Spec: reproduce.curves. Pre: none.
[[nodiscard]] std::vector<double> mean_curve(const std::vector<std::vector<double>>& curves);

/// The index of the best run: the shortest found path, then the fewest turns, then the lowest
/// seed; nullopt when no run found a path. Spec: reproduce.stats.
[[nodiscard]] std::optional<std::size_t> best_run(const std::vector<RunRecord>& runs);

/// The records of `runs` runs of planner `p` (registered as `name`) with the requested parameters,
/// seeds seed, seed + 1, ..., in run order, executed as current_execution() says: `run` on its
/// threads (run_once each), `emit` (placeholder records, one job_json per run appended),
/// `merge` (each record read from the merged results by job_key; missing: UsageError).
/// Spec: reproduce.execution. Pre: runs >= 1.
[[nodiscard]] std::vector<RunRecord> run_records(const planners::Planner& p, const std::string& name,
                                                 const Json& requested, const grid::Grid& g, grid::Cell start,
                                                 grid::Cell goal, grid::CornerPolicy policy, std::uint32_t seed,
                                                 std::int64_t runs, const std::string& context);

/// The JSON of a planner's series of runs on one map (spec reproduce.json, "results"):
/// {"available", "description", "requested" (the overrides: `params`, then the --quick ones of reproduce.quick computed on the
/// defaults overlaid with `params`, which win),
/// "params_used", "seeds": [first, last], "summary" (summary_json), "runs" (run_to_json each),
/// "best" (best_run: seed, length, turns, path, best/mean curves), "mean_best_curve",
/// "mean_iteration_curve", "phase_offset", and for hybrids (phase_offset > 0)
/// "mean_best_curve_phase", "mean_iteration_curve_phase"}. A planner that is not registered gives {"available": false,
/// "reason": "planner 'NAME' is not available in this build"}. Runs use seeds seed, seed + 1, ...
/// With `records_out`, the runs themselves (paths included) are also handed back, in run order
/// (Han's dynamic protocol simulates each run's path, reproduce.han.dynamic).
/// Spec: reproduce.run. Pre: runs >= 1.
[[nodiscard]] Json run_series(const std::string& name, const Json& params, const grid::Grid& g,
                              grid::Cell start, grid::Cell goal, grid::CornerPolicy policy,
                              std::uint32_t seed, std::int64_t runs, bool quick,
                              const Progress& progress, const std::string& context,
                              std::vector<RunRecord>* records_out = nullptr);

/// The per-run values of `key` ("length", "turns", "converged_at", ...) of a run_series result,
/// skipping nulls, in run order.
[[nodiscard]] std::vector<double> run_values(const Json& series, const std::string& key);

/// A double for JSON: null when not finite. Spec: reproduce.json.
[[nodiscard]] Json num(double v);
/// A JSON array of doubles with non-finite values as null.
[[nodiscard]] Json nums(const std::vector<double>& v);

}  // namespace pathref::reproduce
