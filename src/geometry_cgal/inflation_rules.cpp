// JSON adapters for the inflation.* rules (spec/inflation.md). They live in pathref_geometry, not
// in libpathref's src/pathref/rules/, because they call the CGAL-backed functions; they reach the
// registry through rules::add_extension_module (see install_inflation_rules).
// No CGAL header here: only the CGAL-free pathref/geometry/inflation.hpp.
#include "pathref/io/scene_json.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::geometry {

namespace {

using rules::Json;

/// Rule inputs are parsed by nlohmann::json (numbers become doubles): each number is read as the
/// decimal of its shortest round-trip text, exact for up to 15 significant digits
/// (spec/formats.md, "Polygon scene (JSON)", numbers in rule inputs).
Json rows_of(const grid::Grid& g) { return grid::grid_to_json(g); }

Decimal decimal_arg(const Json& in, const char* key) {
  const Json& v = rules::arg(in, key);
  std::optional<Decimal> d;
  if (v.is_number_integer()) d = decimal_from_integer(v.get<std::int64_t>());
  else if (v.is_number_float()) d = decimal_from_double_shortest(v.get<double>());
  else if (v.is_string()) d = parse_decimal(v.get<std::string>());
  if (!d) throw UsageError(std::string("input '") + key + "' must be a decimal number");
  return *d;
}

const std::vector<rules::Field> scene_fields = {
    {"origin", "number[2]", "world lower-left corner [x, y]"},
    {"width", "integer", "W, cells along x"},
    {"height", "integer", "H, cells along y"},
    {"cell_size", "number", "s > 0 (exact decimal)"},
    {"radius", "number", "vehicle radius >= 0"},
    {"margin", "number", "safety margin >= 0; r = radius + margin"},
    {"polygons", "object[]", "[{\"vertices\": [[x, y], ...]}, ...] simple polygons"},
};

void register_inflation_rules(rules::Registry& r) {
  r.add(rules::Rule{
      "inflation.cell-blocked",
      "Cell blocked iff its closed square is within r = radius + margin of an obstacle polygon (exact)",
      "pathref::geometry::inflate_polygons",
      scene_fields,
      {{"rows", "grid", "the inflated W x H map, rows top first, '#' blocked"},
       {"blocked", "integer", "number of blocked cells"}},
      [](const Json& in) {
        const Scene s = io::scene_from_json(in, "<input>", io::SceneKeys::geometry);
        const grid::Grid g = inflate_polygons(s);
        return Json{{"rows", rows_of(g)}, {"blocked", g.blocked_count()}};
      }});
  r.add(rules::Rule{
      "inflation.grid",
      "Grid-level inflation: cell blocked iff its closed square is within r of a blocked cell's square",
      "pathref::geometry::inflate_grid",
      {{"map", "grid", "rows top first"},
       {"cell_size", "number", "s > 0"},
       {"radius", "number", "vehicle radius >= 0"},
       {"margin", "number", "safety margin >= 0; r = radius + margin"}},
      {{"rows", "grid", "the inflated map, rows top first"}},
      [](const Json& in) {
        const grid::Grid m = grid::grid_from_json(rules::arg(in, "map"));
        const Decimal s = decimal_arg(in, "cell_size");
        const Decimal rad = decimal_arg(in, "radius");
        const Decimal mar = decimal_arg(in, "margin");
        require(!s.negative && !s.is_zero(), "cell_size must be > 0");
        require(!rad.negative && !mar.negative, "radius and margin must be >= 0");
        // r = radius + margin as an exact decimal: align exponents (both within the limits)
        const auto add = [](const Decimal& a, const Decimal& b) {
          const std::int32_t e = std::min(a.exp10, b.exp10);
          auto widen = [e](const Decimal& d) {
            std::string t = d.digits;
            t.append(static_cast<std::size_t>(d.exp10 - e), '0');
            return t;
          };
          std::string x = widen(a), y = widen(b);
          if (x.size() < y.size()) std::swap(x, y);
          y.insert(0, x.size() - y.size(), '0');
          std::string sum(x.size() + 1, '0');
          int carry = 0;
          for (std::size_t i = x.size(); i-- > 0;) {
            const int t = (x[i] - '0') + (y[i] - '0') + carry;
            sum[i + 1] = static_cast<char>('0' + t % 10);
            carry = t / 10;
          }
          sum[0] = static_cast<char>('0' + carry);
          std::string text = sum + "e" + std::to_string(e);
          std::size_t nz = 0;
          while (nz + 1 < sum.size() && sum[nz] == '0') ++nz;
          text = sum.substr(nz) + "e" + std::to_string(e);
          auto d = parse_decimal(text);
          if (!d) throw DomainError("radius + margin has more than 30 significant digits");
          return *d;
        };
        return Json{{"rows", rows_of(inflate_grid(m, s, add(rad, mar)))}};
      }});
  auto fields = scene_fields;
  fields.push_back({"start", "cell", "[x, y]"});
  fields.push_back({"goal", "cell", "[x, y]"});
  r.add(rules::Rule{
      "inflation.scene",
      "Inflate a scene and check start/goal: inside the map, not blocked, distinct",
      "pathref::geometry::inflate_scene",
      fields,
      {{"rows", "grid", "the inflated map, rows top first"},
       {"start", "cell", "start cell"},
       {"goal", "cell", "goal cell"}},
      [](const Json& in) {
        Scene s = io::scene_from_json(in, "<input>", io::SceneKeys::geometry);
        const InflatedScene r2 = inflate_scene(s);
        return Json{{"rows", rows_of(r2.grid)}, {"start", grid::cell_to_json(r2.start)},
                    {"goal", grid::cell_to_json(r2.goal)}};
      }});
}

}  // namespace

void install_inflation_rules() { rules::add_extension_module(&register_inflation_rules); }

}  // namespace pathref::geometry
