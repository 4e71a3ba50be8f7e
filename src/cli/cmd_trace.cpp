// Draw traces (spec/rng.md#draw-traces): the trace file `plan --trace` writes, and
// `pathref trace-diff A B`, which names the first draw where two traces disagree.
#include <fmt/core.h>

#include <algorithm>
#include <string>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/trace_file.hpp"
#include "pathref/rng/trace.hpp"

namespace pathref::cli {

void write_trace_file(const std::string& path, const rng::Trace& trace, std::uint32_t seed, const std::string& algo,
                      const nlohmann::json& params) {
  nlohmann::json header{{"algo", algo}, {"params", params}, {"source", "pathref plan --trace"}};
  stamp_version(header);
  write_output_file(path, io::trace_text(trace, seed, header));
}

namespace {

/// "#k u = V  purpose  [context]" of one side.
std::string draw_text(const std::vector<rng::Draw>& d, std::size_t k) {
  if (k >= d.size()) return "(no draw: the trace ends after " + std::to_string(d.size()) + " draws)";
  const rng::Draw& x = d[k];
  return fmt::format("u = {:.17g}  {}{}", x.value, x.purpose.empty() ? "(no purpose given)" : x.purpose,
                     x.context.empty() ? "" : "  [" + x.context + "]");
}

int run_trace_diff(const std::string& a_file, const std::string& b_file, std::size_t before) {
  const io::TraceFile a = io::parse_trace(io::read_text_file(a_file, "trace file"), a_file);
  const io::TraceFile b = io::parse_trace(io::read_text_file(b_file, "trace file"), b_file);
  const auto seed = [](const io::TraceFile& t) { return t.header.contains("seed") ? t.header.at("seed").dump() : "?"; };
  fmt::print("A: {} ({} draws, seed {})\n", a_file, a.draws.size(), seed(a));
  fmt::print("B: {} ({} draws, seed {})\n", b_file, b.draws.size(), seed(b));
  const auto k = rng::first_divergence(a.draws, b.draws);
  if (!k) {
    fmt::print("identical: the {} draws agree bit for bit\n", a.draws.size());
    return 0;
  }
  fmt::print("first divergence at draw #{} (0-based; {} draws agree before it)\n", *k, *k);
  for (std::size_t i = *k - std::min(*k, before); i < *k; ++i)
    fmt::print("  #{} agree  {}\n", i, draw_text(a.draws, i));
  fmt::print("  #{} A      {}\n", *k, draw_text(a.draws, *k));
  fmt::print("  #{} B      {}\n", *k, draw_text(b.draws, *k));
  return 1;
}

}  // namespace

void add_trace_diff_command(CLI::App& app, Action& run) {
  auto* cmd = app.add_subcommand(
      "trace-diff", "Name the first draw where two draw traces (plan --trace, or your own: docs/rng.md) disagree");
  static std::string a, b;
  static std::size_t before = 3;
  cmd->add_option("a", a, "first trace (JSON lines)")->required()->type_name("FILE");
  cmd->add_option("b", b, "second trace (JSON lines)")->required()->type_name("FILE");
  cmd->add_option("--context", before, "agreeing draws to show before the divergence (default 3)")->type_name("N");
  cmd->callback([&run] { run = [] { return run_trace_diff(a, b, before); }; });
}

}  // namespace pathref::cli
