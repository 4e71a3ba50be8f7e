// spec: reproduce.stats, reproduce.judge, reproduce.quick, reproduce.curves, reproduce.run,
// reproduce.shi2022.maps, reproduce.han.maps, reproduce.han.dynamic (spec/reproduce.md)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/reproduce/han.hpp"
#include "pathref/reproduce/report.hpp"
#include "pathref/reproduce/runs.hpp"
#include "pathref/reproduce/shi2022.hpp"
#include "pathref/reproduce/stats.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/sim/motion.hpp"

using namespace pathref;
using V = std::vector<double>;

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
}

TEST_CASE("reproduce.stats: mean and sample std, hand-computed", "[reproduce]") {
  // 2,4,4,4,5,5,7,9: sum 40, mean 5; squared deviations 9+1+1+1+0+0+4+16 = 32;
  // sample variance 32/7 (population 32/8 = 4).
  const V a{2, 4, 4, 4, 5, 5, 7, 9};
  CHECK(reproduce::mean(a) == 5.0);
  CHECK(reproduce::sample_std(a) == std::sqrt(32.0 / 7.0));
  CHECK(reproduce::sample_std(a) != 2.0);  // not the population std
  // 1,2,3,4: mean 2.5; deviations 2.25+0.25+0.25+2.25 = 5; s = sqrt(5/3)
  const V b{1, 2, 3, 4};
  CHECK(reproduce::mean(b) == 2.5);
  CHECK(reproduce::sample_std(b) == std::sqrt(5.0 / 3.0));
  CHECK(reproduce::sample_std(V{7, 7, 7}) == 0.0);
  CHECK(reproduce::minimum(V{3, -1, 2}) == -1.0);
  CHECK(reproduce::maximum(V{3, -1, 2}) == 3.0);
  // the Shi optima: 10 + 14 sqrt2 and 16 + 11 sqrt2; mean of the two = 13 + 12.5 sqrt2 (exact sums differ
  // by rounding only)
  const double c = 10 + 14 * std::numbers::sqrt2, d = 16 + 11 * std::numbers::sqrt2;
  CHECK(reproduce::mean(V{c, d}) == (c + d) / 2);
  CHECK(reproduce::sample_std(V{c, d}) == Approx(std::fabs(c - d) / std::numbers::sqrt2).epsilon(1e-15));
}

TEST_CASE("reproduce.stats: domain and summaries", "[reproduce]") {
  CHECK_THROWS_AS(reproduce::mean(V{}), DomainError);
  CHECK_THROWS_AS(reproduce::sample_std(V{1.0}), DomainError);
  CHECK_THROWS_AS(reproduce::mean(V{1.0, std::nan("")}), DomainError);
  CHECK_THROWS_AS(reproduce::sample_std(V{1.0, inf}), DomainError);
  CHECK_THROWS_AS(reproduce::minimum(V{}), DomainError);
  const auto s0 = reproduce::summarize(V{});
  CHECK(s0.n == 0);
  CHECK_FALSE(s0.mean.has_value());
  const auto s1 = reproduce::summarize(V{4.0});
  CHECK(s1.n == 1);
  CHECK(*s1.mean == 4.0);
  CHECK_FALSE(s1.std.has_value());
  CHECK(*s1.min == 4.0);
  const auto s3 = reproduce::summarize(V{1, 2, 6});
  CHECK(*s3.mean == 3.0);
  CHECK(*s3.std == std::sqrt(7.0));  // (4 + 1 + 9) / 2 = 7
  CHECK(*s3.max == 6.0);
}

