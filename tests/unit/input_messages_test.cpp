// Issue 27, "messages that break the promise": every refusal of bad input names the file, the
// line and column (or the JSON pointer) and what was expected, with no library text and no raw
// control or non-ASCII byte (spec/formats.md message tables, spec/cin2021-ml.md#model-file,
// spec/cli.md#plan-json, spec/han-sim.md scenario format).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/io/model_file.hpp"
#include "pathref/io/wall_following.hpp"
#include "pathref/core/error.hpp"
#include "pathref/io/grid_text.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/path_file.hpp"
#include "pathref/io/plan_json.hpp"
#include "pathref/io/ros_map.hpp"
#include "pathref/ml/classifier.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/io/trace_file.hpp"
#include "pathref/rng/trace.hpp"
#include "pathref/sim/fused.hpp"
#include "pathref/sim/simulate.hpp"

using namespace pathref;
using Json = nlohmann::json;

namespace {

/// The message of the pathref::Error `f` throws ("(no error)" when none; any other exception
/// propagates and fails the test).
template <class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

/// True when `s` holds no control byte, DEL or byte >= 0x80 (what io::printable guarantees).
bool printable_ascii(const std::string& s) {
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u >= 0x7F) return false;
  }
  return true;
}

ml::Dataset small_data() {
  ml::Dataset d;
  d.features = 2;
  d.classes = 4;
  d.x = {0.5, 1, 1, 0.25, 2, 2, 3, 1, 0.75, 3, 2.5, 0.5, 1.5, 1.5, 4, 4};
  d.y = {0, 1, 2, 3, 0, 1, 2, 3};
  return d;
}

std::string model_text(ml::Kind kind) {
  ml::Params p;
  p.k = 3;
  p.forest.trees = 2;
  return io::to_json(ml::train(kind, small_data(), p)).dump();
}

/// Every JSON pointer of `j` (objects, arrays and leaves), root excluded.
void pointers(const Json& j, const std::string& at, std::vector<std::string>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      out.push_back(at + "/" + k);
      pointers(v, at + "/" + k, out);
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      out.push_back(at + "/" + std::to_string(i));
      pointers(j[i], at + "/" + std::to_string(i), out);
    }
  }
}

}  // namespace

