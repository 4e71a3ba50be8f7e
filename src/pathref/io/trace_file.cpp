// Draw-trace files (spec/rng.md#draw-traces): writing and reading the JSON lines.
#include "pathref/io/trace_file.hpp"

#include <fmt/core.h>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"

namespace pathref::io {

std::string trace_text(const Trace& trace, std::uint32_t seed, const nlohmann::json& header) {
  nlohmann::json head{{"format", "pathref-trace"}, {"format_version", 1}, {"seed", seed}};
  for (const auto& [k, v] : header.items()) head[k] = v;
  head["draws"] = trace.draws().size();
  head["dropped"] = trace.dropped();
  std::string s = head.dump() + "\n";
  for (const Draw& d : trace.draws())
    s += fmt::format("{{\"i\":{},\"u\":{:.17g},\"purpose\":{},\"context\":{}}}\n", d.index, d.value,
                     nlohmann::json(d.purpose).dump(), nlohmann::json(d.context).dump());
  return s;
}

TraceFile parse_trace(std::string_view text, std::string_view file_view) {
  const std::string file(file_view);
  TraceFile out;
  std::size_t line = 1;
  bool first = true;
  for (std::size_t at = 0; at < text.size(); ++line) {
    std::size_t nl = text.find('\n', at);
    if (nl == std::string_view::npos) nl = text.size();
    const std::string_view l = text.substr(at, nl - at);
    at = nl + 1;
    if (l.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    const nlohmann::json j = io::parse_json_text(l, file, line);
    // Refusals at the offending value: FILE:LINE:COLUMN: /pointer: what (io::json_error_at).
    const auto fail = [&](const char* ptr, const std::string& what) { throw io::json_error_at(l, file, ptr, what, line); };
    if (!j.is_object()) fail("", "expected a JSON object per line, got " + io::json_kind(j));
    if (first) {
      first = false;
      // find, not value("format", ""): value() throws a library type_error when "format" is not a
      // string (found by the trace_file fuzz target, issue 27)
      if (const auto f = j.find("format"); f != j.end() && *f == "pathref-trace") {
        out.header = j;
        continue;
      }
    }
    const auto num = [&](const char* key) -> const nlohmann::json& {
      const auto it = j.find(key);
      if (it == j.end() || !it->is_number())
        fail(it == j.end() ? "" : (key == std::string("i") ? "/i" : "/u"),
             std::string("expected a draw {\"i\": INDEX, \"u\": VALUE, ...} (no number \"") + key + "\")");
      return *it;
    };
    const nlohmann::json& i = num("i");
    const double u = num("u").get<double>();
    if (!i.is_number_unsigned() || i.get<std::uint64_t>() != out.draws.size())
      fail("/i", fmt::format("expected draw index {} (draws are numbered 0, 1, 2, ... in order), got {}",
                             out.draws.size(), i.dump()));
    if (!(u >= 0.0 && u < 1.0)) fail("/u", fmt::format("expected u in [0, 1), got {}", num("u").dump()));
    Draw d{out.draws.size(), u, "", ""};
    if (const auto p = j.find("purpose"); p != j.end() && p->is_string()) d.purpose = p->get<std::string>();
    if (const auto c = j.find("context"); c != j.end() && c->is_string()) d.context = c->get<std::string>();
    out.draws.push_back(std::move(d));
  }
  return out;
}

}  // namespace pathref::io
