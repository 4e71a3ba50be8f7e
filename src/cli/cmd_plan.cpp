// `pathref plan` (run one planner on one map, print / write JSON / draw SVG) and `pathref maps`
// (list the built-in maps, print one as pathref-grid text). Spec: spec/cli.md#plan, #maps.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/core/version.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/core/error.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/io/builtin_maps.hpp"
#include "pathref/io/grid_text.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/plan_json.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/planners/default_policy.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/trace.hpp"

namespace pathref::cli {

/// "X,Y" with X and Y non-negative decimal integers (at most 18 digits) -> Cell; UsageError
/// naming `option` otherwise.
grid::Cell parse_cell_arg(const std::string& text, const char* option) {
  const auto bad = [&] {
    return UsageError(fmt::format("{} expects X,Y (two non-negative integers), got '{}'", option, text));
  };
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw bad();
  const auto number = [&](const std::string& s) {
    if (s.empty() || s.size() > 18) throw bad();
    std::int64_t v = 0;
    for (const char c : s) {
      if (c < '0' || c > '9') throw bad();
      v = v * 10 + (c - '0');
    }
    return v;
  };
  return grid::Cell{number(text.substr(0, comma)), number(text.substr(comma + 1))};
}

namespace {

using Json = planners::Json;

/// Everything `pathref plan` was given on the command line.
struct PlanOptions {
  std::string map_file;
  std::string builtin;
  std::string algo;
  std::optional<std::string> start;  ///< nullopt: not given (an empty --start "" is an error)
  std::optional<std::string> goal;
  std::optional<std::string> start_xy;  ///< continuous planners only (spec/cli.md#plan-continuous)
  std::optional<std::string> goal_xy;
  bool policy_given = false;
  std::string seed = "1";  ///< decimal text; parsed by parse_seed (CLI11 would read 010 as octal)
  std::string policy;  ///< empty: the planner's default corner policy
  std::vector<std::string> sets;
  bool json = false;
  std::string json_out;
  std::string svg;
  bool cell_numbers = false;  ///< --cell-numbers (figures.cell-numbers): grid planners' figures only
  std::string trace;  ///< --trace FILE (spec/rng.md#draw-traces)
  MapReadArgs read;  ///< --format, --swamp, --water, --max-side, --max-cells (spec/formats.md#cli-map-options)
};

/// The --seed value: a decimal integer in [0, 2^32 - 1], digits only (no sign, no 0x, leading
/// zeros are decimal). UsageError otherwise.
std::uint32_t parse_seed(const std::string& text) {
  const bool digits = !text.empty() && text.size() <= 10 &&
                      text.find_first_not_of("0123456789") == std::string::npos;
  std::uint64_t v = 0;
  if (digits)
    for (const char c : text) v = v * 10 + static_cast<std::uint64_t>(c - '0');
  if (!digits || v > 0xFFFFFFFFu)
    throw UsageError("--seed expects a decimal integer from 0 to 4294967295, got '" + text + "'");
  return static_cast<std::uint32_t>(v);
}

/// --set key=value ...: the value is JSON when it parses as JSON, otherwise a plain string (the
/// same rule as `pathref eval`). UsageError for a missing '=', an empty key or a repeated key.
Json parse_sets(const std::vector<std::string>& sets) {
  Json out = Json::object();
  for (const std::string& a : sets) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set expects key=value, got '" + a + "'");
    const std::string key = a.substr(0, eq);
    if (out.contains(key)) throw UsageError("--set " + key + " given more than once");
    const std::string text = a.substr(eq + 1);
    std::optional<Json> value = io::parse_cli_json_value(text, "--set " + key);
    out[key] = value ? std::move(*value) : Json(text);
  }
  return out;
}

/// A parameter value as --set would accept it back: strings bare unless they would parse as
/// JSON, everything else as JSON.
std::string set_syntax(const Json& v) {
  if (v.is_string()) {
    const auto& s = v.get_ref<const std::string&>();
    try {
      return io::parse_cli_json_value(s, "a parameter") ? v.dump() : s;
    } catch (const UsageError&) {  // JSON beyond the value limits: quoted, so it reads back as this string
      return v.dump();
    }
  }
  return v.dump();
}

/// Checks that an endpoint is a free cell of the map; UsageError naming the option otherwise.
void check_endpoint(const grid::Grid& g, grid::Cell c, const char* which) {
  if (!g.in_bounds(c))
    throw UsageError(fmt::format("{} ({}, {}) is outside the {}x{} map", which, c.x, c.y, g.width(),
                                 g.height()));
  if (g.blocked(c))
    throw UsageError(fmt::format("{} ({}, {}) is a blocked cell", which, c.x, c.y));
}

/// The endpoint from the option if given, else the map's own; UsageError if neither.
grid::Cell endpoint(const std::optional<std::string>& option_value,
                    const std::optional<grid::Cell>& from_map, const char* option, const char* which) {
  if (option_value) return parse_cell_arg(*option_value, option);
  if (from_map) return *from_map;
  throw UsageError(fmt::format("the map defines no {0}: give {1} X,Y", which, option));
}

std::string cells_text(const std::vector<grid::Cell>& path) {
  std::string out;
  for (const auto& c : path) out += fmt::format("{}({},{})", out.empty() ? "" : " ", c.x, c.y);
  return out;
}

/// Why a run found no path, from its extra.failure (spec/cli.md#plan, "Exit codes"): only a
/// search that exhausted the reachable cells proves the goal unreachable; a stochastic planner that
/// gave up says what it gave up on.
std::string why_not_found(const planners::Result& r) {
  const std::string failure =
      r.extra.is_object() && r.extra.contains("failure") && r.extra.at("failure").is_string()
          ? r.extra.at("failure").get<std::string>()
          : std::string();
  if (failure == "init_attempts_exhausted")
    return fmt::format(
        "failure init_attempts_exhausted: the GA initialisation gave up after {} random chains, "
        "init_attempts of one individual all rejected; this does not mean the goal is unreachable "
        "(try another seed, --set init_attempts=N or --set illegal_step=repair)",
        r.extra.value("init_chains", std::int64_t{0}));
  if (failure == "row_blocked")
    return "failure row_blocked: a row between start and goal has no free cell, so the goal is not "
           "reachable";
  if (!failure.empty()) return "failure " + failure;
  if (r.iterations > 0 || !r.best_per_iteration.empty())
    return "no ant or individual reached the goal in the iterations run; this does not prove the "
           "goal unreachable";
  return "the goal is not reachable";
}

/// The human-readable report of a run: what was used, then what came out.
void print_report(const io::PlanRecord& rec, const grid::Grid& g, const Json& j,
                  bool policy_is_default) {
  fmt::print("pathref {} plan\n", std::string(pathref::version()));
  fmt::print("  map         {} ({}{}, {}x{}, {} blocked cells)\n", rec.map.name, rec.map.kind,
             rec.map.file ? " " + *rec.map.file : std::string(), g.width(), g.height(),
             g.blocked_count());
  fmt::print("  algo        {}\n", rec.algo);
  fmt::print("  policy      {} ({}){}\n", grid::to_string(rec.policy), policy_meaning(rec.policy),
             policy_is_default ? ", the planner's default" : "");
  fmt::print("  seed        {}\n", rec.seed);
  std::string params;
  for (const auto& [k, v] : rec.params.items())
    params += (params.empty() ? "" : " ") + k + "=" + set_syntax(v);
  fmt::print("  params      {}\n", params.empty() ? "(none)" : params);
  fmt::print("  start       ({}, {})\n", rec.start.x, rec.start.y);
  fmt::print("  goal        ({}, {})\n", rec.goal.x, rec.goal.y);
  const planners::Result& r = rec.result;
  fmt::print("result\n");
  fmt::print("  found       {}\n", r.found ? std::string("yes") : "no (" + why_not_found(r) + ")");
  if (r.found && r.extra.is_object() && r.extra.value("init_exhausted", false))
    fmt::print("  note        the GA initialisation gave up after {} chains (init_attempts_exhausted): the GA "
               "population is only the {} ant path(s)\n",
               r.extra.value("init_chains", std::int64_t{0}), r.extra.value("population_aco", std::int64_t{0}));
  if (r.found) {
    fmt::print("  length      {}\n", r.length);
    fmt::print("  turns       {}\n", j.at("turns").get<std::int64_t>());
    fmt::print("  cells       {}\n", r.path.size());
    fmt::print("  valid       {} ({})\n", j.at("valid").get<bool>() ? "yes" : "NO",
               j.at("validation").get<std::string>());
  }
  fmt::print("  expansions  {}\n", r.expansions);
  fmt::print("  iterations  {}\n", r.iterations);
  if (!r.best_per_iteration.empty()) {
    const Json& conv = j.at("converged_at");
    fmt::print("  converged   {}\n", conv.is_null() ? std::string("(no solution)")
                                                    : "at iteration " + conv.dump());
  }
  if (!r.extra.empty()) {
    // Long sample lists (a sampled curve) are in the JSON; the report names their size.
    Json shown = r.extra;
    if (shown.contains("curve") && shown["curve"].contains("points"))
      shown["curve"]["points"] = fmt::format("({} points: see --json)", shown["curve"]["points"].size());
    fmt::print("  extra       {}\n", shown.dump());
  }
  if (r.found) fmt::print("  path        {}\n", cells_text(r.path));
}

/// The SVG figure: the map with the path (and, for iterative planners, the convergence curves of
/// the best and mean length per iteration).
std::string plan_svg(const io::PlanRecord& rec, const grid::Grid& g, const Json& j, bool cell_numbers) {
  const planners::Result& r = rec.result;
  const std::string label =
      r.found ? fmt::format("{} (length {:.2f}, {} turns)", rec.algo, r.length,
                            j.at("turns").get<std::int64_t>())
              : rec.algo;
  std::vector<io::PathLayer> layers{{label, r.found ? r.path : std::vector<grid::Cell>{}}};
  // Planners with key nodes and a smoothed curve (astar-kinematic, spec/sensors2023.md): draw
  // the key-node polyline with its nodes marked and the sampled curve.
  if (r.found && r.extra.contains("key_nodes")) {
    io::PathLayer keys{fmt::format("key nodes ({}, {} turns)", r.extra.at("key_nodes").size(),
                                   r.extra.at("turns_key").get<std::int64_t>()),
                       {}};
    for (const auto& c : r.extra.at("key_nodes"))
      keys.path.push_back(grid::Cell{c.at(0).get<std::int64_t>(), c.at(1).get<std::int64_t>()});
    keys.markers = true;
    keys.dashed = true;
    layers.push_back(std::move(keys));
  }
  if (r.found && r.extra.contains("curve")) {
    const Json& c = r.extra.at("curve");
    io::PathLayer curve{fmt::format("B-spline p={} ({}, length {:.2f}, clearance {})",
                                    c.at("degree").get<int>(), c.at("end").get<std::string>(),
                                    c.at("length").get<double>(),
                                    c.at("clearance").at("verdict").get<std::string>()),
                        {}};
    for (const auto& q : c.at("points"))
      curve.points.push_back(geometry::Vec2{q.at(0).get<double>(), q.at(1).get<double>()});
    layers.push_back(std::move(curve));
  }
  const std::string title = fmt::format("{} {}x{}: {}, policy {}, seed {}", rec.map.name, g.width(),
                                        g.height(), rec.algo, grid::to_string(rec.policy), rec.seed);
  if (r.best_per_iteration.empty()) return io::svg_map(g, rec.start, rec.goal, layers, title, cell_numbers);
  std::vector<io::Series> series;
  const auto curve = [](std::string name, const std::vector<double>& y) {
    io::Series s{std::move(name), {}, y};
    for (std::size_t i = 0; i < y.size(); ++i) s.x.push_back(static_cast<double>(i + 1));
    return s;
  };
  series.push_back(curve(rec.algo + " best", r.best_per_iteration));
  series.back().absent = "no path in any iteration";
  if (std::any_of(r.best_per_iteration.begin(), r.best_per_iteration.end(), [](double v) { return std::isfinite(v); }))
    series.back().marks.push_back(static_cast<double>(metrics::iterations_to_converge(r.best_per_iteration)));
  if (!r.mean_per_iteration.empty()) series.push_back(curve(rec.algo + " mean", r.mean_per_iteration));
  return io::svg_map_and_chart(g, rec.start, rec.goal, layers, title, series,
                               io::ChartOptions{"Convergence", "iteration", "path length",
                                                "Ring: the iteration where the best length reaches its final value "
                                                "(metrics.converge).",
                                                "A line is broken at iterations without a path (no finite length)."},
                               cell_numbers);
}

/// `pathref plan`: exit 0 when a path was found, 1 when the goal is unreachable.
int run_plan(const PlanOptions& o) {
  if (continuous::is_continuous_planner(o.algo)) {
    ContinuousPlanArgs a;
    a.map_file = o.map_file;
    a.builtin = o.builtin;
    a.algo = o.algo;
    a.start = o.start;
    a.goal = o.goal;
    a.start_xy = o.start_xy;
    a.goal_xy = o.goal_xy;
    a.seed = parse_seed(o.seed);
    a.policy_given = o.policy_given;
    a.overrides = parse_sets(o.sets);
    a.json = o.json;
    a.json_out = o.json_out;
    if (o.cell_numbers)
      throw UsageError("--cell-numbers numbers grid cells; " + o.algo + " plans in the plane (no cells to number)");
    a.svg = o.svg;
    a.trace = o.trace;
    a.read = o.read;
    return run_continuous_plan(a);
  }
  const planners::Planner* planner = planners::find_planner(o.algo);
  if (planner == nullptr) {
    std::string known;
    for (const auto& p : planners::planners()) known += (known.empty() ? "" : ", ") + p.name;
    for (const auto n : continuous::continuous_planner_names()) known += ", " + std::string(n);
    throw UsageError(fmt::format("unknown --algo '{}' (known: {})", o.algo,
                                 known.empty() ? "none registered" : known));
  }
  if (o.start_xy || o.goal_xy)
    throw UsageError(fmt::format("--{} is for the continuous planners ({}); {} plans on grid cells: give --start/--goal X,Y",
                                 o.start_xy ? "start-xy" : "goal-xy", "rrt, s-rrt", o.algo));
  if (o.cell_numbers && o.svg.empty()) throw UsageError("--cell-numbers goes with --svg FILE");
  const std::uint32_t seed = parse_seed(o.seed);
  const bool policy_is_default = o.policy.empty();
  const grid::CornerPolicy policy =
      policy_is_default ? planners::default_policy(o.algo) : grid::parse_corner_policy(o.policy);
  const Json overrides = parse_sets(o.sets);
  // Validates every --set key and type before anything runs (UsageError names a bad key).
  const Json merged = planners::merge_params(planner->defaults, overrides);
  const std::uint64_t max_memory = max_memory_of(o.read.max_memory);
  const RunMap lm = load_run_map(o.map_file, o.builtin, o.read, planner->bytes_per_cell);
  const grid::Grid& g = lm.map.grid;
  const grid::Cell start = endpoint(o.start, lm.map.start, "--start", "start");
  const grid::Cell goal = endpoint(o.goal, lm.map.goal, "--goal", "goal");
  check_endpoint(g, start, "start");
  check_endpoint(g, goal, "goal");
  if (start == goal)
    throw UsageError(fmt::format("start and goal are the same cell ({}, {}): there is nothing to plan "
                                 "(give different --start and --goal)",
                                 start.x, start.y));

  planners::Request req;
  req.grid = &g;
  req.start = start;
  req.goal = goal;
  req.policy = policy;
  req.seed = seed;
  req.params = overrides;
  req.max_memory = max_memory;
  rng::Trace trace;
  if (!o.trace.empty()) req.trace = &trace;
  io::PlanRecord rec{o.algo, req.seed, req.policy, lm.source, start, goal, merged, planner->run(req)};
  if (!rec.result.params_used.empty()) rec.params = rec.result.params_used;
  if (!o.trace.empty()) write_trace_file(o.trace, trace, seed, o.algo, rec.params);

  const Json j = io::plan_to_json(rec, g);
  // Files first: a file that cannot be written is an error (exit 2) before anything is printed.
  // The figure is drawn before any file is written: a figure that cannot be drawn (cell numbers
  // on cells too small) leaves no JSON file behind.
  const std::string figure = o.svg.empty() ? std::string() : plan_svg(rec, g, j, o.cell_numbers);
  if (!o.json_out.empty()) write_output_file(o.json_out, j.dump(2) + "\n");
  if (!o.svg.empty()) write_figure(o.svg, figure);
  if (o.json)
    fmt::print("{}\n", j.dump(2));
  else
    print_report(rec, g, j, policy_is_default);
  if (!o.json) {
    if (!o.json_out.empty()) fmt::print("wrote {}\n", o.json_out);
    if (!o.svg.empty()) fmt::print("wrote {}\n", o.svg);
    if (!o.trace.empty()) fmt::print("wrote {} ({} draws)\n", o.trace, trace.draws().size());
  }
  return rec.result.found ? 0 : 1;
}

/// "(x, y)" or "-" for an endpoint a map does not define.
std::string endpoint_text(const std::optional<grid::Cell>& c) {
  return c ? fmt::format("({}, {})", c->x, c->y) : std::string("-");
}

/// `pathref maps [NAME] [--svg FILE]`: the table of built-ins, or one map's pathref-grid 1 text
/// (and its drawing).
int run_maps(const std::string& name, const std::string& svg, bool cell_numbers) {
  if (name.empty()) {
    if (!svg.empty()) throw UsageError("maps --svg needs a map NAME");
    if (cell_numbers) throw UsageError("maps --cell-numbers needs a map NAME and --svg FILE");
    for (const io::BuiltinMap& b : io::builtin_maps()) {
      const io::MapFile m = io::load_builtin_map(b);
      fmt::print("{}  {}x{}  start {}  goal {}  {} blocked cells\n", b.name, m.grid.width(),
                 m.grid.height(), endpoint_text(m.start), endpoint_text(m.goal), m.grid.blocked_count());
      fmt::print("    {}\n    source: {}\n", b.description, b.provenance);
    }
    return 0;
  }
  const io::BuiltinMap* b = io::find_builtin_map(name);
  if (b == nullptr)
    throw UsageError(fmt::format("unknown built-in map '{}' (known: {})", name, io::builtin_map_names()));
  if (cell_numbers && svg.empty()) throw UsageError("--cell-numbers goes with --svg FILE");
  fmt::print("{}", b->text);
  if (!svg.empty()) {
    const io::MapFile m = io::load_builtin_map(*b);
    write_figure(svg, io::svg_map(m.grid, m.start, m.goal, {},
                                     fmt::format("{} {}x{}", b->name, m.grid.width(), m.grid.height()), cell_numbers));
  }
  return 0;
}

}  // namespace

