#include "pathref/io/grid_text.hpp"

#include "pathref/io/input_file.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"

namespace pathref::io {

namespace {

/// One physical line of the input: its text without the line terminator ("\n" or "\r\n") and
/// its 1-based number.
struct Line {
  std::string_view text;
  std::size_t number;
};

/// One whitespace-separated word of a header line and its 1-based column (in bytes).
struct Token {
  std::string_view text;
  std::size_t column;
};

/// A numeric header value with where it was written, for later range checks.
struct Located {
  std::int64_t value = 0;
  std::size_t line = 0;
  std::size_t column = 0;
};

/// A coordinate pair from a `start` or `goal` line.
struct LocatedCell {
  Located x;
  Located y;
};

bool is_blank_char(char c) { return c == ' ' || c == '\t'; }

/// A byte as it should appear in an error message: 'c' for printable ASCII, else byte 0xNN.
std::string describe_byte(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return fmt::format("'{}'", c);
  return fmt::format("byte 0x{:02x}", static_cast<unsigned>(u));
}

/// Splits text into lines. "\r\n" ends a line like "\n"; a final line without terminator
/// counts; a '\r' anywhere else is a ParseError (spec: grid-text.line-endings).
std::vector<Line> split_lines(std::string_view text, const std::string& file) {
  std::vector<Line> lines;
  std::size_t start = 0;
  std::size_t number = 1;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    const bool terminated = end != std::string_view::npos;
    if (!terminated) end = text.size();
    std::size_t content_end = end;
    if (terminated && content_end > start && text[content_end - 1] == '\r') --content_end;
    const std::string_view content = text.substr(start, content_end - start);
    const std::size_t cr = content.find('\r');
    if (cr != std::string_view::npos)
      throw ParseError(file, number, cr + 1,
                       "unexpected carriage return (lines must end in LF or CRLF)");
    lines.push_back(Line{content, number});
    start = terminated ? end + 1 : end;
    ++number;
  }
  return lines;
}

/// The whitespace-separated words of a line (separators: space and tab).
std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_blank_char(text[i])) ++i;
    if (i == text.size()) break;
    const std::size_t b = i;
    while (i < text.size() && !is_blank_char(text[i])) ++i;
    out.push_back(Token{text.substr(b, i - b), b + 1});
  }
  return out;
}

/// True for a line that is empty or holds only spaces and tabs.
bool is_blank(std::string_view text) {
  for (const char c : text)
    if (!is_blank_char(c)) return false;
  return true;
}

/// Parses token `index` of a header line as a decimal integer in [lo, hi]; `what` names the
/// value in error messages ("width", "start x", ...).
Located parse_number(const std::vector<Token>& tokens, std::size_t index, const Line& line,
                     const std::string& file, const char* what, std::int64_t lo, std::int64_t hi) {
  if (index >= tokens.size())
    throw ParseError(file, line.number, line.text.size() + 1,
                     fmt::format("expected {} (a decimal integer)", what));
  const Token& t = tokens[index];
  for (const char c : t.text)
    if (c < '0' || c > '9')
      throw ParseError(file, line.number, t.column,
                       fmt::format("expected {} as a decimal integer, got '{}'", what, printable(t.text)));
  // At most 18 digits fit in int64 without overflow; anything longer is out of range anyway.
  std::int64_t v = 0;
  const bool too_long = t.text.size() > 18;
  if (!too_long)
    for (const char c : t.text) v = v * 10 + (c - '0');
  if (too_long || v < lo || v > hi)
    throw ParseError(file, line.number, t.column,
                     fmt::format("{} must be between {} and {}, got {}", what, lo, hi, t.text));
  return Located{v, line.number, t.column};
}

/// Throws unless the line has exactly `count` tokens; `form` is the expected line, for the
/// message.
void expect_end(const std::vector<Token>& tokens, std::size_t count, const Line& line,
                const std::string& file, const char* form) {
  if (tokens.size() > count)
    throw ParseError(file, line.number, tokens[count].column,
                     fmt::format("expected end of line after '{}'", form));
}

/// The first line: exactly "pathref-grid 1".
void parse_magic(const std::vector<Line>& lines, const std::string& file) {
  if (lines.empty())
    throw ParseError(file, 1, 1, "expected 'pathref-grid 1' as the first line, got an empty file");
  const Line& l = lines.front();
  if (l.text.substr(0, 3) == "\xEF\xBB\xBF")
    throw ParseError(file, 1, 1,
                     "expected 'pathref-grid 1' as the first line, got a UTF-8 byte-order mark "
                     "(save the file without it)");
  const auto tokens = tokenize(l.text);
  if (tokens.empty() || tokens[0].text != "pathref-grid" || tokens[0].column != 1)
    throw ParseError(file, 1, 1, "expected 'pathref-grid 1' as the first line");
  if (tokens.size() < 2)
    throw ParseError(file, 1, l.text.size() + 1, "expected the format version after 'pathref-grid'");
  if (tokens[1].text != "1")
    throw ParseError(file, 1, tokens[1].column,
                     fmt::format("unsupported format version '{}' (this reader reads version 1)",
                                 printable(tokens[1].text)));
  expect_end(tokens, 2, l, file, "pathref-grid 1");
}

