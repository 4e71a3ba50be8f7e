#include "pathref/io/ros_map.hpp"

#include "pathref/io/input_file.hpp"
#include "pathref/io/json_text.hpp"

#include <fmt/core.h>

#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"

namespace pathref::io {

namespace {

/// A byte as it should appear in an error message: 'c' for printable ASCII, else byte 0xNN.
std::string describe_byte(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return fmt::format("'{}'", c);
  return fmt::format("byte 0x{:02x}", static_cast<unsigned>(u));
}

/// 1-based line and column of byte `offset` in `text` (lines end at LF; columns count bytes).
std::pair<std::size_t, std::size_t> byte_line_column(std::string_view text, std::size_t offset) {
  std::size_t line = 1;
  std::size_t line_start = 0;
  const std::size_t end = std::min(offset, text.size());
  for (std::size_t i = 0; i < end; ++i)
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  return {line, offset - line_start + 1};
}

// ============================================================================================
// PGM
// ============================================================================================

/// PGM whitespace (Netpbm pgm(5)): blank, tab, LF, CR, vertical tab, form feed.
bool is_pgm_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}
bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// Reads a PGM byte string with positions for errors.
class PgmReader {
 public:
  PgmReader(std::string_view bytes, std::string file) : b_(bytes), file_(std::move(file)) {}

  [[noreturn]] void fail_at(std::size_t offset, const std::string& message) const {
    const auto [line, column] = byte_line_column(b_, offset);
    throw ParseError(file_, line, column, message);
  }

  /// Skips whitespace and comments ('#' to the next LF or CR). Returns true if anything was
  /// skipped.
  bool skip_space_and_comments() {
    const std::size_t start = pos_;
    while (pos_ < b_.size()) {
      if (is_pgm_space(b_[pos_])) {
        ++pos_;
      } else if (b_[pos_] == '#') {
        while (pos_ < b_.size() && b_[pos_] != '\n' && b_[pos_] != '\r') ++pos_;
      } else {
        break;
      }
    }
    return pos_ != start;
  }

  /// One header number (`what`: "width", "height", "maxval") in [lo, hi], preceded by
  /// whitespace/comments and followed by whitespace, a comment or (maxval of P2 only) the end.
  struct Number {
    std::int64_t value;
    std::size_t offset;
  };
  Number header_number(const char* what, std::int64_t lo, std::int64_t hi) {
    skip_space_and_comments();
    if (pos_ >= b_.size())
      fail_at(pos_, fmt::format("unexpected end of file: expected the {} (a decimal integer)", what));
    if (!is_digit(b_[pos_]))
      fail_at(pos_, fmt::format("expected the {} (a decimal integer), got {}", what,
                                describe_byte(b_[pos_])));
    const std::size_t start = pos_;
    while (pos_ < b_.size() && is_digit(b_[pos_])) ++pos_;
    const std::string_view digits = b_.substr(start, pos_ - start);
    std::int64_t v = 0;
    const bool too_long = digits.size() > 18;
    if (!too_long)
      for (const char c : digits) v = v * 10 + (c - '0');
    if (too_long || v < lo || v > hi)
      fail_at(start, fmt::format("{} must be between {} and {}, got {}", what, lo, hi, digits));
    if (pos_ < b_.size() && !is_pgm_space(b_[pos_]) && b_[pos_] != '#')
      fail_at(pos_, fmt::format("expected whitespace after the {}, got {}", what,
                                describe_byte(b_[pos_])));
    return Number{v, start};
  }

  std::string_view b_;
  std::string file_;
  std::size_t pos_ = 0;
};

}  // namespace

