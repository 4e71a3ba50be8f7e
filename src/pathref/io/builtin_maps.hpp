#pragma once
/// \file builtin_maps.hpp
/// Maps compiled into pathref (`pathref plan --builtin NAME`, listed by `pathref maps`). Each is
/// stored as pathref-grid 1 text and read with parse_grid_text, so the built-ins exercise the same
/// reader as user files. No file is read at run time.
/// Spec: spec/cli.md#builtin-maps (each map's provenance; reconstructed maps say what is known
/// and what was chosen).
#include <string_view>
#include <vector>

#include "pathref/io/grid_text.hpp"

namespace pathref::io {

struct BuiltinMap {
  std::string_view name;         ///< --builtin value
  std::string_view description;  ///< one line for `pathref maps`
  std::string_view provenance;   ///< where it comes from; "reconstructed" when it is a reading
  std::string_view text;         ///< pathref-grid 1 text, with name, size, start and goal
};

/// Every built-in map, sorted by name.
[[nodiscard]] const std::vector<BuiltinMap>& builtin_maps();

/// nullptr if there is no built-in of that name.
[[nodiscard]] const BuiltinMap* find_builtin_map(std::string_view name);

/// The parsed map (parse_grid_text with filename "builtin:NAME").
[[nodiscard]] MapFile load_builtin_map(const BuiltinMap& map);

/// The names of all built-ins, comma separated, for error messages.
[[nodiscard]] std::string builtin_map_names();

}  // namespace pathref::io