/// The value of a `name` line: the rest of the line after the keyword and its separating blanks,
/// trailing blanks removed. Control characters are errors.
std::string parse_name(const Line& l, const Token& keyword, const std::string& file) {
  std::size_t b = keyword.column - 1 + keyword.text.size();
  while (b < l.text.size() && is_blank_char(l.text[b])) ++b;
  std::size_t e = l.text.size();
  while (e > b && is_blank_char(l.text[e - 1])) --e;
  if (b == e) throw ParseError(file, l.number, l.text.size() + 1, "expected a name after 'name'");
  for (std::size_t i = b; i < e; ++i) {
    const auto u = static_cast<unsigned char>(l.text[i]);
    if (u < 0x20 || u == 0x7f)
      throw ParseError(file, l.number, i + 1,
                       fmt::format("expected a name without control characters, got {}",
                                   describe_byte(l.text[i])));
  }
  return std::string(l.text.substr(b, e - b));
}

/// Everything the header said, with where it said it.
struct Header {
  std::optional<Located> width;
  std::optional<Located> height;
  std::size_t size_line = 0;
  std::optional<LocatedCell> start;
  std::size_t start_line = 0;
  std::optional<LocatedCell> goal;
  std::size_t goal_line = 0;
  std::optional<std::string> name;
  std::size_t name_line = 0;
  std::size_t map_line = 0;  ///< index into lines of the `map` line
};

/// Throws when a once-only keyword (written at `column`) appears again.
void once(std::size_t first_line, const Line& l, std::size_t column, const std::string& file,
          const char* keyword) {
  if (first_line != 0)
    throw ParseError(file, l.number, column,
                     fmt::format("duplicate '{}' line (first given on line {})", keyword, first_line));
}

/// Header lines after the magic line, up to and including `map`.
Header parse_header(const std::vector<Line>& lines, const std::string& file) {
  Header h;
  constexpr std::int64_t max = grid::Grid::max_cells;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const Line& l = lines[i];
    const auto tokens = tokenize(l.text);
    if (tokens.empty() || tokens[0].text.front() == '#') continue;  // blank or comment
    const std::string_view kw = tokens[0].text;
    if (kw == "size") {
      once(h.size_line, l, tokens[0].column, file, "size");
      h.width = parse_number(tokens, 1, l, file, "width", 1, max);
      h.height = parse_number(tokens, 2, l, file, "height", 1, max);
      expect_end(tokens, 3, l, file, "size W H");
      h.size_line = l.number;
    } else if (kw == "start" || kw == "goal") {
      const bool is_start = kw == "start";
      once(is_start ? h.start_line : h.goal_line, l, tokens[0].column, file, is_start ? "start" : "goal");
      LocatedCell c{parse_number(tokens, 1, l, file, is_start ? "start x" : "goal x", 0, max - 1),
                    parse_number(tokens, 2, l, file, is_start ? "start y" : "goal y", 0, max - 1)};
      expect_end(tokens, 3, l, file, is_start ? "start X Y" : "goal X Y");
      (is_start ? h.start : h.goal) = c;
      (is_start ? h.start_line : h.goal_line) = l.number;
    } else if (kw == "name") {
      once(h.name_line, l, tokens[0].column, file, "name");
      h.name = parse_name(l, tokens[0], file);
      h.name_line = l.number;
    } else if (kw == "map") {
      expect_end(tokens, 1, l, file, "map");
      if (!h.width)
        throw ParseError(file, l.number, tokens[0].column, "expected a 'size W H' line before 'map'");
      h.map_line = i;
      return h;
    } else {
      throw ParseError(file, l.number, tokens[0].column,
                       fmt::format("unknown keyword '{}' (expected size, start, goal, name, map "
                                   "or a # comment)",
                                   printable(kw)));
    }
  }
  const std::size_t eof_line = lines.empty() ? 1 : lines.back().number + 1;
  throw ParseError(file, eof_line, 1, "unexpected end of file: expected the 'map' line");
}

/// Checks that a start/goal cell lies inside the W x H grid.
void check_in_bounds(const LocatedCell& c, std::int64_t w, std::int64_t h, const std::string& file,
                     const char* which) {
  if (c.x.value >= w || c.y.value >= h)
    throw ParseError(file, c.x.line, c.x.column,
                     fmt::format("{} ({}, {}) is outside the {}x{} grid (x must be < {}, y < {})",
                                 which, c.x.value, c.y.value, w, h, w, h));
}

/// Checks row r (0 = top) of the map: exactly w cells of '.' or '#'.
void check_row(const Line& l, std::int64_t r, std::int64_t w, const std::string& file) {
  const auto width = static_cast<std::size_t>(w);
  const std::size_t n = std::min(l.text.size(), width);
  for (std::size_t i = 0; i < n; ++i)
    if (l.text[i] != '.' && l.text[i] != '#')
      throw ParseError(file, l.number, i + 1,
                       fmt::format("expected '.' (free) or '#' (blocked), got {}",
                                   describe_byte(l.text[i])));
  if (l.text.size() < width)
    throw ParseError(file, l.number, l.text.size() + 1,
                     fmt::format("expected {} cells in map row {}, got {}", w, r + 1, l.text.size()));
  if (l.text.size() > width)
    throw ParseError(file, l.number, width + 1,
                     fmt::format("expected end of map row {} after {} cells", r + 1, w));
}

}  // namespace

