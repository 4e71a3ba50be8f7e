// SVG figures (spec/cli.md#svg-figures): checked by structure — well-formed XML, the expected
// elements and counts, and coordinates (lower-left origin, paths through cell centres) — not by
// "non-empty".
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/svg.hpp"

using pathref::grid::Cell;
using pathref::grid::Grid;
namespace io = pathref::io;

namespace {

/// One element of a parsed document: its name, attributes and the text directly inside it.
struct Element {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::string text;
  int depth = 0;
};

/// A small strict XML checker for the subset pathref writes: elements, double-quoted attributes,
/// text with the five predefined entities. Fails the test (via exception) on anything else:
/// unbalanced tags, unquoted/duplicate attributes, raw '<' or a bare '&' in text.
std::vector<Element> parse_xml(const std::string& doc) {
  std::vector<Element> out;
  std::vector<std::size_t> open;  // indices into out
  std::size_t i = 0;
  const auto fail = [&](const std::string& why) {
    throw std::runtime_error("XML error at byte " + std::to_string(i) + ": " + why);
  };
  const auto check_entities = [&](const std::string& s) {
    for (std::size_t k = 0; k < s.size(); ++k) {
      if (s[k] == '<') fail("raw '<' in text or attribute");
      if (s[k] == '&') {
        const auto semi = s.find(';', k);
        const std::string ent = semi == std::string::npos ? "" : s.substr(k, semi - k + 1);
        if (ent != "&amp;" && ent != "&lt;" && ent != "&gt;" && ent != "&quot;" && ent != "&apos;")
          fail("bare '&'");
      }
    }
  };
  const auto is_name = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == ':' || c == '_'; };
  while (i < doc.size()) {
    if (doc[i] != '<') {
      const auto next = doc.find('<', i);
      const std::string text = doc.substr(i, next == std::string::npos ? std::string::npos : next - i);
      check_entities(text);
      if (!open.empty()) out[open.back()].text += text;
      else if (text.find_first_not_of(" \n\t") != std::string::npos) fail("text outside the root");
      if (next == std::string::npos) break;
      i = next;
      continue;
    }
    if (doc.compare(i, 2, "</") == 0) {
      const auto end = doc.find('>', i);
      if (end == std::string::npos) fail("unterminated closing tag");
      const std::string name = doc.substr(i + 2, end - i - 2);
      if (open.empty() || out[open.back()].name != name) fail("mismatched </" + name + ">");
      open.pop_back();
      i = end + 1;
      continue;
    }
    ++i;
    Element e;
    while (i < doc.size() && is_name(doc[i])) e.name += doc[i++];
    if (e.name.empty()) fail("empty element name");
    bool self_closing = false;
    for (;;) {
      while (i < doc.size() && std::isspace(static_cast<unsigned char>(doc[i]))) ++i;
      if (i >= doc.size()) fail("unterminated tag");
      if (doc.compare(i, 2, "/>") == 0) { self_closing = true; i += 2; break; }
      if (doc[i] == '>') { ++i; break; }
      std::string key;
      while (i < doc.size() && is_name(doc[i])) key += doc[i++];
      if (key.empty() || doc.compare(i, 2, "=\"") != 0) fail("attribute without =\"...\"");
      i += 2;
      const auto q = doc.find('"', i);
      if (q == std::string::npos) fail("unterminated attribute");
      const std::string value = doc.substr(i, q - i);
      check_entities(value);
      if (!e.attrs.emplace(key, value).second) fail("duplicate attribute " + key);
      i = q + 1;
    }
    e.depth = static_cast<int>(open.size());
    if (out.empty() == false && open.empty()) fail("second root element");
    out.push_back(e);
    if (!self_closing) open.push_back(out.size() - 1);
  }
  if (!open.empty()) throw std::runtime_error("unclosed <" + out[open.back()].name + ">");
  if (out.empty() || out.front().name != "svg") throw std::runtime_error("root is not <svg>");
  return out;
}

