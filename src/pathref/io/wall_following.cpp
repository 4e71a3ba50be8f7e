#include "pathref/io/wall_following.hpp"

#include "pathref/io/input_file.hpp"
#include "pathref/io/json_text.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "pathref/core/error.hpp"

namespace pathref::io {

using ml::wall_following_labels;
namespace {

bool is_number_text(std::string_view s) {
  // -?digits(.digits)?([eE][+-]?digits)?   or  -?.digits
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  std::size_t digits = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') { ++i; ++digits; }
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') { ++i; ++digits; }
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    std::size_t e = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') { ++i; ++e; }
    if (e == 0) return false;
  }
  return i == s.size();
}

}  // namespace

Dataset parse_wall_following(std::string_view text, std::string_view filename,
                             const DataLimits& limits) {
  const std::string file(filename);
  Dataset d;
  std::size_t pos = 0;
  std::size_t line_no = 0;
  while (pos < text.size()) {
    ++line_no;
    std::size_t end = text.find('\n', pos);
    const bool has_lf = end != std::string_view::npos;
    if (!has_lf) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = has_lf ? end + 1 : text.size();
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.size() > limits.max_line)
      throw ParseError(file, line_no, limits.max_line + 1,
                       "a line of at most " + std::to_string(limits.max_line) + " bytes");
    if (line.empty())
      throw ParseError(file, line_no, 1, "a row 'v1,...,vd,LABEL' (empty line)");
    if (d.rows() >= limits.max_rows)
      throw ParseError(file, line_no, 1, "at most " + std::to_string(limits.max_rows) + " rows");
    // split on ','
    std::size_t col = 0;       // 0-based byte column of the field
    std::size_t fields = 0;
    std::size_t start = 0;
    std::vector<double> values;
    while (true) {
      const std::size_t comma = line.find(',', start);
      const bool last = comma == std::string_view::npos;
      const std::string_view field = line.substr(start, (last ? line.size() : comma) - start);
      col = start + 1;
      ++fields;
      if (last) {
        // the label
        if (values.empty())
          throw ParseError(file, line_no, col, "at least one number before the label");
        int label = -1;
        for (std::size_t k = 0; k < wall_following_labels.size(); ++k)
          if (field == wall_following_labels[k]) label = static_cast<int>(k);
        if (label < 0) {
          if (is_number_text(field))
            throw ParseError(file, line_no, line.size() + 1,
                             "',' and a label (Move-Forward, Slight-Right-Turn, "
                             "Sharp-Right-Turn or Slight-Left-Turn): missing label column");
          throw ParseError(file, line_no, col,
                           "a label Move-Forward, Slight-Right-Turn, Sharp-Right-Turn or "
                           "Slight-Left-Turn, got '" + printable(field, 40) + "'");
        }
        if (d.features == 0) {
          d.features = values.size();
        } else if (values.size() != d.features) {
          throw ParseError(file, line_no, col,
                           std::to_string(d.features) + " numbers before the label (as on line 1), got " +
                               std::to_string(values.size()));
        }
        d.x.insert(d.x.end(), values.begin(), values.end());
        d.y.push_back(label);
        break;
      }
      if (values.size() >= limits.max_features || (d.features != 0 && values.size() >= d.features))
        throw ParseError(file, line_no, col,
                         d.features != 0 ? "the label after " + std::to_string(d.features) + " numbers"
                                         : "at most " + std::to_string(limits.max_features) + " numbers");
      if (!is_number_text(field))
        throw ParseError(file, line_no, col,
                         "a decimal number, got '" + printable(field, 40) + "'");
      double v = 0.0;
      const char* b = field.data();
      if (*b == '+') ++b;
      const auto r = std::from_chars(b, field.data() + field.size(), v);
      if (r.ec != std::errc() || r.ptr != field.data() + field.size() || !std::isfinite(v))
        throw ParseError(file, line_no, col, "a finite decimal number, got '" + printable(field, 40) + "'");
      values.push_back(v);
      start = comma + 1;
    }
    (void)fields;
  }
  if (d.rows() == 0) throw ParseError(file, 1, 1, "at least one row 'v1,...,vd,LABEL' (empty file)");
  return d;
}

Dataset read_wall_following(const std::string& path, const DataLimits& limits) {
  return parse_wall_following(read_input_file(path, "data file", limits.max_bytes), path, limits);
}

}  // namespace pathref::io
