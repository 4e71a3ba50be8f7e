#pragma once
/// \file trace_file.hpp
/// Draw-trace files (spec/rng.md#draw-traces): the JSON-lines text `pathref plan --trace FILE`
/// writes and `pathref trace-diff A B` reads. The trace itself (rng::Trace, rng::Draw,
/// rng::first_divergence) is rng's; its file format is io's (docs/architecture.md#layers).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/rng/trace.hpp"

namespace pathref::io {

using rng::Draw;
using rng::Trace;

/// The JSON-lines text of a trace: a header line {"format": "pathref-trace", "format_version": 1,
/// "seed", plus `header`'s members} then one line per draw {"i", "u", "purpose", "context"}
/// ("u" printed with 17 significant digits, so it reads back to the same double).
[[nodiscard]] std::string trace_text(const Trace& trace, std::uint32_t seed, const nlohmann::json& header);

/// A trace read back: its header and draws. ParseError FILE:LINE:COLUMN on a malformed line
/// (not JSON, a draw without "i" or "u", indices not 0, 1, 2, ..., u outside [0, 1)).
struct TraceFile {
  nlohmann::json header;
  std::vector<Draw> draws;
};
[[nodiscard]] TraceFile parse_trace(std::string_view text, std::string_view file);

}  // namespace pathref::io