TEST_CASE("reproduce.judge: reductions, Welch t, printed numbers", "[reproduce]") {
  CHECK(reproduce::reduction_percent(8, 2) == 75.0);
  CHECK(reproduce::reduction_percent(24, 13) == Approx(45.8333333333).epsilon(1e-10));
  CHECK(reproduce::reduction_percent(10, 12) == -20.0);
  CHECK_THROWS_AS(reproduce::reduction_percent(0, 1), DomainError);
  // a = 1,2,3 (mean 2, s 1), b = 4,5,6 (mean 5, s 1): t = -3 / sqrt(1/3 + 1/3)
  const auto t = reproduce::welch_t(V{1, 2, 3}, V{4, 5, 6});
  REQUIRE(t.has_value());
  CHECK(*t == Approx(-3.0 / std::sqrt(2.0 / 3.0)).epsilon(1e-14));
  CHECK_FALSE(reproduce::welch_t(V{1, 1}, V{2, 2}).has_value());
  CHECK_THROWS_AS(reproduce::welch_t(V{1}, V{2, 3}), DomainError);

  CHECK(reproduce::printed_decimals("29.8") == 1);
  CHECK(reproduce::printed_decimals("31.56") == 2);
  CHECK(reproduce::printed_decimals("26") == 0);
  CHECK_THROWS_AS(reproduce::printed_decimals("2."), DomainError);
  CHECK_THROWS_AS(reproduce::printed_decimals(".5"), DomainError);
  CHECK_THROWS_AS(reproduce::printed_decimals("1e3"), DomainError);
  CHECK(reproduce::matches_printed(10 + 14 * std::numbers::sqrt2, "29.8"));
  CHECK(reproduce::matches_printed(16 + 11 * std::numbers::sqrt2, "31.56"));
  CHECK_FALSE(reproduce::matches_printed(30.384776310850242, "29.8"));  // 8 + 16 sqrt2 - 0.24...
  CHECK(reproduce::matches_printed(13.4, "13"));
  CHECK_FALSE(reproduce::matches_printed(13.6, "13"));
  CHECK(reproduce::fixed(2.0, 2) == "2.00");
  CHECK(reproduce::fixed(0.375, 2) == "0.38");  // exact binary tie: to even
  CHECK(reproduce::fixed(0.125, 2) == "0.12");  // exact binary tie: to even (as Python's format)

  CHECK(reproduce::judge_about_percent(45.8, 46) == reproduce::Verdict::holds);
  CHECK(reproduce::judge_about_percent(36.0, 46) == reproduce::Verdict::holds);  // boundary
  CHECK(reproduce::judge_about_percent(35.9, 46) == reproduce::Verdict::fails);
  CHECK(reproduce::judge_about_percent(-5.0, 21) == reproduce::Verdict::fails);
  CHECK(reproduce::to_string(reproduce::Verdict::fails) == "does not hold");
}

TEST_CASE("reproduce.quick: overrides only the named integer parameters, only downwards", "[reproduce]") {
  const reproduce::Json defaults{{"ants", 50},       {"iterations", 100}, {"alpha", 1.0},
                                 {"aco_ants", 50},   {"aco_iterations", 100}, {"population", 200},
                                 {"generations", 50}, {"rho", 0.9},        {"ants_x", 99},
                                 {"heuristic", "octile"}, {"population2", 5}};
  const reproduce::Json q = reproduce::quick_overrides(defaults);
  CHECK(q == reproduce::Json{{"ants", 8},        {"iterations", 10},  {"aco_ants", 8},
                             {"aco_iterations", 10}, {"population", 20}, {"generations", 10}});
  CHECK(reproduce::quick_overrides(reproduce::Json{{"ants", 5}, {"iterations", 10}}).empty());
  CHECK(reproduce::quick_overrides(reproduce::Json{{"ants", 50.0}}).empty());  // not an integer
}

TEST_CASE("reproduce.curves: pointwise mean where every run is finite", "[reproduce]") {
  const auto m = reproduce::mean_curve({V{inf, 3, 2}, V{4, 3, 1}});
  REQUIRE(m.size() == 3);
  CHECK(std::isinf(m[0]));
  CHECK(m[1] == 3.0);
  CHECK(m[2] == 1.5);
  const auto u = reproduce::mean_curve({V{1, 2}, V{3}});
  REQUIRE(u.size() == 2);
  CHECK(u[0] == 2.0);
  CHECK(std::isinf(u[1]));  // the shorter run has no value there
  CHECK(reproduce::mean_curve({}).empty());
}

