#include "pathref/io/matrix.hpp"

#include <fmt/core.h>

#include <cstdint>
#include <vector>

#include "pathref/core/error.hpp"

namespace pathref::io {

namespace {

using text::Line;

constexpr const char* what_matrix = "a matrix of 0s and 1s (plain rows or NAME = [...])";

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_name_char(char c) { return is_letter(c) || (c >= '0' && c <= '9') || c == '_'; }

/// The part of a line before its `%` comment (the whole line when it has none).
std::string_view code_part(std::string_view line) {
  const auto p = line.find('%');
  return p == std::string_view::npos ? line : line.substr(0, p);
}

/// Index of the first byte that is not a blank at or after `i` (line.size() when none).
std::size_t skip_blanks(std::string_view line, std::size_t i) {
  while (i < line.size() && text::is_blank_char(line[i])) ++i;
  return i;
}

/// Throws for a line holding only `%{` (a MATLAB block comment opener), which this reader does not
/// support (spec/formats.md#matrix).
void reject_block_comment(const Line& l, const std::string& file) {
  const std::size_t b = skip_blanks(l.text, 0);
  std::size_t e = l.text.size();
  while (e > b && text::is_blank_char(l.text[e - 1])) --e;
  if (l.text.substr(b, e - b) == "%{")
    throw ParseError(file, l.number, b + 1,
                     "block comments (%{ ... %}) are not supported; start each comment line with %");
}

/// The rows read so far (top first, '.' free, '#' blocked) and the checks on their shape.
class RowCollector {
 public:
  RowCollector(const std::string& file, const ReadLimits& limits) : file_(file), limits_(limits) {}

  /// Adds one value (0 or 1) of the current row, written at (line, column).
  void add(char value, std::size_t line, std::size_t column) {
    const auto n = static_cast<std::int64_t>(row_.size());
    if (rows_.empty() && n == limits_.max_side)
      throw ParseError(file_, line, column,
                       fmt::format("row 1 has more than {} values (the limit on the width)", limits_.max_side));
    if (rows_.empty() && n == limits_.max_cells)
      throw ParseError(file_, line, column,
                       fmt::format("a matrix of {} columns and 1 rows exceeds the limit of {} cells", n + 1,
                                   limits_.max_cells));
    if (!rows_.empty() && n == width_)
      throw ParseError(file_, line, column,
                       fmt::format("expected end of row {} after {} values (as many as row 1)",
                                   rows_.size() + 1, width_));
    if (row_.empty()) {
      const auto r = static_cast<std::int64_t>(rows_.size());
      if (r == limits_.max_side)
        throw ParseError(file_, line, column,
                         fmt::format("more than {} rows (the limit on the height)", limits_.max_side));
      if (!rows_.empty() && width_ > limits_.max_cells / (r + 1))
        throw ParseError(file_, line, column,
                         fmt::format("a matrix of {} columns and {} rows exceeds the limit of {} cells",
                                     width_, r + 1, limits_.max_cells));
    }
    row_ += value == '1' ? '#' : '.';
  }

  /// Ends the current row (nothing when it is empty); (line, column) is where it ended.
  void end_row(std::size_t line, std::size_t column) {
    if (row_.empty()) return;
    if (rows_.empty()) {
      width_ = static_cast<std::int64_t>(row_.size());
    } else if (static_cast<std::int64_t>(row_.size()) < width_) {
      throw ParseError(file_, line, column,
                       fmt::format("expected {} values in row {} (as many as row 1), got {}", width_,
                                   rows_.size() + 1, row_.size()));
    }
    rows_.push_back(std::move(row_));
    row_.clear();
  }

  [[nodiscard]] bool empty() const noexcept { return rows_.empty(); }
  [[nodiscard]] std::size_t rows() const noexcept { return rows_.size(); }

  /// The grid (allocated only here, after all checks).
  [[nodiscard]] grid::Grid grid() const { return grid::Grid::from_rows_top_first(rows_); }

