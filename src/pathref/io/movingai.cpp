#include "pathref/io/movingai.hpp"

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <system_error>

#include "pathref/core/error.hpp"

namespace pathref::io {

namespace {

using text::Line;

/// One blank-separated word of a line and its 1-based column.
struct Token {
  std::string_view text;
  std::size_t column = 0;
};

/// The blank-separated (space, tab) words of a line.
std::vector<Token> tokenize(std::string_view line) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && text::is_blank_char(line[i])) ++i;
    if (i == line.size()) break;
    const std::size_t b = i;
    while (i < line.size() && !text::is_blank_char(line[i])) ++i;
    out.push_back(Token{line.substr(b, i - b), b + 1});
  }
  return out;
}

/// True for a line of only spaces and tabs (or nothing).
bool is_blank(std::string_view line) {
  for (const char c : line)
    if (!text::is_blank_char(c)) return false;
  return true;
}

/// Throws at the first byte of `t` that is not printable ASCII: "EXPECTED, got byte 0xNN".
void require_printable(const Token& t, const Line& l, const std::string& file, std::string_view expected) {
  for (std::size_t i = 0; i < t.text.size(); ++i) {
    const auto u = static_cast<unsigned char>(t.text[i]);
    if (u < 0x20 || u >= 0x7f)
      throw ParseError(file, l.number, t.column + i,
                       fmt::format("{}, got {}", expected, text::describe_byte(t.text[i])));
  }
}

/// A token for a message, after require_printable: 'TEXT', cut to 32 bytes with "...".
std::string quoted(std::string_view t) {
  if (t.size() <= 32) return fmt::format("'{}'", t);
  return fmt::format("'{}...'", t.substr(0, 32));
}

/// Parses token `t` as a decimal integer in [lo, hi]; `what` names it in messages
/// ("height", "start x", ...). Messages as pathref-grid's (spec/formats.md).
std::int64_t parse_int(const Token& t, const Line& l, const std::string& file, std::string_view what,
                       std::int64_t lo, std::int64_t hi) {
  const std::string expected = fmt::format("expected {} as a decimal integer", what);
  require_printable(t, l, file, expected);
  for (const char c : t.text)
    if (c < '0' || c > '9')
      throw ParseError(file, l.number, t.column, fmt::format("{}, got {}", expected, quoted(t.text)));
  std::int64_t v = 0;
  const bool too_long = t.text.size() > 18;  // 18 digits always fit in int64
  if (!too_long)
    for (const char c : t.text) v = v * 10 + (c - '0');
  if (too_long || v < lo || v > hi)
    throw ParseError(file, l.number, t.column,
                     fmt::format("{} must be between {} and {}, got {}", what, lo, hi, quoted(t.text)));
  return v;
}

/// Throws unless the line has at most `count` tokens; `after` names what ends the line.
void expect_end(const std::vector<Token>& tokens, std::size_t count, const Line& l,
                const std::string& file, std::string_view after) {
  if (tokens.size() > count)
    throw ParseError(file, l.number, tokens[count].column,
                     fmt::format("expected end of line after {}", after));
}

// ---- .map ----------------------------------------------------------------------------------

/// The terrain letters and whether each is free (spec/formats.md#movingai-terrain).
/// Returns 0 = blocked, 1 = free, -1 = not a terrain letter.
int terrain_free(char c, const MovingAiTerrain& terrain) {
  switch (c) {
    case '.': case 'G': return 1;
    case '@': case 'O': case 'T': return 0;
    case 'S': return terrain.swamp_free ? 1 : 0;
    case 'W': return terrain.water_free ? 1 : 0;
    default: return -1;
  }
}

