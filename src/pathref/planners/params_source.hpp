#pragma once
/// \file params_source.hpp
/// A planner's parameters as written in a file (a simulation scenario's /planner/params), so that
/// a planner's refusal of a value at run time names the file, line, column and pointer
/// (spec/han-sim.md, han.sim.scenario-format; issue 27).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/planners/planner.hpp"

namespace pathref::planners {

/// Where a request's parameters were written in a file (a scenario's /planner/params), so that a
/// planner's refusal of a value names it: FILE, the LINE and COLUMN of the value (0 when it came
/// from no text), its JSON pointer.
struct ParamsSource {
  std::string file;
  std::size_t line = 0;
  std::size_t column = 0;
  std::string pointer;
};

// A reader fills a ParamsSource from its text (io::line_column, io::pointer_offset): positions in a
// text are io's (docs/architecture.md#layers).

/// p.run(req). When req.params is not empty and `source` is given, a UsageError or DomainError the
/// planner throws (planners check their parameter values when they run) is rethrown as the
/// ParseError `FILE:LINE:COLUMN: POINTER: the planner NAME refused its parameters: MESSAGE`
/// (`FILE: POINTER: ...` without a line).
[[nodiscard]] Result run_with_params_from(const Planner& p, const Request& req, const std::optional<ParamsSource>& source);

}  // namespace pathref::planners
