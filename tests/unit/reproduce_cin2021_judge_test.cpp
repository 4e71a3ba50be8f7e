// spec: reproduce.judge (judge_printed), reproduce.cin2021-ml.judge, reproduce.cin2021.protocol,
// reproduce.execution (run_records): how the cin2021 reproductions turn runs into verdicts.
#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/reproduce/cin2021.hpp"
#include "pathref/reproduce/cin2021_ml.hpp"
#include "pathref/reproduce/runs.hpp"
#include "pathref/reproduce/stats.hpp"

using namespace pathref;
using reproduce::Direction;
using reproduce::Sense;
using reproduce::Verdict;

TEST_CASE("reproduce.judge: printed digits with direction", "[reproduce][cin2021-judge]") {
  const auto hold = reproduce::judge_printed(93.218, "93.2", Sense::higher_is_better);
  CHECK(hold.verdict == Verdict::holds);
  CHECK(hold.direction == Direction::none);
  // MNB: 58.376 prints as 58.4, not 58.3 -> does not hold, pathref's accuracy higher
  const auto mnb = reproduce::judge_printed(58.376, "58.3", Sense::higher_is_better);
  CHECK(mnb.verdict == Verdict::fails);
  CHECK(mnb.direction == Direction::pathref_better);
  CHECK(reproduce::verdict_text(mnb.verdict, mnb.direction) == "does not hold — pathref better");
  const auto low = reproduce::judge_printed(91.42, "91.5", Sense::higher_is_better);
  CHECK(low.verdict == Verdict::fails);
  CHECK(low.direction == Direction::pathref_worse);
  // a length: lower is better, so a higher value is worse
  CHECK(reproduce::judge_printed(30.1, "29.8", Sense::lower_is_better).direction == Direction::pathref_worse);
  CHECK(reproduce::judge_printed(29.5, "29.8", Sense::lower_is_better).direction == Direction::pathref_better);
  CHECK(reproduce::judge_printed(29.79899, "29.8", Sense::lower_is_better).verdict == Verdict::holds);
  CHECK_THROWS_AS(reproduce::judge_printed(1.0, "1e3", Sense::lower_is_better), DomainError);
}

TEST_CASE("reproduce.cin2021-ml.judge: tenfold numbers by printed digits, the post-hoc reading disclosed",
          "[reproduce][cin2021-judge]") {
  CHECK(reproduce::within_last_digit(58.376, "58.3"));   // what the post-hoc rule was made for
  CHECK_FALSE(reproduce::within_last_digit(91.899, "91.5"));
  CHECK(reproduce::within_last_digit(93.218, "93.2"));
  CHECK_FALSE(reproduce::within_last_digit(58.376, "58.30"));  // two decimals: one unit is 0.01

  const reproduce::Claim mnb = reproduce::tenfold_printed_claim("mnb-tenfold", "MNB 58.3 %", 58.376, "58.3");
  CHECK(mnb.verdict == Verdict::fails);  // the headline rule does not bend to the post-hoc one
  CHECK(mnb.direction == Direction::pathref_better);
  CHECK(mnb.ours == "58.376 (prints as 58.4; +0.076 pp)");
  CHECK(mnb.note.find("post-hoc") != std::string::npos);
  CHECK(mnb.note.find("yes") != std::string::npos);
  CHECK(mnb.statistics.at("n").at("post_hoc_within_last_digit") == true);
  CHECK(mnb.statistics.at("n").at("judgement").at("verdict") == "does not hold");
  CHECK_FALSE(mnb.verdict_2n.has_value());  // deterministic: no 2n

  const reproduce::Claim svm = reproduce::tenfold_printed_claim("svm-tenfold", "SVM 91.5 %", 91.899, "91.5");
  CHECK(svm.verdict == Verdict::fails);
  CHECK(svm.direction == Direction::pathref_better);
  CHECK(svm.ours == "91.899 (prints as 91.9; +0.399 pp)");
  CHECK(svm.note.find(": no") != std::string::npos);

  const reproduce::Claim knn = reproduce::tenfold_printed_claim("knn-tenfold", "KNN 93.2 %", 93.218, "93.2");
  CHECK(knn.verdict == Verdict::holds);
  const reproduce::Claim worse = reproduce::tenfold_printed_claim("x", "x", 88.31, "88.4");
  CHECK(worse.verdict == Verdict::fails);
  CHECK(worse.direction == Direction::pathref_worse);
  CHECK(worse.ours == "88.310 (prints as 88.3; −0.090 pp)");
}