std::vector<Element> with_class(const std::vector<Element>& els, const std::string& name,
                                const std::string& cls) {
  std::vector<Element> r;
  for (const auto& e : els)
    if (e.name == name && e.attrs.count("class") && e.attrs.at("class") == cls) r.push_back(e);
  return r;
}

double attr(const Element& e, const std::string& key) { return std::stod(e.attrs.at(key)); }

/// "x1,y1 x2,y2 ..." -> points.
std::vector<std::pair<double, double>> points(const Element& polyline) {
  std::vector<std::pair<double, double>> r;
  std::istringstream in(polyline.attrs.at("points"));
  std::string pt;
  while (in >> pt) {
    const auto comma = pt.find(',');
    r.emplace_back(std::stod(pt.substr(0, comma)), std::stod(pt.substr(comma + 1)));
  }
  return r;
}

/// All text of the document's elements, concatenated with spaces.
std::string all_text(const std::vector<Element>& els) {
  std::string s;
  for (const auto& e : els) s += e.text + " ";
  return s;
}

}  // namespace

TEST_CASE("svg: the XML checker itself rejects broken documents", "[svg]") {
  CHECK_NOTHROW(parse_xml("<svg a=\"1\"><g><rect/></g><text>a &amp; b</text></svg>"));
  CHECK_THROWS(parse_xml("<svg><g></svg>"));
  CHECK_THROWS(parse_xml("<svg><text>a & b</text></svg>"));
  CHECK_THROWS(parse_xml("<svg a=1></svg>"));
  CHECK_THROWS(parse_xml("<svg a=\"1\" a=\"2\"></svg>"));
  CHECK_THROWS(parse_xml("<g></g>"));
  CHECK_THROWS(parse_xml("<svg></svg><svg></svg>"));
}

TEST_CASE("svg: map has one black rect per blocked cell, (0,0) at the lower left", "[svg]") {
  // 3 x 2, blocked (2,1) (top right) and (0,0) (bottom left).
  const Grid g = Grid::from_rows_top_first({"..#", "#.."});
  const std::vector<io::PathLayer> paths{{"route A", {Cell{1, 0}, Cell{1, 1}, Cell{0, 1}}}};
  const auto els = parse_xml(io::svg_map(g, Cell{1, 0}, Cell{0, 1}, paths, "my map"));
  const auto map = with_class(els, "rect", "map");
  REQUIRE(map.size() == 1);
  const double mx = attr(map[0], "x"), my = attr(map[0], "y");
  const double s = attr(map[0], "width") / 3.0;
  CHECK(attr(map[0], "height") == Approx(2.0 * s));
  const auto obstacles = with_class(els, "rect", "obstacle");
  REQUIRE(obstacles.size() == 2);
  // Document order: top row first, left to right -> (2,1) then (0,0).
  CHECK(attr(obstacles[0], "x") == Approx(mx + 2.0 * s).epsilon(1e-3));
  CHECK(attr(obstacles[0], "y") == Approx(my).epsilon(1e-3));
  CHECK(attr(obstacles[1], "x") == Approx(mx).epsilon(1e-3));
  CHECK(attr(obstacles[1], "y") == Approx(my + s).epsilon(1e-3));
  for (const auto& o : obstacles) CHECK(o.attrs.at("fill") == "black");

  // The path passes through the cell centres, y flipped.
  const auto lines = with_class(els, "polyline", "path");
  REQUIRE(lines.size() == 1);
  const auto pts = points(lines[0]);
  REQUIRE(pts.size() == 3);
  const std::vector<Cell> cells{{1, 0}, {1, 1}, {0, 1}};
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(pts[k].first == Approx(mx + (static_cast<double>(cells[k].x) + 0.5) * s).margin(0.01));
    CHECK(pts[k].second == Approx(my + (1.0 - static_cast<double>(cells[k].y) + 0.5) * s).margin(0.01));
  }
  CHECK(lines[0].attrs.at("data-label") == "route A");

  // Start and goal markers sit on their cell centres and carry S and T.
  const auto start = with_class(els, "g", "start");
  const auto goal = with_class(els, "g", "goal");
  REQUIRE(start.size() == 1);
  REQUIRE(goal.size() == 1);
  std::vector<Element> circles;
  for (const auto& e : els)
    if (e.name == "circle" && e.depth == start[0].depth + 1 && e.attrs.count("r") && attr(e, "r") > 7.0)
      circles.push_back(e);
  REQUIRE(circles.size() == 2);  // start then goal (legend circles have r = 7)
  CHECK(attr(circles[0], "cx") == Approx(mx + 1.5 * s).margin(0.01));
  CHECK(attr(circles[0], "cy") == Approx(my + 1.5 * s).margin(0.01));
  CHECK(attr(circles[1], "cx") == Approx(mx + 0.5 * s).margin(0.01));
  CHECK(attr(circles[1], "cy") == Approx(my + 0.5 * s).margin(0.01));
  const std::string text = all_text(els);
  CHECK(text.find(" S ") != std::string::npos);
  CHECK(text.find(" T ") != std::string::npos);

  // Legend and title.
  REQUIRE(with_class(els, "g", "legend").size() == 1);
  CHECK(text.find("route A") != std::string::npos);
  CHECK(text.find("start S") != std::string::npos);
  CHECK(text.find("goal T") != std::string::npos);
  CHECK(text.find("obstacle") != std::string::npos);
  const auto title = with_class(els, "text", "title");
  REQUIRE(title.size() == 1);
  CHECK(title[0].text == "my map");
  // Grid lines: W-1 vertical + H-1 horizontal segments.
  const auto gl = with_class(els, "path", "gridlines");
  REQUIRE(gl.size() == 1);
  const std::string d = gl[0].attrs.at("d");
  CHECK(std::count(d.begin(), d.end(), 'M') == 2 + 1);
}