/// Line 1: exactly `type octile`.
void parse_type_line(const std::vector<Line>& lines, const std::string& file) {
  if (lines.empty())
    throw ParseError(file, 1, 1, "expected 'type octile' as the first line, got an empty file");
  const Line& l = lines.front();
  if (text::has_bom(l.text))
    throw ParseError(file, 1, 1,
                     "expected 'type octile' as the first line, got a UTF-8 byte-order mark "
                     "(save the file without it)");
  const auto tokens = tokenize(l.text);
  if (tokens.empty() || tokens[0].text != "type")
    throw ParseError(file, 1, tokens.empty() ? 1 : tokens[0].column,
                     "expected 'type octile' as the first line");
  if (tokens.size() < 2)
    throw ParseError(file, 1, l.text.size() + 1, "expected the map type after 'type'");
  if (tokens[1].text != "octile") {
    require_printable(tokens[1], l, file, "expected the map type 'octile'");
    throw ParseError(file, 1, tokens[1].column,
                     fmt::format("unsupported map type {} (this reader reads 'type octile')",
                                 quoted(tokens[1].text)));
  }
  expect_end(tokens, 2, l, file, "'type octile'");
}

/// Width and height with where the later of the two was written.
struct Size {
  std::int64_t width = 0;
  std::int64_t height = 0;
  std::size_t width_line = 0;
  std::size_t width_column = 0;
};

/// Lines 2 and 3: `height H` and `width W`, in either order.
Size parse_size_lines(const std::vector<Line>& lines, const std::string& file, const ReadLimits& limits) {
  Size s;
  std::size_t height_line = 0;
  for (std::size_t i = 1; i <= 2; ++i) {
    const char* expected = height_line == 0 && s.width_line == 0 ? "'height H' or 'width W'"
                           : height_line == 0                     ? "'height H'"
                                                                  : "'width W'";
    if (i >= lines.size())
      throw ParseError(file, text::eof_line(lines), 1,
                       fmt::format("unexpected end of file: expected {}", expected));
    const Line& l = lines[i];
    const auto tokens = tokenize(l.text);
    if (tokens.empty())
      throw ParseError(file, l.number, 1, fmt::format("expected {}, got an empty line", expected));
    const Token& kw = tokens[0];
    const bool is_height = kw.text == "height";
    if (!is_height && kw.text != "width") {
      require_printable(kw, l, file, fmt::format("expected {}", expected));
      throw ParseError(file, l.number, kw.column, fmt::format("expected {}, got {}", expected, quoted(kw.text)));
    }
    const std::size_t first = is_height ? height_line : s.width_line;
    if (first != 0)
      throw ParseError(file, l.number, kw.column,
                       fmt::format("duplicate '{}' line (first given on line {})", kw.text, first));
    const char* what = is_height ? "height" : "width";
    if (tokens.size() < 2)
      throw ParseError(file, l.number, l.text.size() + 1, fmt::format("expected {} (a decimal integer)", what));
    const std::int64_t v = parse_int(tokens[1], l, file, what, 1, limits.max_side);
    expect_end(tokens, 2, l, file, is_height ? "'height H'" : "'width W'");
    if (is_height) {
      s.height = v;
      height_line = l.number;
    } else {
      s.width = v;
      s.width_line = l.number;
      s.width_column = tokens[1].column;
    }
  }
  return s;
}

/// Line 4: exactly `map`.
void parse_map_keyword(const std::vector<Line>& lines, const std::string& file) {
  if (lines.size() < 4)
    throw ParseError(file, text::eof_line(lines), 1, "unexpected end of file: expected the 'map' line");
  const Line& l = lines[3];
  const auto tokens = tokenize(l.text);
  if (tokens.empty() || tokens[0].text != "map")
    throw ParseError(file, l.number, tokens.empty() ? 1 : tokens[0].column,
                     "expected 'map' after the height and width lines");
  expect_end(tokens, 1, l, file, "'map'");
}

/// Checks map row r (0 = top): exactly w terrain letters.
void check_map_row(const Line& l, std::int64_t r, std::int64_t w, const MovingAiTerrain& terrain,
                   const std::string& file) {
  const auto width = static_cast<std::size_t>(w);
  const std::size_t n = std::min(l.text.size(), width);
  for (std::size_t i = 0; i < n; ++i)
    if (terrain_free(l.text[i], terrain) < 0)
      throw ParseError(file, l.number, i + 1,
                       fmt::format("expected a MovingAI terrain letter (. G S W @ O T), got {}",
                                   text::describe_byte(l.text[i])));
  if (l.text.size() < width)
    throw ParseError(file, l.number, l.text.size() + 1,
                     fmt::format("expected {} cells in map row {}, got {}", w, r + 1, l.text.size()));
  if (l.text.size() > width)
    throw ParseError(file, l.number, width + 1,
                     fmt::format("expected end of map row {} after {} cells", r + 1, w));
}

