#pragma once
/// \file plan_json.hpp
/// The JSON record of one planning run (`pathref plan --json` / `--json-out`), shared by the CLI,
/// the tests and commands that read a plan back (e.g. `pathref drive` from stdin).
/// Schema "pathref-plan" version 1: spec/cli.md#plan-json.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"

namespace pathref::io {

using Json = nlohmann::json;

/// Where the map of a run came from.
struct MapSource {
  std::string kind;                 ///< "builtin" or "file"
  std::string name;                 ///< built-in name; for a file its `name` line, else the path
  std::optional<std::string> file;  ///< the path given to --map (nullopt for a built-in)
};

/// Everything that determines a run and what it returned.
struct PlanRecord {
  std::string algo;
  std::uint32_t seed = 1;
  grid::CornerPolicy policy = grid::CornerPolicy::strict;
  MapSource map;
  grid::Cell start;
  grid::Cell goal;
  planners::Json params;      ///< every parameter value used (defaults included)
  planners::Result result;
};

/// The "pathref-plan" v1 object for a run on grid `g` (spec/cli.md#plan-json). Derived fields
/// are recomputed here from result.path with the metrics module (turns, valid, validation,
/// converged_at), so every planner reports them the same way. Non-finite numbers (e.g. +inf
/// "no solution in this iteration") are written as null.
/// Pre: result.path cells in bounds of g when found (DomainError from the metrics otherwise).
[[nodiscard]] Json plan_to_json(const PlanRecord& run, const grid::Grid& g);

/// What a reader of a plan record needs back: the map, the endpoints and the path.
struct PlanJsonView {
  std::string algo;
  grid::CornerPolicy policy = grid::CornerPolicy::strict;
  grid::Grid grid;
  grid::Cell start;
  grid::Cell goal;
  bool found = false;
  std::vector<grid::Cell> path;
};

/// Reads back the fields of a "pathref-plan" v1 object that describe the map and the path
/// (spec/cli.md#plan-json). Every refusal is a ParseError at the offending value: a missing or
/// ill-typed field, format/format_version not "pathref-plan"/1, rows of different lengths or
/// characters other than '.' and '#', `map.width`/`map.height` (or `map.blocked`) that contradict
/// `map.rows`. `source` names the input (e.g. "<stdin>"); with `text`, the record's JSON text
/// (`first_line`: the line of the file it begins on), messages are `SOURCE:LINE:COLUMN: /pointer:
/// what`, without it `SOURCE: /pointer: what`.
[[nodiscard]] PlanJsonView plan_from_json(const Json& doc, std::string_view source, std::string_view text = {},
                                          std::size_t first_line = 1);

}  // namespace pathref::io
