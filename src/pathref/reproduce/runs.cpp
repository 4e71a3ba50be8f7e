#include "pathref/reproduce/runs.hpp"

#include <fmt/core.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <thread>

#include "pathref/core/error.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/reproduce/stats.hpp"
#include "pathref/vehicle/drive.hpp"

namespace pathref::reproduce {

const planners::Planner* available(const std::string& name) { return planners::find_planner(name); }

namespace {
bool eight_neighbour_chain(const std::vector<grid::Cell>& path) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    const std::int64_t dx = path[i].x - path[i - 1].x;
    const std::int64_t dy = path[i].y - path[i - 1].y;
    if ((dx == 0 && dy == 0) || dx < -1 || dx > 1 || dy < -1 || dy > 1) return false;
  }
  return !path.empty();
}
std::optional<std::int64_t> converge_or_null(const std::vector<double>& curve) {
  bool any_finite = false;
  for (const double v : curve) {
    if (std::isnan(v) || v == -std::numeric_limits<double>::infinity()) return std::nullopt;
    any_finite = any_finite || std::isfinite(v);
  }
  if (!any_finite) return std::nullopt;
  return metrics::iterations_to_converge(curve);
}
}  // namespace

RunRecord run_once(const planners::Planner& planner, const grid::Grid& g, grid::Cell start,
                   grid::Cell goal, grid::CornerPolicy policy, std::uint32_t seed,
                   const Json& params) {
  planners::Request req;
  req.grid = &g;
  req.start = start;
  req.goal = goal;
  req.policy = policy;
  req.seed = seed;
  req.params = params;
  const auto t0 = std::chrono::steady_clock::now();
  planners::Result res = planner.run(req);
  const auto t1 = std::chrono::steady_clock::now();
  RunRecord r;
  r.seed = seed;
  r.wall_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  r.found = res.found && !res.path.empty();
  r.iterations = res.iterations;
  r.params_used = res.params_used;
  r.extra = res.extra;
  r.best_per_iteration = res.best_per_iteration;
  r.mean_per_iteration = res.mean_per_iteration;
  r.converged_at_whole = converge_or_null(r.best_per_iteration);
  r.converged_at = r.converged_at_whole;
  const Json& ga_phase = at_or_null(r.extra, {"phase_iterations", "ga"});
  if (ga_phase.is_number_integer()) {
    const auto mg = ga_phase.get<std::int64_t>();
    const auto total = static_cast<std::int64_t>(r.best_per_iteration.size());
    if (mg >= 0 && mg <= total) {
      r.phase_offset = total - mg;
      const std::vector<double> tail(r.best_per_iteration.begin() + r.phase_offset, r.best_per_iteration.end());
      r.converged_at = converge_or_null(tail);
    }
  }
  if (r.found) {
    r.path = std::move(res.path);
    r.length = metrics::path_length(r.path);
    r.turns = metrics::turn_count(r.path);
    const metrics::PathCheck check = metrics::validate_path(g, r.path, start, goal, policy);
    r.valid = check.valid;
    r.validation = check.reason;
    if (eight_neighbour_chain(r.path))
      r.drive_time = vehicle::path_time(r.path, 1.0, vehicle::Base::mecanum, vehicle::DriveParams{}).time;
  } else {
    r.validation = "not_found";
  }
  return r;
}

Json quick_overrides(const Json& defaults) {
  Json out = Json::object();
  if (!defaults.is_object()) return out;
  for (auto it = defaults.begin(); it != defaults.end(); ++it) {
    const std::string& key = it.key();
    const Json& value = it.value();
    if (!value.is_number_integer()) continue;
    const std::string base = key.rfind("aco_", 0) == 0 ? key.substr(4) : key;
    std::int64_t q = 0;
    if (base == "ants") q = 8;
    else if (base == "iterations" || base == "generations") q = 10;
    else if (base == "population") q = 20;
    else continue;
    if (value.get<std::int64_t>() > q) out[key] = q;
  }
  return out;
}

