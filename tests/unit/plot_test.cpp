// The plotting layer (spec/figures.md): text measurement, titles, legends with absent series, log
// axes, the label placer, and the root element every figure gets.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pathref/io/plot.hpp"
#include "pathref/io/svg.hpp"

namespace io = pathref::io;
namespace plot = pathref::io::plot;

namespace {
// Plain string scanning, no std::regex: g++ 12 reports a false -Wmaybe-uninitialized inside
// <regex> under the sanitizer build's -O1, and -Werror makes that a build failure.

/// Every value of attribute `name` in `svg`, in document order.
std::vector<std::string> attr_values(const std::string& svg, const std::string& name) {
  std::vector<std::string> out;
  const std::string key = " " + name + "=\"";
  for (auto at = svg.find(key); at != std::string::npos; at = svg.find(key, at + 1)) {
    const auto begin = at + key.size();
    const auto end = svg.find('"', begin);
    if (end == std::string::npos) break;
    out.push_back(svg.substr(begin, end - begin));
  }
  return out;
}
/// The text of every <text class="CLS" ...>TEXT</text> element (TEXT without '<').
std::vector<std::string> texts_of(const std::string& svg, const std::string& cls) {
  std::vector<std::string> out;
  const std::string open = "<text class=\"" + cls + "\"";
  for (auto at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    const auto gt = svg.find('>', at);
    if (gt == std::string::npos) break;
    const auto lt = svg.find('<', gt);
    if (lt == std::string::npos || svg.compare(lt, 7, "</text>") != 0) continue;
    out.push_back(svg.substr(gt + 1, lt - gt - 1));
  }
  return out;
}
/// The value of attribute `name` of the element whose opening tag contains position `at` (the
/// attribute must lie between `at` and the tag's '>'); "" when it is not there.
std::string attr_of_element(const std::string& svg, std::size_t at, const std::string& name) {
  const auto end = svg.find('>', at);
  const std::string key = " " + name + "=\"";
  const auto p = svg.find(key, at);
  if (p == std::string::npos || end == std::string::npos || p > end) return "";
  const auto begin = p + key.size();
  return svg.substr(begin, svg.find('"', begin) - begin);
}
}  // namespace

TEST_CASE("figures.text-width: characters x size x 0.66, UTF-8 counted by code point", "[figures]") {
  CHECK(plot::glyphs("abc") == 3);
  CHECK(plot::glyphs("η = 1/d") == 7);  // η is two bytes
  CHECK(plot::glyphs("GA — none") == 9);
  CHECK(plot::text_width("abcd", 10.0) == Approx(4 * 10.0 * 0.66));
  CHECK(plot::text_width("") == 0.0);
}

TEST_CASE("figures.title: wrapped to the width, paths shown by their last component", "[figures]") {
  CHECK(plot::strip_paths("../shared/data/maps/a.map 20x20: astar") == "a.map 20x20: astar");
  CHECK(plot::strip_paths("no path here") == "no path here");
  CHECK(plot::strip_paths("dir/") == "dir/");  // nothing after the slash: kept
  CHECK(plot::strip_paths("η = 1/d, km/h") == "η = 1/d, km/h");  // not paths
  CHECK(plot::strip_paths("maps/a.map a/b/c") == "a.map c");
  const auto lines = plot::wrap("one two three four five six seven eight nine ten", 10.0, 60.0);
  REQUIRE(lines.size() > 1);
  for (const auto& l : lines) CHECK(plot::text_width(l, 10.0) <= 60.0);
  CHECK(plot::wrap("", 10.0, 60.0).empty());
  const auto cut = plot::wrap("abcdefghijklmnopqrstuvwxyz", 10.0, 33.0);  // 5 characters a line
  REQUIRE(cut.size() == 6);
  CHECK(cut[0] == "abcde");
  CHECK(cut[5] == "z");
  // A long title with a path: left-aligned at the margin, every line inside the canvas.
  const std::string title(
      "/very/long/folder/name/that/nobody/wants/to/read/rooms40x30.map 40x30: iha, policy strict, seed 12345, "
      "with an explanation that goes on and on and on");
  const std::string svg = io::svg_map(pathref::grid::Grid(4, 3), std::nullopt, std::nullopt, {}, title);
  const auto tl = texts_of(svg, "title");
  REQUIRE(tl.size() >= 2);
  CHECK(tl[0].rfind("rooms40x30.map", 0) == 0);
  for (const auto& l : tl) {
    CHECK(l.find('/') == std::string::npos);
    CHECK(plot::kMargin + plot::text_width(l, plot::kTitleFont) <= plot::kWidth - plot::kMargin + 1e-9);
  }
}

TEST_CASE("figures.font, figures.text: viewBox, font stack, no text below 7 pt at 252 pt", "[figures]") {
  const double inf = std::numeric_limits<double>::infinity();
  for (const std::string& svg :
       {io::svg_line_chart({{"a", {1, 2, 3}, {3, inf, 1}}}, {"t", "x", "y"}),
        io::svg_map(pathref::grid::Grid::from_rows_top_first({"..#", "#.."}), pathref::grid::Cell{0, 1},
                    pathref::grid::Cell{2, 0}, {{"p", {pathref::grid::Cell{0, 1}, pathref::grid::Cell{1, 1}}}}, "m"),
        io::svg_bar_chart({"bars", "%", {"A", "B"}, {{"paper", {}, {50, 60}}, {"pathref", {}, {55, 65}}}, 100.0, 1})}) {
    CHECK(svg.find("viewBox=\"0 0 504.00 ") != std::string::npos);
    CHECK(svg.find("font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\"") != std::string::npos);
    for (const auto& fs : attr_values(svg, "font-size")) CHECK(std::stod(fs) * 252.0 / 504.0 >= 7.0);
  }
}

