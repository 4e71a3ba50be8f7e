// `pathref check`: validate a path produced by another program on a map (spec/check.md):
// the first invalid step and why, length, turns, the optimum (Dijkstra) and the ratio,
// clearance; several paths at once (a folder or a JSON-lines file) with a summary.
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "pathref/core/version.hpp"
#include "pathref/core/error.hpp"
#include "pathref/io/path_check.hpp"
#include "pathref/io/path_file.hpp"
#include "pathref/reproduce/stats.hpp"
#include "pathref/rules/registry.hpp"

namespace pathref::cli {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct CheckOptions {
  std::string map_file, builtin, path;
  std::string path_format = "auto";
  std::string base, origin;  ///< "" = the format's default
  std::optional<std::string> policy, start, goal;
  bool json = false;
  std::string json_out;
  MapReadArgs read;
};

/// The files of --path: the file itself, or every regular file of a folder (sorted, not recursive).
std::vector<fs::path> path_inputs(const std::string& path) {
  if (!fs::is_directory(path)) return {fs::path(path)};
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(path))
    if (e.is_regular_file() && e.path().filename().string().front() != '.') files.push_back(e.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw UsageError("--path: the folder '" + path + "' has no file");
  return files;
}

bool is_json_lines(const fs::path& p) {
  const std::string ext = p.extension().string();
  return ext == ".jsonl" || ext == ".ndjson";
}

Json number_or_null(std::optional<double> v) { return v && std::isfinite(*v) ? rules::number(*v) : Json(nullptr); }

struct Endpoints {
  grid::Cell start, goal;
  std::string start_from, goal_from;
};

struct Checked {
  Json j;  ///< the per-path JSON object of spec/check.md#check-json
  bool valid = false;
  std::optional<double> length, ratio;
};

/// Checks one path (spec/check.md#verdict, #metrics) with the library's checker (io::check_path,
/// shared with the Python module); the optimum is computed once per (start, goal).
Checked check_one(const io::PathRecord& rec, const std::vector<grid::Cell>& path, const grid::Grid& g,
                  const Endpoints& e, grid::CornerPolicy policy,
                  std::map<std::pair<std::int64_t, std::int64_t>, std::optional<double>>& optimum_cache) {
  std::optional<double> optimum;
  if (g.free(e.start) && g.free(e.goal)) {
    const auto key = std::make_pair(g.index(e.start), g.index(e.goal));
    auto it = optimum_cache.find(key);
    if (it == optimum_cache.end()) it = optimum_cache.emplace(key, io::optimum_length(g, e.start, e.goal, policy)).first;
    optimum = it->second;
  }
  const io::PathReport r = io::check_path(g, path, e.start, e.goal, policy, optimum);
  Checked c;
  c.valid = r.check.valid;
  c.length = r.length;
  c.ratio = r.ratio;
  c.j = Json{{"name", rec.name},
             {"format", std::string(io::to_string(rec.format))},
             {"nodes", path.size()},
             {"start", {e.start.x, e.start.y}},
             {"start_from", e.start_from},
             {"goal", {e.goal.x, e.goal.y}},
             {"goal_from", e.goal_from}};
  c.j.update(io::path_report_json(r, path));
  return c;
}

Json summary_json(const std::vector<double>& values) {
  const reproduce::Summary s = reproduce::summarize(values);
  return Json{{"n", s.n}, {"mean", number_or_null(s.mean)}, {"sd", number_or_null(s.std)},
              {"min", number_or_null(s.min)}, {"max", number_or_null(s.max)}};
}

std::string shown(const Json& v) {
  if (v.is_null()) return "-";
  if (v.is_number_float()) return fmt::format("{:.6g}", v.get<double>());
  return v.dump();
}

int run_check(const CheckOptions& o) {
  const io::PathFormat format = io::parse_path_format(o.path_format);
  std::optional<grid::CornerPolicy> policy_opt;
  if (o.policy) policy_opt = grid::parse_corner_policy(*o.policy);
  const auto int_option = [](const std::string& text, const char* option) {
    if (text != "0" && text != "1") throw UsageError(fmt::format("{} expects 0 or 1, got '{}'", option, text));
    return std::int64_t{text == "1"};
  };
  std::optional<std::int64_t> base;
  if (!o.base.empty()) base = int_option(o.base, "--base");
  std::optional<io::RowOrigin> origin;
  if (!o.origin.empty()) origin = io::parse_row_origin(o.origin);
  std::optional<grid::Cell> start_arg, goal_arg;
  if (o.start) start_arg = parse_cell_arg(*o.start, "--start");
  if (o.goal) goal_arg = parse_cell_arg(*o.goal, "--goal");

  // Read every path first (all input is checked before anything is printed).
  std::vector<io::PathRecord> records;
  for (const fs::path& p : path_inputs(o.path)) {
    auto rs = io::parse_path_text(io::read_text_file(p.string(), "path file"), p.string(), format, is_json_lines(p));
    for (auto& r : rs) records.push_back(std::move(r));
  }
  for (const auto& r : records)
    if (r.format == io::PathFormat::plan && (base || origin))
      throw UsageError(r.name + " is a pathref-plan record (cells [x, y], base 0, origin lower): --base and --origin "
                                "apply to xy, node and rowcol paths");

  std::optional<RunMap> map;
  if (!o.map_file.empty() || !o.builtin.empty()) map = load_run_map(o.map_file, o.builtin, o.read);
  if (!map && records.front().format != io::PathFormat::plan)
    throw UsageError("give the map: --map FILE or --builtin NAME (only a pathref-plan record carries its map)");

  Json results = Json::array();
  std::vector<double> lengths, ratios;
  std::size_t n_valid = 0;
  std::map<std::pair<std::int64_t, std::int64_t>, std::optional<double>> cache;
  Json map_json;
  std::string policy_from;
  grid::CornerPolicy policy_used = grid::CornerPolicy::strict;
  for (const io::PathRecord& rec : records) {
    std::optional<io::PlanJsonView> view;
    if (rec.format == io::PathFormat::plan) view = io::plan_from_json(rec.plan, rec.name);
    const grid::Grid& g = map ? map->map.grid : view->grid;
    const std::int64_t b = base.value_or(rec.format == io::PathFormat::node || rec.format == io::PathFormat::rowcol ? 1 : 0);
    const io::RowOrigin org = origin.value_or(
        rec.format == io::PathFormat::node || rec.format == io::PathFormat::rowcol ? io::RowOrigin::upper
                                                                                   : io::RowOrigin::lower);
    const std::vector<grid::Cell> path = io::path_cells(rec, g.width(), g.height(), b, org);
    const auto pick = [&](const std::optional<grid::Cell>& arg, const char* option, std::optional<grid::Cell> from_plan,
                          const std::optional<grid::Cell>& from_map, bool first) -> std::pair<grid::Cell, std::string> {
      if (arg) return {*arg, option};
      if (from_plan) return {*from_plan, "the plan record"};
      if (from_map) return {*from_map, "the map"};
      if (path.empty()) return {grid::Cell{0, 0}, "none"};
      return {first ? path.front() : path.back(), first ? "the path's first node (not checked)" : "the path's last node (not checked)"};
    };
    const auto [s, s_from] = pick(start_arg, "--start", view ? std::optional<grid::Cell>(view->start) : std::nullopt,
                                  map ? map->map.start : std::nullopt, true);
    const auto [gl, g_from] = pick(goal_arg, "--goal", view ? std::optional<grid::Cell>(view->goal) : std::nullopt,
                                   map ? map->map.goal : std::nullopt, false);
    const grid::CornerPolicy policy = policy_opt ? *policy_opt : view ? view->policy : grid::CornerPolicy::strict;
    policy_used = policy;
    policy_from = policy_opt ? "--policy" : view ? "the plan record" : "default";
    Checked c = check_one(rec, path, g, Endpoints{s, gl, s_from, g_from}, policy, cache);
    c.j["policy"] = std::string(grid::to_string(policy));
    c.j["base"] = rec.format == io::PathFormat::plan ? 0 : b;
    c.j["origin"] = std::string(io::to_string(rec.format == io::PathFormat::plan ? io::RowOrigin::lower : org));
    c.j["cells"] = Json::array();
    for (const grid::Cell p : path) c.j["cells"].push_back({p.x, p.y});
    if (c.valid) {
      ++n_valid;
      if (c.length) lengths.push_back(*c.length);
      if (c.ratio) ratios.push_back(*c.ratio);
    }
    if (map_json.is_null())
      map_json = map ? Json{{"source", map->source.kind}, {"name", map->source.name},
                            {"file", map->source.file ? Json(*map->source.file) : Json(nullptr)},
                            {"width", g.width()}, {"height", g.height()}, {"blocked", g.blocked_count()}}
                     : Json{{"source", "plan"}, {"name", rec.name}, {"file", nullptr}, {"width", g.width()},
                            {"height", g.height()}, {"blocked", g.blocked_count()}};
    results.push_back(std::move(c.j));
  }
  const std::size_t n = records.size();
  Json doc{{"format", "pathref-check"},
                 {"format_version", 1},
                 {"map", map_json},
                 {"paths", results},
                 {"summary", {{"paths", n}, {"valid", n_valid}, {"invalid", n - n_valid},
                              {"length", summary_json(lengths)}, {"ratio", summary_json(ratios)}}}};
  stamp_version(doc);
  if (!o.json_out.empty()) write_output_file(o.json_out, doc.dump(2) + "\n");
  if (o.json) {
    fmt::print("{}\n", doc.dump(2));
  } else {
    fmt::print("pathref {} check\n", std::string(pathref::version()));
    fmt::print("  map         {} ({}{}, {}x{}, {} blocked cells)\n", map_json["name"].get<std::string>(),
               map_json["source"].get<std::string>(),
               map_json["file"].is_null() ? std::string() : " " + map_json["file"].get<std::string>(),
               map_json["width"].dump(), map_json["height"].dump(), map_json["blocked"].dump());
    fmt::print("  policy      {} ({}), from {}\n", grid::to_string(policy_used), policy_meaning(policy_used), policy_from);
    if (n == 1) {
      const Json& r = results[0];
      fmt::print("  path        {} ({}, base {}, origin {}), {} nodes\n", r["name"].get<std::string>(),
                 r["format"].get<std::string>(), r["base"].dump(), r["origin"].get<std::string>(), r["nodes"].dump());
      fmt::print("  start       ({}, {}) from {}\n", r["start"][0].dump(), r["start"][1].dump(),
                 r["start_from"].get<std::string>());
      fmt::print("  goal        ({}, {}) from {}\n", r["goal"][0].dump(), r["goal"][1].dump(),
                 r["goal_from"].get<std::string>());
      fmt::print("result\n");
      fmt::print("  valid       {}\n", r["valid"].get<bool>()
                                            ? std::string("yes")
                                            : fmt::format("NO: {} at node {}: {}", r["reason"].get<std::string>(),
                                                          r["index"].dump(), r["message"].get<std::string>()));
      fmt::print("  length      {}\n", r["length"].is_null() ? "-" : r["length"].dump());
      fmt::print("  turns       {}\n", r["turns"].is_null() ? "-" : r["turns"].dump());
      fmt::print("  optimum     {}\n", r["optimum"].is_null() ? "- (start or goal not free, or the goal is not reachable)"
                                                              : r["optimum"].dump() + " (dijkstra, same policy)");
      fmt::print("  ratio       {}\n", r["ratio"].is_null() ? "-" : r["ratio"].dump());
      fmt::print("  clearance   {}\n", r["clearance"].is_null() ? "-" : r["clearance"].dump() + " (cell units)");
    } else {
      fmt::print("{:<32} {:<5} {:<14} {:>6} {:>12} {:>6} {:>10} {:>10}\n", "path", "valid", "reason", "node", "length",
                 "turns", "ratio", "clearance");
      for (const Json& r : results)
        fmt::print("{:<32} {:<5} {:<14} {:>6} {:>12} {:>6} {:>10} {:>10}\n", r["name"].get<std::string>(),
                   r["valid"].get<bool>() ? "yes" : "NO", r["reason"].get<std::string>(),
                   r["index"].get<std::int64_t>() < 0 ? std::string("-") : r["index"].dump(), shown(r["length"]),
                   shown(r["turns"]), shown(r["ratio"]), shown(r["clearance"]));
      const Json& sm = doc["summary"];
      fmt::print("summary: {} paths, {} valid, {} invalid\n", n, n_valid, n - n_valid);
      for (const char* k : {"length", "ratio"}) {
        const Json& s = sm[k];
        fmt::print("  {:<6} of valid paths: n {}, mean {}, sd {}, min {}, max {}\n", k, s["n"].dump(), shown(s["mean"]),
                   shown(s["sd"]), shown(s["min"]), shown(s["max"]));
      }
    }
    if (!o.json_out.empty()) fmt::print("wrote {}\n", o.json_out);
  }
  return n_valid == n ? 0 : 1;
}

}  // namespace

