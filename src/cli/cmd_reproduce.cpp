// `pathref reproduce shi2022 --simple FILE --complex FILE ...` and `pathref reproduce han ...`:
// run a paper's experimental protocol with the registered planners and write the report
// (markdown), every number (reproduce.json) and the figures (SVG). Spec: spec/reproduce.md.
#include <fmt/core.h>
#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "pathref/io/input_file.hpp"
#include "pathref/core/version.hpp"
#include "pathref/core/error.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/reproduce/cin2021.hpp"
#include "pathref/reproduce/cin2021_srrt.hpp"
#include "pathref/reproduce/han.hpp"
#include "pathref/reproduce/runs.hpp"
#include "pathref/reproduce/sensors2023.hpp"
#include "pathref/reproduce/shi2022.hpp"

namespace pathref::cli {

namespace {

using Json = nlohmann::json;

struct ReproduceOptions {
  std::string simple;
  std::string complex;
  std::string runs;
  std::string sweep_runs;
  std::string maps_per_edge;
  std::string edges;
  std::string seed = "1";
  std::string out_dir = "docs/reproduction";
  std::string policy = "strict";
  std::string orientation = "paper";
  std::string map_b;
  std::string map_c;
  bool quick = false;
  std::string jobs = "1";       ///< --jobs N: threads (reproduce.execution)
  std::string emit_jobs;        ///< --emit-jobs FILE: write one command per run instead of running
  std::string job_results;      ///< --job-results DIR: where the emitted commands write (default FILE.results)
  std::string merge;            ///< --merge DIR: build the report from the emitted commands' outputs
  bool redraw = false;          ///< --redraw: rewrite report and figures from OUT_DIR/PAPER/reproduce.json
};

/// A decimal integer in [lo, hi], digits only (leading zeros are decimal); UsageError otherwise.
std::int64_t parse_int(const std::string& text, const char* option, std::int64_t lo, std::int64_t hi) {
  const bool digits =
      !text.empty() && text.size() <= 18 && text.find_first_not_of("0123456789") == std::string::npos;
  std::int64_t v = 0;
  if (digits)
    for (const char c : text) v = v * 10 + (c - '0');
  if (!digits || v < lo || v > hi)
    throw UsageError(fmt::format("{} expects a decimal integer from {} to {}, got '{}'", option, lo, hi, text));
  return v;
}

std::string iso_now_utc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string machine_description() {
  std::string s;
  utsname u{};
  if (uname(&u) == 0) s = fmt::format("{} {} {}", u.sysname, u.release, u.machine);
  std::ifstream cpu("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpu, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) s += "; " + line.substr(colon + 2);
      break;
    }
  }
  s += fmt::format("; {} hardware threads", std::thread::hardware_concurrency());
  return s;
}

/// CMAKE_BUILD_TYPE from the CMakeCache.txt beside the running binary, else what the compiler says.
std::string build_type() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    std::ifstream cache(exe.parent_path() / "CMakeCache.txt");
    std::string line;
    while (std::getline(cache, line))
      if (line.rfind("CMAKE_BUILD_TYPE:", 0) == 0) {
        const auto eq = line.find('=');
        if (eq != std::string::npos && eq + 1 < line.size()) return line.substr(eq + 1) + " (CMakeCache.txt)";
      }
  }
#if defined(NDEBUG) && defined(__OPTIMIZE__)
  return "optimised, NDEBUG (no CMakeCache.txt beside the binary)";
#elif defined(__OPTIMIZE__)
  return "optimised, assertions on (no CMakeCache.txt beside the binary)";
#else
  return "unoptimised (no CMakeCache.txt beside the binary)";
#endif
}

void write_file(const std::filesystem::path& p, const std::string& text) { write_output_file(p.string(), text); }

grid::Grid load_grid(const std::string& file) {
  io::MapReadOptions opt;
  return io::load_map_file(file, opt).map.grid;
}

