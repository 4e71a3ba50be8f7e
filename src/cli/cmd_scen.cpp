// `pathref scen FILE.scen`: run every (every Nth) scenario of a MovingAI scenario file and compare
// pathref's length with the file's optimal length to the precision the file prints.
// Spec: spec/formats.md#cli-scen, spec/formats.md#movingai-scen, #scen-agreement.
#include <fmt/core.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "pathref/core/version.hpp"
#include "pathref/core/error.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/movingai.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/planners/search.hpp"

namespace pathref::cli {

namespace {

using Json = nlohmann::json;

struct ScenOptions {
  std::string file;
  std::string map;
  std::string algo = "astar";
  std::string every = "1";
  std::string digits = "6";
  std::string jobs = "1";
  bool json = false;
  MapReadArgs read;
};

/// A decimal integer option in [lo, hi], digits only; UsageError naming `option` otherwise.
std::int64_t parse_count(const std::string& text, const char* option, std::int64_t lo, std::int64_t hi) {
  const bool digits = !text.empty() && text.size() <= 10 && text.find_first_not_of("0123456789") == std::string::npos;
  std::int64_t v = 0;
  if (digits)
    for (const char c : text) v = v * 10 + (c - '0');
  if (!digits || v < lo || v > hi)
    throw UsageError(fmt::format("{} expects a decimal integer from {} to {}, got '{}'", option, lo, hi, text));
  return v;
}

/// A map used by the scenarios, with the path it was read from.
struct ScenMap {
  std::string path;
  io::MapFile map;
};

/// The file a scenario's map column names (spec/formats.md#cli-scen "Which map"): --map when given, else
/// the column resolved against the scenario file's directory, else its last path component there.
std::string resolve_map_path(const std::string& column, const ScenOptions& o, const io::Scenario& s) {
  namespace fs = std::filesystem;
  if (!o.map.empty()) return o.map;
  const fs::path dir = fs::path(o.file).parent_path();
  const fs::path direct = dir / fs::path(column);
  const fs::path base = dir / fs::path(column).filename();
  std::error_code ec;
  if (fs::exists(direct, ec)) return direct.string();
  if (fs::exists(base, ec)) return base.string();
  throw UsageError(fmt::format("cannot find the map '{}' named on line {} of '{}' (tried '{}' and '{}'); give "
                               "--map FILE",
                               column, s.line, o.file, direct.string(), base.string()));
}

/// The outcome of one scenario.
struct ScenResult {
  const io::Scenario* scenario = nullptr;
  std::size_t index = 0;  ///< 1-based position in the file
  double tolerance = 0.0;
  bool found = false;
  double length = 0.0;
  bool agree = false;
  double cpu_seconds = 0.0;  ///< CPU time of the thread running this scenario's planner call
};

/// CPU time of the calling thread, in seconds (CLOCK_THREAD_CPUTIME_ID: user + system).
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

int run_scen(const ScenOptions& o) {
  const planners::Planner* planner = planners::find_planner(o.algo);
  if (planner == nullptr) {
    std::string known;
    for (const auto& p : planners::planners()) known += (known.empty() ? "" : ", ") + p.name;
    throw UsageError(fmt::format("unknown --algo '{}' (known: {})", o.algo, known.empty() ? "none registered" : known));
  }
  const auto every = parse_count(o.every, "--every", 1, 2147483647);
  const int digits = static_cast<int>(parse_count(o.digits, "--digits", 0, 17));
  const auto jobs = static_cast<std::size_t>(parse_count(o.jobs, "--jobs", 1, 256));
  const io::MapReadOptions read = map_read_options(o.read, planner->bytes_per_cell);
  const std::string text = io::read_text_file(o.file, "scenario file");
  const io::ScenFile sf = io::parse_movingai_scen(text, o.file, read.limits);

  // Every map is read and every scenario checked against its map before anything runs.
  std::map<std::string, ScenMap> maps;  // by map column (one entry when --map is given)
  std::vector<const ScenMap*> map_of;
  for (const io::Scenario& s : sf.scenarios) {
    const std::string key = o.map.empty() ? s.map : std::string();
    auto it = maps.find(key);
    if (it == maps.end()) {
      const std::string path = resolve_map_path(s.map, o, s);
      it = maps.emplace(key, ScenMap{path, io::load_map_file(path, read).map}).first;
    }
    io::check_scenario_on_map(s, it->second.map.grid, it->second.path, o.file);
    map_of.push_back(&it->second);
  }

  // The scenarios to run, in file order; each result is stored at its own position, so the
  // report does not depend on --jobs (each worker has its own search workspace, and a search's
  // result does not depend on the workspace: spec/search.md "Reusing the search state").
  std::vector<std::size_t> to_run;
  for (std::size_t i = 0; i < sf.scenarios.size(); i += static_cast<std::size_t>(every)) to_run.push_back(i);
  std::vector<ScenResult> results(to_run.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto worker = [&] {
    search::Workspace workspace;
    try {
      for (std::size_t n = next++; n < to_run.size(); n = next++) {
        const std::size_t i = to_run[n];
        const io::Scenario& s = sf.scenarios[i];
        const grid::Grid& g = map_of[i]->map.grid;
        planners::Request req;
        req.grid = &g;
        req.start = io::from_movingai(s.start_x.value, s.start_y.value, g.height());
        req.goal = io::from_movingai(s.goal_x.value, s.goal_y.value, g.height());
        req.policy = grid::CornerPolicy::strict;
        req.seed = 1;
        req.workspace = &workspace;
        req.max_memory = read.limits.max_memory / jobs;  // spec/cli.md#memory: each worker's share
        const double t0 = thread_cpu_seconds();
        const planners::Result r = planner->run(req);
        const double t1 = thread_cpu_seconds();
        ScenResult& res = results[n];
        res.scenario = &s;
        res.index = i + 1;
        res.tolerance = io::agreement_tolerance(s.optimal, digits);
        res.found = r.found;
        res.length = r.found ? r.length : 0.0;
        res.agree = r.found && io::lengths_agree(r.length, s.optimal, res.tolerance);
        res.cpu_seconds = t1 - t0;
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = to_run.size();  // the other workers stop after their current scenario
    }
  };
  const auto wall0 = std::chrono::steady_clock::now();
  if (jobs == 1) {
    worker();
  } else {
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < jobs; ++t) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (failure) std::rethrow_exception(failure);
  double cpu = 0.0;
  for (const auto& r : results) cpu += r.cpu_seconds;
  const double per_query = results.empty() ? 0.0 : cpu / static_cast<double>(results.size());
  std::size_t agree = 0;
  for (const auto& r : results) agree += r.agree ? 1 : 0;
  const std::size_t differ = results.size() - agree;

  if (o.json) {
    Json j;
    j["format"] = "pathref-scen";
    j["format_version"] = 1;
    stamp_version(j);
    j["file"] = o.file;
    j["scen_version"] = sf.version;
    j["algo"] = o.algo;
    j["policy"] = "strict";
    j["every"] = every;
    j["writer_digits"] = digits;
    j["jobs"] = jobs;
    j["coordinates"] = "movingai: (0,0) is the upper-left cell, x = column, y = row counted downwards";
    Json jm = Json::array();
    for (const auto& [key, m] : maps)
      jm.push_back({{"file", m.path}, {"width", m.map.grid.width()}, {"height", m.map.grid.height()},
                    {"blocked", m.map.grid.blocked_count()}});
    j["maps"] = jm;
    Json js = Json::array();
    for (const auto& r : results) {
      const io::Scenario& s = *r.scenario;
      js.push_back({{"index", r.index},
                    {"line", s.line},
                    {"bucket", s.bucket},
                    {"map", s.map},
                    {"start", {s.start_x.value, s.start_y.value}},
                    {"goal", {s.goal_x.value, s.goal_y.value}},
                    {"optimal", s.optimal.text},
                    {"tolerance", r.tolerance},
                    {"found", r.found},
                    {"length", r.found ? Json(r.length) : Json(nullptr)},
                    {"agree", r.agree},
                    {"cpu_seconds", r.cpu_seconds}});
    }
    j["scenarios"] = js;
    j["summary"] = {{"scenarios", sf.scenarios.size()}, {"run", results.size()}, {"agree", agree}, {"differ", differ}};
    j["timing"] = {{"jobs", jobs},
                   {"cpu_seconds", cpu},
                   {"cpu_seconds_per_query", per_query},
                   {"wall_seconds", wall},
                   {"clock", "thread CPU time (user + system) of each planner call, summed; wall time of all runs"}};
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("pathref {} scen {}\n", std::string(pathref::version()), o.file);
    fmt::print("  version     {} ({} columns)\n", sf.version, sf.version == 1 ? 9 : 7);
    for (const auto& [key, m] : maps)
      fmt::print("  map         {} ({}x{}, {} blocked cells)\n", m.path, m.map.grid.width(), m.map.grid.height(),
                 m.map.grid.blocked_count());
    fmt::print("  algo        {}\n", o.algo);
    fmt::print("  policy      strict (diagonal needs both orthogonal neighbours free; MovingAI convention)\n");
    fmt::print("  every       {} ({} of {} scenarios)\n", every, results.size(), sf.scenarios.size());
    fmt::print("  tolerance   one unit in the last of max(printed, {}) significant digits\n", digits);
    fmt::print("  coordinates as in the file: (0,0) = upper-left cell, x = column, y = row downwards\n");
    for (const auto& r : results) {
      const io::Scenario& s = *r.scenario;
      const std::string mine = r.found ? fmt::format("{}", r.length) : std::string("none");
      const std::string verdict = r.agree ? "agree" : r.found ? fmt::format("DIFFER (tolerance {})", r.tolerance)
                                                              : std::string("DIFFER (no path found)");
      fmt::print("scenario {} line {} bucket {} start ({}, {}) goal ({}, {}) optimal {} pathref {} {}\n", r.index,
                 s.line, s.bucket, s.start_x.value, s.start_y.value, s.goal_x.value, s.goal_y.value, s.optimal.text,
                 mine, verdict);
    }
    fmt::print("summary: {} run, {} agree, {} differ ({} scenarios in the file, every {})\n", results.size(), agree,
               differ, sf.scenarios.size(), every);
    fmt::print("time: {:.3f} ms CPU per query ({:.3f} s CPU in {} planner calls, {:.3f} s wall, --jobs {})\n",
               per_query * 1e3, cpu, results.size(), wall, jobs);
  }
  return differ == 0 ? 0 : 1;
}

}  // namespace

void add_scen_command(CLI::App& app, Action& run) {
  static ScenOptions o;
  std::string algos;
  for (const auto& p : planners::planners()) algos += (algos.empty() ? "" : ", ") + p.name;
  auto* cmd = app.add_subcommand(
      "scen", "Run the scenarios of a MovingAI .scen file; compare each length with the file's optimal length");
  cmd->add_option("file", o.file, "the scenario file (version 1, or version 0 without width/height)")
      ->type_name("FILE.scen")
      ->required();
  cmd->add_option("--map", o.map, "the map for every scenario (default: the map column, see spec/formats.md#cli-scen)")
      ->type_name("FILE");
  cmd->add_option("--algo", o.algo, "planner: " + (algos.empty() ? std::string("(none registered)") : algos))
      ->type_name("NAME")
      ->capture_default_str();
  cmd->add_option("--every", o.every, "run scenarios 1, 1+N, 1+2N, ... (all lines are still checked)")
      ->type_name("N")
      ->capture_default_str();
  cmd->add_option("--digits", o.digits,
                  "significant digits the file's writer printed before dropping trailing zeros (0: as printed)")
      ->type_name("P")
      ->capture_default_str();
  cmd->add_option("--jobs", o.jobs,
                  "run the scenarios on N threads (1..256); the results and their order do not depend on N")
      ->type_name("N")
      ->capture_default_str();
  cmd->add_flag("--json", o.json, "print one JSON object (format pathref-scen 1) instead of the report");
  add_map_read_options(cmd, o.read);
  cmd->callback([&run] { run = [] { return run_scen(o); }; });
}

}  // namespace pathref::cli
