// The generic golden runner over golden/: every vector of every rule, through the registry.
#include <catch2/catch.hpp>

#include "pathref/golden/runner.hpp"
#include "pathref/rules/registry.hpp"
#include "support/paths.hpp"

using pathref::golden::Json;
using pathref::golden::Status;

TEST_CASE("golden: every vector in golden/ passes", "[golden]") {
  const auto report = pathref::golden::check_directory(pathref::testing::source_dir() + "/golden");
  REQUIRE(report.cases.size() > 0);
  for (const auto& c : report.cases) {
    INFO(c.file << " rule " << c.rule << " tcId " << c.tc_id << ": " << c.message);
    CHECK(c.status != Status::fail);
  }
}

TEST_CASE("golden: the runner detects a wrong expected value", "[golden]") {
  // A runner that cannot fail proves nothing: perturb a vector and require a failure.
  const Json doc = Json::parse(R"({
    "rule": "rng.index", "notes": {},
    "testGroups": [{"provenance": "hand", "tolerance": {"abs": 0, "rel": 0, "why": "integer"},
      "tests": [{"tcId": 1, "input": {"u": 0.5, "n": 4}, "expected": {"k": 3}, "result": "valid"},
                {"tcId": 2, "input": {"u": 0.5, "n": 0}, "expected": {"error": "DomainError"}, "result": "invalid"},
                {"tcId": 3, "input": {"u": 0.5, "n": 4}, "expected": {"error": "DomainError"}, "result": "invalid"}]}]})");
  const auto report = pathref::golden::check_document(doc, "inline");
  REQUIRE(report.cases.size() == 3);
  CHECK(report.cases[0].status == Status::fail);  // floor(0.5*4) = 2, not 3
  CHECK(report.cases[1].status == Status::pass);
  CHECK(report.cases[2].status == Status::fail);  // no error is raised for n = 4
}

TEST_CASE("golden: tolerance comparison is max(abs, rel*|expected|)", "[golden]") {
  const Json tol = {{"abs", 1e-12}, {"rel", 0.0}};
  CHECK(pathref::golden::compare(1.0, 1.0 + 5e-13, tol).empty());
  CHECK_FALSE(pathref::golden::compare(1.0, 1.0 + 5e-12, tol).empty());
  const Json rel = {{"abs", 0.0}, {"rel", 1e-9}};
  CHECK(pathref::golden::compare(1e6, 1e6 + 1e-4, rel).empty());
  CHECK_FALSE(pathref::golden::compare(1e6, 1e6 + 1e-2, rel).empty());
  CHECK_FALSE(pathref::golden::compare(Json::array({1, 2}), Json::array({1, 2, 3}), tol).empty());
  CHECK(pathref::golden::compare("inf", "inf", tol).empty());
  CHECK_FALSE(pathref::golden::compare("inf", 1e308, tol).empty());
  CHECK_FALSE(pathref::golden::compare(3, 4, Json{{"abs", 10.0}}).empty());  // integers exact
}

TEST_CASE("golden: every registered rule has a golden file", "[golden][traceability]") {
  const auto report = pathref::golden::check_directory(pathref::testing::source_dir() + "/golden");
  for (const auto& rule : pathref::rules::registry().all()) {
    INFO("rule " << rule.id);
    const bool covered = std::any_of(report.cases.begin(), report.cases.end(),
                                     [&](const auto& c) { return c.rule == rule.id; });
    CHECK(covered);
  }
}

TEST_CASE("golden: canonical_text is Python's json.dumps(indent=2, sort_keys=True)", "[golden]") {
  // tools/golden-lint requires exactly this text; floats follow Python's repr, not nlohmann's
  // Grisu2 (which is not always shortest and switches to exponent form from 1e15 on).
  const Json doc = Json::parse(R"({"b": [1e15, 3705226666457467.5, 754468566810601.2, 1e16, 1e-5,
      0.0001, 0.0, -0.0, 5e-324, 0.1, 2, -3, 1.7976931348623157e308, 5.31652058774973e+16],
      "a": {"x": "\u00e9\n", "e": [], "o": {}}, "c": true, "d": null})");
  const std::string expected =
      "{\n"
      "  \"a\": {\n"
      "    \"e\": [],\n"
      "    \"o\": {},\n"
      "    \"x\": \"\xc3\xa9\\n\"\n"
      "  },\n"
      "  \"b\": [\n"
      "    1000000000000000.0,\n"
      "    3705226666457467.5,\n"
      "    754468566810601.2,\n"
      "    1e+16,\n"
      "    1e-05,\n"
      "    0.0001,\n"
      "    0.0,\n"
      "    -0.0,\n"
      "    5e-324,\n"
      "    0.1,\n"
      "    2,\n"
      "    -3,\n"
      "    1.7976931348623157e+308,\n"
      "    5.31652058774973e+16\n"
      "  ],\n"
      "  \"c\": true,\n"
      "  \"d\": null\n"
      "}\n";
  CHECK(pathref::golden::canonical_text(doc) == expected);
}