PgmImage parse_pgm(std::string_view bytes, std::string_view filename) {
  PgmReader r(bytes, std::string(filename));
  if (bytes.empty()) r.fail_at(0, "expected a PGM magic number 'P2' or 'P5', got an empty file");
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '2' && bytes[1] != '5')) {
    if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7')
      r.fail_at(0, fmt::format("unsupported Netpbm format 'P{}' (pathref reads the grayscale "
                               "formats P2 and P5)",
                               bytes[1]));
    r.fail_at(0, "expected a PGM magic number 'P2' or 'P5' (pathref reads only PGM images; "
                 "convert other image formats to PGM)");
  }
  const bool plain = bytes[1] == '2';
  r.pos_ = 2;
  if (r.pos_ < bytes.size() && !is_pgm_space(bytes[r.pos_]) && bytes[r.pos_] != '#')
    r.fail_at(r.pos_, fmt::format("expected whitespace after the magic number 'P{}', got {}",
                                  bytes[1], describe_byte(bytes[r.pos_])));
  constexpr std::int64_t max = grid::Grid::max_cells;
  const auto w = r.header_number("width", 1, max);
  const auto h = r.header_number("height", 1, max);
  const auto m = r.header_number("maxval", 1, 65535);
  if (w.value > max / h.value)
    r.fail_at(w.offset, fmt::format("a {}x{} image exceeds the limit of {} cells", w.value, h.value, max));

  PgmImage img;
  img.width = w.value;
  img.height = h.value;
  img.maxval = static_cast<std::uint32_t>(m.value);
  {
    const auto [line, column] = byte_line_column(bytes, m.offset);
    img.maxval_line = line;
    img.maxval_column = column;
  }
  const auto n = static_cast<std::size_t>(w.value * h.value);

  if (!plain) {
    // Exactly one whitespace byte (a comment may come first; the byte ending it counts).
    if (r.pos_ < bytes.size() && bytes[r.pos_] == '#')
      while (r.pos_ < bytes.size() && bytes[r.pos_] != '\n' && bytes[r.pos_] != '\r') ++r.pos_;
    if (r.pos_ >= bytes.size())
      r.fail_at(r.pos_, "unexpected end of file: expected one whitespace byte and the pixel data "
                        "after the maxval");
    ++r.pos_;  // header_number guaranteed it is whitespace (or the comment's line end)
    const std::size_t bps = img.maxval > 255 ? 2 : 1;
    const std::size_t data_start = r.pos_;
    const std::size_t need = n * bps;
    const std::size_t have = bytes.size() - data_start;
    if (have < need)
      r.fail_at(data_start,
                fmt::format("unexpected end of file in the pixel data: expected {} bytes ({}x{} "
                            "pixels, {} byte{} each) from byte offset {}, got {}",
                            need, img.width, img.height, bps, bps == 1 ? "" : "s", data_start, have));
    img.pixels.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t off = data_start + i * bps;
      std::uint32_t v = static_cast<unsigned char>(bytes[off]);
      if (bps == 2) v = (v << 8) | static_cast<unsigned char>(bytes[off + 1]);
      if (v > img.maxval)
        r.fail_at(data_start,
                  fmt::format("pixel value {} at byte offset {} (column {}, row {}) is larger than "
                              "the maxval {}",
                              v, off, i % static_cast<std::size_t>(img.width) + 1,
                              i / static_cast<std::size_t>(img.width) + 1, img.maxval));
      img.pixels[i] = static_cast<std::uint16_t>(v);
    }
    for (std::size_t off = data_start + need; off < bytes.size(); ++off)
      if (!is_pgm_space(bytes[off]))
        r.fail_at(off, fmt::format("expected end of file after the pixel data, got {} at byte "
                                   "offset {} (files with more than one image are not supported)",
                                   describe_byte(bytes[off]), off));
    return img;
  }

  // P2: the samples as decimal text. A sample takes at least 2 bytes (digit + separator) except
  // the last, so a file with fewer than 2n - 1 bytes left cannot hold n samples: only then is
  // the vector allocated, after a validating pass has found the exact error.
  const std::size_t samples_start = r.pos_;
  const bool may_fit = bytes.size() - samples_start >= 2 * n - 1;
  const auto read_samples = [&](bool store) {
    r.pos_ = samples_start;
    for (std::size_t i = 0; i < n; ++i) {
      r.skip_space_and_comments();
      if (r.pos_ >= bytes.size())
        r.fail_at(r.pos_, fmt::format("unexpected end of file: expected pixel value {} of {}", i + 1, n));
      if (!is_digit(bytes[r.pos_]))
        r.fail_at(r.pos_, fmt::format("expected pixel value {} of {} (a decimal integer), got {}",
                                      i + 1, n, describe_byte(bytes[r.pos_])));
      const std::size_t start = r.pos_;
      while (r.pos_ < bytes.size() && is_digit(bytes[r.pos_])) ++r.pos_;
      const std::string_view digits = bytes.substr(start, r.pos_ - start);
      std::uint32_t v = 0;
      const bool too_long = digits.size() > 6;
      if (!too_long)
        for (const char c : digits) v = v * 10 + static_cast<std::uint32_t>(c - '0');
      if (too_long || v > img.maxval)
        r.fail_at(start, fmt::format("pixel value {} (column {}, row {}) is larger than the maxval {}",
                                     digits, i % static_cast<std::size_t>(img.width) + 1,
                                     i / static_cast<std::size_t>(img.width) + 1, img.maxval));
      if (r.pos_ < bytes.size() && !is_pgm_space(bytes[r.pos_]) && bytes[r.pos_] != '#')
        r.fail_at(r.pos_, fmt::format("expected whitespace after pixel value {} of {}, got {}", i + 1,
                                      n, describe_byte(bytes[r.pos_])));
      if (store) img.pixels[i] = static_cast<std::uint16_t>(v);
    }
    r.skip_space_and_comments();
    if (r.pos_ < bytes.size())
      r.fail_at(r.pos_, fmt::format("expected end of file after the {} pixel values", n));
  };
  if (!may_fit) read_samples(false);  // throws: the data cannot be complete
  img.pixels.resize(n);
  read_samples(true);
  return img;
}