 private:
  const std::string& file_;
  const ReadLimits& limits_;
  std::vector<std::string> rows_;
  std::string row_;
  std::int64_t width_ = 0;
};

/// Checks one value token (already cut at blanks, commas, ...): it must be "0" or "1".
void check_value(std::string_view token, const Line& l, std::size_t column, const std::string& file) {
  if (token == "0" || token == "1") return;
  for (std::size_t i = 0; i < token.size(); ++i) {
    const auto u = static_cast<unsigned char>(token[i]);
    if (u < 0x20 || u >= 0x7f)
      throw ParseError(file, l.number, column + i,
                       fmt::format("expected 0 (free) or 1 (obstacle), got {}", text::describe_byte(token[i])));
  }
  const std::string shown = token.size() <= 32 ? std::string(token) : std::string(token.substr(0, 32)) + "...";
  throw ParseError(file, l.number, column, fmt::format("expected 0 (free) or 1 (obstacle), got '{}'", shown));
}

/// The plain form: one row per line starting at line index `first`.
grid::Grid parse_plain(const std::vector<Line>& lines, std::size_t first, const std::string& file,
                       const ReadLimits& limits) {
  RowCollector rows(file, limits);
  std::size_t gap_line = 0;  // a blank line after the rows started
  for (std::size_t li = first; li < lines.size(); ++li) {
    const Line& l = lines[li];
    reject_block_comment(l, file);
    const std::string_view code = code_part(l.text);
    std::size_t i = skip_blanks(code, 0);
    if (i == code.size()) {
      if (!rows.empty() && gap_line == 0) gap_line = l.number;
      continue;
    }
    if (gap_line != 0)
      throw ParseError(file, l.number, i + 1,
                       fmt::format("expected end of file after the {} matrix rows (a blank line ended "
                                   "the matrix on line {})",
                                   rows.rows(), gap_line));
    bool need_value = true;  // at the start, and after a comma
    std::size_t comma_column = 0;
    while (i < code.size()) {
      if (code[i] == ',') {
        if (need_value)
          throw ParseError(file, l.number, i + 1, "expected 0 (free) or 1 (obstacle), got ','");
        need_value = true;
        comma_column = i + 1;
        i = skip_blanks(code, i + 1);
        continue;
      }
      const std::size_t b = i;
      while (i < code.size() && !text::is_blank_char(code[i]) && code[i] != ',') ++i;
      check_value(code.substr(b, i - b), l, b + 1, file);
      rows.add(code[b], l.number, b + 1);
      need_value = false;
      comma_column = 0;
      i = skip_blanks(code, i);
    }
    if (comma_column != 0)
      throw ParseError(file, l.number, comma_column, "expected a value after ','");
    rows.end_row(l.number, code.size() + 1);
  }
  return rows.grid();
}

/// The MATLAB form starting at line index `li`, column index `i` (the name or the '[').
grid::Grid parse_matlab(const std::vector<Line>& lines, std::size_t li, std::size_t i,
                        const std::string& file, const ReadLimits& limits) {
  const Line& head = lines[li];
  std::string_view code = code_part(head.text);
  std::string lhs;
  if (is_letter(code[i])) {
    const std::size_t b = i;
    while (i < code.size() && is_name_char(code[i])) ++i;
    lhs = std::string(code.substr(b, i - b));
    i = skip_blanks(code, i);
    if (i == code.size() || code[i] != '=')
      throw ParseError(file, head.number, i + 1, fmt::format("expected '=' after '{}'", lhs));
    i = skip_blanks(code, i + 1);
    if (i == code.size() || code[i] != '[')
      throw ParseError(file, head.number, i + 1, fmt::format("expected '[' after '{} ='", lhs));
  }
  const std::size_t open_line = head.number;
  ++i;  // past '['
  RowCollector rows(file, limits);
  std::size_t comma_column = 0;  // a ',' waiting for its value
  bool need_value = true;        // no value yet in this row, or a ',' just read
  const auto no_pending_comma = [&](const Line& l) {
    if (comma_column != 0) throw ParseError(file, l.number, comma_column, "expected a value after ','");
  };
  for (;;) {
    const Line& l = lines[li];
    code = code_part(l.text);
    bool continued = false;
    while (i < code.size()) {
      const char c = code[i];
      if (text::is_blank_char(c)) {
        ++i;
      } else if (c == ',') {
        if (need_value)
          throw ParseError(file, l.number, i + 1, "expected 0 (free) or 1 (obstacle), got ','");
        need_value = true;
        comma_column = ++i;
      } else if (c == ';') {
        no_pending_comma(l);
        rows.end_row(l.number, i + 1);
        need_value = true;
        ++i;
      } else if (c == ']') {
        no_pending_comma(l);
        rows.end_row(l.number, i + 1);
        if (rows.empty()) throw ParseError(file, l.number, i + 1, "expected at least one row of 0s and 1s before ']'");
        // After ']': an optional ';', then only blanks and a comment.
        i = skip_blanks(code, i + 1);
        if (i < code.size() && code[i] == ';') i = skip_blanks(code, i + 1);
        if (i < code.size())
          throw ParseError(file, l.number, i + 1, "expected ';', a % comment or end of line after ']'");
        for (std::size_t k = li + 1; k < lines.size(); ++k) {
          reject_block_comment(lines[k], file);
          const std::string_view rest = code_part(lines[k].text);
          const std::size_t j = skip_blanks(rest, 0);
          if (j < rest.size())
            throw ParseError(file, lines[k].number, j + 1,
                             "expected end of file after the matrix (one assignment per file)");
        }
        return rows.grid();
      } else if (code.substr(i, 3) == "...") {
        continued = true;  // the rest of the line is ignored and the line end is no row end
        break;
      } else {
        const std::size_t b = i;
        while (i < code.size() && !text::is_blank_char(code[i]) && code[i] != ',' && code[i] != ';' &&
               code[i] != ']' && code.substr(i, 3) != "...")
          ++i;
        check_value(code.substr(b, i - b), l, b + 1, file);
        rows.add(code[b], l.number, b + 1);
        need_value = false;
        comma_column = 0;
      }
    }
    if (!continued) {
      no_pending_comma(l);
      rows.end_row(l.number, code.size() + 1);
      need_value = true;
    }
    ++li;
    i = 0;
    if (li == lines.size())
      throw ParseError(file, text::eof_line(lines), 1,
                       fmt::format("unexpected end of file: expected ']' to close the '[' of line {}", open_line));
    reject_block_comment(lines[li], file);
  }
}

}  // namespace

MapFile parse_matrix(std::string_view text_in, std::string_view filename, const ReadLimits& limits) {
  check_limits(limits);
  const std::string file(filename);
  const std::vector<Line> lines = text::split_lines(text_in, file);
  if (lines.empty()) throw ParseError(file, 1, 1, fmt::format("expected {}, got an empty file", what_matrix));
  if (text::has_bom(lines.front().text))
    throw ParseError(file, 1, 1,
                     fmt::format("expected {}, got a UTF-8 byte-order mark (save the file without it)", what_matrix));
  for (std::size_t li = 0; li < lines.size(); ++li) {
    reject_block_comment(lines[li], file);
    const std::string_view code = code_part(lines[li].text);
    const std::size_t i = skip_blanks(code, 0);
    if (i == code.size()) continue;  // blank or comment line
    grid::Grid g = (is_letter(code[i]) || code[i] == '[') ? parse_matlab(lines, li, i, file, limits)
                                                          : parse_plain(lines, li, file, limits);
    return MapFile{std::move(g), std::nullopt, std::nullopt, ""};
  }
  throw ParseError(file, text::eof_line(lines), 1, fmt::format("unexpected end of file: expected {}", what_matrix));
}

std::string to_matrix_text(const grid::Grid& g) {
  std::string out;
  out.reserve(static_cast<std::size_t>(2 * g.cell_count()));
  for (const std::string& row : g.to_rows_top_first()) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i > 0) out += ' ';
      out += row[i] == '#' ? '1' : '0';
    }
    out += '\n';
  }
  return out;
}

std::string to_matlab_text(const grid::Grid& g) {
  std::string out = "G = [";
  out.reserve(static_cast<std::size_t>(2 * g.cell_count() + 6 * g.height() + 8));
  const auto rows = g.to_rows_top_first();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (r > 0) out += "\n     ";
    for (std::size_t i = 0; i < rows[r].size(); ++i) {
      if (i > 0) out += ' ';
      out += rows[r][i] == '#' ? '1' : '0';
    }
  }
  out += "];\n";
  return out;
}

}  // namespace pathref::io
