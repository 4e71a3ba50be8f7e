// `pathref reproduce cin2021-ml`: cin2021 §3.3's hold-out and tenfold protocols with pathref's
// classifiers beside scikit-learn's (spec/cin2021-ml.md#reproduction). Writes
// <out>/cin2021-ml.md, <out>/cin2021-ml/reproduce.json and the two bar charts.
#include <fmt/core.h>
#include <sys/utsname.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>

#include "commands.hpp"
#include "pathref/core/version.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/core/error.hpp"
#include "pathref/reproduce/cin2021_ml.hpp"
#include "pathref/reproduce/runs.hpp"

namespace pathref::cli {
namespace {

using Json = nlohmann::json;

struct Options {
  std::string data = "../shared/data/uci-wall-following";
  std::string seeds = "10";
  std::string first_seed = "1";
  std::string out_dir = "docs/reproduction";
  std::string sklearn = "auto";
  std::string python = "/usr/bin/python3";
  std::string jobs = "1";
  bool quick = false;
  bool redraw = false;  ///< --redraw: rewrite report and figures from OUT_DIR/cin2021-ml/reproduce.json
};

std::string now_utc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string machine() {
  std::string s;
  utsname u{};
  if (uname(&u) == 0) s = fmt::format("{} {} {}", u.sysname, u.release, u.machine);
  std::ifstream cpu("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpu, line))
    if (line.rfind("model name", 0) == 0) {
      s += "; " + line.substr(line.find(':') + 2);
      break;
    }
  return s + fmt::format("; {} hardware threads", std::thread::hardware_concurrency());
}

int to_int(const std::string& s, const char* opt, int lo, int hi) {
  if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos || std::stoi(s) < lo || std::stoi(s) > hi)
    throw UsageError(fmt::format("{} expects an integer from {} to {}, got '{}'", opt, lo, hi, s));
  return std::stoi(s);
}

void write(const std::filesystem::path& p, const std::string& text) {
  write_output_file(p.string(), text);
  fmt::print("wrote {}\n", p.string());
}

int run(const Options& o) {
  namespace fs = std::filesystem;
  reproduce::Cin2021MlConfig cfg;
  cfg.data_file = (fs::path(o.data) / "sensor_readings_4.data").string();
  if (!fs::exists(cfg.data_file)) throw UsageError("no " + cfg.data_file + " (--data names the folder of the UCI files)");
  cfg.seeds = to_int(o.seeds, "--seeds", 2, 1000);
  const int jobs = to_int(o.jobs, "--jobs", 1, 256);
  cfg.first_seed = static_cast<std::uint32_t>(to_int(o.first_seed, "--first-seed", 0, 1000000000));
  cfg.quick = o.quick;
  const fs::path dir(o.out_dir);
  std::string cmd = fmt::format("pathref reproduce cin2021-ml --data {} --seeds {} --first-seed {} --out-dir {} --sklearn {}",
                                o.data, cfg.seeds, cfg.first_seed, o.out_dir, o.sklearn);
  if (jobs != 1) cmd += fmt::format(" --jobs {}", jobs);
  if (o.quick) cmd += " --quick";
  cfg.provenance = reproduce::Provenance{cmd,
#ifdef NDEBUG
                                         "optimised, NDEBUG",
#else
                                         "assertions on",
#endif
                                         now_utc(), machine(), std::string(pathref::version())};
  cfg.progress = [](const std::string& line) { fmt::print(stderr, "[reproduce] {}\n", line); };
  std::string sk_file;
  if (o.redraw) {
    // nothing is run: the scikit-learn column is already in the document
  } else if (o.sklearn == "auto") {
    sk_file = (dir / "cin2021-ml" / "sklearn.json").string();
    fs::create_directories(dir / "cin2021-ml");
    const std::string script = "tools/reproduce/cin2021_ml_sklearn.py";
    if (!fs::exists(script)) throw UsageError("--sklearn auto runs " + script + " from the repository root; run there or give --sklearn FILE|off");
    const std::string call = fmt::format("{} {} --data {} --seeds {} --first-seed {} --out {}", o.python, script,
                                         cfg.data_file, cfg.seeds, cfg.first_seed, sk_file);
    fmt::print(stderr, "[reproduce] scikit-learn: {}\n", call);
    if (std::system(call.c_str()) != 0) {
      fmt::print(stderr, "[reproduce] scikit-learn run failed (is python3-sklearn installed for {}?): its column stays empty\n", o.python);
      sk_file.clear();
    }
  } else if (o.sklearn != "off") {
    sk_file = o.sklearn;
  }
  if (!sk_file.empty()) {
    cfg.sklearn = io::parse_json_text(io::read_text_file(sk_file, "scikit-learn results file"), sk_file);
  }
  cfg.provenance.jobs = jobs;
  Json doc;
  if (o.redraw) {
    const std::string f = (dir / "cin2021-ml" / "reproduce.json").string();
    doc = io::parse_json_text(io::read_text_file(f, "reproduction document"), f);
  } else {
    reproduce::Execution ex;
    ex.jobs = jobs;
    const reproduce::ExecutionScope scope(ex);
    doc = reproduce::run_cin2021_ml(cfg);
  }
  write(dir / "cin2021-ml" / "reproduce.json", doc.dump(1) + "\n");
  for (const auto& [name, svg] : reproduce::cin2021_ml_figures(doc)) write(dir / "cin2021-ml" / name, svg);
  write(dir / "cin2021-ml.md", reproduce::cin2021_ml_markdown(doc, "cin2021-ml/reproduce.json"));
  std::map<std::string, int> count;
  for (const Json& c : doc.at("claims")) ++count[c.at("verdict").get<std::string>()];
  fmt::print("cin2021-ml: {} claims: {} hold, {} do not hold, {} inconclusive, {} cannot be tested\n", doc.at("claims").size(),
             count["holds"], count["does not hold"], count["inconclusive"], count["cannot be tested"]);
  return 0;
}

}  // namespace

void add_reproduce_cin2021_ml(CLI::App* reproduce, Action& run_action) {
  static Options o;
  auto* c = reproduce->add_subcommand("cin2021-ml", "cin2021 §3: the ML decision model, Figs. 3-4 (hold-out and tenfold)");
  c->add_option("--data", o.data, "folder of the UCI wall-following files")->type_name("DIR")->capture_default_str();
  c->add_option("--seeds", o.seeds, "n: hold-out split seeds per reading and forest seeds (2n are run; verdicts at n and 2n)")->type_name("N")->capture_default_str();
  c->add_option("--first-seed", o.first_seed, "seed of the first split")->type_name("S")->capture_default_str();
  c->add_option("--out-dir", o.out_dir, "directory of the report")->type_name("DIR")->capture_default_str();
  c->add_option("--sklearn", o.sklearn, "auto (run tools/reproduce/cin2021_ml_sklearn.py), off, or a FILE it wrote")
      ->type_name("auto|off|FILE")->capture_default_str();
  c->add_option("--python", o.python, "interpreter with scikit-learn (Debian python3-sklearn)")->type_name("PATH")->capture_default_str();
  c->add_option("--jobs", o.jobs, "forest seeds in parallel on N threads (results identical to --jobs 1 except wall times)")
      ->type_name("N")->capture_default_str();
  c->add_flag("--quick", o.quick, "10-tree forests: a smoke test");
  c->add_flag("--redraw", o.redraw,
              "run nothing: write the report and its figures again from OUT_DIR/cin2021-ml/reproduce.json of an earlier run");
  c->callback([&run_action] { run_action = [] { return run(o); }; });
}

}  // namespace pathref::cli
