#include "pathref/io/json_text.hpp"

#include "pathref/core/error.hpp"

namespace pathref::io {

std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t byte) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}

nlohmann::json parse_json_text(std::string_view text, std::string_view file) {
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is 1-based: the byte at which the parser stopped (0 when unknown).
    const auto [line, col] = line_column(text, e.byte == 0 ? 0 : e.byte - 1);
    throw ParseError(std::string(file), line, col, "invalid JSON (" + std::string(e.what()) + ")");
  }
}

}  // namespace pathref::io