/// Writes md, json and figures; prints one "wrote" line per file, then the verdict counts.
int write_outputs(const Json& doc, const std::string& out_dir, const std::string& paper, const std::string& md,
                  const std::vector<std::pair<std::string, std::string>>& figures) {
  namespace fs = std::filesystem;
  const fs::path dir(out_dir);
  std::vector<fs::path> written;
  const fs::path md_path = dir / (paper + ".md");
  const fs::path json_path = dir / paper / "reproduce.json";
  write_file(json_path, doc.dump(1) + "\n");
  written.push_back(json_path);
  for (const auto& [name, svg] : figures) {
    write_file(dir / paper / name, svg);
    written.push_back(dir / paper / name);
  }
  write_file(md_path, md);
  written.push_back(md_path);
  for (const auto& p : written) fmt::print("wrote {}\n", p.string());
  int holds = 0, fails = 0, not_significant = 0, inconclusive = 0, untestable = 0;
  for (const Json& c : doc.at("claims")) {
    const auto v = c.at("verdict").get<std::string>();
    if (v == "holds") ++holds;
    else if (v == "does not hold") ++fails;
    else if (v == "not significant") ++not_significant;
    else if (v == "inconclusive") ++inconclusive;
    else ++untestable;
  }
  fmt::print("{}: {} claims: {} hold, {} do not hold, {} not significant, {} inconclusive, {} cannot be tested ({:.1f} s)\n",
             paper, doc.at("claims").size(), holds, fails, not_significant, inconclusive, untestable,
             doc.at("provenance").at("total_wall_s").get<double>());
  return 0;
}

reproduce::Progress progress_printer() {
  return [](const std::string& line) { fmt::print(stderr, "[reproduce] {}\n", line); };
}

reproduce::Provenance provenance(const std::string& command) {
  reproduce::Provenance p;
  p.command = command;
  p.build_type = build_type();
  p.date_utc = iso_now_utc();
  p.machine = machine_description();
  p.pathref_version = std::string(pathref::version());
  return p;
}

/// A shell word: 'text' with every ' written as '\''.
std::string shell_quote(const std::string& text) {
  std::string q = "'";
  for (const char c : text) {
    if (c == '\'') q += "'\\''";
    else q += c;
  }
  return q + "'";
}

/// The reproduce.execution options of `o`, appended to the provenance command.
std::string execution_suffix(const ReproduceOptions& o) {
  std::string s;
  if (o.jobs != "1") s += " --jobs " + o.jobs;
  if (!o.merge.empty()) s += " --merge " + o.merge;
  return s;
}

/// Every run's record in DIR (the outputs of the commands of --emit-jobs), by job key.
std::map<std::string, Json> read_job_results(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw UsageError(fmt::format("--merge: '{}' is not a directory", dir));
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::map<std::string, Json> out;
  for (const fs::path& f : files) {
    const std::string text = io::read_input_file(f.string(), "job result", io::document_limits.max_bytes);
    Json j;
    try {
      j = io::parse_json_text(text, f.string());
    } catch (const ParseError& e) {
      throw UsageError(fmt::format("--merge: {} (did its job fail?)", e.what()));
    }
    if (!j.is_object() || j.value("format", "") != "pathref-reproduce-run" || !j.contains("key") || !j.contains("record"))
      throw UsageError(fmt::format("--merge: '{}' is not the output of 'pathref reproduce run-job'", f.string()));
    const auto key = j.at("key").get<std::string>();
    const auto [it, fresh] = out.emplace(key, j.at("record"));
    if (!fresh && it->second != j.at("record"))
      throw UsageError(fmt::format("--merge: two different results for the run '{}' in '{}'", key, dir));
  }
  return out;
}

/// Runs `produce` under the execution that o's --jobs, --emit-jobs and --merge select
/// (spec reproduce.execution) and hands the document to `write`; with --emit-jobs writes the
/// commands instead and no report.
/// --redraw: the document of an earlier run, read back from OUT_DIR/PAPER/reproduce.json (nothing is
/// run; the report and the figures are written again from it, e.g. after a change of the figures).
Json earlier_doc(const ReproduceOptions& o, const std::string& paper) {
  if (!o.emit_jobs.empty() || !o.merge.empty()) throw UsageError("--redraw excludes --emit-jobs and --merge");
  const std::string f = (std::filesystem::path(o.out_dir) / paper / "reproduce.json").string();
  return io::parse_json_text(io::read_text_file(f, "reproduction document"), f);
}