namespace {
void check_pgm_image(const PgmImage& image) {
  require(image.width >= 1 && image.height >= 1 && image.width <= grid::Grid::max_cells / image.height,
          "PGM writer: the image size must be at least 1x1 and at most Grid::max_cells pixels");
  require(image.maxval >= 1 && image.maxval <= 65535, "PGM writer: maxval must be in [1, 65535]");
  require(image.pixels.size() == static_cast<std::size_t>(image.width * image.height),
          "PGM writer: pixels.size() must be width * height");
  for (const std::uint16_t v : image.pixels)
    require(v <= image.maxval, "PGM writer: a sample is larger than the maxval");
}
}  // namespace

std::string to_pgm_p5(const PgmImage& image) {
  check_pgm_image(image);
  std::string out = fmt::format("P5\n{} {}\n{}\n", image.width, image.height, image.maxval);
  const bool two = image.maxval > 255;
  out.reserve(out.size() + image.pixels.size() * (two ? 2 : 1));
  for (const std::uint16_t v : image.pixels) {
    if (two) out += static_cast<char>(static_cast<unsigned char>(v >> 8));
    out += static_cast<char>(static_cast<unsigned char>(v & 0xffU));
  }
  return out;
}

std::string to_pgm_p2(const PgmImage& image) {
  check_pgm_image(image);
  std::string out = fmt::format("P2\n{} {}\n{}\n", image.width, image.height, image.maxval);
  const auto w = static_cast<std::size_t>(image.width);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    out += fmt::format("{}", image.pixels[i]);
    out += (i % w == w - 1) ? '\n' : ' ';
  }
  return out;
}

// ============================================================================================
// map_server YAML (a strict subset)
// ============================================================================================

RosMapMode parse_ros_map_mode(std::string_view name) {
  if (name == "trinary") return RosMapMode::trinary;
  if (name == "scale") return RosMapMode::scale;
  if (name == "raw") return RosMapMode::raw;
  throw UsageError(fmt::format("unknown map mode '{}' (expected trinary, scale or raw)", printable(name)));
}

std::string_view to_string(RosMapMode mode) noexcept {
  switch (mode) {
    case RosMapMode::trinary: return "trinary";
    case RosMapMode::scale: return "scale";
    case RosMapMode::raw: return "raw";
  }
  return "trinary";
}

UnknownAs parse_unknown_as(std::string_view name) {
  if (name == "blocked") return UnknownAs::blocked;
  if (name == "free") return UnknownAs::free;
  throw UsageError(fmt::format("unknown value '{}' for unknown cells (expected blocked or free)", printable(name)));
}

std::string_view to_string(UnknownAs u) noexcept { return u == UnknownAs::free ? "free" : "blocked"; }

namespace {

bool is_blank_char(char c) { return c == ' ' || c == '\t'; }

/// A YAML scalar or a one-line flow sequence of scalars, with positions.
struct Scalar {
  std::string text;
  std::size_t column = 0;  ///< 1-based column of the first byte (the quote for quoted scalars)
  bool quoted = false;
};
struct Value {
  bool is_sequence = false;
  Scalar scalar;                 ///< when !is_sequence
  std::vector<Scalar> items;     ///< when is_sequence
  std::size_t column = 0;        ///< where the value starts
};

constexpr const char* kKeyList = "image, resolution, origin, negate, occupied_thresh, free_thresh, mode";

class YamlReader {
 public:
  YamlReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(std::size_t line, std::size_t column, const std::string& message) const {
    throw ParseError(file_, line, column, message);
  }

  /// Position after the value: only blanks, then an optional comment (' #' ...).
  void expect_line_end(std::string_view t, std::size_t i, std::size_t line, const std::string& after) const {
    while (i < t.size() && is_blank_char(t[i])) ++i;
    if (i < t.size() && t[i] != '#')
      fail(line, i + 1, fmt::format("expected end of line after {}, got {}", after, describe_byte(t[i])));
  }

