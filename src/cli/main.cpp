// pathref: the command-line front end of the reference implementation.
#include <fmt/core.h>

#include <algorithm>
#include <string_view>
#include <system_error>
#include <vector>

#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/core/version.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/geometry/obstacles.hpp"

int main(int argc, char** argv) {
  // inflation.* rules (pathref_geometry, CGAL) join the registry before its first use.
  pathref::geometry::install_inflation_rules();
  // cin2021 S-RRT rules (exact collision checks in pathref_geometry) likewise.
  pathref::geometry::install_srrt_rules();
  CLI::App app{"pathref " + std::string(pathref::version()) +
               " - formally specified reference implementation of grid path planners"};
  app.require_subcommand(1);
  // --version: pathref's version and the golden-vector set it was built with (docs/versioning.md).
  app.set_version_flag("--version", std::string(pathref::version()) + " (golden vectors " +
                                        std::string(pathref::golden_set_version()) + ")");
  pathref::cli::Action run;
  pathref::cli::add_plan_commands(app, run);
  pathref::cli::add_eval_command(app, run);
  pathref::cli::add_golden_command(app, run);
  pathref::cli::add_check_command(app, run);
  pathref::cli::add_conform_command(app, run);
  pathref::cli::add_drive_command(app, run);
  pathref::cli::add_scen_command(app, run);
  pathref::cli::add_convert_command(app, run);
  pathref::cli::add_inflate_command(app, run);
  pathref::cli::add_simulate_command(app, run);
  pathref::cli::add_reproduce_command(app, run);
  pathref::cli::add_learn_commands(app, run);
  pathref::cli::add_trace_diff_command(app, run);
  // `pathref classify ... -- v1 v2`: classify takes every non-option argument as a value, so a
  // `--` (the usual end-of-options mark, which CLI11 would hand to the top-level app) is dropped
  // there (spec/cin2021-ml.md, classify).
  std::vector<char*> args(argv, argv + argc);
  if (argc > 1 && std::string_view(argv[1]) == "classify") {
    const auto dd = std::find_if(args.begin() + 2, args.end(), [](const char* a) { return std::string_view(a) == "--"; });
    if (dd != args.end()) args.erase(dd);
  }
  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    // CLI11 returns 0 for --help/--version; every real argument error is exit 2.
    return code == 0 ? 0 : 2;
  }
  try {
    return run ? run() : 2;
  } catch (const pathref::ParseError& e) {
    fmt::print(stderr, "pathref: error: {}\n", e.what());
    return 2;
  } catch (const pathref::Error& e) {
    fmt::print(stderr, "pathref: {}: {}\n", e.kind(), e.what());
    return 2;
  } catch (const std::system_error& e) {
    // Writing a result failed (standard output or a file: full disk, a file size limit, a closed
    // pipe): the environment refused the output, not a defect (spec/cli.md#exit-codes).
    fmt::print(stderr, "pathref: error: cannot write the output: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "pathref: internal error: {}\n", e.what());
    return 3;
  }
}