int execute(const ReproduceOptions& o, const std::string& paper, const std::function<Json()>& produce,
            const std::function<int(const Json&)>& write) {
  if (o.redraw) return write(earlier_doc(o, paper));
  if (!o.emit_jobs.empty() && !o.merge.empty()) throw UsageError("--emit-jobs and --merge exclude each other");
  reproduce::Execution ex;
  ex.jobs = static_cast<int>(parse_int(o.jobs, "--jobs", 1, 256));
  std::vector<Json> emitted;
  std::map<std::string, Json> merged;
  if (!o.emit_jobs.empty()) {
    ex.mode = reproduce::Execution::Mode::emit;
    ex.emitted = &emitted;
  } else if (!o.merge.empty()) {
    merged = read_job_results(o.merge);
    ex.mode = reproduce::Execution::Mode::merge;
    ex.merged = &merged;
    ex.merged_from = o.merge;
  }
  const reproduce::ExecutionScope scope(ex);
  const Json doc = produce();
  if (o.emit_jobs.empty()) return write(doc);
  namespace fs = std::filesystem;
  const std::string results = o.job_results.empty() ? o.emit_jobs + ".results" : o.job_results;
  std::error_code ec;
  fs::create_directories(results, ec);
  if (ec) throw UsageError(fmt::format("cannot create '{}'", results));
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const std::string pathref = ec ? std::string("pathref") : exe.string();
  std::string text;
  for (std::size_t i = 0; i < emitted.size(); ++i)
    text += fmt::format("{} reproduce run-job {} > {}\n", shell_quote(pathref), shell_quote(emitted[i].dump()),
                        shell_quote((fs::path(results) / fmt::format("{:06}.json", i + 1)).string()));
  write_file(fs::path(o.emit_jobs), text);
  fmt::print("wrote {} ({} jobs; their outputs go to {})\n", o.emit_jobs, emitted.size(), results);
  fmt::print("next: run every line (e.g. parallel -j N < {}), then the same reproduce command with --merge {}\n",
             o.emit_jobs, results);
  return 0;
}

int run_shi(const ReproduceOptions& o) {
  reproduce::ShiConfig cfg;
  cfg.runs = o.runs.empty() ? (o.quick ? 3 : 50) : parse_int(o.runs, "--runs", 1, 10000);
  cfg.seed = static_cast<std::uint32_t>(parse_int(o.seed, "--seed", 0, 4294967295LL));
  if (static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(cfg.runs) - 1 > 4294967295ULL)
    throw UsageError("--seed + --runs - 1 must not exceed 4294967295");
  cfg.policy = grid::parse_corner_policy(o.policy);
  cfg.orientation = reproduce::parse_orientation(o.orientation);
  cfg.quick = o.quick;
  cfg.simple = reproduce::ProtocolMap{o.simple, load_grid(o.simple)};
  cfg.complex = reproduce::ProtocolMap{o.complex, load_grid(o.complex)};
  std::string cmd = fmt::format(
      "pathref reproduce shi2022 --simple {} --complex {} --runs {} --seed {} --policy {} --orientation {} --out-dir {}",
      o.simple, o.complex, cfg.runs, cfg.seed, o.policy, o.orientation, o.out_dir);
  if (o.quick) cmd += " --quick";
  cfg.provenance = provenance(cmd + execution_suffix(o));
  cfg.provenance.jobs = static_cast<int>(parse_int(o.jobs, "--jobs", 1, 256));
  cfg.provenance.execution = o.merge.empty() ? "run" : "merge";
  cfg.progress = progress_printer();
  return execute(o, "shi2022", [&] { return reproduce::run_shi2022(cfg); }, [&](const Json& doc) {
    return write_outputs(doc, o.out_dir, "shi2022", reproduce::shi2022_markdown(doc, "shi2022", "shi2022/reproduce.json"),
                         reproduce::shi2022_figures(doc));
  });
}