TEST_CASE("figures.absent, figures.legend: absent series say why, the legend is below the data", "[figures]") {
  const double inf = std::numeric_limits<double>::infinity();
  io::Series ga{"GA", {1, 2}, {inf, inf}};
  ga.absent = "no feasible run";
  const std::string svg = io::svg_line_chart({ga, {"IHA", {1, 2}, {3, 2}}}, {"t", "x", "y"});
  CHECK(svg.find(">GA — no feasible run</text>") != std::string::npos);
  CHECK(svg.find(">IHA</text>") != std::string::npos);
  CHECK(svg.find("data-label=\"GA\"") == std::string::npos);  // nothing drawn for GA
  // The legend starts below the plot area and the x label.
  const auto area_at = svg.find("class=\"plot-area\" x=\"");
  REQUIRE(area_at != std::string::npos);
  const std::string area_y = attr_of_element(svg, area_at, "y"), area_h = attr_of_element(svg, area_at, "height");
  REQUIRE(!area_y.empty());
  REQUIRE(!area_h.empty());
  const double bottom = std::stod(area_y) + std::stod(area_h);
  const auto legend_at = svg.find("<g class=\"legend\">");
  REQUIRE(legend_at != std::string::npos);
  const auto first_text = svg.find("<text x=\"", legend_at);
  REQUIRE(first_text != std::string::npos);
  const std::string legend_y = attr_of_element(svg, first_text, "y");
  REQUIRE(!legend_y.empty());
  CHECK(std::stod(legend_y) > bottom + 14.0);
  // A break in a line gets the caption that explains it.
  io::ChartOptions opt{"t", "x", "y"};
  opt.gap_note = "some run had no path yet";
  const std::string gap = io::svg_line_chart({{"mean", {1, 2, 3}, {3, inf, 1}}}, opt);
  CHECK(gap.find(">some run had no path yet</text>") != std::string::npos);
  CHECK(svg.find("class=\"caption\"") == std::string::npos);  // no break, no caption
}

TEST_CASE("figures.log: a log y axis when one series dwarfs the rest, else linear", "[figures]") {
  CHECK(plot::wants_log(1.0, 20.0));
  CHECK_FALSE(plot::wants_log(1.0, 19.9));
  CHECK_FALSE(plot::wants_log(0.0, 100.0));
  CHECK_FALSE(plot::wants_log(-1.0, 100.0));
  const std::vector<io::Series> s{{"big", {1, 2}, {500, 600}}, {"small", {1, 2}, {10, 12}}};
  const std::string auto_svg = io::svg_line_chart(s, {"t", "x", "length"});
  CHECK(texts_of(auto_svg, "y-label") == std::vector<std::string>{"length (log scale)"});
  io::ChartOptions lin{"t", "x", "length"};
  lin.y_scale = io::YScale::linear;
  CHECK(texts_of(io::svg_line_chart(s, lin), "y-label") == std::vector<std::string>{"length"});
  const plot::Scale ls = plot::log_scale(10.0, 600.0);
  CHECK(ls.lo == 10.0);
  CHECK(ls.hi == 1000.0);
  CHECK(ls.map(100.0, 0.0, 1.0) == Approx(0.5));
  // figures.axes: a linear range is padded, so the minimum is not on the frame.
  const plot::Scale lin_s = plot::linear_scale(30.0, 60.0);
  CHECK(lin_s.lo < 30.0);
  CHECK(lin_s.hi > 60.0);
}

TEST_CASE("figures.labels: labels stay inside the box and off each other, or are dropped", "[figures]") {
  plot::LabelPlacer p(plot::Box{0.0, 0.0, 100.0, 100.0});
  const std::string a = p.place(50.0, 50.0, "12", 3.0, "t", "black");
  const std::string b = p.place(50.0, 50.0, "13", 3.0, "t", "black");
  REQUIRE_FALSE(a.empty());
  REQUIRE_FALSE(b.empty());
  CHECK((attr_values(a, "x") != attr_values(b, "x") || attr_values(a, "y") != attr_values(b, "y")));
  // near the right edge: placed to the left of the point
  const std::string c = p.place(98.0, 20.0, "wide", 3.0, "t", "black");
  REQUIRE_FALSE(c.empty());
  CHECK(std::stod(attr_values(c, "x")[0]) + plot::text_width("wide") <= 100.0);
  // a label wider than the box fits nowhere
  CHECK(p.place(50.0, 50.0, "far too long a label for this box", 3.0, "t", "black").empty());
}

TEST_CASE("figures.time-marks: mark interval and marked samples", "[figures]") {
  CHECK(plot::mark_step(16.6) == 1.0);
  CHECK(plot::mark_step(22.0) == 2.0);
  CHECK(plot::mark_step(1000.0) == 50.0);
  const auto m = plot::mark_samples({0.0, 0.5, 1.0, 1.25, 3.5}, 1.0);
  REQUIRE(m.size() == 3);  // 0 at sample 0, 1 at sample 2, 2 (and 3) at sample 4
  CHECK(m[1] == std::pair<std::size_t, double>{2, 1.0});
  CHECK(m[2] == std::pair<std::size_t, double>{4, 2.0});
}
