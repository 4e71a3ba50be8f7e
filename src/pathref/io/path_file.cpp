#include "pathref/io/path_file.hpp"

#include <fmt/core.h>

#include <charconv>
#include <cmath>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/plan_json.hpp"

namespace pathref::io {

using Json = nlohmann::json;

PathFormat parse_path_format(std::string_view name) {
  if (name == "auto") return PathFormat::automatic;
  if (name == "plan") return PathFormat::plan;
  if (name == "xy") return PathFormat::xy;
  if (name == "node") return PathFormat::node;
  if (name == "rowcol") return PathFormat::rowcol;
  throw UsageError(fmt::format("unknown path format '{}' (known: auto, plan, xy, node, rowcol)", name));
}

std::string_view to_string(PathFormat format) noexcept {
  switch (format) {
    case PathFormat::automatic: return "auto";
    case PathFormat::plan: return "plan";
    case PathFormat::xy: return "xy";
    case PathFormat::node: return "node";
    case PathFormat::rowcol: return "rowcol";
  }
  return "?";
}

RowOrigin parse_row_origin(std::string_view name) {
  if (name == "lower") return RowOrigin::lower;
  if (name == "upper") return RowOrigin::upper;
  throw UsageError(fmt::format("unknown row origin '{}' (known: lower, upper)", name));
}

std::string_view to_string(RowOrigin origin) noexcept { return origin == RowOrigin::lower ? "lower" : "upper"; }

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// A number token whose value is an integer of magnitude <= max_path_number: `[+-]digits[.digits]
/// [(e|E)[+-]digits]` ("3", "-2", "3.0", "3.0000000e+00" as MATLAB's save -ascii writes it).
/// nullopt-like: returns false when the token is not such a number.
bool integral_value(std::string_view t, std::int64_t& out) {
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  const std::size_t digits_at = i;
  while (i < t.size() && is_digit(t[i])) ++i;
  if (i == digits_at || i - digits_at > 40) return false;
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && is_digit(t[i])) ++i;
  }
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    const std::size_t e_at = i;
    while (i < t.size() && is_digit(t[i])) ++i;
    if (i == e_at || i - e_at > 4) return false;
  }
  if (i != t.size()) return false;
  const std::string_view body = t[0] == '+' ? t.substr(1) : t;
  double v = 0.0;
  const auto r = std::from_chars(body.data(), body.data() + body.size(), v);
  if (r.ec != std::errc() || r.ptr != body.data() + body.size()) return false;
  if (!(std::fabs(v) <= static_cast<double>(max_path_number)) || v != std::floor(v)) return false;
  out = static_cast<std::int64_t>(v);
  return true;
}

/// A JSON value that is a number with an integral value of magnitude <= max_path_number.
bool integral_value(const Json& v, std::int64_t& out) {
  if (!v.is_number()) return false;
  const double d = v.get<double>();
  if (!(std::fabs(d) <= static_cast<double>(max_path_number)) || d != std::floor(d)) return false;
  out = static_cast<std::int64_t>(d);
  return true;
}

void push_number(PathRecord& rec, std::int64_t v, const std::string& file, std::size_t line, std::size_t col) {
  const std::size_t per_node = rec.format == PathFormat::node ? 1 : 2;
  if (rec.numbers.size() / per_node >= max_path_nodes && rec.numbers.size() % per_node == 0)
    throw ParseError(file, line, col, fmt::format("a path has more than {} nodes", max_path_nodes));
  rec.numbers.push_back(v);
}

struct Token {
  std::string_view text;
  std::size_t column;
};
struct Row {
  std::vector<Token> tokens;
  std::size_t line;
};

/// Text rows: a line, or a ';'-separated part of one (MATLAB mat2str); '#' and '%' start a
/// comment; blanks, tabs, commas, '[' and ']' separate numbers.
std::vector<Row> text_rows(std::string_view text, const std::string& file) {
  std::vector<Row> rows;
  Row cur{{}, 1};
  std::size_t line = 1, col = 1, count = 0;
  bool comment = false;
  auto end_row = [&](std::size_t next_line) {
    if (!cur.tokens.empty()) rows.push_back(std::move(cur));
    cur = Row{{}, next_line};
  };
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      end_row(line + 1);
      ++line;
      col = 1;
      comment = false;
      ++i;
      continue;
    }
    if (comment) {
      ++i;
      ++col;
      continue;
    }
    if (c == '#' || c == '%') {
      comment = true;
    } else if (c == ';') {
      end_row(line);
    } else if (c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '[' || c == ']') {
      // separator
    } else {
      std::size_t j = i;
      while (j < text.size() && text[j] != '\n' && text[j] != ' ' && text[j] != '\t' && text[j] != ',' &&
             text[j] != '\r' && text[j] != ';' && text[j] != '[' && text[j] != ']' && text[j] != '#' &&
             text[j] != '%')
        ++j;
      if (++count > 2 * max_path_nodes)
        throw ParseError(file, line, col, fmt::format("a path has more than {} nodes", max_path_nodes));
      cur.line = line;
      cur.tokens.push_back(Token{text.substr(i, j - i), col});
      col += j - i;
      i = j;
      continue;
    }
    ++i;
    ++col;
  }
  end_row(line);
  return rows;
}