  /// Parses the value of `key` starting at byte i of line text t.
  Value parse_value(std::string_view t, std::size_t i, std::size_t line, std::string_view key) const {
    Value v;
    v.column = i + 1;
    const char c = t[i];
    if (c == '[') {
      v.is_sequence = true;
      ++i;
      for (;;) {
        while (i < t.size() && is_blank_char(t[i])) ++i;
        if (i >= t.size())
          fail(line, i + 1, fmt::format("expected ']' to close the sequence of '{}' on the same line "
                                        "(multi-line sequences are not part of the accepted subset)",
                                        key));
        if (t[i] == ']' && v.items.empty()) {
          ++i;
          break;
        }
        const std::size_t b = i;
        while (i < t.size() && t[i] != ',' && t[i] != ']' && !is_blank_char(t[i])) ++i;
        if (i == b)
          fail(line, i + 1, fmt::format("expected a number in the sequence of '{}', got {}", key,
                                        describe_byte(t[i])));
        Scalar s{std::string(t.substr(b, i - b)), b + 1, false};
        if (s.text.front() == '[' || s.text.front() == '{' || s.text.front() == '"' ||
            s.text.front() == '\'')
          fail(line, b + 1, fmt::format("expected a plain number in the sequence of '{}' (nested "
                                        "or quoted items are not part of the accepted subset)",
                                        key));
        v.items.push_back(std::move(s));
        while (i < t.size() && is_blank_char(t[i])) ++i;
        if (i >= t.size())
          fail(line, i + 1, fmt::format("expected ']' to close the sequence of '{}' on the same line "
                                        "(multi-line sequences are not part of the accepted subset)",
                                        key));
        if (t[i] == ',') {
          ++i;
          continue;
        }
        if (t[i] == ']') {
          ++i;
          break;
        }
        fail(line, i + 1, fmt::format("expected ',' or ']' in the sequence of '{}', got {}", key,
                                      describe_byte(t[i])));
      }
      expect_line_end(t, i, line, fmt::format("the sequence of '{}'", key));
      return v;
    }
    if (c == '"' || c == '\'') {
      std::string out;
      std::size_t j = i + 1;
      bool closed = false;
      while (j < t.size()) {
        const char d = t[j];
        if (c == '\'' && d == '\'') {
          if (j + 1 < t.size() && t[j + 1] == '\'') {
            out += '\'';
            j += 2;
            continue;
          }
          closed = true;
          ++j;
          break;
        }
        if (c == '"' && d == '"') {
          closed = true;
          ++j;
          break;
        }
        if (c == '"' && d == '\\') {
          if (j + 1 < t.size() && (t[j + 1] == '\\' || t[j + 1] == '"')) {
            out += t[j + 1];
            j += 2;
            continue;
          }
          fail(line, j + 1, "unsupported escape in a double-quoted string (only \\\\ and \\\" are "
                            "accepted)");
        }
        out += d;
        ++j;
      }
      if (!closed)
        fail(line, i + 1, fmt::format("unterminated {}-quoted string (quoted values must end on the "
                                      "same line)",
                                      c == '"' ? "double" : "single"));
      expect_line_end(t, j, line, fmt::format("the value of '{}'", key));
      v.scalar = Scalar{std::move(out), i + 1, true};
      return v;
    }
    const bool indicator_dash = (c == '-' || c == '?' || c == ':') && (i + 1 >= t.size() || is_blank_char(t[i + 1]));
    if (indicator_dash || c == '{' || c == '&' || c == '*' || c == '!' || c == '|' || c == '>' ||
        c == '%' || c == '@' || c == '`' || c == ',' || c == ']' || c == '}')
      fail(line, i + 1, fmt::format("unsupported YAML syntax {} in the value of '{}' (the accepted "
                                    "subset has plain and quoted scalars and one-line [ ] sequences)",
                                    describe_byte(c), key));
    // Plain scalar: up to a comment (" #") or the end of the line, trailing blanks removed.
    std::size_t e = i;
    while (e < t.size() && !(t[e] == '#' && is_blank_char(t[e - 1]))) ++e;
    while (e > i && is_blank_char(t[e - 1])) --e;
    const std::string_view text = t.substr(i, e - i);
    for (std::size_t k = 0; k + 1 < text.size(); ++k)
      if (text[k] == ':' && is_blank_char(text[k + 1]))
        fail(line, i + k + 1, fmt::format("unexpected ': ' in the value of '{}' (nested mappings are "
                                          "not part of the accepted subset; quote the value)",
                                          key));
    v.scalar = Scalar{std::string(text), i + 1, false};
    return v;
  }

