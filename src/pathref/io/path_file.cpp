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

/// Whether c ends a number token (a separator, a row or line end, a comment start).
bool token_end(char c) {
  return c == '\n' || c == ' ' || c == '\t' || c == ',' || c == '\r' || c == ';' || c == '[' || c == ']' ||
         c == '#' || c == '%';
}

/// One text row: a line, or a ';'-separated part of one (MATLAB mat2str); '#' and '%' start a
/// comment; blanks, tabs, commas, '[' and ']' separate numbers. A row is kept as its byte range
/// and counts, not as a list of tokens (spec/formats.md#limits: the text reader holds the text
/// and 8 bytes per number, nothing per token), and its tokens are scanned again when read.
struct RowSpan {
  std::size_t begin = 0;   ///< offset of the row's first byte
  std::size_t end = 0;     ///< offset just past the row (its ';' or '\n' not included)
  std::size_t line = 1;    ///< 1-based line
  std::size_t column = 1;  ///< 1-based column of the byte at `begin`
  std::size_t count = 0;   ///< tokens in the row
  std::size_t first_column = 1;  ///< column of its first token
};

/// Calls fn(token text, column) for every token of `row`, in order.
template <class Fn>
void for_each_token(std::string_view text, const RowSpan& row, Fn&& fn) {
  std::size_t col = row.column;
  for (std::size_t i = row.begin; i < row.end;) {
    const char c = text[i];
    if (c == '#' || c == '%') return;  // the rest of the line is a comment
    if (c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '[' || c == ']') {
      ++i;
      ++col;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && !token_end(text[j])) ++j;
    fn(text.substr(i, j - i), col);
    col += j - i;
    i = j;
  }
}

/// The rows of `text` one at a time (empty rows skipped), with the token counts of the old
/// token-list reader: more than 2 x max_path_nodes numbers in the whole text is a ParseError at
/// the first number too many, raised while scanning (before anything is stored).
class RowScanner {
 public:
  RowScanner(std::string_view text, const std::string& file) : text_(text), file_(file) {}
  /// The next non-empty row into `out`; false at the end of the text.
  bool next(RowSpan& out) {
    while (i_ <= text_.size()) {
      RowSpan row;
      row.begin = i_;
      row.line = line_;
      row.column = col_;
      bool comment = false;
      bool newline = false;
      while (i_ < text_.size()) {
        const char c = text_[i_];
        if (c == '\n') {
          newline = true;
          break;
        }
        if (comment) {
          ++i_;
          ++col_;
          continue;
        }
        if (c == '#' || c == '%') {
          comment = true;
        } else if (c == ';') {
          break;
        } else if (!(c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '[' || c == ']')) {
          std::size_t j = i_;
          while (j < text_.size() && !token_end(text_[j])) ++j;
          if (++count_ > 2 * max_path_nodes)
            throw ParseError(file_, line_, col_, fmt::format("a path has more than {} nodes", max_path_nodes));
          if (row.count++ == 0) row.first_column = col_;
          col_ += j - i_;
          i_ = j;
          continue;
        }
        ++i_;
        ++col_;
      }
      row.end = i_;
      if (i_ >= text_.size()) {
        i_ = text_.size() + 1;  // done after this row
      } else {
        ++i_;  // past the ';' or '\n'
        if (newline) {
          ++line_;
          col_ = 1;
        } else {
          ++col_;
        }
      }
      if (row.count > 0) {
        out = row;
        return true;
      }
    }
    return false;
  }
  /// Numbers seen so far.
  [[nodiscard]] std::size_t numbers() const noexcept { return count_; }

 private:
  std::string_view text_;
  const std::string& file_;
  std::size_t i_ = 0;
  std::size_t line_ = 1;
  std::size_t col_ = 1;
  std::size_t count_ = 0;
};


PathRecord read_text(std::string_view text, const std::string& file, PathFormat format) {
  // Pass 1: row counts only (no token stored), for the format detection and its messages.
  RowSpan first, mismatch, row;
  std::size_t rows = 0;
  bool all2 = true, all1 = true, mismatched = false;
  {
    RowScanner scan(text, file);
    while (scan.next(row)) {
      if (rows++ == 0) first = row;
      all2 = all2 && row.count == 2;
      all1 = all1 && row.count == 1;
      if (!mismatched && row.count != first.count) {
        mismatched = true;
        mismatch = row;
      }
    }
  }
  if (rows == 0) throw ParseError(file, 1, 1, "no path: the file has no number (expected x y lines or node numbers)");
  if (format == PathFormat::automatic) {
    if (all2) {
      format = PathFormat::xy;
    } else if (all1 || rows == 1) {
      format = PathFormat::node;
    } else {
      if (mismatched)
        throw ParseError(file, mismatch.line, mismatch.first_column,
                         fmt::format("expected {} number(s) on this line like line {} (two per line: x y; "
                                     "one per line: node numbers), got {}",
                                     first.count, first.line, mismatch.count));
      throw ParseError(file, first.line, first.first_column,
                       fmt::format("{} numbers per line: expected two (x y) or one (a node number); give "
                                   "--path-format for a row vector of node numbers",
                                   first.count));
    }
  }
  if (format == PathFormat::plan)
    throw ParseError(file, first.line, first.first_column, "expected a pathref-plan JSON object");
  // Pass 2: the numbers, in file order, with the errors of the one-pass reader in the same order.
  // A text with more numbers than max_path_nodes nodes of this format is read without storing
  // (its limit error comes at the same number as before): the numbers are stored only when they
  // fit (spec/formats.md#limits: 8 bytes per number, at most 2 x 2^24 numbers).
  const std::size_t per_node = format == PathFormat::node ? 1 : 2;
  PathRecord rec{file, format, {}, nullptr};
  std::size_t total = 0;
  {
    RowScanner scan(text, file);
    while (scan.next(row)) total += row.count;
  }
  const bool store = total <= max_path_nodes * per_node;
  if (store) rec.numbers.reserve(total);
  std::size_t seen = 0;
  RowScanner scan(text, file);
  while (scan.next(row)) {
    if (format != PathFormat::node && row.count != 2)
      throw ParseError(file, row.line, row.first_column,
                       fmt::format("expected two numbers ({}) on this line, got {}",
                                   format == PathFormat::xy ? "x y" : "row col", row.count));
    for_each_token(text, row, [&](std::string_view t, std::size_t column) {
      std::int64_t v = 0;
      if (!integral_value(t, v))
        throw ParseError(file, row.line, column,
                         fmt::format("expected an integer of magnitude at most {} (a cell coordinate or node "
                                     "number), got '{}'",
                                     max_path_number, printable(t, 24)));
      if (seen / per_node >= max_path_nodes && seen % per_node == 0)
        throw ParseError(file, row.line, column, fmt::format("a path has more than {} nodes", max_path_nodes));
      ++seen;
      if (store) rec.numbers.push_back(v);
    });
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