TEST_CASE("svg: cell numbers i = y*W + x at cell centres, white on obstacles, none under S and T", "[svg]") {
  // figures.cell-numbers. Same 3 x 2 map: blocked (2,1) and (0,0); S = (1,0) = 1, T = (0,1) = 3.
  const Grid g = Grid::from_rows_top_first({"..#", "#.."});
  const auto plain = parse_xml(io::svg_map(g, Cell{1, 0}, Cell{0, 1}, {}, "m"));
  CHECK(with_class(plain, "g", "cell-numbers").empty());  // off by default
  const auto els = parse_xml(io::svg_map(g, Cell{1, 0}, Cell{0, 1}, {}, "m", true));
  const auto map = with_class(els, "rect", "map");
  REQUIRE(map.size() == 1);
  const double mx = attr(map[0], "x"), my = attr(map[0], "y"), s = attr(map[0], "width") / 3.0;
  // The texts directly inside <g class="cell-numbers">, in document order.
  std::vector<Element> numbers;
  int group_depth = -1;
  for (const auto& e : els) {
    if (group_depth >= 0 && e.depth <= group_depth) break;
    if (group_depth >= 0 && e.name == "text" && e.depth == group_depth + 1) numbers.push_back(e);
    if (e.name == "g" && e.attrs.count("class") && e.attrs.at("class") == "cell-numbers") group_depth = e.depth;
  }
  // Written out by hand: cells in row order (y = 0 first), without S (1) and T (3).
  struct Expected { std::string text; double cx, cy; bool on_obstacle; };
  const std::vector<Expected> expected{{"0", 0.5, 0.5, true}, {"2", 2.5, 0.5, false},
                                       {"4", 1.5, 1.5, false}, {"5", 2.5, 1.5, true}};
  REQUIRE(numbers.size() == expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    CHECK(numbers[k].text == expected[k].text);
    CHECK(attr(numbers[k], "x") == Approx(mx + expected[k].cx * s).margin(0.01));
    // Baseline 0.36 font sizes below the centre; y flipped (row 0 at the bottom).
    CHECK(attr(numbers[k], "y") == Approx(my + (2.0 - expected[k].cy) * s + 0.36 * 14.0).margin(0.01));
    CHECK(attr(numbers[k], "font-size") >= 14.0);
    CHECK((numbers[k].attrs.count("fill") == 1 && numbers[k].attrs.at("fill") == "white") == expected[k].on_obstacle);
  }
  // 20 x 20: "399" needs about 31 units a cell, the map gets about 23 -> a UsageError naming the limit.
  const Grid big(20, 20);
  CHECK_THROWS_AS(io::svg_map(big, Cell{0, 0}, Cell{19, 19}, {}, "big", true), pathref::UsageError);
  CHECK_NOTHROW(io::svg_map(big, Cell{0, 0}, Cell{19, 19}, {}, "big"));
}

