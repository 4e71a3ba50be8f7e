// Draw traces (spec/rng.md#draw-traces): what a traced stream records, the file format read back
// exactly, first_divergence, and (property) that tracing changes no planner's result and records
// exactly the draws the planner consumed.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/io/trace_file.hpp"
#include "pathref/rng/trace.hpp"
#include "support/generators.hpp"

using namespace pathref;

TEST_CASE("trace: a traced stream records index, value, purpose and context - values unchanged", "[rng][trace]") {
  rng::Stream plain(42), traced(42);
  rng::Trace t;
  traced.set_trace(&t);
  CHECK(traced.tracing());
  CHECK_FALSE(plain.tracing());
  const double a0 = plain.next_double(), a1 = plain.next_double(), a2 = plain.next_double();
  CHECK(traced.next_double("first") == a0);
  traced.set_context("step 1");
  CHECK(traced.next_double("second") == a1);
  traced.set_trace(nullptr);
  CHECK(traced.next_double("not recorded") == a2);
  REQUIRE(t.draws().size() == 2);
  CHECK(t.draws()[0].index == 0);
  CHECK(t.draws()[0].value == 0.3745401188473625);  // NumPy RandomState(42).random_sample()
  CHECK(t.draws()[0].purpose == "first");
  CHECK(t.draws()[0].context.empty());
  CHECK(t.draws()[1].index == 1);
  CHECK(t.draws()[1].purpose == "second");
  CHECK(t.draws()[1].context == "step 1");
  CHECK(traced.doubles_drawn() == 3);
}

TEST_CASE("trace: the limit keeps the first draws and counts the rest", "[rng][trace]") {
  rng::Stream s(1);
  rng::Trace t(3);
  s.set_trace(&t);
  for (int i = 0; i < 5; ++i) (void)s.next_double("x");
  CHECK(t.draws().size() == 3);
  CHECK(t.dropped() == 2);
  CHECK(t.draws().back().index == 2);
}

TEST_CASE("trace: text round trip is exact, header kept", "[rng][trace]") {
  rng::Stream s(2024);
  rng::Trace t;
  s.set_trace(&t);
  for (int i = 0; i < 200; ++i) {
    if (i % 50 == 0) s.set_context("block \"" + std::to_string(i / 50) + "\"");  // quotes are escaped
    (void)s.next_double(i % 2 == 0 ? "even" : "odd");
  }
  const std::string text = io::trace_text(t, 2024, nlohmann::json{{"algo", "test"}});
  const io::TraceFile back = io::parse_trace(text, "t.jsonl");
  CHECK(back.header.at("seed") == 2024);
  CHECK(back.header.at("algo") == "test");
  CHECK(back.header.at("draws") == 200);
  REQUIRE(back.draws.size() == t.draws().size());
  for (std::size_t k = 0; k < back.draws.size(); ++k) {
    CHECK(back.draws[k].value == t.draws()[k].value);  // 17 significant digits: the same double
    CHECK(back.draws[k].purpose == t.draws()[k].purpose);
    CHECK(back.draws[k].context == t.draws()[k].context);
  }
  CHECK_FALSE(rng::first_divergence(back.draws, t.draws()).has_value());
}

TEST_CASE("trace: first_divergence", "[rng][trace]") {
  const auto d = [](std::vector<double> v) {
    std::vector<rng::Draw> out;
    for (std::size_t k = 0; k < v.size(); ++k) out.push_back(rng::Draw{k, v[k], "", ""});
    return out;
  };
  CHECK_FALSE(rng::first_divergence(d({}), d({})).has_value());
  CHECK_FALSE(rng::first_divergence(d({0.5, 0.25}), d({0.5, 0.25})).has_value());
  CHECK(rng::first_divergence(d({0.5, 0.25}), d({0.5, 0.26})) == 1U);
  CHECK(rng::first_divergence(d({0.5}), d({0.5, 0.26})) == 1U);        // A ends
  CHECK(rng::first_divergence(d({0.5, 0.25}), d({})) == 0U);            // B empty
  CHECK(rng::first_divergence(d({0.1}), d({std::nextafter(0.1, 1.0)})) == 0U);  // one ulp is a divergence
}