/// One line saying what the corner policy allows (spec/grid.md grid.corner-policy).
const char* policy_meaning(grid::CornerPolicy p) {
  switch (p) {
    case grid::CornerPolicy::never: return "4-connected, no diagonal moves";
    case grid::CornerPolicy::strict: return "diagonal needs both orthogonal neighbours free";
    case grid::CornerPolicy::one: return "diagonal needs at least one orthogonal neighbour free";
    case grid::CornerPolicy::always: return "diagonal allowed between any two free cells";
  }
  return "";
}

RunMap load_run_map(const std::string& map_file, const std::string& builtin, const MapReadArgs& read,
                    std::uint64_t bytes_per_cell) {
  if (map_file.empty() == builtin.empty())
    throw UsageError("give exactly one of --map FILE or --builtin NAME (see pathref maps)");
  if (!builtin.empty()) {
    const io::BuiltinMap* b = io::find_builtin_map(builtin);
    if (b == nullptr)
      throw UsageError(fmt::format("unknown built-in map '{}' (known: {})", builtin, io::builtin_map_names()));
    return {io::load_builtin_map(*b), io::MapSource{"builtin", std::string(b->name), std::nullopt}};
  }
  io::MapFile m = io::load_map_file(map_file, map_read_options(read, bytes_per_cell)).map;
  const std::string name = m.name.empty() ? map_file : m.name;
  return {std::move(m), io::MapSource{"file", name, map_file}};
}