TEST_CASE("svg: several paths, escaping, empty path, no endpoints", "[svg]") {
  const Grid g(4, 4);
  const std::vector<io::PathLayer> paths{
      {"a <b> & \"c\"", {Cell{0, 0}, Cell{1, 1}}}, {"none", {}}, {"third", {Cell{3, 3}}}};
  const auto els = parse_xml(io::svg_map(g, std::nullopt, std::nullopt, paths, "t & t"));
  CHECK(with_class(els, "polyline", "path").size() == 2);  // the empty path draws nothing
  CHECK(with_class(els, "rect", "obstacle").empty());
  CHECK(with_class(els, "g", "start").empty());
  CHECK(with_class(els, "g", "goal").empty());
  const std::string text = all_text(els);
  CHECK(text.find("a &lt;b&gt; &amp; &quot;c&quot;") != std::string::npos);
  CHECK(text.find("none (no path)") != std::string::npos);
  CHECK(with_class(els, "text", "title")[0].text == "t &amp; t");
  // Two different paths get two different colours.
  const auto lines = with_class(els, "polyline", "path");
  CHECK(lines[0].attrs.at("stroke") != lines[1].attrs.at("stroke"));
}

TEST_CASE("svg: map preconditions and large maps", "[svg]") {
  const Grid g(3, 3);
  CHECK_THROWS_AS(io::svg_map(g, Cell{3, 0}, std::nullopt, {}, ""), pathref::DomainError);
  CHECK_THROWS_AS(io::svg_map(g, std::nullopt, Cell{0, -1}, {}, ""), pathref::DomainError);
  CHECK_THROWS_AS(io::svg_map(g, std::nullopt, std::nullopt, {{"p", {Cell{0, 0}, Cell{0, 3}}}}, ""),
                  pathref::DomainError);
  Grid big(150, 120);
  big.set_blocked(Cell{149, 119}, true);
  const auto els = parse_xml(io::svg_map(big, Cell{0, 0}, std::nullopt, {}, "big"));
  CHECK(with_class(els, "rect", "obstacle").size() == 1);
  CHECK(with_class(els, "path", "gridlines").empty());  // no grid lines above 100 cells a side
  CHECK(io::svg_map(big, Cell{0, 0}, std::nullopt, {}, "big") ==
        io::svg_map(big, Cell{0, 0}, std::nullopt, {}, "big"));  // deterministic
}

