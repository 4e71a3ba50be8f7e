// Polygon scene reader/writer (spec/formats.md, "Polygon scene (JSON)").
#include "pathref/io/scene_json.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "pathref/core/error.hpp"
#include "pathref/io/input_file.hpp"
#include "pathref/io/json_text.hpp"

namespace pathref::io {

using geometry::Decimal;
using geometry::decimal_from_double_shortest;
using geometry::decimal_from_integer;
using geometry::parse_decimal;
using geometry::max_polygon_vertices;
using geometry::max_scene_file_bytes;
using geometry::max_scene_polygons;
using geometry::max_scene_vertices;

using Json = nlohmann::json;

namespace {

constexpr const char* format_name = "pathref-scene 1";

/// Reads values with JSON-pointer error messages.
class Reader {
 public:
  /// `text`: the file's JSON text, for line and column (empty for a value that came from no file).
  Reader(std::string_view file, std::string_view text) : file_(file), text_(text) {}

  [[noreturn]] void fail(const std::string& ptr, const std::string& what) const {
    throw io::json_error_at(text_, file_, ptr, what);
  }

  static std::string kind(const Json& v) {
    if (v.is_binary() || v.is_number_float()) return "a non-integer number";
    if (v.is_number()) return "an integer";
    const std::string t = v.type_name();
    return (t == "object" || t == "array" ? "an " : "a ") + t;
  }

  std::int64_t integer(const Json& v, const std::string& ptr, std::int64_t lo, std::int64_t hi) const {
    const std::string want = "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (v.is_number_unsigned()) {
      const auto u = v.get<std::uint64_t>();
      // JSON's non-negative integers arrive as unsigned: both bounds apply (a width of 0 was let
      // through here and failed later as "start ... is not free" or a DomainError, issue 27).
      if (u > static_cast<std::uint64_t>(hi) || static_cast<std::int64_t>(u) < lo)
        fail(ptr, want + ", got " + std::to_string(u));
      return static_cast<std::int64_t>(u);
    }
    if (v.is_number_integer()) {
      const auto i = v.get<std::int64_t>();
      if (i < lo || i > hi) fail(ptr, want + ", got " + std::to_string(i));
      return i;
    }
    fail(ptr, want + ", got " + kind(v));
  }

  Decimal decimal(const Json& v, const std::string& ptr) const {
    const std::string want = "expected a number (at most 30 significant digits, |exponent| <= 30)";
    std::optional<Decimal> d;
    if (v.is_number_unsigned()) {
      d = parse_decimal(std::to_string(v.get<std::uint64_t>()));
    } else if (v.is_number_integer()) {
      d = decimal_from_integer(v.get<std::int64_t>());
    } else if (v.is_binary()) {
      const auto& b = v.get_binary();
      d = parse_decimal(std::string(b.begin(), b.end()));
      if (!d) fail(ptr, want + ", got " + std::string(b.begin(), b.end()));
    } else if (v.is_number_float()) {
      d = decimal_from_double_shortest(v.get<double>());
    } else {
      fail(ptr, want + ", got " + kind(v));
    }
    if (!d) fail(ptr, want);
    return *d;
  }

  Decimal decimal_at_least(const Json& v, const std::string& ptr, bool strictly_positive) const {
    Decimal d = decimal(v, ptr);
    if (d.negative || (strictly_positive && d.is_zero()))
      fail(ptr, strictly_positive ? "expected a number > 0, got " + to_string(d)
                                  : "expected a number >= 0, got " + to_string(d));
    return d;
  }

  Point point(const Json& v, const std::string& ptr) const {
    if (!v.is_array() || v.size() != 2) fail(ptr, "expected [x, y] (an array of two numbers), got " + kind(v) + (v.is_array() ? " of " + std::to_string(v.size()) + " elements" : ""));
    return Point{decimal(v[0], ptr + "/0"), decimal(v[1], ptr + "/1")};
  }

  grid::Cell cell(const Json& v, const std::string& ptr) const {
    if (!v.is_array() || v.size() != 2) fail(ptr, "expected a cell [x, y] (two integers), got " + kind(v));
    constexpr std::int64_t big = std::int64_t{1} << 40;
    return grid::Cell{integer(v[0], ptr + "/0", -big, big), integer(v[1], ptr + "/1", -big, big)};
  }