TEST_CASE("reproduce.stats: best run is shortest, then fewest turns, then lowest seed", "[reproduce]") {
  std::vector<reproduce::RunRecord> runs(4);
  runs[0].seed = 1, runs[0].found = false;
  runs[1].seed = 2, runs[1].found = true, runs[1].length = 5.0, runs[1].turns = 3;
  runs[2].seed = 3, runs[2].found = true, runs[2].length = 5.0, runs[2].turns = 1;
  runs[3].seed = 4, runs[3].found = true, runs[3].length = 6.0, runs[3].turns = 0;
  CHECK(reproduce::best_run(runs) == std::optional<std::size_t>{2});
  runs[1].turns = 1;
  CHECK(reproduce::best_run(runs) == std::optional<std::size_t>{1});
  CHECK_FALSE(reproduce::best_run(std::vector<reproduce::RunRecord>(2)).has_value());
}

TEST_CASE("reproduce.run: registered planners by name, missing ones reported", "[reproduce]") {
  // 3x3 open grid: the shortest (0,0) -> (2,2) path is the diagonal, 2 sqrt2, no turn.
  const grid::Grid g(3, 3);
  const auto missing = reproduce::run_series("no-such-planner", reproduce::Json::object(), g, {0, 0}, {2, 2},
                                             grid::CornerPolicy::strict, 1, 5, false, {}, "test");
  CHECK(missing.at("available") == false);
  CHECK(missing.at("reason") == "planner 'no-such-planner' is not available in this build");
  const auto d = reproduce::run_series("dijkstra", reproduce::Json::object(), g, {0, 0}, {2, 2},
                                       grid::CornerPolicy::strict, 7, 2, false, {}, "test");
  REQUIRE(d.at("available") == true);
  CHECK(d.at("seeds") == reproduce::Json::array({7, 8}));
  CHECK(d.at("summary").at("found") == 2);
  CHECK(d.at("summary").at("valid") == 2);
  CHECK(d.at("summary").at("length").at("min").get<double>() == 2 * std::numbers::sqrt2);
  CHECK(d.at("summary").at("length").at("std").get<double>() == 0.0);
  CHECK(d.at("summary").at("turns").at("max").get<double>() == 0.0);
  CHECK(d.at("best").at("path") == reproduce::Json::parse("[[0,0],[1,1],[2,2]]"));
  CHECK(reproduce::run_values(d, "length") == V{2 * std::numbers::sqrt2, 2 * std::numbers::sqrt2});
  // an L-shaped corridor: one turn, length 4
  const grid::Grid l = grid::Grid::from_rows_top_first({"..#", "#.#", "#.."});  // top row first
  const auto t = reproduce::run_series("dijkstra", reproduce::Json::object(), l, {0, 2}, {2, 0},
                                       grid::CornerPolicy::strict, 1, 1, false, {}, "test");
  CHECK(t.at("summary").at("length").at("min").get<double>() == 4.0);
  CHECK(t.at("summary").at("turns").at("min").get<double>() == 2.0);
}

TEST_CASE("reproduce.shi2022.maps: MATLAB endpoints and blocked endpoints", "[reproduce]") {
  const grid::Grid g(20, 10);
  const auto [s, e] = reproduce::shi2022_endpoints(g, reproduce::Orientation::file);
  CHECK(s == grid::Cell{0, 9});
  CHECK(e == grid::Cell{19, 0});
  const auto [ps, pe] = reproduce::shi2022_endpoints(g, reproduce::Orientation::paper);
  CHECK(ps == grid::Cell{0, 0});
  CHECK(pe == grid::Cell{19, 9});
  // paper orientation: the file's first row (top as read) becomes y = 0
  const grid::Grid f = grid::Grid::from_rows_top_first({"#..", "...", "..#"});
  const grid::Grid p = reproduce::oriented(f, reproduce::Orientation::paper);
  CHECK(p.blocked(grid::Cell{0, 0}));
  CHECK(p.blocked(grid::Cell{2, 2}));
  CHECK_FALSE(p.blocked(grid::Cell{0, 2}));
  CHECK(reproduce::oriented(f, reproduce::Orientation::file) == f);
  CHECK_THROWS_AS(reproduce::parse_orientation("up"), UsageError);
  reproduce::ShiConfig cfg;
  cfg.simple = reproduce::ProtocolMap{"blocked.txt", grid::Grid::from_rows_top_first({"#.", ".."})};
  cfg.complex = reproduce::ProtocolMap{"free.txt", grid::Grid(2, 2)};
  cfg.runs = 1;
  CHECK_THROWS_WITH(reproduce::run_shi2022(cfg),
                    "start (0, 0) is a blocked cell of the simple map 'blocked.txt'");
  cfg.orientation = reproduce::Orientation::file;
  cfg.simple = reproduce::ProtocolMap{"blocked.txt", grid::Grid::from_rows_top_first({"..", ".#"})};
  CHECK_THROWS_WITH(reproduce::run_shi2022(cfg),
                    "goal (1, 0) is a blocked cell of the simple map 'blocked.txt'");
}