void add_plan_commands(CLI::App& app, Action& run) {
  static PlanOptions o;
  std::string algos;
  for (const auto& p : planners::planners()) algos += (algos.empty() ? "" : ", ") + p.name;
  for (const auto n : continuous::continuous_planner_names()) algos += ", " + std::string(n);
  auto* plan = app.add_subcommand(
      "plan", "Run one planner on one map; print the path, its metrics, the seed and every parameter");
  auto* map_opt = plan->add_option("--map", o.map_file, "map file: pathref-grid, MovingAI .map or 0/1 matrix (spec/formats.md)")->type_name("FILE");
  auto* builtin_opt = plan->add_option("--builtin", o.builtin, "built-in map name (see pathref maps)")->type_name("NAME");
  map_opt->excludes(builtin_opt);
  plan->add_option("--algo", o.algo, "planner: " + (algos.empty() ? std::string("(none registered)") : algos))
      ->type_name("NAME")
      ->required();
  static std::string start_text;
  static std::string goal_text;
  auto* start_opt =
      plan->add_option("--start", start_text, "start cell X,Y (default: the map's start)")->type_name("X,Y");
  auto* goal_opt =
      plan->add_option("--goal", goal_text, "goal cell X,Y (default: the map's goal)")->type_name("X,Y");
  static std::string start_xy_text;
  static std::string goal_xy_text;
  auto* start_xy_opt = plan->add_option("--start-xy", start_xy_text,
                                        "continuous planners (rrt, s-rrt): start in world coordinates")
                           ->type_name("X,Y");
  auto* goal_xy_opt = plan->add_option("--goal-xy", goal_xy_text,
                                       "continuous planners (rrt, s-rrt): goal in world coordinates")
                          ->type_name("X,Y");
  plan->add_option("--seed", o.seed, "seed of the random stream, 0 to 4294967295 (spec/rng.md)")
      ->type_name("N")
      ->capture_default_str();  // a string, parsed by parse_seed
  auto* policy_opt = plan->add_option("--policy", o.policy,
                                      "corner policy for diagonal moves (spec/grid.md); default: the "
                                      "planner's (strict; always for aco-classic and ga-classic)")
      ->type_name("POLICY")
      ->check(CLI::IsMember({"never", "strict", "one", "always"}));
  plan->add_option("--set", o.sets, "planner parameter key=value (repeatable; value JSON or plain string)")
      ->type_name("KEY=VALUE");
  add_map_read_options(plan, o.read);
  plan->add_flag("--json", o.json, "print one JSON object (schema pathref-plan 1) instead of the report");
  plan->add_option("--json-out", o.json_out, "also write the JSON object to FILE")->type_name("FILE");
  plan->add_option("--svg", o.svg, "write an SVG figure: map, obstacles, S, T, path, legend (+ convergence)")
      ->type_name("FILE");
  plan->add_flag("--cell-numbers", o.cell_numbers,
                 "with --svg: number every cell i = y*W + x as in Shi's Fig. 1A (small maps; an error when "
                 "the numbers do not fit the cells)");
  plan->add_option("--trace", o.trace,
                   "write every random draw (index, value, purpose, context) as JSON lines to FILE "
                   "(spec/rng.md#draw-traces; compare two with pathref trace-diff)")
      ->type_name("FILE");
  plan->callback([&run, start_opt, goal_opt, start_xy_opt, goal_xy_opt, policy_opt] {
    if (start_opt->count() > 0) o.start = start_text;
    if (goal_opt->count() > 0) o.goal = goal_text;
    if (start_xy_opt->count() > 0) o.start_xy = start_xy_text;
    if (goal_xy_opt->count() > 0) o.goal_xy = goal_xy_text;
    o.policy_given = policy_opt->count() > 0;
    run = [] { return run_plan(o); };
  });

  auto* maps = app.add_subcommand("maps", "List the built-in maps, or print one as pathref-grid 1 text");
  static std::string show;
  static std::string show_svg;
  maps->add_option("name", show, "print this built-in map as pathref-grid 1 text");
  maps->add_option("--svg", show_svg, "with NAME: also draw the map (S, T, obstacles) to FILE")->type_name("FILE");
  static bool show_numbers = false;
  maps->add_flag("--cell-numbers", show_numbers, "with --svg: number every cell i = y*W + x (Shi's Fig. 1A)");
  maps->callback([&run] { run = [] { return run_maps(show, show_svg, show_numbers); }; });
}

}  // namespace pathref::cli
