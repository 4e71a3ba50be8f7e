#pragma once
/// \file scene_map.hpp
/// A polygon scene read as a map: the io::MapReadOptions::scene_to_map hook, implemented with
/// the exact inflation of pathref_geometry. It lives here, above io (docs/architecture.md#layers:
/// geometry is below the formats; the CGAL library and its adapters to io are above them).
/// Before 0.3.0 it was declared in pathref/geometry/inflation.hpp.
#include <string>
#include <string_view>

#include "pathref/geometry/inflation.hpp"
#include "pathref/io/map_file.hpp"

namespace pathref::geometry {

/// A scene file's text as a map (what `pathref plan --map FILE.json` and `convert` read; the
/// io::MapReadOptions::scene_to_map hook): parse_scene_json, then the scene's width and height
/// are checked against `limits` before any grid is allocated (ParseError `FILE:0:0: /width: a
/// WxH grid exceeds the limit of N cells per side` or `... of N cells`), then inflate_scene; its
/// DomainErrors are reported as `FILE: /start: ...` (naming the file). The map's name is the
/// scene's. Spec: spec/formats.md#polygon-scene-json ("As a map"), inflation.scene.
[[nodiscard]] io::MapFile scene_map(std::string_view text, const std::string& filename,
                                    const io::ReadLimits& limits);

}  // namespace pathref::geometry