Json num(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json nums(const std::vector<double>& v) {
  Json a = Json::array();
  for (const double x : v) a.push_back(num(x));
  return a;
}

Json run_to_json(const RunRecord& r) {
  Json j = Json::object();
  j["seed"] = r.seed;
  j["found"] = r.found;
  j["valid"] = r.valid;
  j["validation"] = r.validation;
  j["length"] = r.found ? num(r.length) : Json(nullptr);
  j["turns"] = r.found ? Json(r.turns) : Json(nullptr);
  j["converged_at"] = r.converged_at ? Json(*r.converged_at) : Json(nullptr);
  j["converged_at_whole_curve"] = r.converged_at_whole ? Json(*r.converged_at_whole) : Json(nullptr);
  j["iterations"] = r.iterations;
  j["drive_time_s"] = r.drive_time ? num(*r.drive_time) : Json(nullptr);
  j["wall_ms"] = num(r.wall_ms);
  if (r.extra.is_object() && r.extra.contains("phase")) j["phase"] = r.extra.at("phase");
  if (r.extra.is_object() && r.extra.contains("failure") && r.extra.at("failure").is_string())
    j["failure"] = r.extra.at("failure");
  // The GA population the planner actually built (GA-based planners, spec/shi2022-ga.md "Population").
  if (r.extra.is_object()) {
    Json pop = Json::object();
    for (const char* k : {"population_size", "population_init", "population_aco", "init_built", "init_exhausted", "init_chains"})
      if (r.extra.contains(k)) pop[k] = r.extra.at(k);
    if (!pop.empty()) j["population"] = pop;
  }
  return j;
}

namespace {
Json stat_json(const std::vector<double>& values) {
  const Summary s = summarize(values);
  auto opt = [](const std::optional<double>& v) { return v ? num(*v) : Json(nullptr); };
  return Json{{"n", s.n}, {"mean", opt(s.mean)}, {"std", opt(s.std)}, {"min", opt(s.min)}, {"max", opt(s.max)}};
}
}  // namespace

Json summary_json(const std::vector<RunRecord>& runs) {
  std::vector<double> length, turns, conv, conv_whole, iters, drive, wall;
  std::int64_t found = 0, valid = 0;
  for (const RunRecord& r : runs) {
    wall.push_back(r.wall_ms);
    if (!r.found) continue;
    ++found;
    if (r.valid) ++valid;
    length.push_back(r.length);
    turns.push_back(static_cast<double>(r.turns));
    if (r.converged_at) conv.push_back(static_cast<double>(*r.converged_at));
    if (r.converged_at_whole) conv_whole.push_back(static_cast<double>(*r.converged_at_whole));
    iters.push_back(static_cast<double>(r.iterations));
    if (r.drive_time) drive.push_back(*r.drive_time);
  }
  return Json{{"runs", runs.size()},        {"found", found},
              {"valid", valid},             {"length", stat_json(length)},
              {"turns", stat_json(turns)},  {"converged_at", stat_json(conv)},
              {"converged_at_whole_curve", stat_json(conv_whole)},
              {"iterations", stat_json(iters)}, {"drive_time_s", stat_json(drive)},
              {"wall_ms", stat_json(wall)}};
}

std::vector<double> mean_curve(const std::vector<std::vector<double>>& curves) {
  std::size_t len = 0;
  for (const auto& c : curves) len = std::max(len, c.size());
  std::vector<double> out(len, std::numeric_limits<double>::infinity());
  if (curves.empty()) return out;
  for (std::size_t t = 0; t < len; ++t) {
    double sum = 0.0;
    bool ok = true;
    for (const auto& c : curves) {
      if (t >= c.size() || !std::isfinite(c[t])) {
        ok = false;
        break;
      }
      sum += c[t];
    }
    if (ok) out[t] = sum / static_cast<double>(curves.size());
  }
  return out;
}

std::optional<std::size_t> best_run(const std::vector<RunRecord>& runs) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunRecord& r = runs[i];
    if (!r.found) continue;
    if (!best) {
      best = i;
      continue;
    }
    const RunRecord& b = runs[*best];
    if (r.length < b.length || (r.length == b.length && (r.turns < b.turns ||
                                                         (r.turns == b.turns && r.seed < b.seed))))
      best = i;
  }
  return best;
}

}  // namespace pathref::reproduce