TEST_CASE("reproduce.execution: run_records runs, emits and merges the same runs", "[reproduce][cin2021-judge]") {
  const grid::Grid g = reproduce::rect_grid(6, 6, {{2, 1, 3, 3}});
  const planners::Planner* p = reproduce::available("aco-cin");
  REQUIRE(p != nullptr);
  const nlohmann::json params = reproduce::quick_overrides(p->defaults);
  const grid::Cell s{0, 0}, t{5, 5};
  const auto one = reproduce::run_records(*p, "aco-cin", params, g, s, t, grid::CornerPolicy::strict, 7, 4, "test");
  REQUIRE(one.size() == 4);
  std::vector<reproduce::RunRecord> two;
  {
    reproduce::Execution ex;
    ex.jobs = 2;
    const reproduce::ExecutionScope scope(ex);
    two = reproduce::run_records(*p, "aco-cin", params, g, s, t, grid::CornerPolicy::strict, 7, 4, "test");
  }
  std::vector<nlohmann::json> emitted;
  std::map<std::string, nlohmann::json> merged;
  {
    reproduce::Execution ex;
    ex.mode = reproduce::Execution::Mode::emit;
    ex.emitted = &emitted;
    const reproduce::ExecutionScope scope(ex);
    const auto placeholders = reproduce::run_records(*p, "aco-cin", params, g, s, t, grid::CornerPolicy::strict, 7, 4, "test");
    CHECK(placeholders.size() == 4);
    CHECK_FALSE(placeholders[0].found);
  }
  REQUIRE(emitted.size() == 4);
  for (const auto& job : emitted) {
    const auto out = reproduce::run_job(job);
    merged[out.at("key").get<std::string>()] = out.at("record");
  }
  std::vector<reproduce::RunRecord> three;
  {
    reproduce::Execution ex;
    ex.mode = reproduce::Execution::Mode::merge;
    ex.merged = &merged;
    const reproduce::ExecutionScope scope(ex);
    three = reproduce::run_records(*p, "aco-cin", params, g, s, t, grid::CornerPolicy::strict, 7, 4, "test");
  }
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(one[i].seed == 7 + i);
    CHECK(two[i].seed == one[i].seed);
    CHECK(two[i].path == one[i].path);
    CHECK(three[i].path == one[i].path);
    CHECK(three[i].extra == one[i].extra);
  }
}

TEST_CASE("reproduce.cin2021.protocol: claims judged at n and 2n, readings as alternatives", "[reproduce][cin2021-judge]") {
  reproduce::CinConfig cfg;
  cfg.runs = 3;
  cfg.seed = 1;
  cfg.quick = true;
  const auto doc = reproduce::run_cin2021(cfg);
  CHECK(doc.at("protocol").at("runs_2n") == 6);
  CHECK(doc.at("results").at("s1").at("hga-aco-cin").at("runs").size() == 6);
  const auto& claims = doc.at("claims");
  CHECK(claims.size() == 3 * 4 * 2);  // 3 scenarios x C1-C4 x {ACO, GA}
  CHECK(doc.at("reading_claims").size() == 3 * 4 * 2 * 2 + 3 * 2);  // two readings each, and C3/total
  CHECK(doc.at("cross_paper").empty());  // Shi's maps not given
  const std::set<std::string> allowed = {"holds", "does not hold", "not significant", "cannot be tested"};
  std::set<std::string> ids;
  for (const auto& c : doc.at("reading_claims")) ids.insert(c.at("id").get<std::string>());
  for (const auto& c : claims) {
    CHECK(allowed.count(c.at("verdict").get<std::string>()) == 1);
    // every claim rests on the colony's readings and names its alternatives, which exist
    REQUIRE(c.at("depends_on").size() >= 2);
    const std::string id = c.at("id").get<std::string>();
    CHECK(ids.count(id + "@any_stuck") == 1);
    CHECK(ids.count(id + "@goal_inverse") == 1);
    if (id.rfind("C3.", 0) == 0) CHECK(ids.count(id + "/total") == 1);
    if (c.at("verdict") == "cannot be tested") continue;
    CHECK(c.at("rule").get<std::string>().find("Mann–Whitney") != std::string::npos);
    CHECK(c.at("statistics").at("n").at("kind") == "comparison");
    CHECK(c.at("statistics").at("n").at("a").at("n").get<int>() <= 3);  // the first n runs
    CHECK(c.at("at_2n").is_object());
    CHECK(c.at("statistics").at("2n").at("a").at("n").get<int>() > 3);
    CHECK(c.at("statistics").at("n").contains("mean_difference_ci"));
    CHECK(c.at("verdict_text").get<std::string>().size() > 0);
  }
  CHECK_THROWS_AS(([] {
                    reproduce::CinConfig bad;
                    bad.runs = 1;
                    (void)reproduce::run_cin2021(bad);
                  }()),
                  UsageError);
}
