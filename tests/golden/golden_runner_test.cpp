// The generic golden runner over golden/: every vector of every rule, through the registry.
#include <catch2/catch.hpp>

#include "pathref/golden/runner.hpp"
#include "pathref/rules/registry.hpp"

using pathref::golden::Json;
using pathref::golden::Status;

TEST_CASE("golden: every vector in golden/ passes", "[golden]") {
  const auto report = pathref::golden::check_directory(PATHREF_SOURCE_DIR "/golden");
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
  const auto report = pathref::golden::check_directory(PATHREF_SOURCE_DIR "/golden");
  for (const auto& rule : pathref::rules::registry().all()) {
    INFO("rule " << rule.id);
    const bool covered = std::any_of(report.cases.begin(), report.cases.end(),
                                     [&](const auto& c) { return c.rule == rule.id; });
    CHECK(covered);
  }
}