namespace pathref::reproduce {

std::vector<RunRecord> run_records(const planners::Planner& p, const std::string& name, const Json& requested,
                                   const grid::Grid& g, grid::Cell start, grid::Cell goal, grid::CornerPolicy policy,
                                   std::uint32_t seed, std::int64_t runs, const std::string& context) {
  require(runs >= 1, "run_records: runs must be >= 1");
  std::vector<RunRecord> records(static_cast<std::size_t>(runs));
  const Execution& ex = current_execution();
  const auto seed_of = [&](std::size_t i) { return static_cast<std::uint32_t>(seed + static_cast<std::uint64_t>(i)); };
  if (ex.mode == Execution::Mode::run) {
    parallel_for(records.size(), [&](std::size_t i) { records[i] = run_once(p, g, start, goal, policy, seed_of(i), requested); });
    return records;
  }
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (ex.mode == Execution::Mode::emit) {
      if (ex.emitted != nullptr) ex.emitted->push_back(job_json(context, name, requested, g, start, goal, policy, seed_of(i)));
      records[i].seed = seed_of(i);
      records[i].validation = "not_found";
      records[i].params_used = requested;
      continue;
    }
    const std::string key = job_key(context, name, requested, g, start, goal, policy, seed_of(i));
    const auto it = ex.merged == nullptr ? decltype(ex.merged->end()){} : ex.merged->find(key);
    if (ex.merged == nullptr || it == ex.merged->end())
      throw UsageError(fmt::format("--merge: no result for the run '{}' in '{}' ({} results read)", key,
                                   ex.merged_from, ex.merged == nullptr ? 0 : ex.merged->size()));
    records[i] = record_from_json_full(it->second);
  }
  return records;
}