// ---- .scen ---------------------------------------------------------------------------------

/// The column names of a scenario line, by version (spec/formats.md#movingai-scen).
const std::vector<const char*>& field_names(int version) {
  static const std::vector<const char*> v1{"bucket", "map", "width", "height", "start x",
                                           "start y", "goal x", "goal y", "optimal length"};
  static const std::vector<const char*> v0{"bucket", "map", "start x", "start y", "goal x",
                                           "goal y", "optimal length"};
  return version == 1 ? v1 : v0;
}

/// The version line, if line `l` is one: 1 or 0; nullopt when its first word is not `version`.
std::optional<int> parse_version_line(const Line& l, const std::string& file) {
  const auto tokens = tokenize(l.text);
  if (tokens.empty() || tokens[0].text != "version") return std::nullopt;
  if (tokens.size() < 2)
    throw ParseError(file, l.number, l.text.size() + 1, "expected the scenario version after 'version'");
  const std::string_view v = tokens[1].text;
  int version = 0;
  if (v == "1" || v == "1.0") {
    version = 1;
  } else if (v != "0" && v != "0.0") {
    require_printable(tokens[1], l, file, "expected the scenario version 1");
    throw ParseError(file, l.number, tokens[1].column,
                     fmt::format("unsupported scenario version {} (this reader reads 1, 1.0, 0 and 0.0)",
                                 quoted(v)));
  }
  expect_end(tokens, 2, l, file, fmt::format("'version {}'", v));
  return version;
}

/// One scenario line of a version-`version` file.
Scenario parse_scenario_line(const Line& l, int version, const std::string& file, const ReadLimits& limits) {
  const auto tokens = tokenize(l.text);
  const auto& names = field_names(version);
  const std::size_t n = names.size();
  if (tokens.size() < n)
    throw ParseError(file, l.number, l.text.size() + 1,
                     fmt::format("expected the {} (field {} of {})", names[tokens.size()],
                                 tokens.size() + 1, n));
  if (tokens.size() > n) {
    if (version == 0 && tokens.size() == 9)
      throw ParseError(file, l.number, tokens[n].column,
                       "expected end of line after 7 fields (a file without a version line is "
                       "version 0: bucket, map, start x, start y, goal x, goal y, optimal length); "
                       "a file with width and height columns needs 'version 1' as its first line");
    throw ParseError(file, l.number, tokens[n].column,
                     fmt::format("expected end of line after the optimal length (field {})", n));
  }
  constexpr std::int64_t max_coord = grid::Grid::max_cells - 1;
  Scenario s;
  s.line = l.number;
  s.bucket = parse_int(tokens[0], l, file, "bucket", 0, 2147483647);
  const Token& map = tokens[1];
  for (std::size_t i = 0; i < map.text.size(); ++i) {
    const auto u = static_cast<unsigned char>(map.text[i]);
    if (u < 0x20 || u == 0x7f)
      throw ParseError(file, l.number, map.column + i,
                       fmt::format("expected a map file name without control characters, got {}",
                                   text::describe_byte(map.text[i])));
  }
  s.map = std::string(map.text);
  s.map_column = map.column;
  std::size_t k = 2;
  const auto field = [&](const char* what, std::int64_t lo, std::int64_t hi) {
    const Token& t = tokens[k++];
    return ScenField{parse_int(t, l, file, what, lo, hi), t.column};
  };
  if (version == 1) {
    s.width = field("width", 1, limits.max_side);
    s.height = field("height", 1, limits.max_side);
  }
  s.start_x = field("start x", 0, max_coord);
  s.start_y = field("start y", 0, max_coord);
  s.goal_x = field("goal x", 0, max_coord);
  s.goal_y = field("goal y", 0, max_coord);
  const Token& len = tokens[k];
  const auto printed = parse_printed_length(len.text);
  if (!printed) {
    const std::string expected = "expected the optimal length as a decimal number such as 3.41421";
    require_printable(len, l, file, expected);
    throw ParseError(file, l.number, len.column, fmt::format("{}, got {}", expected, quoted(len.text)));
  }
  s.optimal = *printed;
  s.optimal_column = len.column;
  if (version == 1) {
    const auto inside = [&](const ScenField& x, const ScenField& y, const char* which) {
      if (x.value >= s.width->value || y.value >= s.height->value)
        throw ParseError(file, l.number, x.column,
                         fmt::format("{} ({}, {}) is outside the {}x{} map of this line (x must be "
                                     "< {}, y < {})",
                                     which, x.value, y.value, s.width->value, s.height->value,
                                     s.width->value, s.height->value));
    };
    inside(s.start_x, s.start_y, "start");
    inside(s.goal_x, s.goal_y, "goal");
  }
  if (s.start_x.value == s.goal_x.value && s.start_y.value == s.goal_y.value)
    throw ParseError(file, l.number, s.start_x.column,
                     fmt::format("start ({}, {}) equals the goal (a scenario needs two different cells)",
                                 s.start_x.value, s.start_y.value));
  return s;
}

}  // namespace