TEST_CASE("trace: malformed traces are ParseErrors at their line", "[rng][trace]") {
  const auto message = [](const std::string& text) {
    try {
      (void)io::parse_trace(text, "t.jsonl");
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message("{\"i\":0,\"u\":0.5}\n{\"i\":2,\"u\":0.5}\n").find("t.jsonl:2:6: /i: expected draw index 1") != std::string::npos);
  CHECK(message("{\"i\":0,\"u\":1.0}\n").find("u in [0, 1)") != std::string::npos);
  CHECK(message("{\"i\":0}\n").find("no number \"u\"") != std::string::npos);
  CHECK(message("[1,2]\n").find("a JSON object per line") != std::string::npos);
  CHECK(message("{\"i\":0,\"u\":0.5}\n\n{\"i\":1,\"u\":\n").find("t.jsonl:3:") != std::string::npos);
  CHECK(message("{\"i\":-1,\"u\":0.5}\n").find("draw index 0") != std::string::npos);
  // A first line whose "format" is not a string is a draw, not a header (was: a library type_error
  // escaping as an internal error, exit 3; fuzz/corpus/trace_file/crash-format-not-string.jsonl).
  CHECK(message("{\"format\":1}\n").find("t.jsonl:1:1: /: expected a draw") != std::string::npos);
  CHECK(io::parse_trace("{\"format\":[1],\"i\":0,\"u\":0.5}\n", "t.jsonl").draws.size() == 1);
  // A user's minimal trace: no header, no purpose, no context; blank lines ignored.
  CHECK(io::parse_trace("\n{\"i\":0,\"u\":0.5}\r\n{\"i\":1,\"u\":0}\n", "t.jsonl").draws.size() == 2);
}

TEST_CASE("prop_trace_changes_no_planner_result", "[rng][trace][prop]") {
  // Every stochastic planner: the traced run returns the same path, length and curves, and its
  // trace holds one record per draw, numbered 0, 1, 2, ... (the planners' draw counts are what
  // golden whole-run vectors pin; here the oracle is the untraced run).
  rc::prop("traced == untraced; trace indices are 0..n-1", [] {
    const grid::Grid g = *testing::gen_grid(7, 7, 0.25);
    std::vector<grid::Cell> free_cells;
    for (std::int64_t y = 0; y < g.height(); ++y)
      for (std::int64_t x = 0; x < g.width(); ++x)
        if (g.free(grid::Cell{x, y})) free_cells.push_back(grid::Cell{x, y});
    RC_PRE(free_cells.size() >= 2);
    static const std::vector<std::string> algos{"aco", "iaco-shi", "iaco-han", "ga", "iga-shi", "hybrid-ga-aco",
                                                "iha", "ga-cin", "aco-cin", "hga-aco-cin"};
    const std::string algo = *rc::gen::elementOf(algos);
    planners::Request req;
    req.grid = &g;
    req.start = free_cells.front();
    req.goal = free_cells.back();
    req.policy = *testing::gen_policy();
    req.seed = *rc::gen::arbitrary<std::uint32_t>();
    const planners::Planner* p = planners::find_planner(algo);
    RC_ASSERT(p != nullptr);
    const planners::Json colony{{"iterations", 2}, {"ants", 3}};
    const planners::Json ga{{"generations", 2}, {"population", 6}};
    const planners::Json hybrid{{"generations", 2}, {"population", 6}, {"aco_iterations", 2}, {"aco_ants", 3}};
    req.params = algo == "hybrid-ga-aco" || algo == "iha" || algo == "hga-aco-cin" ? hybrid
                 : algo.find("aco") != std::string::npos                          ? colony
                                                                                 : ga;
    const planners::Result plain = p->run(req);
    rng::Trace t;
    req.trace = &t;
    const planners::Result traced = p->run(req);
    RC_ASSERT(traced.found == plain.found);
    RC_ASSERT(traced.path == plain.path);
    RC_ASSERT(traced.length == plain.length);
    // curves: equal value for value, NaN (an iteration without a path) matching NaN
    const auto same = [](const std::vector<double>& x, const std::vector<double>& y) {
      if (x.size() != y.size()) return false;
      for (std::size_t k = 0; k < x.size(); ++k)
        if (!(x[k] == y[k] || (std::isnan(x[k]) && std::isnan(y[k])))) return false;
      return true;
    };
    RC_ASSERT(same(traced.best_per_iteration, plain.best_per_iteration));
    RC_ASSERT(same(traced.mean_per_iteration, plain.mean_per_iteration));
    rng::Stream replay(req.seed);
    for (std::size_t k = 0; k < t.draws().size(); ++k) {
      RC_ASSERT(t.draws()[k].index == k);
      RC_ASSERT(t.draws()[k].value == replay.next_double());
      RC_ASSERT(!t.draws()[k].purpose.empty());
    }
  });
}