PathRecord read_text(std::string_view text, const std::string& file, PathFormat format) {
  const std::vector<Row> rows = text_rows(text, file);
  if (rows.empty()) throw ParseError(file, 1, 1, "no path: the file has no number (expected x y lines or node numbers)");
  if (format == PathFormat::automatic) {
    bool all2 = true, all1 = true;
    for (const Row& r : rows) {
      all2 = all2 && r.tokens.size() == 2;
      all1 = all1 && r.tokens.size() == 1;
    }
    if (all2) {
      format = PathFormat::xy;
    } else if (all1 || rows.size() == 1) {
      format = PathFormat::node;
    } else {
      const std::size_t want = rows[0].tokens.size();
      for (const Row& r : rows)
        if (r.tokens.size() != want)
          throw ParseError(file, r.line, r.tokens[0].column,
                           fmt::format("expected {} number(s) on this line like line {} (two per line: x y; "
                                       "one per line: node numbers), got {}",
                                       want, rows[0].line, r.tokens.size()));
      throw ParseError(file, rows[0].line, rows[0].tokens[0].column,
                       fmt::format("{} numbers per line: expected two (x y) or one (a node number); give "
                                   "--path-format for a row vector of node numbers",
                                   want));
    }
  }
  if (format == PathFormat::plan)
    throw ParseError(file, rows[0].line, rows[0].tokens[0].column, "expected a pathref-plan JSON object");
  PathRecord rec{file, format, {}, nullptr};
  for (const Row& r : rows) {
    if (format != PathFormat::node && r.tokens.size() != 2)
      throw ParseError(file, r.line, r.tokens[0].column,
                       fmt::format("expected two numbers ({}) on this line, got {}",
                                   format == PathFormat::xy ? "x y" : "row col", r.tokens.size()));
    for (const Token& t : r.tokens) {
      std::int64_t v = 0;
      if (!integral_value(t.text, v))
        throw ParseError(file, r.line, t.column,
                         fmt::format("expected an integer of magnitude at most {} (a cell coordinate or node "
                                     "number), got '{}'",
                                     max_path_number, printable(t.text, 24)));
      push_number(rec, v, file, r.line, t.column);
    }
  }
  return rec;
}