TEST_CASE("reproduce.han.maps: edges and ratios", "[reproduce]") {
  const auto e = reproduce::han_protocol_edges();
  REQUIRE(e.size() == 19);
  CHECK(e.front() == 10);
  CHECK(e.back() == 100);
  CHECK(e[1] == 15);
  CHECK(reproduce::han_ratio(0, 3) == 0.2);
  CHECK(reproduce::han_ratio(1, 3) == 0.45);
  CHECK(reproduce::han_ratio(2, 3) == 0.7);
  CHECK(reproduce::han_ratio(0, 1) == 0.45);
  CHECK_THROWS_AS(reproduce::han_ratio(3, 3), DomainError);
}

TEST_CASE("reproduce.han.dynamic: the two scripted obstacles meet the path when the robot would", "[reproduce]") {
  // A straight path along y = 0.5 from x = 0.5 to x = 20.5: arc s lies at (0.5 + s, 0.5), the
  // direction is +x. The draws of seed 7, in the spec's order, give f1, side, v1, f2, v2.
  std::vector<grid::Cell> path;
  for (std::int64_t x = 0; x <= 20; ++x) path.push_back(grid::Cell{x, 0});
  rng::Stream st(7);
  const double f1 = 0.2 + (0.6 * st.next_double());
  const double side = st.next_double() < 0.5 ? 1.0 : -1.0;
  const double v1 = 0.25 + (0.75 * st.next_double());
  const double f2 = 0.5 + (0.4 * st.next_double());
  const double v2 = 0.25 + (0.75 * st.next_double());
  const auto o = reproduce::han_dynamic_obstacles(path, 7);
  REQUIRE(o.size() == 2);
  const double T1 = sim::ramp_cruise_time(f1 * 20.0, 1.0, 1.0);
  const double T2 = sim::ramp_cruise_time(f2 * 20.0, 1.0, 1.0);
  // O1 crosses perpendicularly (velocity (0, side v1)) and is at (0.5 + f1 L, 0.5) at T1.
  CHECK(o[0].velocity.x == 0.0);
  CHECK(o[0].velocity.y == side * v1);
  CHECK(o[0].position.x + o[0].velocity.x * T1 == Approx(0.5 + f1 * 20.0).margin(1e-12));
  CHECK(o[0].position.y + o[0].velocity.y * T1 == Approx(0.5).margin(1e-12));
  // O2 comes head-on (velocity (-v2, 0)) and is at (0.5 + f2 L, 0.5) at T2.
  CHECK(o[1].velocity.x == -v2);
  CHECK(o[1].velocity.y == 0.0);
  CHECK(o[1].position.x + o[1].velocity.x * T2 == Approx(0.5 + f2 * 20.0).margin(1e-12));
  CHECK(o[1].position.y == 0.5);
  CHECK(o[0].radius == 0.3);
  CHECK(f1 >= 0.2);
  CHECK(f2 >= 0.5);
  CHECK_THROWS_AS(reproduce::han_dynamic_obstacles(std::vector<grid::Cell>{grid::Cell{0, 0}}, 1), DomainError);
}