TEST_CASE("formats.model: a model file's refusals are located and never library text", "[cin2021-ml][formats]") {
  // version 2 at its value, with the line and column of the text
  const std::string gnb = model_text(ml::Kind::gnb);
  {
    Json j = Json::parse(gnb);
    j["version"] = 2;
    const std::string text = j.dump(1);
    const std::string m = message_of([&] { (void)io::parse_model(text, "m.json"); });
    CHECK(m.find("m.json:") == 0);
    CHECK(m.find(": /version: expected 1 (this reader reads model file version 1), got 2") != std::string::npos);
    CHECK(m.find("m.json:1:1:") == std::string::npos);  // not at 1:1 as before issue 27
  }
  // a string where an array is expected, a missing key of a tree (the two library texts of issue 27)
  {
    Json j = Json::parse(gnb);
    j["model"]["mean"] = "abc";
    CHECK(message_of([&] { (void)io::parse_model(j.dump(), "m.json"); })
              .find(": /model/mean: expected an array, got a string") != std::string::npos);
    Json t = Json::parse(model_text(ml::Kind::tree));
    t["model"].erase("feature");
    CHECK(message_of([&] { (void)io::parse_model(t.dump(), "t.json"); })
              .find(": /model: missing key \"feature\" (expected one feature index per node, -1 at a leaf)") !=
          std::string::npos);
    Json r = Json::parse(model_text(ml::Kind::rf));
    r["model"]["trees"][1]["left"] = Json::array({1});
    CHECK(message_of([&] { (void)io::parse_model(r.dump(), "r.json"); })
              .find(": /model/trees/1/left: expected ") != std::string::npos);
  }
  // a shape that contradicts features and classes, and a value out of its range
  {
    Json j = Json::parse(model_text(ml::Kind::knn));
    j["model"]["y"][0] = 7;
    CHECK(message_of([&] { (void)io::model_from_json(j, "k.json"); }) ==
          "k.json: /model/y/0: expected an integer in [0, 3], got 7");
    j = Json::parse(model_text(ml::Kind::knn));
    j["model"]["x"].push_back(1.0);
    CHECK(message_of([&] { (void)io::model_from_json(j, "k.json"); }) ==
          "k.json: /model/x: expected 16 values (rows of /model/y * features), got 17");
  }
  // Every value of every kind's file replaced by a string, or removed: accepted or a located
  // ParseError, never another exception (nlohmann's type_error / out_of_range escaped before).
  for (const ml::Kind kind : {ml::Kind::mnb, ml::Kind::gnb, ml::Kind::svm, ml::Kind::knn, ml::Kind::rf, ml::Kind::tree}) {
    const Json base = Json::parse(model_text(kind));
    REQUIRE_NOTHROW(io::parse_model(base.dump(), "m.json"));
    std::vector<std::string> ptrs;
    pointers(base, "", ptrs);
    for (const std::string& p : ptrs) {
      for (int mode = 0; mode < 2; ++mode) {
        Json j = base;
        const Json::json_pointer jp(p);
        if (mode == 0) {
          j[jp] = "\x01x";
        } else if (j[jp.parent_pointer()].is_object()) {
          j[jp.parent_pointer()].erase(jp.back());
        } else {
          continue;
        }
        INFO(ml::to_string(kind) << " " << p << (mode == 0 ? " := string" : " removed"));
        try {
          (void)io::parse_model(j.dump(), "m.json");
        } catch (const ParseError& e) {
          const std::string m = e.what();
          CHECK(m.rfind("m.json:1:", 0) == 0);
          CHECK(m.find(": /") != std::string::npos);
          CHECK(m.find("json.exception") == std::string::npos);
          CHECK(printable_ascii(m));
        }
      }
    }
  }
}

TEST_CASE("cin2021.knn: a squared distance that overflows is outside the domain", "[cin2021-ml]") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(ml::first_overflow(std::vector<double>{1.0, 4.0}) == std::nullopt);
  CHECK(ml::first_overflow(std::vector<double>{1.0, inf, std::nan("")}) == std::size_t{1});
  CHECK(ml::first_overflow(std::vector<double>{0.0, std::nan("")}) == std::size_t{1});
  ml::Knn m;
  m.k = 1;
  m.train.features = 1;
  m.train.classes = 2;
  m.train.x = {-1e140, 1e140};
  m.train.y = {0, 1};
  // finite inputs: (1e308 + 1e140)^2 overflows to inf (was: "knn_vote: distances must be >= 0")
  const std::vector<double> big{1e308};
  CHECK(message_of([&] { (void)ml::predict(m, big); })
            .find("KNN: the squared distance from the sample to training row 0 overflows") == 0);
  // weight 0 times an infinite square is NaN, which must never reach the ordering
  m.weights = {0.0};
  CHECK(message_of([&] { (void)ml::predict(m, big); }).find("training row 0 overflows") != std::string::npos);
  // large but finite squared distances are ordered as usual: (1e150 - 1e140)^2 < (1e150 + 1e140)^2
  m.weights.clear();
  const std::vector<double> x{1e150};
  CHECK(ml::predict(m, x) == 1);
}

