#pragma once
/// \file json_text.hpp
/// JSON text with positions: one place that turns a byte offset into a 1-based line and column
/// and a JSON syntax error into a ParseError at its real line and column (spec/cli.md#exit-codes,
/// "a ParseError: FILE:LINE:COLUMN: what was expected").
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

namespace pathref::io {

/// The 1-based (line, column) of byte offset `byte` of `text` (columns count bytes; LF ends a
/// line; an offset past the end is the position after the last byte).
[[nodiscard]] std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t byte);

/// Parses `text` as strict JSON; a syntax error is a ParseError `FILE:LINE:COLUMN: invalid JSON
/// (...)` at the byte where the parser stopped, and so is a number too large for a double
/// (nlohmann's out_of_range 406, which carries no position of its own). `file` is only used in the
/// message; `first_line` is the line of the file on which `text` begins (JSON-lines files).
[[nodiscard]] nlohmann::json parse_json_text(std::string_view text, std::string_view file,
                                             std::size_t first_line = 1);

}  // namespace pathref::io