TEST_CASE("reproduce.markdown: numbers come from the document", "[reproduce]") {
  const reproduce::Json results = reproduce::Json::parse(R"({
    "x": {"available": true, "summary": {"runs": 3, "found": 2, "valid": 2,
      "length": {"min": 29.79898987322334, "mean": 30.5, "std": null},
      "turns": {"mean": 2.5, "std": 0.7071067811865476, "min": 2},
      "converged_at": {"mean": 13.0, "std": 1.0}, "converged_at_whole_curve": {"mean": 113.0},
      "drive_time_s": {"mean": 21.125}, "wall_ms": {"mean": 4.25}}},
    "y": {"available": false, "reason": "planner 'y' is not available in this build"}})");
  const std::string md = reproduce::md_results_table(results, {"x", "y", "z"}, "k");
  CHECK(md.find("<!-- results:k -->") == 0);
  CHECK(md.find("| `x` | 3 | 2 | 2 | 29.7990 | 30.5000 | — | 2.50 | 0.71 | 2 | 13.00 | 1.00 | 113.00 | 21.12 | 4.2 |") !=
        std::string::npos);
  CHECK(md.find("| `y` | not available in this build |") != std::string::npos);
  CHECK(md.find("| `z` | not available in this build |") != std::string::npos);
}

TEST_CASE("reproduce.markdown: verdict summary lists the ids per verdict", "[reproduce]") {
  reproduce::Claim a{"A.1", "t", "s", "1", "1", "r", reproduce::Verdict::holds, ""};
  reproduce::Claim b{"B.2", "t", "s", "1", "2", "r", reproduce::Verdict::fails, ""};
  reproduce::Claim c{"C.3", "t", "s", "1", "—", "", reproduce::Verdict::untestable, "why"};
  reproduce::Claim d{"D.4", "t", "s", "1", "1", "r", reproduce::Verdict::holds, ""};
  const reproduce::Json claims = reproduce::Json::array(
      {reproduce::claim_json(a), reproduce::claim_json(b), reproduce::claim_json(c), reproduce::claim_json(d)});
  CHECK(reproduce::md_verdict_summary(claims) ==
        "4 claims (verdicts on the protocol's n runs): 2 hold, 1 do not hold, 0 not significant, 0 inconclusive, "
        "1 cannot be tested.\n\n- holds: A.1, D.4\n- does not hold: B.2\n- not significant: —\n- inconclusive: —\n"
        "- cannot be tested: C.3\n- verdict changes between n and 2n runs: none\n");
  const std::string table = reproduce::md_claims(claims);
  CHECK(table.find("| B.2 | t | s | 1 | 2 | **does not hold** | — | r |") != std::string::npos);
  CHECK(table.find("| C.3 | t | s | 1 | — | cannot be tested | — | why |") != std::string::npos);
  // a verdict with its direction, at n and at 2n, and a reading it depends on
  reproduce::Claim e{"E.5", "t", "s", "29.8", "x", "r", reproduce::Verdict::inconclusive, ""};
  e.direction = reproduce::Direction::pathref_better;
  e.verdict_2n = reproduce::Verdict::fails;
  e.direction_2n = reproduce::Direction::pathref_better;
  e.depends_on = {"reading k (alternative: E.5k)"};
  const reproduce::Json ej = reproduce::claim_json(e);
  CHECK(ej["verdict_text"] == "inconclusive — pathref better");
  CHECK(ej["at_2n"]["verdict_text"] == "does not hold — pathref better");
  CHECK(ej["changed"] == true);
  CHECK(ej["change_note"].get<std::string>().find("more runs narrowed") != std::string::npos);
  const std::string te = reproduce::md_claims(reproduce::Json::array({ej}));
  CHECK(te.find("| E.5 † | t | s | 29.8 | x | inconclusive — pathref better | **changed:** does not hold — pathref "
                "better | r; † depends on reading k (alternative: E.5k) |") != std::string::npos);
}

