#include "pathref/io/builtin_maps.hpp"

#include <algorithm>
#include <string>

namespace pathref::io {

namespace {

// Shi et al. 2022 (doi:10.3389/fbioe.2022.905983) §5.3.2, the 6x6 physical experiment. The text
// gives: 6x6 grid, start S lower left (cell 0), goal T upper right (cell 35), obstacles at four
// positions occupying five cells. The figure is not available: the layout below is OUR
// reconstruction (spec/cli.md#builtin-maps): cells 8, 16, 19-20 (the two-cell obstacle) and 27.
// It blocks the straight diagonal S-T under the strict corner policy only (see the spec).
constexpr std::string_view kShi6x6 =
    "pathref-grid 1\n"
    "# Reconstructed: Shi et al. 2022 sec. 5.3.2 physical experiment (figure unavailable).\n"
    "# Known: 6x6, S lower left, T upper right, 4 obstacles covering 5 cells.\n"
    "# Chosen: obstacle cells 8, 16, 19+20, 27 (index = y*6 + x).\n"
    "name shi6x6\n"
    "size 6 6\n"
    "start 0 0\n"
    "goal 5 5\n"
    "map\n"
    "......\n"
    "...#..\n"
    ".##...\n"
    "....#.\n"
    "..#...\n"
    "......\n";

// pathref's own 20x20 test map (not from any paper or data set). Shortest S-T lengths by corner
// policy (spec/cli.md#builtin-maps): never 52, strict 46 + 3*sqrt(2), one 34 + 9*sqrt(2),
// always 18 + 10*sqrt(2).
constexpr std::string_view kGrid20 =
    "pathref-grid 1\n"
    "# pathref's own design: walls, a one-cell corridor, a spiral room, corner-touching\n"
    "# obstacles and a diagonal squeeze, so that every corner policy gives another path.\n"
    "name grid20\n"
    "size 20 20\n"
    "start 0 0\n"
    "goal 19 19\n"
    "map\n"
    "....#...............\n"
    "....#...............\n"
    "....#...#########...\n"
    "....#...#.......#...\n"
    "....#...#.#####.#...\n"
    "....#.........#.#...\n"
    "....#######.#.#.#...\n"
    "..........#.#.#.....\n"
    "..........#.#.####..\n"
    ".######...#.#.....#.\n"
    "......#...#.######.#\n"
    "......#.....#.......\n"
    ".##...#######.......\n"
    "..#.................\n"
    "..#....#........#...\n"
    "..#.....#......#....\n"
    "..#######.....#.....\n"
    "..............#.....\n"
    ".....#..............\n"
    "....#...............\n";

}  // namespace

const std::vector<BuiltinMap>& builtin_maps() {
  static const std::vector<BuiltinMap> all = [] {
    std::vector<BuiltinMap> v{
        {"grid20", "20x20 test map: walls, a corridor, a spiral room; the corner policy changes the path",
         "pathref's own design (spec/cli.md#builtin-maps)", kGrid20},
        {"shi6x6", "6x6 layout of Shi et al. 2022's physical experiment (sec. 5.3.2), S lower left, T upper right",
         "RECONSTRUCTED from the text of Shi et al. 2022 sec. 5.3.2: the figure is unavailable; "
         "obstacle cells chosen by pathref (spec/cli.md#builtin-maps)",
         kShi6x6},
    };
    std::sort(v.begin(), v.end(), [](const BuiltinMap& a, const BuiltinMap& b) { return a.name < b.name; });
    return v;
  }();
  return all;
}

const BuiltinMap* find_builtin_map(std::string_view name) {
  for (const BuiltinMap& m : builtin_maps())
    if (m.name == name) return &m;
  return nullptr;
}

MapFile load_builtin_map(const BuiltinMap& map) {
  return parse_grid_text(map.text, "builtin:" + std::string(map.name));
}

std::string builtin_map_names() {
  std::string out;
  for (const BuiltinMap& m : builtin_maps()) out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

}  // namespace pathref::io