  std::string file_;
};

/// YAML 1.2 core-schema float syntax: [-+]? ( \. [0-9]+ | [0-9]+ ( \. [0-9]* )? ) ( [eE] [-+]? [0-9]+ )?
bool is_yaml_number(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  std::size_t int_digits = 0;
  while (i < s.size() && is_digit(s[i])) ++i, ++int_digits;
  std::size_t frac_digits = 0;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i, ++frac_digits;
  }
  if (int_digits == 0 && frac_digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    std::size_t exp_digits = 0;
    while (i < s.size() && is_digit(s[i])) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  return i == s.size();
}

}  // namespace

RosMapMeta parse_ros_yaml(std::string_view text, std::string_view filename, bool allow_unknown_keys) {
  const YamlReader y{std::string(filename)};
  RosMapMeta meta;
  struct Seen {
    std::size_t line = 0;
    std::size_t column = 0;  ///< of the value
  };
  Seen image, resolution, origin, negate, occ, fre, mode;
  bool document_started = false;  // a "---" or a key was seen
  bool document_ended = false;    // "..." was seen
  std::size_t number = 0;
  std::size_t last_line = 0;
  std::size_t start = 0;

  const auto parse_number_scalar = [&](const Scalar& s, std::size_t line, const std::string& what) {
    if (s.quoted || !is_yaml_number(s.text))
      y.fail(line, s.column, fmt::format("expected {} as a number, got '{}'", what, printable(s.text)));
    std::string_view digits = s.text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double d = 0.0;
    const auto res = std::from_chars(digits.data(), digits.data() + digits.size(), d);
    if (res.ec != std::errc() || res.ptr != digits.data() + digits.size() || !std::isfinite(d))
      y.fail(line, s.column, fmt::format("{} '{}' is out of the range of a binary64 number", what, printable(s.text)));
    return d;
  };

  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    const bool terminated = end != std::string_view::npos;
    if (!terminated) end = text.size();
    std::size_t content_end = end;
    if (terminated && content_end > start && text[content_end - 1] == '\r') --content_end;
    std::string_view t = text.substr(start, content_end - start);
    ++number;
    last_line = number;
    start = terminated ? end + 1 : end;
    if (const std::size_t cr = t.find('\r'); cr != std::string_view::npos)
      y.fail(number, cr + 1, "unexpected carriage return (lines must end in LF or CRLF)");
    std::size_t i0 = 0;
    if (number == 1 && t.substr(0, 3) == "\xEF\xBB\xBF") i0 = 3;  // a UTF-8 BOM is allowed
    for (std::size_t k = i0; k < t.size(); ++k) {
      const auto u = static_cast<unsigned char>(t[k]);
      if ((u < 0x20 && t[k] != '\t') || u == 0x7f)
        y.fail(number, k + 1, fmt::format("unexpected control character {}", describe_byte(t[k])));
    }
    std::size_t i = i0;
    while (i < t.size() && is_blank_char(t[i])) ++i;
    if (i == t.size() || t[i] == '#') continue;  // blank or comment line
    if (document_ended)
      y.fail(number, i + 1, "expected end of file after the document end marker '...'");
    const std::string_view rest = t.substr(i0);
    const auto marker = [&](std::string_view m) {
      return i == i0 && rest.substr(0, 3) == m && (rest.size() == 3 || is_blank_char(rest[3]));
    };
    if (marker("---")) {
      if (document_started)
        y.fail(number, 1, "unexpected document start marker '---' (a map_server YAML file holds one "
                          "document)");
      document_started = true;
      y.expect_line_end(t, i0 + 3, number, "'---'");
      continue;
    }
    if (marker("...")) {
      document_ended = true;
      y.expect_line_end(t, i0 + 3, number, "'...'");
      continue;
    }
    if (i != i0)
      y.fail(number, i + 1, "expected a key at column 1 (indented lines and nested mappings are not "
                            "part of the accepted subset)");
    if (t[i] == '%')
      y.fail(number, i + 1, "YAML directives ('%...') are not part of the accepted subset");
    // key
    const std::size_t kb = i;
    while (i < t.size() && (is_digit(t[i]) || (t[i] >= 'a' && t[i] <= 'z') || (t[i] >= 'A' && t[i] <= 'Z') ||
                            t[i] == '_' || t[i] == '-'))
      ++i;
    if (i == kb || i >= t.size() || t[i] != ':' || (i + 1 < t.size() && !is_blank_char(t[i + 1])))
      y.fail(number, kb + 1, "expected 'key: value' (keys are plain words followed by ': ')");
    const std::string key(t.substr(kb, i - kb));
    document_started = true;
    ++i;  // ':'
    while (i < t.size() && is_blank_char(t[i])) ++i;
    Seen* seen = nullptr;
    if (key == "image") seen = &image;
    else if (key == "resolution") seen = &resolution;
    else if (key == "origin") seen = &origin;
    else if (key == "negate") seen = &negate;
    else if (key == "occupied_thresh") seen = &occ;
    else if (key == "free_thresh") seen = &fre;
    else if (key == "mode") seen = &mode;
    if (seen == nullptr) {
      if (allow_unknown_keys) continue;
      y.fail(number, kb + 1, fmt::format("unknown key '{}' (map_server reads {})", printable(key), kKeyList));
    }
    if (seen->line != 0)
      y.fail(number, kb + 1, fmt::format("duplicate key '{}' (first given on line {})", printable(key), seen->line));
    if (i >= t.size() || t[i] == '#')
      y.fail(number, i + 1, fmt::format("expected a value after '{}:' on the same line", key));
    const Value v = y.parse_value(t, i, number, key);
    seen->line = number;
    seen->column = v.column;
    const auto scalar = [&](const char* what) -> const Scalar& {
      if (v.is_sequence)
        y.fail(number, v.column, fmt::format("expected {}, got a sequence", what));
      return v.scalar;
    };
    if (key == "image") {
      const Scalar& s = scalar("the image file name");
      if (!s.quoted && (s.text == "~" || s.text == "null" || s.text == "Null" || s.text == "NULL"))
        y.fail(number, s.column, "expected the image file name, got null");
      if (s.text.empty()) y.fail(number, s.column, "expected the image file name, got an empty string");
      for (const char c : s.text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f)
          y.fail(number, s.column, fmt::format("expected an image file name without control "
                                               "characters, got {}",
                                               describe_byte(c)));
      }
      meta.image = s.text;
      meta.image_line = number;
      meta.image_column = s.column;
    } else if (key == "resolution") {
      const Scalar& s = scalar("resolution as a number");
      meta.resolution = parse_number_scalar(s, number, "resolution");
      if (!(meta.resolution > 0.0))
        y.fail(number, s.column, fmt::format("resolution must be greater than 0, got {}", s.text));
    } else if (key == "origin") {
      if (!v.is_sequence)
        y.fail(number, v.column, fmt::format("expected origin as a sequence [x, y, yaw], got '{}'", printable(v.scalar.text)));
      if (v.items.size() != 3)
        y.fail(number, v.column, fmt::format("expected origin as a sequence of 3 numbers [x, y, yaw], "
                                             "got {} item{}",
                                             v.items.size(), v.items.size() == 1 ? "" : "s"));
      static constexpr const char* names[3] = {"origin x", "origin y", "origin yaw"};
      for (std::size_t k = 0; k < 3; ++k) meta.origin[k] = parse_number_scalar(v.items[k], number, names[k]);
    } else if (key == "negate") {
      const Scalar& s = scalar("negate as 0, 1, true or false");
      if (!s.quoted && s.text == "0") meta.negate = false;
      else if (!s.quoted && s.text == "1") meta.negate = true;
      else if (!s.quoted && (s.text == "false" || s.text == "False" || s.text == "FALSE")) meta.negate = false;
      else if (!s.quoted && (s.text == "true" || s.text == "True" || s.text == "TRUE")) meta.negate = true;
      else y.fail(number, s.column, fmt::format("expected negate as 0, 1, true or false, got '{}'", s.text));
    } else if (key == "occupied_thresh" || key == "free_thresh") {
      const Scalar& s = scalar(key == "occupied_thresh" ? "occupied_thresh as a number" : "free_thresh as a number");
      const double d = parse_number_scalar(s, number, key);
      if (!(d >= 0.0 && d <= 1.0))
        y.fail(number, s.column, fmt::format("{} must be between 0 and 1, got {}", key, s.text));
      (key == "occupied_thresh" ? meta.occupied_thresh : meta.free_thresh) = d;
    } else {  // mode
      const Scalar& s = scalar("mode as trinary, scale or raw");
      if (s.text == "trinary") meta.mode = RosMapMode::trinary;
      else if (s.text == "scale") meta.mode = RosMapMode::scale;
      else if (s.text == "raw") meta.mode = RosMapMode::raw;
      else y.fail(number, s.column, fmt::format("expected mode as trinary, scale or raw, got '{}'", s.text));
    }
  }

  const std::size_t eof_line = last_line + 1;
  const std::pair<const Seen*, const char*> required[] = {
      {&image, "image"}, {&resolution, "resolution"}, {&origin, "origin"}, {&negate, "negate"},
      {&occ, "occupied_thresh"}, {&fre, "free_thresh"}};
  for (const auto& [seen, name] : required)
    if (seen->line == 0)
      y.fail(eof_line, 1, fmt::format("missing required key '{}' (map_server requires image, "
                                      "resolution, origin, negate, occupied_thresh, free_thresh)",
                                      name));
  if (meta.free_thresh > meta.occupied_thresh)
    y.fail(fre.line, fre.column, fmt::format("free_thresh ({}) must not be larger than occupied_thresh ({})",
                                             meta.free_thresh, meta.occupied_thresh));
  if (meta.mode == RosMapMode::raw && meta.negate)
    y.fail(negate.line, negate.column,
           "negate must be 0 in mode raw (ROS 1 map_server inverts raw values when negated, Nav2 "
           "does not; pathref does not guess)");
  return meta;
}