void add_check_command(CLI::App& app, Action& run) {
  static CheckOptions o;
  auto* cmd = app.add_subcommand(
      "check", "Check a path produced elsewhere on a map: the first invalid step and why, length, turns, the optimum "
               "and the ratio, clearance (spec/check.md)");
  auto* map_opt = cmd->add_option("--map", o.map_file, "the map file (any format pathref reads)")->type_name("FILE");
  cmd->add_option("--builtin", o.builtin, "a built-in map (pathref maps)")->type_name("NAME")->excludes(map_opt);
  cmd->add_option("--path", o.path,
                  "the path: a file (pathref-plan JSON, JSON [[x,y],...], x y lines, node numbers, row col lines), "
                  "a JSON-lines file (.jsonl, one path a line) or a folder of such files")
      ->type_name("FILE|DIR")
      ->required();
  cmd->add_option("--path-format", o.path_format, "auto, plan, xy, node (MATLAB node numbers), rowcol (MATLAB [row, col])")
      ->type_name("FORMAT")
      ->check(CLI::IsMember({"auto", "plan", "xy", "node", "rowcol"}))
      ->capture_default_str();
  cmd->add_option("--base", o.base, "index base of the numbers: 0 or 1 (default: 0 for xy, 1 for node and rowcol)")
      ->type_name("0|1");
  cmd->add_option("--origin", o.origin,
                  "where row 0 is: lower (pathref, y up) or upper (first matrix row on top; default for node and rowcol)")
      ->type_name("lower|upper")
      ->check(CLI::IsMember({"lower", "upper"}));
  cmd->add_option("--policy", o.policy, "corner policy (default: the plan record's, else strict)")
      ->type_name("never|strict|one|always")
      ->check(CLI::IsMember({"never", "strict", "one", "always"}));
  cmd->add_option("--start", o.start, "the start cell X,Y (default: the plan record's, else the map's)")->type_name("X,Y");
  cmd->add_option("--goal", o.goal, "the goal cell X,Y (default: the plan record's, else the map's)")->type_name("X,Y");
  cmd->add_flag("--json", o.json, "print the pathref-check JSON object instead of the report");
  cmd->add_option("--json-out", o.json_out, "also write the JSON object to FILE")->type_name("FILE");
  add_map_read_options(cmd, o.read);
  cmd->callback([&run] { run = [] { return run_check(o); }; });
}

}  // namespace pathref::cli
