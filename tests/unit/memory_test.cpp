// spec: cli.memory (spec/cli.md#memory), the "Memory" paragraphs of shi2022.plan.aco,
// search.astar and shi2022.plan.ga, spec/formats.md#limits (path files)
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <utility>

#include "pathref/core/error.hpp"
#include "pathref/core/memory.hpp"
#include "pathref/io/builtin_maps.hpp"
#include "pathref/io/path_file.hpp"
#include "pathref/planners/ant_colony.hpp"
#include "pathref/planners/genetic.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/planners/search.hpp"

using namespace pathref;
using grid::Cell;
using grid::Grid;
using planners::Json;

namespace {

planners::Request request(const Grid& g, Cell s, Cell t, std::uint64_t max_memory, Json params = Json::object()) {
  planners::Request req;
  req.grid = &g;
  req.start = s;
  req.goal = t;
  req.params = std::move(params);
  req.max_memory = max_memory;
  return req;
}

const planners::Planner& planner(const std::string& name) {
  const planners::Planner* p = planners::find_planner(name);
  REQUIRE(p != nullptr);
  return *p;
}

/// The message of the UsageError `f` throws ("" when it throws none).
template <class F>
std::string usage_message(F&& f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("cli.memory: --max-memory sizes are bytes or K/M/G/T (powers of 1024), at least 1M") {
  CHECK(memory::parse_size("512M") == 512ULL << 20);
  CHECK(memory::parse_size("4G") == 4ULL << 30);
  CHECK(memory::parse_size("4g") == 4ULL << 30);
  CHECK(memory::parse_size("4GiB") == 4ULL << 30);
  CHECK(memory::parse_size("2T") == 2ULL << 40);
  CHECK(memory::parse_size("1048576") == 1048576ULL);
  CHECK(memory::parse_size("1024K") == 1048576ULL);
  for (const char* bad : {"", "G", "4X", "-1", "1.5G", "0", "1K", "1048575", "4G ", " 4G", "99999999999T"})
    CHECK_THROWS_AS(memory::parse_size(bad), UsageError);
  CHECK(usage_message([] { (void)memory::parse_size("12Q"); }).find("--max-memory expects a size") == 0);
  CHECK(memory::default_limit == 4ULL << 30);
}

TEST_CASE("cli.memory: a refusal names the estimate and the limit") {
  const std::string m = usage_message([] { memory::require_within(5368709120ULL, 4294967296ULL, "a run"); });
  CHECK(m.find("a run needs an estimated 5368709120 bytes (5.0 GiB), more than the memory limit of "
               "4294967296 bytes (4.0 GiB)") == 0);
  CHECK(m.find("--max-memory") != std::string::npos);
  CHECK_NOTHROW(memory::require_within(4294967296ULL, 4294967296ULL, "a run"));  // the limit itself fits
  CHECK(memory::times(UINT64_MAX / 2, 3) == UINT64_MAX);  // saturating, never wraps
  CHECK(memory::plus(UINT64_MAX - 1, 5) == UINT64_MAX);
}

TEST_CASE("shi2022.plan.aco memory: aco-classic on an empty 4096x4096 map is refused before allocating, naming the estimate") {
  const Grid g(4096, 4096);  // 16 MB: the only allocation of this test
  const planners::Request req = request(g, Cell{0, 0}, Cell{4095, 4095}, std::uint64_t{1} << 30,
                                        Json{{"ants", 2}, {"iterations", 1}});
  const std::string m = usage_message([&] { (void)planner("aco-classic").run(req); });
  // 4096^2 cells x 84 bytes per cell = 1409286144 bytes
  CHECK(ant_colony::memory_estimate(4096 * 4096) == 1409286144ULL);
  CHECK(m.find("the ant colony on a 4096x4096 grid (84 bytes per cell) needs an estimated 1409286144 bytes "
               "(1.3 GiB), more than the memory limit of 1073741824 bytes (1.0 GiB)") == 0);
  CHECK(planner("aco-classic").bytes_per_cell == ant_colony::bytes_per_cell);
}

TEST_CASE("shi2022.plan.aco memory: the ants' walks are counted as they grow") {
  // The per-cell state fits (64^2 x 84 bytes), the walks do not: a path from corner to corner has
  // at least 64 cells, each held as an 8-byte index in the walk and in the tabu list.
  const Grid g(64, 64);
  const std::uint64_t fixed = ant_colony::memory_estimate(64 * 64);
  const planners::Request req = request(g, Cell{0, 0}, Cell{63, 63}, fixed + 256, Json{{"ants", 2}, {"iterations", 1}});
  const std::string m = usage_message([&] { (void)planner("aco-classic").run(req); });
  CHECK(m.find("the ant colony on a 64x64 grid (84 bytes per cell) and its stored paths so far needs an estimated") == 0);
  // Within the limit the run is the run without a limit: the limit changes no draw and no result.
  const planners::Request roomy = request(g, Cell{0, 0}, Cell{63, 63}, fixed + (std::uint64_t{8} << 20),
                                          Json{{"ants", 3}, {"iterations", 2}});
  const planners::Request unlimited = request(g, Cell{0, 0}, Cell{63, 63}, UINT64_MAX, Json{{"ants", 3}, {"iterations", 2}});
  const planners::Result a = planner("aco-classic").run(roomy);
  const planners::Result b = planner("aco-classic").run(unlimited);
  CHECK(a.found == b.found);
  CHECK(a.path == b.path);
  CHECK(a.extra == b.extra);
}

TEST_CASE("search.astar memory: astar, dijkstra and astar-han refuse a grid whose 20 bytes per cell exceed the limit") {
  const Grid g(2048, 2048);  // 2048^2 x 20 = 83886080 bytes
  for (const char* algo : {"astar", "dijkstra", "astar-han", "astar-kinematic"}) {
    INFO(algo);
    const planners::Request req = request(g, Cell{0, 0}, Cell{2047, 2047}, std::uint64_t{64} << 20);
    const std::string m = usage_message([&] { (void)planner(algo).run(req); });
    CHECK(m.find(std::string(algo) + " on a 2048x2048 grid (20 bytes per cell) needs an estimated 83886080 bytes "
                 "(80.0 MiB), more than the memory limit of 67108864 bytes (64.0 MiB)") == 0);
    CHECK(planner(algo).bytes_per_cell == search::bytes_per_cell);
  }
  // A* at the cell limit: 2^28 cells x 20 bytes = 5 GiB, more than the default 4 GiB: the memory
  // estimate, not --max-cells, decides (spec/cli.md#memory).
  CHECK(search::memory_estimate(grid::Grid::max_cells) > memory::default_limit);
}

TEST_CASE("shi2022.plan.ga memory: the stored paths are counted from the initial population on") {
  const Grid g(20, 20);
  const planners::Request req = request(g, Cell{0, 0}, Cell{19, 19}, 2000);
  const std::string m = usage_message([&] { (void)planner("ga").run(req); });
  CHECK(m.find("the GA on a 20x20 grid, with its stored paths of the initial population needs an estimated") == 0);
  CHECK(genetic::memory_estimate(400, {}) == 800);
}

TEST_CASE("formats.path-limits: a path text of 2^24 + 1 nodes is refused at the first node too many, nothing stored") {
  // node format: one number per line; 2^24 + 1 lines of "7"
  std::string text((io::max_path_nodes + 1) * 2, '\n');
  for (std::size_t i = 0; i < text.size(); i += 2) text[i] = '7';
  try {
    (void)io::parse_path_text(text, "big.txt", io::PathFormat::node, false);
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(e.line() == io::max_path_nodes + 1);
    CHECK(e.column() == 1);
    CHECK(std::string(e.what()).find("a path has more than 16777216 nodes") != std::string::npos);
  }
  // The same reader still reads what it read before (rows split by ';', comments, xy detection).
  const auto recs = io::parse_path_text("# a path\n1 2 % c\n[3, 4; 5 6]\n", "p.txt", io::PathFormat::automatic, false);
  REQUIRE(recs.size() == 1);
  CHECK(recs[0].format == io::PathFormat::xy);
  CHECK(recs[0].numbers == std::vector<std::int64_t>{1, 2, 3, 4, 5, 6});
  try {
    (void)io::parse_path_text("1 2\n3 4 5\n", "p.txt", io::PathFormat::xy, false);
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(e.line() == 2);
    CHECK(e.column() == 1);
    CHECK(std::string(e.what()).find("expected two numbers (x y) on this line, got 3") != std::string::npos);
  }
}