TEST_CASE("reproduce.shi2022.readings: planners re-run under each reading, claims re-judged", "[reproduce]") {
  reproduce::ShiConfig cfg;
  // 6x6 maps with one wall gap: the section 4.2 initialisation has feasible chains on both.
  const grid::Grid g = grid::Grid::from_rows_top_first({"......", "......", "##.###", "......", "......", "......"});
  cfg.simple = reproduce::ProtocolMap{"a.txt", g};
  cfg.complex = reproduce::ProtocolMap{"b.txt", g};
  cfg.runs = 2;
  cfg.quick = true;
  const reproduce::Json doc = reproduce::run_shi2022(cfg);
  for (const auto& r : reproduce::shi2022_readings())
    for (const auto& p : r.planners)
      for (const char* key : {"simple", "complex"}) {
        const reproduce::Json& s = doc.at("results").at(key).at(p + "@" + r.key);
        INFO(p << "@" << r.key);
        REQUIRE(s.at("available").get<bool>());
        for (auto it = r.params.begin(); it != r.params.end(); ++it)
          CHECK(s.at("params_used").at(it.key()) == it.value());
        CHECK(s.at("summary").at("runs") == 4);  // 2n runs (reproduce.judge)
      }
  std::set<std::string> ids;
  for (const reproduce::Json& c : doc.at("reading_claims")) ids.insert(c.at("id").get<std::string>());
  // blocked: the GA columns and IHA's (T3.1 = GA optimal length, T3.3 = IHA's), never the
  // traditional hybrid's (T3.2)
  CHECK(ids.count("T3.1b") == 1);
  CHECK(ids.count("T4.10b") == 1);
  CHECK(ids.count("E.2b") == 1);
  CHECK(ids.count("T3.3b") == 1);
  CHECK(ids.count("T3.2b") == 0);
  CHECK(ids.count("M.1b") == 0);
  // reject: the same planners
  CHECK(ids.count("T3.1r") == 1);
  CHECK(ids.count("T3.3r") == 1);
  CHECK(ids.count("T3.2r") == 0);
  // pernode: the weighted-fitness planners only (IGA, IGA*, IHA), not the single GA's column
  CHECK(ids.count("T3.3p") == 1);
  CHECK(ids.count("T3.1p") == 0);
  CHECK(ids.count("T3.2p") == 0);
  // length: both hybrids' columns, and the reductions that read IHA
  CHECK(ids.count("T3.2l") == 1);
  CHECK(ids.count("T3.3l") == 1);
  CHECK(ids.count("R.4l") == 1);
  CHECK(ids.count("T3.1l") == 0);
  CHECK(ids.count("E.1l") == 0);  // IACO vs IACO*: no hybrid
  // invlen: IHA only
  CHECK(ids.count("T3.3f") == 1);
  CHECK(ids.count("T3.2f") == 0);
  CHECK(doc.at("protocol").at("readings").size() == reproduce::shi2022_readings().size());
  const std::string md = reproduce::shi2022_markdown(doc, "fig", "r.json");
  CHECK(md.find("## Readings that change the outcome") != std::string::npos);
  CHECK(md.find("<!-- results:complex-blocked -->") != std::string::npos);
  CHECK(md.find("<!-- results:complex-pernode -->") != std::string::npos);
}