// ---- .map ------------------------------------------------------------------------------------

MapFile parse_movingai_map(std::string_view text_in, std::string_view filename,
                           const MovingAiTerrain& terrain, const ReadLimits& limits) {
  check_limits(limits);
  const std::string file(filename);
  const std::vector<Line> lines = text::split_lines(text_in, file);
  parse_type_line(lines, file);
  const Size size = parse_size_lines(lines, file, limits);
  const std::int64_t w = size.width;
  const std::int64_t h = size.height;
  if (w > limits.max_cells / h)
    throw ParseError(file, size.width_line, size.width_column,
                     fmt::format("a {}x{} map exceeds the limit of {} cells", w, h, limits.max_cells));
  parse_map_keyword(lines, file);
  // All H rows are checked before the grid is allocated.
  constexpr std::size_t first = 4;
  for (std::int64_t r = 0; r < h; ++r) {
    const std::size_t i = first + static_cast<std::size_t>(r);
    if (i >= lines.size())
      throw ParseError(file, text::eof_line(lines), 1,
                       fmt::format("unexpected end of file: expected map row {} of {}", r + 1, h));
    check_map_row(lines[i], r, w, terrain, file);
  }
  for (std::size_t i = first + static_cast<std::size_t>(h); i < lines.size(); ++i)
    if (!is_blank(lines[i].text))
      throw ParseError(file, lines[i].number, 1,
                       fmt::format("expected end of file after the {} map rows", h));
  MapFile m{grid::Grid(w, h), std::nullopt, std::nullopt, ""};
  for (std::int64_t r = 0; r < h; ++r) {
    const std::string_view row = lines[first + static_cast<std::size_t>(r)].text;
    for (std::int64_t x = 0; x < w; ++x)
      if (terrain_free(row[static_cast<std::size_t>(x)], terrain) == 0)
        m.grid.set_blocked(grid::Cell{x, h - 1 - r}, true);
  }
  return m;
}

std::string to_movingai_map(const grid::Grid& g) {
  std::string out = fmt::format("type octile\nheight {}\nwidth {}\nmap\n", g.height(), g.width());
  out.reserve(out.size() + static_cast<std::size_t>(g.cell_count() + g.height()));
  for (std::string row : g.to_rows_top_first()) {
    for (char& c : row) c = c == '#' ? '@' : '.';
    out += row;
    out += '\n';
  }
  return out;
}

// ---- lengths ---------------------------------------------------------------------------------