TEST_CASE("svg: line chart draws each series with a legend entry", "[svg]") {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<io::Series> series{
      {"GA", {1, 2, 3, 4}, {40, 35, 30, 30}},
      {"ACO", {1, 2, 3, 4, 5}, {inf, 38, inf, 31, 29}},  // broken at the infinities
  };
  const auto els = parse_xml(io::svg_line_chart(series, {"Convergence", "iteration", "best length"}));
  const auto lines = with_class(els, "polyline", "series");
  // GA: one run; ACO: runs {2} and {4, 5} -> a lone point (circle + 1-point polyline) and a line.
  REQUIRE(lines.size() == 3);
  CHECK(lines[0].attrs.at("data-label") == "GA");
  CHECK(points(lines[0]).size() == 4);
  CHECK(points(lines[1]).size() == 1);
  CHECK(points(lines[2]).size() == 2);
  CHECK(with_class(els, "circle", "point").size() == 1);
  CHECK(lines[0].attrs.at("stroke") != lines[1].attrs.at("stroke"));

  // Every point lies in the plot area; larger values are drawn higher (smaller y).
  const auto area = with_class(els, "rect", "plot-area");
  REQUIRE(area.size() == 1);
  const double ax = attr(area[0], "x"), ay = attr(area[0], "y");
  const double aw = attr(area[0], "width"), ah = attr(area[0], "height");
  for (const auto& l : lines)
    for (const auto& [px, py] : points(l)) {
      CHECK(px >= ax - 1e-9);
      CHECK(px <= ax + aw + 1e-9);
      CHECK(py >= ay - 1e-9);
      CHECK(py <= ay + ah + 1e-9);
    }
  const auto ga = points(lines[0]);
  CHECK(ga[0].second < ga[1].second);   // 40 above 35
  CHECK(ga[2].second == Approx(ga[3].second));
  CHECK(ga[0].first < ga[1].first);

  const std::string text = all_text(els);
  REQUIRE(with_class(els, "g", "legend").size() == 1);
  CHECK(text.find("GA") != std::string::npos);
  CHECK(text.find("ACO") != std::string::npos);
  CHECK(with_class(els, "text", "title")[0].text == "Convergence");
  CHECK(with_class(els, "text", "x-label")[0].text == "iteration");
  CHECK(with_class(els, "text", "y-label")[0].text == "best length");
  CHECK(with_class(els, "g", "xticks").size() == 1);
  CHECK(with_class(els, "g", "yticks").size() == 1);
}

TEST_CASE("svg: chart edge cases", "[svg]") {
  CHECK_THROWS_AS(io::svg_line_chart({{"bad", {1, 2}, {1}}}, {}), pathref::DomainError);
  // Nothing drawable: axes and legend only, still well-formed.
  const double inf = std::numeric_limits<double>::infinity();
  auto els = parse_xml(io::svg_line_chart({{"none yet", {1, 2}, {inf, inf}}}, {"t", "x", "y"}));
  CHECK(with_class(els, "polyline", "series").empty());
  CHECK(all_text(els).find("none yet") != std::string::npos);
  els = parse_xml(io::svg_line_chart({}, {"empty", "x", "y"}));
  CHECK(with_class(els, "g", "legend").empty());
  // A flat line is drawn inside the plot area.
  els = parse_xml(io::svg_line_chart({{"flat", {1, 2, 3}, {7, 7, 7}}}, {}));
  const auto line = with_class(els, "polyline", "series");
  REQUIRE(line.size() == 1);
  const auto area = with_class(els, "rect", "plot-area")[0];
  for (const auto& [px, py] : points(line[0])) {
    CHECK(py > attr(area, "y"));
    CHECK(py < attr(area, "y") + attr(area, "height"));
  }
}

TEST_CASE("svg: map and chart stacked in one column-wide figure", "[svg]") {
  // spec/figures.md figures.canvas: 504 units wide, the chart below the map.
  const Grid g = Grid::from_rows_top_first({".#", ".."});
  const auto els = parse_xml(io::svg_map_and_chart(
      g, Cell{0, 0}, Cell{1, 0}, {{"aco", {Cell{0, 0}, Cell{1, 0}}}}, "map",
      {{"aco best", {1, 2, 3}, {3, 2, 1}}}, {"curve", "iteration", "length"}));
  CHECK(with_class(els, "g", "panel").size() == 2);
  CHECK(with_class(els, "rect", "obstacle").size() == 1);
  CHECK(with_class(els, "polyline", "path").size() == 1);
  CHECK(with_class(els, "polyline", "series").size() == 1);
  CHECK(with_class(els, "g", "legend").size() == 2);
  CHECK(with_class(els, "text", "title").size() == 2);
  CHECK(attr(els[0], "width") == Approx(504.0));
  const auto map = with_class(els, "rect", "map")[0];
  const auto area = with_class(els, "rect", "plot-area")[0];
  CHECK(attr(area, "y") > attr(map, "y") + attr(map, "height"));
  CHECK(attr(area, "y") + attr(area, "height") < attr(els[0], "height"));
}