TEST_CASE("reproduce.judge: value, reduction and comparison claims at n and 2n", "[reproduce]") {
  const V n{29.79899, 29.79899, 29.79899, 29.79899};
  const V two{29.79899, 29.79899, 29.79899, 29.79899, 29.79899, 29.79899, 29.79899, 29.79899};
  reproduce::Claim c;
  reproduce::value_claim(c, n, two, 29.8, reproduce::Quantity::length, reproduce::Sense::lower_is_better,
                         reproduce::BootStatistic::mean, {}, 4);
  CHECK(c.verdict == reproduce::Verdict::holds);
  REQUIRE(c.verdict_2n.has_value());
  CHECK(*c.verdict_2n == reproduce::Verdict::holds);
  CHECK(c.ours == "mean 29.7990 [29.7990, 29.7990]");
  CHECK(c.statistics["n"]["margin"].get<double>() == 0.01 * 29.8);
  reproduce::Claim one;
  reproduce::value_claim(one, V{30.0}, V{}, 29.8, reproduce::Quantity::length, reproduce::Sense::lower_is_better,
                         reproduce::BootStatistic::mean, {}, 4);
  CHECK(one.verdict == reproduce::Verdict::untestable);
  reproduce::Claim r;  // IHA 2 turns against GA 17: reduction 88 %
  reproduce::reduction_claim(r, V{2, 2, 2, 2}, V{17, 17, 17, 17}, V{}, V{}, 88, {});
  CHECK(r.verdict == reproduce::Verdict::holds);  // 100 (17 - 2) / 17 = 88.2
  reproduce::Claim worse;
  reproduce::reduction_claim(worse, V{10, 10, 10}, V{17, 17, 17}, V{}, V{}, 88, {});
  CHECK(worse.verdict == reproduce::Verdict::fails);
  CHECK(worse.direction == reproduce::Direction::pathref_worse);
  reproduce::Claim cmp;
  reproduce::comparison_claim(cmp, V{1, 2, 3, 4, 5, 6, 7, 8}, V{11, 12, 13, 14, 15, 16, 17, 18}, V{}, V{},
                              reproduce::Claimed::a_less, 2);
  CHECK(cmp.verdict == reproduce::Verdict::holds);
  CHECK(cmp.statistics["n"]["test"] == "Mann-Whitney U (two-sided)");
  CHECK_FALSE(cmp.verdict_2n.has_value());
  CHECK(reproduce::verdict_change_note(reproduce::Verdict::holds, reproduce::Direction::none, reproduce::Verdict::holds,
                                       reproduce::Direction::none)
            .empty());
}

TEST_CASE("reproduce.execution: --jobs, emitted jobs and merged records give the same series", "[reproduce]") {
  const grid::Grid g = grid::Grid::from_rows_top_first({"......", ".##...", "......", "...#..", "......", "......"});
  const auto series = [&] {
    return reproduce::run_series("aco", reproduce::Json::object(), g, {0, 0}, {5, 5}, grid::CornerPolicy::strict, 3, 4,
                                 true, {}, "test");
  };
  const auto strip = [](reproduce::Json j) {
    for (auto& r : j["runs"]) r.erase("wall_ms");
    j["summary"].erase("wall_ms");
    return j;
  };
  const reproduce::Json one = series();
  reproduce::Json two;
  {
    reproduce::Execution ex;
    ex.jobs = 2;
    const reproduce::ExecutionScope scope(ex);
    two = series();
  }
  CHECK(strip(one) == strip(two));
  std::vector<reproduce::Json> jobs;
  {
    reproduce::Execution ex;
    ex.mode = reproduce::Execution::Mode::emit;
    ex.emitted = &jobs;
    const reproduce::ExecutionScope scope(ex);
    (void)series();
  }
  REQUIRE(jobs.size() == 4);
  std::map<std::string, reproduce::Json> merged;
  for (const auto& job : jobs) {
    const reproduce::Json out = reproduce::run_job(job);
    CHECK(out["key"] == job["key"]);
    // lossless: the record survives a text round trip
    const reproduce::Json back = reproduce::Json::parse(out.dump());
    CHECK(reproduce::record_to_json_full(reproduce::record_from_json_full(back["record"])) == back["record"]);
    merged.emplace(out["key"].get<std::string>(), back["record"]);
  }
  {
    reproduce::Execution ex;
    ex.mode = reproduce::Execution::Mode::merge;
    ex.merged = &merged;
    const reproduce::ExecutionScope scope(ex);
    CHECK(strip(series()) == strip(one));
    merged.erase(merged.begin());
    CHECK_THROWS_AS(series(), UsageError);
  }
  reproduce::Json bad = jobs[0];
  bad["seed"] = 99;
  CHECK_THROWS_AS(reproduce::run_job(bad), UsageError);
  // parallel_for visits every index once
  std::vector<int> seen(100, 0);
  {
    reproduce::Execution ex;
    ex.jobs = 3;
    const reproduce::ExecutionScope scope(ex);
    reproduce::parallel_for(seen.size(), [&](std::size_t i) { seen[i] += 1; });
  }
  CHECK(std::all_of(seen.begin(), seen.end(), [](int v) { return v == 1; }));
}