TEST_CASE("cli.plan-json: a plan record whose map.width or map.height contradicts its rows is refused",
          "[formats][check]") {
  io::PlanRecord run;
  run.algo = "astar";
  run.map = io::MapSource{"builtin", "t", std::nullopt};
  run.start = grid::Cell{0, 0};
  run.goal = grid::Cell{2, 0};
  run.params = Json::object();
  run.result.found = true;
  run.result.path = {{0, 0}, {1, 0}, {2, 0}};
  run.result.length = 2.0;
  const grid::Grid g = grid::Grid::from_rows_top_first({"...", ".#."});
  const Json good = io::plan_to_json(run, g);
  CHECK_NOTHROW(io::plan_from_json(good, "p.json"));
  Json bad = good;
  bad["map"]["width"] = 4;
  CHECK(message_of([&] { (void)io::plan_from_json(bad, "p.json"); }) ==
        "p.json: /map/width: expected 3 (the length of each of /map/rows), got 4");
  bad = good;
  bad["map"]["height"] = 1;
  CHECK(message_of([&] { (void)io::plan_from_json(bad, "p.json"); }) ==
        "p.json: /map/height: expected 2 (the number of /map/rows), got 1");
  bad = good;
  bad["map"]["blocked"] = 0;
  CHECK(message_of([&] { (void)io::plan_from_json(bad, "p.json"); }) ==
        "p.json: /map/blocked: expected 1 (the number of '#' in /map/rows), got 0");
  bad = good;
  bad["map"]["rows"][1] = ".x.";
  CHECK(message_of([&] { (void)io::plan_from_json(bad, "p.json"); }) ==
        "p.json: /map/rows/1: expected only '.' (free) and '#' (blocked), got 'x' at character 2");
  // read as a path file: at the value's line and column
  bad = good;
  bad["map"]["width"] = 4;
  const std::string text = bad.dump(2);
  const std::string m = message_of([&] { (void)io::parse_path_text(text, "p.json", io::PathFormat::automatic, false); });
  CHECK(m.find(": /map/width: expected 3 (the length of each of /map/rows), got 4") != std::string::npos);
  CHECK(m.rfind("p.json:", 0) == 0);
  CHECK(m.rfind("p.json: ", 0) == std::string::npos);  // a line and a column, not the pointer alone
  // the same record as line 2 of a JSON-lines file: line 2
  const std::string lines = good.dump() + "\n" + bad.dump() + "\n";
  CHECK(message_of([&] { (void)io::parse_path_text(lines, "p.jsonl", io::PathFormat::automatic, true); })
            .rfind("p.jsonl:2:", 0) == 0);
}

TEST_CASE("han.sim.scenario-format: path steps, the planner and its parameters are refused at their pointers",
          "[han-sim]") {
  const std::string head = R"({"format": "pathref-sim 1", "map": [".#..", "...."], "start": [0, 0], "goal": [3, 0], )";
  const auto error = [&](const std::string& rest) {
    return message_of([&] { (void)sim::parse_scenario(head + rest, "s.json", ""); });
  };
  CHECK(error(R"("path": [[0, 0], [2, 0], [3, 0]]})") ==
        "s.json:1:104: /path/1: expected a free cell one step from (0, 0) allowed under the corner policy strict, got (2, 0)");
  CHECK(error(R"("path": [[0, 1], [1, 1]]})").find("/path/0: expected the start (0, 0), got (0, 1)") != std::string::npos);
  CHECK(error(R"("path": [[0, 0], [1, 0]]})").find("/path/1: expected the goal (3, 0) as the last cell, got (1, 0)") !=
        std::string::npos);
  CHECK(error(R"("planner": "nope"})").find("s.json:1:") == 0);
  CHECK(error(R"("planner": "nope"})").find("/planner: expected a planner name (") != std::string::npos);
  CHECK(error(R"("planner": {"name": "nope"}})").find("/planner/name: expected a planner name (") != std::string::npos);
  CHECK(error(R"("planner": {"name": "astar", "params": {"bogus": 1}}})")
            .find("/planner/params/bogus: expected a parameter of astar: unknown parameter 'bogus' (known: heuristic)") !=
        std::string::npos);
  CHECK(error(R"("planner": {"name": "astar", "params": {"heuristic": 1}}})")
            .find("/planner/params/heuristic: expected a parameter of astar: parameter 'heuristic' must be of the same "
                  "type as its default \"octile\"") != std::string::npos);
  // a value the planner refuses only when it runs: at /planner/params with line and column
  const sim::Scenario bad_value =
      sim::parse_scenario(head + R"("planner": {"name": "astar", "params": {"heuristic": "nope"}}})", "s.json", "");
  CHECK(message_of([&] { (void)sim::global_path(bad_value); })
            .find("s.json:1:126: /planner/params: the planner astar refused its parameters: unknown heuristic 'nope'") == 0);
  // pathref-sim 2 shares the planner check
  const std::string fused = R"({"format": "pathref-sim 2", "map": ["....", "...."], "start": [0, 0], "goal": [3, 0], "planner": {"name": "astar", "params": {"bogus": 1}}})";
  CHECK(message_of([&] { (void)dwa::parse_fused_scenario(fused, "f.json", ""); })
            .find("/planner/params/bogus: expected a parameter of astar") != std::string::npos);
}