int run_han_cmd(const ReproduceOptions& o) {
  reproduce::HanConfig cfg;
  cfg.runs = o.runs.empty() ? (o.quick ? 3 : 50) : parse_int(o.runs, "--runs", 1, 10000);
  cfg.sweep_runs = o.sweep_runs.empty() ? (o.quick ? 2 : 3) : parse_int(o.sweep_runs, "--sweep-runs", 1, 10000);
  cfg.maps_per_edge = o.maps_per_edge.empty() ? (o.quick ? 1 : 3) : parse_int(o.maps_per_edge, "--maps-per-edge", 1, 100);
  cfg.seed = static_cast<std::uint32_t>(parse_int(o.seed, "--seed", 0, 4294967295LL));
  cfg.policy = grid::parse_corner_policy(o.policy);
  cfg.quick = o.quick;
  if (o.edges.empty()) {
    cfg.edges = o.quick ? std::vector<std::int64_t>{10, 15} : reproduce::han_protocol_edges();
  } else {
    std::stringstream in(o.edges);
    std::string item;
    while (std::getline(in, item, ',')) cfg.edges.push_back(parse_int(item, "--edges", 2, 1000));
    if (cfg.edges.empty()) throw UsageError("--edges expects a comma-separated list of edges, got ''");
  }
  const std::uint64_t n_maps = cfg.edges.size() * static_cast<std::uint64_t>(cfg.maps_per_edge);
  if (static_cast<std::uint64_t>(cfg.seed) + std::max<std::uint64_t>(n_maps, static_cast<std::uint64_t>(std::max(cfg.runs, cfg.sweep_runs))) - 1 >
      4294967295ULL)
    throw UsageError("--seed + number of maps (or runs) - 1 must not exceed 4294967295");
  std::string edges;
  for (const auto e : cfg.edges) edges += (edges.empty() ? "" : ",") + std::to_string(e);
  std::string cmd = fmt::format(
      "pathref reproduce han --runs {} --sweep-runs {} --maps-per-edge {} --edges {} --seed {} --policy {} --out-dir {}",
      cfg.runs, cfg.sweep_runs, cfg.maps_per_edge, edges, cfg.seed, o.policy, o.out_dir);
  if (o.quick) cmd += " --quick";
  cfg.provenance = provenance(cmd + execution_suffix(o));
  cfg.provenance.jobs = static_cast<int>(parse_int(o.jobs, "--jobs", 1, 256));
  cfg.provenance.execution = o.merge.empty() ? "run" : "merge";
  cfg.progress = progress_printer();
  return execute(o, "han", [&] { return reproduce::run_han(cfg); }, [&](const Json& doc) {
    return write_outputs(doc, o.out_dir, "han", reproduce::han_markdown(doc, "han", "han/reproduce.json"),
                         reproduce::han_figures(doc));
  });
}

int run_cin2021_cmd(const ReproduceOptions& o) {
  reproduce::CinConfig cfg;
  cfg.quick = o.quick;
  cfg.runs = o.runs.empty() ? (o.quick ? 3 : 20) : parse_int(o.runs, "--runs", 2, 10000);
  cfg.seed = static_cast<std::uint32_t>(parse_int(o.seed, "--seed", 0, 0xFFFFFFFFLL));
  cfg.policy = grid::parse_corner_policy(o.policy);
  if (static_cast<std::uint64_t>(cfg.seed) + 2 * static_cast<std::uint64_t>(cfg.runs) - 1 > 4294967295ULL)
    throw UsageError("--seed + 2 --runs - 1 must not exceed 4294967295 (2n runs are made, reproduce.judge)");
  if (!o.map_b.empty()) cfg.map_b = reproduce::ProtocolMap{o.map_b, load_grid(o.map_b)};
  if (!o.map_c.empty()) cfg.map_c = reproduce::ProtocolMap{o.map_c, load_grid(o.map_c)};
  std::string command = fmt::format("pathref reproduce cin2021-hga-aco --runs {} --seed {} --policy {}", cfg.runs,
                                    cfg.seed, o.policy);
  if (!o.map_b.empty()) command += " --map-b " + o.map_b;
  if (!o.map_c.empty()) command += " --map-c " + o.map_c;
  if (o.quick) command += " --quick";
  command += " --out-dir " + o.out_dir;
  cfg.provenance = provenance(command + execution_suffix(o));
  cfg.provenance.jobs = static_cast<int>(parse_int(o.jobs, "--jobs", 1, 256));
  cfg.provenance.execution = o.merge.empty() ? "run" : "merge";
  cfg.progress = progress_printer();
  return execute(o, "cin2021-hga-aco", [&] { return reproduce::run_cin2021(cfg); }, [&](const Json& doc) {
    return write_outputs(doc, o.out_dir, "cin2021-hga-aco",
                         reproduce::cin2021_markdown(doc, "cin2021-hga-aco", "cin2021-hga-aco/reproduce.json"),
                         reproduce::cin2021_figures(doc));
  });
}