Json run_series(const std::string& name, const Json& params, const grid::Grid& g, grid::Cell start,
                grid::Cell goal, grid::CornerPolicy policy, std::uint32_t seed, std::int64_t runs,
                bool quick, const Progress& progress, const std::string& context,
                std::vector<RunRecord>* records_out) {
  require(runs >= 1, "run_series: runs must be >= 1");
  const planners::Planner* p = available(name);
  if (p == nullptr) {
    const std::string reason = "planner '" + name + "' is not available in this build";
    if (progress) progress(context + ": " + reason);
    return Json{{"available", false}, {"reason", reason}};
  }
  Json requested = params.is_object() ? params : Json::object();
  if (quick) {
    Json merged = p->defaults;
    for (auto it = requested.begin(); it != requested.end(); ++it) merged[it.key()] = it.value();
    const Json quick_params = quick_overrides(merged);
    for (auto it = quick_params.begin(); it != quick_params.end(); ++it) requested[it.key()] = it.value();
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<RunRecord> records = run_records(*p, name, requested, g, start, goal, policy, seed, runs, context);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Json out = Json::object();
  out["available"] = true;
  out["description"] = p->description;
  if (!requested.empty()) {  // the description names the planner's defaults: say what this series overrode
    std::string o;
    for (auto it = requested.begin(); it != requested.end(); ++it)
      o += (o.empty() ? "" : ", ") + it.key() + " = " + (it.value().is_string() ? it.value().get<std::string>() : it.value().dump());
    out["description"] = p->description + " [these runs override the defaults: " + o + "]";
  }
  out["requested"] = requested;
  out["params_used"] = records.front().params_used;
  out["seeds"] = Json::array({records.front().seed, records.back().seed});
  out["summary"] = summary_json(records);
  Json rs = Json::array();
  std::vector<std::vector<double>> best_curves, mean_curves, best_phase, mean_phase;
  for (const RunRecord& r : records) {
    rs.push_back(run_to_json(r));
    best_curves.push_back(r.best_per_iteration);
    mean_curves.push_back(r.mean_per_iteration);
    const auto off = static_cast<std::size_t>(r.phase_offset);
    best_phase.emplace_back(r.best_per_iteration.begin() + static_cast<std::ptrdiff_t>(std::min(off, r.best_per_iteration.size())),
                            r.best_per_iteration.end());
    mean_phase.emplace_back(r.mean_per_iteration.begin() + static_cast<std::ptrdiff_t>(std::min(off, r.mean_per_iteration.size())),
                            r.mean_per_iteration.end());
  }
  out["runs"] = rs;
  if (const auto b = best_run(records)) {
    const RunRecord& r = records[*b];
    Json path = Json::array();
    for (const grid::Cell c : r.path) path.push_back(Json::array({c.x, c.y}));
    out["best"] = Json{{"seed", r.seed},
                       {"length", num(r.length)},
                       {"turns", r.turns},
                       {"path", path},
                       {"best_per_iteration", nums(r.best_per_iteration)},
                       {"mean_per_iteration", nums(r.mean_per_iteration)}};
  } else {
    out["best"] = nullptr;
  }
  out["mean_best_curve"] = nums(mean_curve(best_curves));
  out["mean_iteration_curve"] = nums(mean_curve(mean_curves));
  out["phase_offset"] = records.front().phase_offset;
  if (records.front().phase_offset > 0) {
    out["mean_best_curve_phase"] = nums(mean_curve(best_phase));
    out["mean_iteration_curve_phase"] = nums(mean_curve(mean_phase));
  }
  if (progress)
    progress(fmt::format("{}: {} x{} done in {:.1f} s ({} found)", context, name, runs, secs,
                         out["summary"]["found"].get<std::int64_t>()));
  if (records_out != nullptr) *records_out = std::move(records);
  return out;
}

namespace {
Execution& execution_slot() {
  static Execution e;
  return e;
}

Json full_num(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}
double full_num_from(const Json& v, const char* what) {
  if (v.is_number()) return v.get<double>();
  if (v.is_string()) {
    const auto s = v.get<std::string>();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  }
  throw UsageError(std::string("run record: '") + what + "' must be a number");
}
Json full_nums(const std::vector<double>& v) {
  Json a = Json::array();
  for (const double x : v) a.push_back(full_num(x));
  return a;
}
std::vector<double> full_nums_from(const Json& v, const char* what) {
  if (!v.is_array()) throw UsageError(std::string("run record: '") + what + "' must be an array");
  std::vector<double> out;
  out.reserve(v.size());
  for (const Json& x : v) out.push_back(full_num_from(x, what));
  return out;
}
const Json& field(const Json& j, const char* key) {
  if (!j.is_object() || !j.contains(key)) throw UsageError(std::string("run record: missing '") + key + "'");
  return j.at(key);
}
}  // namespace

const Execution& current_execution() { return execution_slot(); }

ExecutionScope::ExecutionScope(Execution e) : previous_(execution_slot()) {
  require(e.jobs >= 1, "ExecutionScope: jobs must be >= 1");
  execution_slot() = std::move(e);
}
ExecutionScope::~ExecutionScope() { execution_slot() = previous_; }

void parallel_for(std::size_t n, const std::function<void(std::size_t)>& fn) {
  const auto threads = static_cast<std::size_t>(std::max(1, current_execution().jobs));
  if (threads == 1 || n <= 1) {
    for (std::size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        fn(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < std::min(threads, n); ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

std::string job_key(const std::string& context, const std::string& name, const Json& requested, const grid::Grid& g,
                    grid::Cell start, grid::Cell goal, grid::CornerPolicy policy, std::uint32_t seed) {
  std::uint64_t h = 14695981039346656037ULL;
  auto mix = [&h](std::string_view s) {
    for (const char ch : s) {
      h ^= static_cast<unsigned char>(ch);
      h *= 1099511628211ULL;
    }
  };
  for (const std::string& row : g.to_rows_top_first()) {
    mix(row);
    mix("\n");
  }
  mix(fmt::format("{},{};{},{};{}", start.x, start.y, goal.x, goal.y, grid::to_string(policy)));
  return fmt::format("{}|{}|{}|{}|{:016x}", context, name, requested.dump(), seed, h);
}

Json job_json(const std::string& context, const std::string& name, const Json& requested, const grid::Grid& g,
              grid::Cell start, grid::Cell goal, grid::CornerPolicy policy, std::uint32_t seed) {
  return Json{{"key", job_key(context, name, requested, g, start, goal, policy, seed)},
              {"context", context},
              {"planner", name},
              {"params", requested},
              {"seed", seed},
              {"policy", std::string(grid::to_string(policy))},
              {"start", Json::array({start.x, start.y})},
              {"goal", Json::array({goal.x, goal.y})},
              {"rows", grid::grid_to_json(g)}};
}

Json record_to_json_full(const RunRecord& r) {
  Json path = Json::array();
  for (const grid::Cell c : r.path) path.push_back(Json::array({c.x, c.y}));
  return Json{{"seed", r.seed},
              {"found", r.found},
              {"valid", r.valid},
              {"validation", r.validation},
              {"length", full_num(r.length)},
              {"turns", r.turns},
              {"converged_at", r.converged_at ? Json(*r.converged_at) : Json(nullptr)},
              {"converged_at_whole", r.converged_at_whole ? Json(*r.converged_at_whole) : Json(nullptr)},
              {"phase_offset", r.phase_offset},
              {"iterations", r.iterations},
              {"drive_time", r.drive_time ? full_num(*r.drive_time) : Json(nullptr)},
              {"wall_ms", full_num(r.wall_ms)},
              {"path", path},
              {"best_per_iteration", full_nums(r.best_per_iteration)},
              {"mean_per_iteration", full_nums(r.mean_per_iteration)},
              {"params_used", r.params_used},
              {"extra", r.extra}};
}

RunRecord record_from_json_full(const Json& j) {
  RunRecord r;
  try {
    r.seed = field(j, "seed").get<std::uint32_t>();
    r.found = field(j, "found").get<bool>();
    r.valid = field(j, "valid").get<bool>();
    r.validation = field(j, "validation").get<std::string>();
    r.length = full_num_from(field(j, "length"), "length");
    r.turns = field(j, "turns").get<std::int64_t>();
    if (!field(j, "converged_at").is_null()) r.converged_at = field(j, "converged_at").get<std::int64_t>();
    if (!field(j, "converged_at_whole").is_null()) r.converged_at_whole = field(j, "converged_at_whole").get<std::int64_t>();
    r.phase_offset = field(j, "phase_offset").get<std::int64_t>();
    r.iterations = field(j, "iterations").get<std::int64_t>();
    if (!field(j, "drive_time").is_null()) r.drive_time = full_num_from(field(j, "drive_time"), "drive_time");
    r.wall_ms = full_num_from(field(j, "wall_ms"), "wall_ms");
    for (const Json& c : field(j, "path")) r.path.push_back(grid::cell_from_json(c));
    r.best_per_iteration = full_nums_from(field(j, "best_per_iteration"), "best_per_iteration");
    r.mean_per_iteration = full_nums_from(field(j, "mean_per_iteration"), "mean_per_iteration");
    r.params_used = field(j, "params_used");
    r.extra = field(j, "extra");
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(std::string("run record: malformed (") + e.what() + ")");
  }
  return r;
}

Json run_job(const Json& job) {
  try {
    const std::string name = field(job, "planner").get<std::string>();
    const planners::Planner* p = available(name);
    if (p == nullptr) throw UsageError("run-job: planner '" + name + "' is not available in this build");
    const grid::Grid g = grid::grid_from_json(field(job, "rows"));
    const grid::Cell start = grid::cell_from_json(field(job, "start"));
    const grid::Cell goal = grid::cell_from_json(field(job, "goal"));
    const grid::CornerPolicy policy = grid::parse_corner_policy(field(job, "policy").get<std::string>());
    const auto seed = field(job, "seed").get<std::uint32_t>();
    const Json& params = field(job, "params");
    const std::string key = job_key(field(job, "context").get<std::string>(), name, params, g, start, goal, policy, seed);
    if (key != field(job, "key").get<std::string>())
      throw UsageError("run-job: the job's key does not match its contents (edited job?)");
    const RunRecord r = run_once(*p, g, start, goal, policy, seed, params);
    return Json{{"format", "pathref-reproduce-run"}, {"format_version", 1}, {"key", key}, {"record", record_to_json_full(r)}};
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(std::string("run-job: malformed job (") + e.what() + ")");
  }
}

std::vector<double> run_values(const Json& series, const std::string& key) {
  std::vector<double> v;
  const Json& runs = at_or_null(series, {"runs"});
  if (!runs.is_array()) return v;
  for (const Json& r : runs) {
    const Json& x = at_or_null(r, {key});
    if (x.is_number()) v.push_back(x.get<double>());
  }
  return v;
}

}  // namespace pathref::reproduce