TEST_CASE("planners: every planner takes its own defaults key by key", "[planners]") {
  for (const planners::Planner& p : planners::planners()) {
    INFO(p.name);
    CHECK(planners::first_bad_param(p, p.defaults) == std::nullopt);
    const auto bad = planners::first_bad_param(p, Json{{"no_such_parameter", 1}});
    REQUIRE(bad.has_value());
    CHECK(bad->first == "no_such_parameter");
  }
}

TEST_CASE("formats: a polygon scene given where only grid maps are read says what to do", "[formats]") {
  const std::string m = message_of([] {
    (void)io::parse_map_text("{}", "s.json", io::MapFormat::scene, io::MapReadOptions{});
  });
  CHECK(m.find("'s.json' is a polygon scene (pathref-scene 1)") == 0);
  CHECK(m.find("pathref inflate s.json -o MAP.grid") != std::string::npos);
  CHECK(m.find("MapReadOptions") == std::string::npos);
}

TEST_CASE("formats: readers quote input through io::printable (no raw NUL or BOM bytes)", "[formats]") {
  const std::string nul("\0", 1);
  const std::string bom = "\xEF\xBB\xBF";
  const auto clean = [](const std::string& m) {
    INFO(m);
    CHECK(m != "(no error)");
    CHECK(printable_ascii(m));
  };
  const std::string g1 = message_of([&] { (void)io::parse_grid_text("pathref-grid 1\nsi" + nul + "ze 3 3\n", "g.txt"); });
  clean(g1);
  CHECK(g1.find("unknown keyword 'si\\x00ze'") != std::string::npos);
  clean(message_of([&] { (void)io::parse_grid_text("pathref-grid " + bom + "1\n", "g.txt"); }));
  clean(message_of([&] { (void)io::parse_grid_text("pathref-grid 1\nsize 3" + nul + " 3\n", "g.txt"); }));
  const std::string d = message_of([&] { (void)io::parse_wall_following("1,2,Move-Forward\n1," + bom + "2,Move-Forward\n", "d.data"); });
  clean(d);
  CHECK(d.find("'\\xEF\\xBB\\xBF2'") != std::string::npos);
  clean(message_of([&] { (void)io::parse_wall_following("1,2,Move" + nul + "Forward\n", "d.data"); }));
  clean(message_of([&] { (void)io::parse_ros_yaml("image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                                                  "occupied_thresh: 0.65\nfree_thresh: 0.196\nk" + bom + "ey: 1\n",
                                                  "m.yaml"); }));
  clean(message_of([&] { (void)io::parse_ros_yaml("image: m.pgm\nresolution: 0." + bom + "05\n", "m.yaml"); }));
  clean(message_of([&] { (void)io::parse_path_text("1 2\n3 " + bom + "4\n", "p.txt", io::PathFormat::automatic, false); }));
  clean(message_of([&] { (void)io::parse_path_text("1 2\n3 4" + nul + "\n", "p.txt", io::PathFormat::automatic, false); }));
  clean(message_of([&] { (void)io::parse_trace("{\"i\": 0, \"u\": 2, \"" + bom + "\": 1}\n", "t.jsonl"); }));
  const std::string t = message_of([&] { (void)io::parse_trace("{\"i\": 1, \"u\": 0.5}\n", "t.jsonl"); });
  CHECK(t == "t.jsonl:1:7: /i: expected draw index 0 (draws are numbered 0, 1, 2, ... in order), got 1");
}