namespace {
void check_meta(const RosMapMeta& m) {
  require(!m.image.empty(), "to_ros_yaml: the image name is empty");
  for (const char c : m.image) {
    const auto u = static_cast<unsigned char>(c);
    require(u >= 0x20 && u != 0x7f, "to_ros_yaml: the image name contains a control character");
  }
  require(std::isfinite(m.resolution) && m.resolution > 0.0, "to_ros_yaml: resolution must be finite and > 0");
  for (const double d : m.origin) require(std::isfinite(d), "to_ros_yaml: origin must be finite");
  require(m.free_thresh >= 0.0 && m.free_thresh <= m.occupied_thresh && m.occupied_thresh <= 1.0,
          "to_ros_yaml: thresholds must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
  require(!(m.mode == RosMapMode::raw && m.negate), "to_ros_yaml: negate is not allowed in mode raw");
}

/// Shortest decimal that reads back as exactly `d` (fmt's default for doubles).
std::string number_text(double d) { return fmt::format("{}", d); }
}  // namespace

std::string to_ros_yaml(const RosMapMeta& meta) {
  check_meta(meta);
  std::string image = "\"";
  for (const char c : meta.image) {
    if (c == '"' || c == '\\') image += '\\';
    image += c;
  }
  image += '"';
  return fmt::format(
      "image: {}\nmode: {}\nresolution: {}\norigin: [{}, {}, {}]\nnegate: {}\noccupied_thresh: {}\n"
      "free_thresh: {}\n",
      image, to_string(meta.mode), number_text(meta.resolution), number_text(meta.origin[0]),
      number_text(meta.origin[1]), number_text(meta.origin[2]), meta.negate ? 1 : 0,
      number_text(meta.occupied_thresh), number_text(meta.free_thresh));
}

// ============================================================================================
// Occupancy
// ============================================================================================

Occupancy classify_pixel(std::uint32_t v, std::uint32_t maxval, const RosMapMeta& meta) {
  require(maxval >= 1 && maxval <= 65535 && v <= maxval, "classify_pixel: need 1 <= maxval <= 65535 and v <= maxval");
  double p = 0.0;
  if (meta.mode == RosMapMode::raw) {
    require(maxval == 255 && !meta.negate, "classify_pixel: mode raw needs maxval 255 and no negate");
    if (v > 100) return Occupancy::unknown;
    p = static_cast<double>(v) / 100.0;
  } else {
    const auto m = static_cast<double>(maxval);
    p = meta.negate ? static_cast<double>(v) / m : static_cast<double>(maxval - v) / m;
  }
  if (p > meta.occupied_thresh) return Occupancy::occupied;
  if (p < meta.free_thresh) return Occupancy::free;
  return Occupancy::unknown;
}

RosMap ros_map_from_image(const PgmImage& image, const RosMapMeta& meta, const RosMapOptions& options,
                          std::string_view image_name) {
  if (meta.mode == RosMapMode::raw && image.maxval != 255)
    throw ParseError(std::string(image_name), image.maxval_line, image.maxval_column,
                     fmt::format("mode raw needs an 8-bit image with maxval 255, got maxval {}", image.maxval));
  RosMap out{MapFile{grid::Grid(image.width, image.height), std::nullopt, std::nullopt, ""}, meta,
             std::string(image_name), 0};
  // Occupancy depends only on the sample value: for images with more pixels than possible
  // values, classify each value once (a table of maxval + 1 entries); else classify each pixel.
  const bool use_table = image.pixels.size() > static_cast<std::size_t>(image.maxval);
  std::vector<Occupancy> table;
  if (use_table) {
    table.resize(static_cast<std::size_t>(image.maxval) + 1);
    for (std::uint32_t v = 0; v <= image.maxval; ++v) table[v] = classify_pixel(v, image.maxval, meta);
  }
  const std::int64_t w = image.width;
  const std::int64_t h = image.height;
  for (std::int64_t row = 0; row < h; ++row)
    for (std::int64_t x = 0; x < w; ++x) {
      const std::uint16_t v = image.pixels[static_cast<std::size_t>(row * w + x)];
      const Occupancy o = use_table ? table[v] : classify_pixel(v, image.maxval, meta);
      if (o == Occupancy::unknown) ++out.unknown_cells;
      if (o == Occupancy::occupied || (o == Occupancy::unknown && options.unknown == UnknownAs::blocked))
        out.map.grid.set_blocked(grid::Cell{x, h - 1 - row}, true);
    }
  return out;
}

RosMap parse_ros_map(std::string_view yaml_text, std::string_view yaml_name, std::string_view pgm_bytes,
                     std::string_view image_path, const RosMapOptions& options) {
  const RosMapMeta meta = parse_ros_yaml(yaml_text, yaml_name, options.allow_unknown_keys);
  const PgmImage image = parse_pgm(pgm_bytes, image_path);
  return ros_map_from_image(image, meta, options, image_path);
}

namespace {
/// Reads a file for load_ros_map through io::read_input_file's checks; throws `fail(reason)`
/// when it cannot (spec/formats.md#input-files).
template <class Fail>
std::string read_file_bytes(const std::string& path, Fail fail) {
  std::string out, reason;
  if (!try_read_input_file(path, max_map_file_bytes, out, reason)) fail(reason);
  return out;
}
}  // namespace

RosMap load_ros_map(const std::string& yaml_path, const RosMapOptions& options) {
  namespace fs = std::filesystem;
  const std::string yaml = read_file_bytes(yaml_path, [&](const std::string& reason) {
    throw UsageError(fmt::format("cannot read map file '{}': {}", printable(yaml_path, 300), reason));
  });
  const RosMapMeta meta = parse_ros_yaml(yaml, yaml_path, options.allow_unknown_keys);
  fs::path image = fs::path(meta.image);
  if (!image.is_absolute()) image = fs::path(yaml_path).parent_path() / image;
  const std::string image_path = image.string();
  const std::string bytes = read_file_bytes(image_path, [&](const std::string& reason) {
    throw ParseError(yaml_path, meta.image_line, meta.image_column,
                     fmt::format("cannot read image file '{}': {}", printable(image_path, 300), reason));
  });
  const PgmImage img = parse_pgm(bytes, image_path);
  return ros_map_from_image(img, meta, options, image_path);
}

RosMapFiles to_ros_map(const grid::Grid& g, double resolution, const std::array<double, 3>& origin,
                       const std::string& image_name) {
  RosMapMeta meta;
  meta.image = image_name;
  meta.resolution = resolution;
  meta.origin = origin;
  meta.negate = false;
  meta.occupied_thresh = 0.65;
  meta.free_thresh = 0.196;
  meta.mode = RosMapMode::trinary;
  std::string yaml = to_ros_yaml(meta);  // checks the preconditions
  PgmImage img;
  img.width = g.width();
  img.height = g.height();
  img.maxval = 255;
  img.pixels.resize(static_cast<std::size_t>(g.cell_count()));
  for (std::int64_t row = 0; row < g.height(); ++row)
    for (std::int64_t x = 0; x < g.width(); ++x)
      img.pixels[static_cast<std::size_t>(row * g.width() + x)] =
          g.blocked(grid::Cell{x, g.height() - 1 - row}) ? std::uint16_t{0} : std::uint16_t{254};
  return RosMapFiles{std::move(yaml), to_pgm_p5(img)};
}

void write_ros_map(const std::string& yaml_path, const grid::Grid& g, double resolution,
                   const std::array<double, 3>& origin) {
  namespace fs = std::filesystem;
  const fs::path yp(yaml_path);
  const fs::path image_name = yp.stem().string() + ".pgm";
  const RosMapFiles files = to_ros_map(g, resolution, origin, image_name.string());
  const auto write = [](const fs::path& p, const std::string& data) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    if (!out) throw UsageError(fmt::format("cannot write '{}': {}", p.string(), std::strerror(errno)));
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out) throw UsageError(fmt::format("cannot write '{}'", p.string()));
  };
  write(yp.parent_path() / image_name, files.pgm);
  write(yp, files.yaml);
}

}  // namespace pathref::io