/// One JSON value (a whole file, or a line of a JSON-lines file) as a path. `text` is its JSON
/// text, beginning on line `line` of `file`: every refusal is `FILE:LINE:COLUMN: /pointer: what`.
PathRecord read_json_value(const Json& doc, const std::string& name, const std::string& file, std::size_t line,
                           PathFormat format, std::string_view text) {
  const auto fail = [&](const std::string& ptr, const std::string& what) {
    throw json_error_at(text, file, ptr, what, line);
  };
  if (doc.is_object()) {
    if (format != PathFormat::automatic && format != PathFormat::plan)
      fail("", fmt::format("a JSON object is a pathref-plan record, not '{}' numbers", to_string(format)));
    if (doc.value("format", Json()) != "pathref-plan")
      fail("", "a JSON object must be a pathref-plan record (\"format\": \"pathref-plan\"); "
               "other paths are a JSON array of [x, y] or of node numbers");
    const auto it = doc.find("path");
    if (it == doc.end() || !it->is_array()) fail(it == doc.end() ? "" : "/path", "the pathref-plan record has no 'path' array");
    PathRecord rec{name, PathFormat::plan, {}, doc};
    for (std::size_t i = 0; i < it->size(); ++i) {
      const Json& c = (*it)[i];
      std::int64_t x = 0, y = 0;
      if (!c.is_array() || c.size() != 2 || !integral_value(c[0], x) || !integral_value(c[1], y))
        fail("/path/" + std::to_string(i), "expected [x, y] (two integers)");
      push_number(rec, x, file, line, 1);
      push_number(rec, y, file, line, 1);
    }
    // The whole record is checked here, where its text is at hand (its map rows against
    // map.width/height, its endpoints and policy), so a contradiction is reported at its place.
    (void)plan_from_json(doc, file, text, line);
    return rec;
  }
  if (!doc.is_array()) fail("", "expected a JSON array of [x, y] cells or of node numbers, or a pathref-plan object");
  if (doc.empty()) fail("", "no path: the JSON array is empty");
  if (format == PathFormat::plan) fail("", "expected a pathref-plan JSON object, got an array");
  if (format == PathFormat::automatic) format = doc[0].is_array() ? PathFormat::xy : PathFormat::node;
  PathRecord rec{name, format, {}, nullptr};
  for (std::size_t i = 0; i < doc.size(); ++i) {
    const Json& c = doc[i];
    if (format == PathFormat::node) {
      std::int64_t n = 0;
      if (!integral_value(c, n))
        fail("/" + std::to_string(i), fmt::format("expected a node number (an integer of magnitude at most {})", max_path_number));
      push_number(rec, n, file, line, 1);
      continue;
    }
    std::int64_t a = 0, b = 0;
    if (!c.is_array() || c.size() != 2 || !integral_value(c[0], a) || !integral_value(c[1], b))
      fail("/" + std::to_string(i), fmt::format("expected {} (two integers of magnitude at most {})",
                                                format == PathFormat::xy ? "[x, y]" : "[row, col]", max_path_number));
    push_number(rec, a, file, line, 1);
    push_number(rec, b, file, line, 1);
  }
  return rec;
}

}  // namespace

std::vector<PathRecord> parse_path_text(std::string_view text, std::string_view file_view, PathFormat format,
                                        bool json_lines) {
  const std::string file(file_view);
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 BOM
  std::vector<PathRecord> out;
  if (json_lines) {
    std::size_t line = 1;
    for (std::size_t at = 0; at <= text.size();) {
      std::size_t nl = text.find('\n', at);
      if (nl == std::string_view::npos) nl = text.size();
      const std::string_view l = text.substr(at, nl - at);
      if (l.find_first_not_of(" \t\r") != std::string_view::npos) {
        const Json doc = parse_json_text(l, file, line);
        out.push_back(read_json_value(doc, file + ":" + std::to_string(line), file, line, format, l));
      }
      at = nl + 1;
      ++line;
    }
    if (out.empty()) throw ParseError(file, 1, 1, "no path: the JSON-lines file has no non-blank line");
    return out;
  }
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  const char c0 = first == std::string_view::npos ? '\0' : text[first];
  if (c0 == '{' || (c0 == '[' && text.find(';') == std::string_view::npos))
    out.push_back(read_json_value(parse_json_text(text, file), file, file, 1, format, text));
  else
    out.push_back(read_text(text, file, format));
  return out;
}

std::vector<grid::Cell> path_cells(const PathRecord& record, std::int64_t width, std::int64_t height,
                                   std::int64_t base, RowOrigin origin) {
  require(width >= 1 && height >= 1, "path_cells: the map must have width and height >= 1");
  const auto row_to_y = [&](std::int64_t row) { return origin == RowOrigin::lower ? row : height - 1 - row; };
  std::vector<grid::Cell> cells;
  const auto& v = record.numbers;
  switch (record.format) {
    case PathFormat::plan:
      for (std::size_t i = 0; i + 1 < v.size(); i += 2) cells.push_back({v[i], v[i + 1]});
      break;
    case PathFormat::xy:
      for (std::size_t i = 0; i + 1 < v.size(); i += 2) cells.push_back({v[i] - base, row_to_y(v[i + 1] - base)});
      break;
    case PathFormat::rowcol:
      for (std::size_t i = 0; i + 1 < v.size(); i += 2) cells.push_back({v[i + 1] - base, row_to_y(v[i] - base)});
      break;
    case PathFormat::node:
      for (const std::int64_t n : v) {
        const std::int64_t k = n - base;
        std::int64_t row = k / width;
        if (k % width != 0 && k < 0) --row;  // floor division
        cells.push_back({k - row * width, row_to_y(row)});
      }
      break;
    case PathFormat::automatic: throw DomainError("path_cells: the record's format is not resolved");
  }
  return cells;
}

}  // namespace pathref::io
