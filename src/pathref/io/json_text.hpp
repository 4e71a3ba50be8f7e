#pragma once
/// \file json_text.hpp
/// The one JSON reading layer of pathref (spec/formats.md#json). Every JSON text pathref reads —
/// scenes, simulation scenarios, golden files, path and trace files, model files, reproduction
/// documents, `--set` and `eval` values, `conform` answers, the Python module's arguments — goes
/// through parse_json_text, which
/// - refuses a text over its size limit before parsing (JsonLimits::max_bytes),
/// - refuses a UTF-8 byte order mark (RFC 8259 §8.1: a JSON text is not preceded by one),
/// - bounds the nesting depth while parsing, before any deeper value is built
///   (JsonLimits::max_depth), so no later code (destruction, comparison, printing) recurses deeper,
/// - refuses duplicate object keys,
/// - reports every error as a ParseError `FILE:LINE:COLUMN: what was expected`, with no library
///   exception prefix and no raw control or non-ASCII byte in the message.
/// Readers that find a wrong value after parsing report it with json_error_at (FILE:LINE:COLUMN of
/// the value a JSON pointer names, and the pointer).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "pathref/core/error.hpp"

namespace pathref::io {

/// The limits of one JSON reading (spec/formats.md#json-limits).
struct JsonLimits {
  /// Arrays and objects nested at most this deep: `1`, `"a"` are depth 0, `[]` depth 1, `[[1]]` 2.
  /// pathref's own documents nest at most 11 deep (golden whole-run vectors); 64 leaves room.
  std::size_t max_depth = 64;
  /// The text's size in bytes. The parsed value takes at most ~30 bytes per text byte
  /// (measured, spec/formats.md#json-limits), so the default bounds a document's memory by ~1 GB.
  std::size_t max_bytes = std::size_t{32} << 20;
  /// Keep each floating-point number's decimal text (as a binary value holding the text) instead
  /// of its double, for readers that convert decimals exactly (polygon scenes, spec/formats.md#scene).
  bool decimal_text = false;
};

/// A pathref document read from a file (scene, scenario, golden, path, trace, model, reproduction):
/// depth 64, 32 MiB.
inline constexpr JsonLimits document_limits{};
/// One command-line value (`--set k=V`, `eval k=V`): depth 64, 1 MiB.
inline constexpr JsonLimits cli_value_limits{64, std::size_t{1} << 20, false};
/// One line a `conform` program answers: depth 64, 16 MiB (spec/conform.md).
inline constexpr JsonLimits answer_limits{64, std::size_t{16} << 20, false};

/// The 1-based (line, column) of byte offset `byte` of `text` (columns count bytes; LF ends a
/// line; an offset past the end is the position after the last byte).
[[nodiscard]] std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t byte);

/// Parses `text` as strict JSON (RFC 8259) under `limits`. Every refusal is a ParseError
/// `FILE:LINE:COLUMN: ...` at the byte where the text stops being acceptable: a syntax error, a
/// number too large for a double, a nesting deeper than limits.max_depth (at the bracket that goes
/// one level too deep), a duplicate key (at the second occurrence), a byte order mark (1:1), a text
/// over limits.max_bytes (1:1). `file` is only used in messages; `first_line` is the line of the
/// file on which `text` begins (JSON-lines files).
[[nodiscard]] nlohmann::json parse_json_text(std::string_view text, std::string_view file,
                                             std::size_t first_line = 1, const JsonLimits& limits = document_limits);

/// A command-line value: the JSON value when `text` is JSON, std::nullopt when it is not JSON at
/// all (the caller then takes it as a plain string, spec/cli.md#values). A text that is JSON
/// but breaks a limit of cli_value_limits (too deep, too large, a duplicate key) is a UsageError
/// naming `what` (e.g. "--set alpha") and the column: such a value is never taken as a string.
[[nodiscard]] std::optional<nlohmann::json> parse_cli_json_value(std::string_view text, std::string_view what);

/// The byte offset of the value that JSON pointer `pointer` (RFC 6901, "" = the whole text) names
/// in `text`, a text parse_json_text accepted; for a pointer that names no value, the offset of
/// the deepest value on its way that exists (so a missing key is reported at its object).
/// Iterative: its stack does not grow with the text's depth.
[[nodiscard]] std::size_t pointer_offset(std::string_view text, std::string_view pointer);

/// A ParseError `FILE:LINE:COLUMN: POINTER: WHAT` for the value `pointer` names in `text` (a
/// text parse_json_text accepted; `first_line` as there; the root pointer "" is shown as "/").
/// With an empty `text` (a value that came from no file) it is `FILE: POINTER: WHAT`.
[[nodiscard]] ParseError json_error_at(std::string_view text, std::string_view file, std::string_view pointer,
                                       const std::string& what, std::size_t first_line = 1);

/// `text` made safe to print inside a message: control bytes, DEL and bytes >= 0x80 become `\xNN`,
/// and at most `max_bytes` input bytes are shown (then "..."). Used for every piece of input echoed
/// into a message.
[[nodiscard]] std::string printable(std::string_view text, std::size_t max_bytes = 80);

/// The kind of a JSON value as messages name it: "null", "a boolean", "a number", "a string",
/// "an array", "an object".
[[nodiscard]] std::string json_kind(const nlohmann::json& v);

}  // namespace pathref::io