MapFile parse_grid_text(std::string_view text, std::string_view filename) {
  const std::string file(filename);
  const std::vector<Line> lines = split_lines(text, file);
  parse_magic(lines, file);
  const Header h = parse_header(lines, file);
  const std::int64_t w = h.width->value;
  const std::int64_t ht = h.height->value;
  if (w > grid::Grid::max_cells / ht)
    throw ParseError(file, h.width->line, h.width->column,
                     fmt::format("a {}x{} grid exceeds the limit of {} cells", w, ht,
                                 grid::Grid::max_cells));
  if (h.start) check_in_bounds(*h.start, w, ht, file, "start");
  if (h.goal) check_in_bounds(*h.goal, w, ht, file, "goal");

  // The rows: exactly H lines right after `map`, checked before the grid is allocated.
  const std::size_t first = h.map_line + 1;
  for (std::int64_t r = 0; r < ht; ++r) {
    const std::size_t i = first + static_cast<std::size_t>(r);
    if (i >= lines.size())
      throw ParseError(file, lines.back().number + 1, 1,
                       fmt::format("unexpected end of file: expected map row {} of {}", r + 1, ht));
    check_row(lines[i], r, w, file);
  }
  for (std::size_t i = first + static_cast<std::size_t>(ht); i < lines.size(); ++i)
    if (!is_blank(lines[i].text))
      throw ParseError(file, lines[i].number, 1,
                       fmt::format("expected end of file after the {} map rows", ht));

  MapFile m{grid::Grid(w, ht), std::nullopt, std::nullopt, h.name.value_or("")};
  for (std::int64_t r = 0; r < ht; ++r) {
    const std::string_view row = lines[first + static_cast<std::size_t>(r)].text;
    for (std::int64_t x = 0; x < w; ++x)
      if (row[static_cast<std::size_t>(x)] == '#') m.grid.set_blocked(grid::Cell{x, ht - 1 - r}, true);
  }
  const auto endpoint = [&](const std::optional<LocatedCell>& c, const char* which) -> std::optional<grid::Cell> {
    if (!c) return std::nullopt;
    const grid::Cell cell{c->x.value, c->y.value};
    if (!m.grid.free(cell))
      throw ParseError(file, c->x.line, c->x.column,
                       fmt::format("{} ({}, {}) is a blocked cell", which, cell.x, cell.y));
    return cell;
  };
  m.start = endpoint(h.start, "start");
  m.goal = endpoint(h.goal, "goal");
  if (m.start && m.goal && *m.start == *m.goal)
    throw ParseError(file, h.goal->x.line, h.goal->x.column,
                     fmt::format("goal ({}, {}) is the start cell (given on line {}): start and goal must differ",
                                 m.goal->x, m.goal->y, h.start_line));
  return m;
}

std::string to_grid_text(const MapFile& map) {
  const grid::Grid& g = map.grid;
  for (const char c : map.name) {
    const auto u = static_cast<unsigned char>(c);
    require(u >= 0x20 && u != 0x7f, "to_grid_text: the map name contains a control character");
  }
  require(map.name.empty() || (!is_blank_char(map.name.front()) && !is_blank_char(map.name.back())),
          "to_grid_text: the map name starts or ends with a space or tab");
  require(!map.start || g.free(*map.start), "to_grid_text: start is not a free cell of the grid");
  require(!map.goal || g.free(*map.goal), "to_grid_text: goal is not a free cell of the grid");
  require(!map.start || !map.goal || !(*map.start == *map.goal), "to_grid_text: start and goal are the same cell");
  std::string out = "pathref-grid 1\n";
  if (!map.name.empty()) out += "name " + map.name + "\n";
  out += fmt::format("size {} {}\n", g.width(), g.height());
  if (map.start) out += fmt::format("start {} {}\n", map.start->x, map.start->y);
  if (map.goal) out += fmt::format("goal {} {}\n", map.goal->x, map.goal->y);
  out += "map\n";
  out.reserve(out.size() + static_cast<std::size_t>(g.cell_count() + g.height()));
  // The rows of Grid::to_rows_top_first, written straight into the text (no second copy of the
  // map as a vector of rows: spec/formats.md#limits, 1 byte per cell for the text).
  for (std::int64_t y = g.height() - 1; y >= 0; --y) {
    for (std::int64_t x = 0; x < g.width(); ++x) out.push_back(g.blocked(grid::Cell{x, y}) ? '#' : '.');
    out.push_back('\n');
  }
  return out;
}

MapFile read_grid_file(const std::string& path) {
  const std::string text = read_input_file(path, "map file", max_map_file_bytes);
  return parse_grid_text(text, path);
}

}  // namespace pathref::io
