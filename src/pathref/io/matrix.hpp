#pragma once
/// \file matrix.hpp
/// 0/1 occupancy matrices as MATLAB scripts and users write them: either plain rows of 0s and 1s
/// (one matrix row per line, values separated by blanks or commas) or one MATLAB assignment
/// `NAME = [0 0 1; 0 1 0];` (rows separated by `;` or line ends, `...` continuations, `%`
/// comments). 1 = obstacle, 0 = free; the first matrix row is the TOP row of the map (pathref
/// y = H - 1), so matrix element (r, c), 1-based, is pathref cell (c - 1, H - r).
/// Spec: spec/formats.md#matrix (grammar, every error message, limits).
#include <string>
#include <string_view>

#include "pathref/grid/grid.hpp"
#include "pathref/io/grid_text.hpp"
#include "pathref/io/map_file.hpp"

namespace pathref::io {

/// Parses a 0/1 matrix in either form (the form is decided by the first character that is not
/// a blank or inside a % comment: a letter -> MATLAB assignment, otherwise plain rows). The result
/// has no start, goal or name. ParseError(filename, line, column, what was expected) for any
/// deviation from spec/formats.md#matrix; the number of rows, the row length and W * H are
/// checked against `limits` while reading, before the grid is allocated; the memory used is
/// bounded by a small multiple of the size of `text`.
[[nodiscard]] MapFile parse_matrix(std::string_view text, std::string_view filename,
                                   const ReadLimits& limits = {});

/// Plain rows: each row top first as `0`/`1` separated by single spaces, LF after each row.
/// Post: parse_matrix(to_matrix_text(g), f).grid == g.
[[nodiscard]] std::string to_matrix_text(const grid::Grid& g);

/// A MATLAB assignment: `G = [` and the first row, each further row on its own line indented by
/// five spaces, `];` and LF after the last row; values separated by single spaces, e.g.
/// "G = [0 1\n     1 0];\n". Post: parse_matrix(to_matlab_text(g), f).grid == g.
[[nodiscard]] std::string to_matlab_text(const grid::Grid& g);

}  // namespace pathref::io