int run_sensors2023_cmd(const ReproduceOptions& o) {
  reproduce::Sensors2023Config cfg;
  cfg.maps = o.maps_per_edge.empty() ? (o.quick ? 4 : 30) : parse_int(o.maps_per_edge, "--maps", 1, 10000);
  cfg.seed = static_cast<std::uint32_t>(parse_int(o.seed, "--seed", 0, 4294967295LL));
  cfg.quick = o.quick;
  if (static_cast<std::uint64_t>(cfg.seed) + 100000ULL > 4294967295ULL)
    throw UsageError("--seed must leave room for the random maps' seeds (seed + 100000 <= 4294967295)");
  if (!o.emit_jobs.empty() || !o.merge.empty())
    throw UsageError("reproduce sensors2023 runs its simulations itself: --emit-jobs and --merge are not supported (use --jobs)");
  std::string cmd = fmt::format("pathref reproduce sensors2023 --maps {} --seed {} --out-dir {}", cfg.maps, cfg.seed, o.out_dir);
  if (o.quick) cmd += " --quick";
  const int jobs = static_cast<int>(parse_int(o.jobs, "--jobs", 1, 256));
  if (jobs != 1) cmd += fmt::format(" --jobs {}", jobs);
  cfg.provenance = provenance(cmd);
  cfg.provenance.jobs = jobs;
  cfg.progress = progress_printer();
  reproduce::Execution ex;
  ex.jobs = jobs;
  const reproduce::ExecutionScope scope(ex);
  const Json doc = o.redraw ? earlier_doc(o, "sensors2023") : reproduce::run_sensors2023(cfg);
  return write_outputs(doc, o.out_dir, "sensors2023",
                       reproduce::sensors2023_markdown(doc, "sensors2023", "sensors2023/reproduce.json"),
                       reproduce::sensors2023_figures(doc));
}

int run_srrt_cmd(const ReproduceOptions& o) {
  if (o.redraw) {
    const Json doc = earlier_doc(o, "cin2021-srrt");
    return write_outputs(doc, o.out_dir, "cin2021-srrt",
                         reproduce::cin2021_srrt_markdown(doc, "cin2021-srrt", "cin2021-srrt/reproduce.json"),
                         reproduce::cin2021_srrt_figures(doc));
  }
  reproduce::SrrtReproduceOptions so;
  so.runs = o.runs.empty() ? (o.quick ? 3 : 20) : parse_int(o.runs, "--runs", 2, 1000);
  so.seed = static_cast<std::uint32_t>(parse_int(o.seed, "--seed", 0, 4294967295LL));
  if (static_cast<std::uint64_t>(so.seed) + 2 * static_cast<std::uint64_t>(so.runs) - 1 > 4294967295ULL)
    throw UsageError("--seed + 2 --runs - 1 must not exceed 4294967295 (2n runs are made, reproduce.judge)");
  std::string cmd = fmt::format("pathref reproduce cin2021-srrt --runs {} --seed {} --out-dir {}", so.runs, so.seed,
                                o.out_dir);
  if (o.quick) cmd += " --quick";
  so.provenance = provenance(cmd);
  so.progress = progress_printer();
  std::string load;  // the machine's load when the wall-clock times were measured (reported beside them)
  {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    if (in >> a >> b >> c) load = a + " " + b + " " + c;
  }
  reproduce::SrrtReproduction rep = reproduce::reproduce_cin2021_srrt(so);
  if (!load.empty()) rep.doc["provenance"]["load_average"] = load;
  return write_outputs(rep.doc, o.out_dir, "cin2021-srrt",
                       reproduce::cin2021_srrt_markdown(rep.doc, "cin2021-srrt", "cin2021-srrt/reproduce.json"),
                       rep.files);
}