 private:
  std::string file_;
  std::string_view text_;
};

/// scene_from_json with the file's text at hand for line and column (parse_scene_json).
Scene scene_from_json_text(const Json& obj, std::string_view filename, SceneKeys keys, std::string_view text) {
  const Reader rd(filename, text);
  if (!obj.is_object()) rd.fail("", "expected a JSON object (a pathref-scene 1), got " + Reader::kind(obj));
  static const std::set<std::string> known = {"format", "name", "origin", "width", "height", "cell_size",
                                              "radius", "margin", "polygons", "start", "goal"};
  for (const auto& [k, v] : obj.items()) {
    (void)v;
    if (known.count(k) == 0) rd.fail("/" + k, "unknown key (expected one of format, name, origin, width, height, cell_size, radius, margin, polygons, start, goal)");
  }
  auto need = [&](const char* k) -> const Json& {
    if (!obj.contains(k)) rd.fail("", std::string("missing key \"") + k + "\"");
    return obj.at(k);
  };
  Scene s;
  if (keys == SceneKeys::file || obj.contains("format")) {
    const Json& f = need("format");
    if (!f.is_string() || f.get<std::string>() != format_name)
      rd.fail("/format", std::string("expected \"") + format_name + "\"");
  }
  if (obj.contains("name")) {
    if (!obj.at("name").is_string()) rd.fail("/name", "expected a string, got " + Reader::kind(obj.at("name")));
    s.name = obj.at("name").get<std::string>();
  }
  s.origin = rd.point(need("origin"), "/origin");
  s.width = rd.integer(need("width"), "/width", 1, grid::Grid::max_cells);
  s.height = rd.integer(need("height"), "/height", 1, grid::Grid::max_cells);
  if (s.width * s.height > grid::Grid::max_cells)
    rd.fail("/height", "expected width * height <= 2^28 cells, got " + std::to_string(s.width) + " * " + std::to_string(s.height));
  s.cell_size = rd.decimal_at_least(need("cell_size"), "/cell_size", true);
  s.radius = rd.decimal_at_least(need("radius"), "/radius", false);
  s.margin = rd.decimal_at_least(need("margin"), "/margin", false);
  const Json& polys = need("polygons");
  if (!polys.is_array()) rd.fail("/polygons", "expected an array of polygons, got " + Reader::kind(polys));
  if (polys.size() > max_scene_polygons)
    rd.fail("/polygons", "expected at most 100000 polygons, got " + std::to_string(polys.size()));
  std::size_t total = 0;
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const std::string p = "/polygons/" + std::to_string(i);
    const Json& po = polys[i];
    if (!po.is_object()) rd.fail(p, "expected a polygon object {\"vertices\": [[x, y], ...]}, got " + Reader::kind(po));
    for (const auto& [k, v] : po.items()) {
      (void)v;
      if (k != "vertices") rd.fail(p + "/" + k, "unknown key (expected \"vertices\")");
    }
    if (!po.contains("vertices")) rd.fail(p, "missing key \"vertices\"");
    const Json& vs = po.at("vertices");
    if (!vs.is_array()) rd.fail(p + "/vertices", "expected an array of [x, y] points, got " + Reader::kind(vs));
    if (vs.size() > max_polygon_vertices)
      rd.fail(p + "/vertices", "expected at most 100000 vertices, got " + std::to_string(vs.size()));
    total += vs.size();
    if (total > max_scene_vertices)
      rd.fail(p + "/vertices", "expected at most 1000000 vertices in all polygons together");
  }
  s.polygons.reserve(polys.size());
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const std::string p = "/polygons/" + std::to_string(i) + "/vertices";
    const Json& vs = polys[i].at("vertices");
    Polygon poly;
    poly.vertices.reserve(vs.size());
    for (std::size_t j = 0; j < vs.size(); ++j) poly.vertices.push_back(rd.point(vs[j], p + "/" + std::to_string(j)));
    s.polygons.push_back(std::move(poly));
  }
  if (keys == SceneKeys::file || obj.contains("start")) s.start = rd.cell(need("start"), "/start");
  if (keys == SceneKeys::file || obj.contains("goal")) s.goal = rd.cell(need("goal"), "/goal");
  return s;
}

}  // namespace

Scene scene_from_json(const Json& obj, std::string_view filename, SceneKeys keys) {
  return scene_from_json_text(obj, filename, keys, {});
}

Scene parse_scene_json(std::string_view text, std::string_view filename) {
  io::JsonLimits limits = io::document_limits;
  limits.max_bytes = max_scene_file_bytes;
  limits.decimal_text = true;  // every non-integer number keeps its exact decimal text
  const Json root = io::parse_json_text(text, filename, 1, limits);
  return scene_from_json_text(root, filename, SceneKeys::file, text);
}

std::string to_scene_json(const Scene& s) {
  std::ostringstream o;
  auto pt = [](const Point& p) {
    std::string t = "[";  // appended piecewise: g++ 12 -O3 reports a false -Wrestrict for "[" + s
    t += to_string(p.x);
    t += ", ";
    t += to_string(p.y);
    t += ']';
    return t;
  };
  o << "{\n  \"format\": \"" << format_name << "\",\n";
  if (!s.name.empty()) o << "  \"name\": " << Json(s.name).dump() << ",\n";
  o << "  \"origin\": " << pt(s.origin) << ",\n  \"width\": " << s.width << ",\n  \"height\": " << s.height
    << ",\n  \"cell_size\": " << to_string(s.cell_size) << ",\n  \"radius\": " << to_string(s.radius)
    << ",\n  \"margin\": " << to_string(s.margin) << ",\n  \"polygons\": [";
  for (std::size_t i = 0; i < s.polygons.size(); ++i) {
    o << (i ? ",\n    " : "\n    ") << "{\"vertices\": [";
    const auto& vs = s.polygons[i].vertices;
    for (std::size_t j = 0; j < vs.size(); ++j) o << (j ? ", " : "") << pt(vs[j]);
    o << "]}";
  }
  o << (s.polygons.empty() ? "]" : "\n  ]");
  if (s.start) o << ",\n  \"start\": [" << s.start->x << ", " << s.start->y << "]";
  if (s.goal) o << ",\n  \"goal\": [" << s.goal->x << ", " << s.goal->y << "]";
  o << "\n}\n";
  return o.str();
}

Scene read_scene_file(const std::string& path) {
  return parse_scene_json(io::read_input_file(path, "scene file", max_scene_file_bytes), path);
}

}  // namespace pathref::io
