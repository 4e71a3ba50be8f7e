#pragma once
/// \file wall_following.hpp
/// Reading the UCI Wall-Following Robot Navigation data (Freire et al. 2009, doi:10.24432/C57C8W)
/// as cin2021 §3 uses it into an ml::Dataset (ml/data.hpp). The data set is ml's; its text format
/// is io's (docs/architecture.md#layers). Spec: spec/cin2021-ml.md#data (grammar, limits, errors).
#include <cstddef>
#include <string>
#include <string_view>

#include "pathref/ml/data.hpp"

namespace pathref::io {

using ml::Dataset;

/// Limits checked while reading, before anything grows beyond them.
struct DataLimits {
  std::size_t max_rows = 1'000'000;
  std::size_t max_features = 64;
  std::size_t max_line = 4096;  ///< bytes per line, without the line end
  std::size_t max_bytes = std::size_t{256} << 20;  ///< the file's size, checked before reading
};

/// Parses the UCI text: each line `v_1,...,v_d,LABEL` (d >= 1 equal on every line, v_i a finite
/// decimal number, LABEL one of wall_following_labels), LF or CRLF line ends, the last line
/// with or without a line end. ParseError(filename, line, column, what was expected) on any
/// deviation (missing or extra column, unknown label, non-number, empty line, a limit exceeded).
/// Spec: cin2021.data (spec/cin2021-ml.md).
[[nodiscard]] Dataset parse_wall_following(std::string_view text, std::string_view filename,
                                           const DataLimits& limits = {});

/// Reads (io::read_input_file: a regular file of at most limits.max_bytes, else UsageError with the
/// reason) and parses a file.
[[nodiscard]] Dataset read_wall_following(const std::string& path, const DataLimits& limits = {});

}  // namespace pathref::io