void add_common(CLI::App* cmd, ReproduceOptions& o) {
  cmd->add_option("--runs", o.runs, "runs per stochastic planner and map (default: the paper's protocol — 50 for shi2022 and han, 20 for cin2021-hga-aco and cin2021-srrt; 3 with --quick)")->type_name("N");
  cmd->add_option("--seed", o.seed, "first seed; run r uses seed + r (spec/reproduce.md)")
      ->type_name("S")
      ->capture_default_str();
  cmd->add_option("--out-dir", o.out_dir, "directory of the report, its JSON and figures")
      ->type_name("DIR")
      ->capture_default_str();
  cmd->add_option("--policy", o.policy, "corner policy (spec/grid.md)")
      ->type_name("P")
      ->check(CLI::IsMember({"never", "strict", "one", "always"}))
      ->capture_default_str();
  cmd->add_flag("--quick", o.quick, "few runs, few iterations: a smoke test that finishes in seconds");
  cmd->add_option("--jobs", o.jobs, "runs in parallel on N threads (results identical to --jobs 1 except wall times)")
      ->type_name("N")
      ->capture_default_str();
  cmd->add_option("--emit-jobs", o.emit_jobs,
                  "write one self-contained command per run to FILE (for GNU parallel or a job array) instead of running")
      ->type_name("FILE");
  cmd->add_option("--job-results", o.job_results, "with --emit-jobs: where the commands write their results (default FILE.results)")
      ->type_name("DIR");
  cmd->add_option("--merge", o.merge, "build the report from the results of the --emit-jobs commands in DIR")
      ->type_name("DIR");
  cmd->add_flag("--redraw", o.redraw,
                "run nothing: write the report and its figures again from OUT_DIR/PAPER/reproduce.json of an earlier run");
}

}  // namespace

