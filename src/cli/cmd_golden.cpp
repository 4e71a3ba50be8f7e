// `pathref golden check [DIR]` and `pathref golden regenerate [DIR]` (spec/golden-format.md).
#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/golden/runner.hpp"

namespace pathref::cli {

namespace fs = std::filesystem;

namespace {
std::string default_golden_dir() { return std::string(PATHREF_SOURCE_DIR) + "/golden"; }

std::vector<fs::path> golden_files(const fs::path& dir) {
  if (!fs::is_directory(dir)) throw UsageError("not a directory: " + dir.string());
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".json" &&
        e.path().parent_path().filename() != "schema")
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}
}  // namespace

void add_golden_command(CLI::App& app, Action& run) {
  auto* cmd = app.add_subcommand("golden", "Check the library against golden vectors, or regenerate them");
  cmd->require_subcommand(1);
  static std::string dir = default_golden_dir();
  static bool verbose = false;
  auto* check = cmd->add_subcommand("check", "Run every golden vector in DIR; exit 1 on any failure");
  check->add_option("dir", dir, "golden directory")->capture_default_str();
  check->add_flag("-v,--verbose", verbose, "print every case");
  check->callback([&run] {
    run = [] {
      const auto report = golden::check_directory(dir);
      for (const auto& c : report.cases)
        if (verbose || c.status == golden::Status::fail)
          fmt::print("{} {} tcId {} ({}): {}\n",
                     c.status == golden::Status::fail ? "FAIL" : "ok  ", c.rule, c.tc_id, c.file,
                     c.message);
      const auto failed = report.count(golden::Status::fail);
      fmt::print("golden: {} passed, {} failed\n", report.count(golden::Status::pass), failed);
      return failed == 0 ? 0 : 1;
    };
  });
  static std::string regen_dir = default_golden_dir();
  auto* regen = cmd->add_subcommand(
      "regenerate",
      "Recompute expected values with the library and rewrite the files in place (review the diff!)");
  regen->add_option("dir", regen_dir, "golden directory")->capture_default_str();
  regen->callback([&run] {
    run = [] {
      // Two phases: compute every file first, write only when all succeeded, so a hand-value
      // mismatch in one file never leaves the directory half rewritten.
      std::vector<std::pair<fs::path, std::string>> rewrites;
      for (const auto& p : golden_files(regen_dir)) {
        std::ifstream in(p);
        const std::string before{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const auto doc = golden::Json::parse(before);
        std::string after = golden::canonical_text(golden::regenerate_document(doc, p.string()));
        if (before != after) rewrites.emplace_back(p, std::move(after));
      }
      for (const auto& [p, text] : rewrites) {
        std::ofstream(p) << text;
        fmt::print("rewrote {}\n", p.string());
      }
      const std::size_t changed = rewrites.size();
      fmt::print("golden regenerate: {} file(s) changed; review with git diff\n", changed);
      return 0;
    };
  });
}

}  // namespace pathref::cli