std::optional<PrintedLength> parse_printed_length(std::string_view t) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t b = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i - b;
  };
  const std::size_t int_digits = digits();
  if (int_digits == 0) return std::nullopt;
  std::size_t frac_digits = 0;
  if (i < t.size() && t[i] == '.') {
    ++i;
    frac_digits = digits();
    if (frac_digits == 0) return std::nullopt;
  }
  const std::size_t mantissa_end = i;
  int exponent = 0;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    bool negative = false;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) negative = t[i++] == '-';
    const std::size_t b = i;
    const std::size_t n = digits();
    if (n == 0 || n > 3) return std::nullopt;
    for (std::size_t k = b; k < i; ++k) exponent = exponent * 10 + (t[k] - '0');
    if (negative) exponent = -exponent;
  }
  if (i != t.size() || int_digits + frac_digits > 40) return std::nullopt;
  PrintedLength p;
  p.text = std::string(t);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
  p.value = v;
  p.last_digit_exponent = exponent - static_cast<int>(frac_digits);
  // Significant digits: from the first non-zero mantissa digit to the last printed one.
  std::size_t sig = 0;
  bool seen = false;
  for (std::size_t k = 0; k < mantissa_end; ++k) {
    if (t[k] == '.') continue;
    seen = seen || t[k] != '0';
    if (seen) ++sig;
  }
  p.significant_digits = seen ? static_cast<int>(sig) : 1;
  return p;
}

double agreement_tolerance(const PrintedLength& length, int writer_digits) {
  require(writer_digits >= 0 && writer_digits <= 17, "agreement_tolerance: writer digits must be in [0, 17]");
  const int dropped = std::max(0, writer_digits - length.significant_digits);
  const int k = length.last_digit_exponent - dropped;
  // The double nearest 10^k, read from its decimal text (correctly rounded, unlike pow).
  const std::string s = fmt::format("1e{}", k);
  double u = 0.0;
  const auto result = std::from_chars(s.data(), s.data() + s.size(), u);
  if (result.ec == std::errc::result_out_of_range) u = k < 0 ? 0.0 : HUGE_VAL;  // under/overflow
  return u;
}

bool lengths_agree(double computed, const PrintedLength& printed, double tolerance) noexcept {
  return std::fabs(computed - printed.value) <= tolerance;
}

// ---- .scen -----------------------------------------------------------------------------------

ScenFile parse_movingai_scen(std::string_view text_in, std::string_view filename, const ReadLimits& limits) {
  check_limits(limits);
  const std::string file(filename);
  const std::vector<Line> lines = text::split_lines(text_in, file);
  if (lines.empty())
    throw ParseError(file, 1, 1, "expected a 'version 1' line or a scenario line, got an empty file");
  if (text::has_bom(lines.front().text))
    throw ParseError(file, 1, 1,
                     "expected a 'version 1' line or a scenario line, got a UTF-8 byte-order mark "
                     "(save the file without it)");
  ScenFile out;
  std::size_t i = 0;
  while (i < lines.size() && is_blank(lines[i].text)) ++i;
  out.version = 0;
  if (i < lines.size()) {
    if (const auto v = parse_version_line(lines[i], file)) {
      out.version = *v;
      ++i;
    }
  }
  for (; i < lines.size(); ++i) {
    if (is_blank(lines[i].text)) continue;
    out.scenarios.push_back(parse_scenario_line(lines[i], out.version, file, limits));
  }
  if (out.scenarios.empty())
    throw ParseError(file, text::eof_line(lines), 1, "unexpected end of file: expected a scenario line");
  return out;
}

void check_scenario_on_map(const Scenario& s, const grid::Grid& g, std::string_view map_name,
                           std::string_view filename) {
  const std::string file(filename);
  const std::int64_t w = g.width();
  const std::int64_t h = g.height();
  if (s.width && (s.width->value != w || s.height->value != h))
    throw ParseError(file, s.line, s.width->column,
                     fmt::format("the map {} is {}x{} but this line says {}x{} (pathref does not "
                                 "scale maps)",
                                 map_name, w, h, s.width->value, s.height->value));
  const auto check = [&](const ScenField& x, const ScenField& y, const char* which) {
    if (x.value >= w || y.value >= h)
      throw ParseError(file, s.line, x.column,
                       fmt::format("{} ({}, {}) is outside the {}x{} map {} (x must be < {}, y < {})",
                                   which, x.value, y.value, w, h, map_name, w, h));
    if (g.blocked(from_movingai(x.value, y.value, h)))
      throw ParseError(file, s.line, x.column,
                       fmt::format("{} ({}, {}) is a blocked cell of {}", which, x.value, y.value, map_name));
  };
  check(s.start_x, s.start_y, "start");
  check(s.goal_x, s.goal_y, "goal");
}

}  // namespace pathref::io
