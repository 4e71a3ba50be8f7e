// `pathref golden check [DIR]` and `pathref golden regenerate DIR` (spec/golden-format.md,
// spec/cli.md#golden).
#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/golden/runner.hpp"
#include "pathref/io/map_file.hpp"

namespace pathref::cli {

namespace fs = std::filesystem;

void add_golden_command(CLI::App& app, Action& run) {
  auto* cmd = app.add_subcommand("golden", "Check the library against golden vectors, or regenerate them");
  cmd->require_subcommand(1);
  static std::string dir = "golden";
  static bool verbose = false;
  auto* check = cmd->add_subcommand("check", "Run every golden vector in DIR; exit 1 on any failure");
  check->add_option("dir", dir, "golden directory (default: ./golden of the working directory)")->capture_default_str();
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
  static std::string regen_dir;
  auto* regen = cmd->add_subcommand(
      "regenerate",
      "Recompute expected values with the library and rewrite the files in place (review the diff!)");
  regen->add_option("dir", regen_dir, "golden directory to rewrite (required: nothing is rewritten by default)")
      ->required();
  regen->callback([&run] {
    run = [] {
      // Two phases: compute every file first, write only when all succeeded, so a hand-value
      // mismatch in one file never leaves the directory half rewritten.
      std::vector<std::pair<fs::path, std::string>> rewrites;
      for (const auto& p : golden::golden_files(regen_dir)) {
        const std::string before = io::read_text_file(p.string(), "golden file");
        const auto doc = golden::read_document(p);
        std::string after = golden::canonical_text(golden::regenerate_document(doc, p.string()));
        if (before != after) rewrites.emplace_back(p, std::move(after));
      }
      for (const auto& [p, text] : rewrites) {
        write_output_file(p.string(), text);
        fmt::print("rewrote {}\n", p.string());
      }
      const std::size_t changed = rewrites.size();
      fmt::print("golden regenerate: {} file(s) changed; review with git diff\n", changed);
      return 0;
    };
  });
}

}  // namespace pathref::cli
