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

namespace {

/// A SAX consumer that builds nothing and keeps the byte offset of the first error: nlohmann's
/// out_of_range (a number too large for a double, error 406) carries no position, the SAX call does.
class ErrorPosition final : public nlohmann::json_sax<nlohmann::json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) override {
    position_ = position;
    return false;
  }
  [[nodiscard]] std::size_t position() const noexcept { return position_; }

 private:
  std::size_t position_ = 0;
};

}  // namespace

nlohmann::json parse_json_text(std::string_view text, std::string_view file, std::size_t first_line) {
  std::size_t byte = 0;  // 1-based byte at which the parser stopped (0 when unknown)
  std::string what;
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    byte = e.byte;
    what = e.what();
  } catch (const nlohmann::json::exception& e) {  // out_of_range 406: a number that overflows a double
    ErrorPosition where;
    (void)nlohmann::json::sax_parse(text.begin(), text.end(), &where);
    byte = where.position();
    what = e.what();
  }
  const auto [line, col] = line_column(text, byte == 0 ? 0 : byte - 1);
  throw ParseError(std::string(file), first_line - 1 + line, col, "invalid JSON (" + what + ")");
}

}  // namespace pathref::io