void add_reproduce_command(CLI::App& app, Action& run) {
  static ReproduceOptions shi;
  static ReproduceOptions han;
  static ReproduceOptions cin;
  static ReproduceOptions s23;
  auto* cmd = app.add_subcommand("reproduce", "Run a paper's experiments and write the report, JSON and figures "
                                              "(spec/reproduce.md)");
  cmd->require_subcommand(1);
  auto* s = cmd->add_subcommand("shi2022", "Shi et al. 2022, Tables 3-5 and Figures 8-12");
  s->add_option("--simple", shi.simple, "the simple 20x20 map (e.g. matlab-maps/mapC_20x20_winsleo_traditional.txt)")
      ->type_name("FILE")
      ->required();
  s->add_option("--complex", shi.complex, "the complex 20x20 map (e.g. matlab-maps/mapB_20x20_ga.txt)")
      ->type_name("FILE")
      ->required();
  add_common(s, shi);
  s->add_option("--orientation", shi.orientation,
                "paper: the file's first row is y = 0 (Shi's frame); file: first row on top (spec/reproduce.md)")
      ->type_name("O")
      ->check(CLI::IsMember({"paper", "file"}))
      ->capture_default_str();
  s->callback([&run] { run = [] { return run_shi(shi); }; });
  auto* h = cmd->add_subcommand("han", "Han (IJACSA), random maps of edge 10-100 m: convergence, length, time");
  add_common(h, han);
  h->add_option("--sweep-runs", han.sweep_runs, "runs per stochastic planner on maps of edges other than 10 (default 3; 2 with --quick)")
      ->type_name("M");
  h->add_option("--maps-per-edge", han.maps_per_edge, "random maps per edge (default 3; 1 with --quick)")->type_name("K");
  h->add_option("--edges", han.edges, "comma-separated map edges (default 10,15,...,100; 10,15 with --quick)")
      ->type_name("LIST");
  h->callback([&run] { run = [] { return run_han_cmd(han); }; });
  auto* c = cmd->add_subcommand("cin2021-hga-aco",
                                "cin2021 §5.6: HGA-ACO vs ACO vs GA on three 20x20 scenarios (Table 3), "
                                "and on Shi's maps B and C when given");
  add_common(c, cin);
  c->add_option("--map-b", cin.map_b, "Shi's complex map (matlab-maps/mapB_20x20_ga.txt), optional")->type_name("FILE");
  c->add_option("--map-c", cin.map_c, "Shi's simple map (matlab-maps/mapC_20x20_winsleo_traditional.txt), optional")
      ->type_name("FILE");
  c->callback([&run] { run = [] { return run_cin2021_cmd(cin); }; });
  add_reproduce_cin2021_ml(cmd, run);
  static ReproduceOptions srrt;
  auto* r = cmd->add_subcommand("cin2021-srrt",
                                "cin2021 §4.3: S-RRT vs RRT on three rebuilt 20x20 scenes, 20 runs each (spec/reproduce.md)");
  r->add_option("--runs", srrt.runs, "n runs per series and scene; 2n are run (default 20; 3 with --quick)")->type_name("N");
  r->add_option("--seed", srrt.seed, "first seed; run i uses seed + i in every series")->type_name("S")->capture_default_str();
  r->add_option("--out-dir", srrt.out_dir, "directory of the report, its JSON and figures")
      ->type_name("DIR")
      ->capture_default_str();
  r->add_flag("--quick", srrt.quick, "3 runs: a smoke test that finishes in seconds");
  r->add_flag("--redraw", srrt.redraw,
              "run nothing but each scene's first two runs: write the report and its figures again from "
              "OUT_DIR/cin2021-srrt/reproduce.json of an earlier run");
  r->callback([&run] { run = [] { return run_srrt_cmd(srrt); }; });
  static std::string job_text;
  auto* j = cmd->add_subcommand("run-job", "Run one job written by --emit-jobs and print its result (JSON) on stdout");
  j->add_option("job", job_text, "the job: a JSON object, or @FILE")->required();
  j->callback([&run] {
    run = [] {
      std::string text = job_text;
      std::string job_source = "<job>";
      if (!text.empty() && text[0] == '@') {
        const std::string file = text.substr(1);
        text = io::read_input_file(file, "job file", io::document_limits.max_bytes);
        job_source = file;
      }
      const Json job = io::parse_json_text(text, job_source);
      Json out = reproduce::run_job(job);
      stamp_version(out);
      fmt::print("{}\n", out.dump());
      return 0;
    };
  });
  auto* k = cmd->add_subcommand("sensors2023",
                                "Sensors 2023 (kinematic A* + following DWA): rebuilt 21x21 scene and random maps, Tables 2-4 "
                                "(spec/sensors2023-dwa.md)");
  k->add_option("--maps", s23.maps_per_edge,
                "n: claims judged on n random 21x21 maps and on 2n (default 30; 4 with --quick)")->type_name("M");
  k->add_option("--jobs", s23.jobs, "simulate the random maps on N threads (results identical to --jobs 1 except wall times)")
      ->type_name("N")
      ->capture_default_str();
  k->add_option("--seed", s23.seed, "first random-map seed")->type_name("S")->capture_default_str();
  k->add_option("--out-dir", s23.out_dir, "directory of the report, its JSON and figures")->type_name("DIR")->capture_default_str();
  k->add_flag("--quick", s23.quick, "4 (and 8) random maps: a smoke test");
  k->add_flag("--redraw", s23.redraw,
              "run nothing: write the report and its figures again from OUT_DIR/sensors2023/reproduce.json of an earlier run");
  k->callback([&run] { run = [] { return run_sensors2023_cmd(s23); }; });
}

}  // namespace pathref::cli
