// spec: cin2021 rules (spec/index/cin2021-hga-aco.json, cin2021-srrt.json, cin2021-ml.json).
// Tests added for issue 17's mutation target (tools/mutate.d/catalogue.json, the cin2021 entries): each case pins the
// boundary or constant a catalogued mutant changes, with an oracle derived by hand in the comment.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "pathref/io/scene_json.hpp"
#include "pathref/continuous/rrt.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/core/error.hpp"
#include "pathref/equations/aco.hpp"
#include "pathref/equations/ga.hpp"
#include "pathref/equations/ga_operators.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/equations/proportional.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/ml/classifier.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/draws.hpp"

using namespace pathref;
using grid::Cell;

namespace {
// Register the S-RRT rules (pathref_geometry) before anything builds the rule registry.
const bool srrt_rules_installed = (geometry::install_srrt_rules(), true);

geometry::ObstacleMap empty_world() {
  const std::string text =
      "{\"format\": \"pathref-scene 1\", \"origin\": [0, 0], \"width\": 10, \"height\": 10, "
      "\"cell_size\": 1, \"radius\": 0, \"margin\": 0, \"polygons\": [], \"start\": [0, 0], \"goal\": [1, 0]}";
  return geometry::ObstacleMap::from_scene(io::parse_scene_json(text, "t.json"));
}

ml::Dataset ml_data(std::size_t features, std::vector<double> x, std::vector<int> y, std::size_t classes) {
  ml::Dataset d;
  d.features = features;
  d.classes = classes;
  d.x = std::move(x);
  d.y = std::move(y);
  return d;
}

// cin2021-ml's hand SVM model: three classes, one support vector each at 0, 1, 2, gamma = ln 2
// (K = 2^-d^2); pair (0,1): sv0 +1, sv1 -1; pair (0,2): sv0 +1, sv2 -1; pair (1,2): sv1 +1, sv2 -1.
ml::SvmModel hand_svm() {
  ml::SvmModel m;
  m.classes = 3;
  m.features = 1;
  m.gamma = std::log(2.0);
  m.labels = {0, 1, 2};
  m.n_sv = {1, 1, 1};
  m.sv = {0, 1, 2};
  m.sv_rows = {0, 1, 2};
  m.coef = {1, -1, -1, 1, 1, -1};
  m.rho = {0, 0, 0};
  return m;
}
}  // namespace

TEST_CASE("cin2021.eq16: a jump of two cells is not adjacent, in x and in y", "[cin2021][mutants]") {
  const grid::Grid g(5, 5);
  // (0,0) -> (2,0): |dx| = 2 > 1, the second node is not an 8-neighbour of the first
  const std::vector<Cell> px{Cell{0, 0}, Cell{2, 0}};
  const auto cx = metrics::validate_path(g, px, Cell{0, 0}, Cell{2, 0}, grid::CornerPolicy::strict);
  CHECK_FALSE(cx.valid);
  CHECK(cx.reason == "not_adjacent");
  CHECK(cx.index == 1);
  const std::vector<Cell> py{Cell{0, 0}, Cell{0, 2}};
  const auto cy = metrics::validate_path(g, py, Cell{0, 0}, Cell{0, 2}, grid::CornerPolicy::strict);
  CHECK_FALSE(cy.valid);
  CHECK(cy.reason == "not_adjacent");
  // one diagonal step on a free grid is adjacent and legal
  const std::vector<Cell> pd{Cell{0, 0}, Cell{1, 1}};
  CHECK(metrics::validate_path(g, pd, Cell{0, 0}, Cell{1, 1}, grid::CornerPolicy::strict).valid);
}

TEST_CASE("cin2021.eq19: path length sums every segment, the first included", "[cin2021][mutants]") {
  // three unit steps: 3; one diagonal step: sqrt(2) (a mutant that skips the first segment gives 2 and 0)
  const std::vector<Cell> p{Cell{0, 0}, Cell{1, 0}, Cell{2, 0}, Cell{2, 1}};
  CHECK(metrics::path_length(p) == 3.0);
  const std::vector<Cell> q{Cell{0, 0}, Cell{1, 1}};
  CHECK(metrics::path_length(q) == std::sqrt(2.0));
}

TEST_CASE("cin2021.eq20: f1 is the inverse length, exactly", "[cin2021][mutants]") {
  CHECK(ga::inverse_length(4.0) == 0.25);
  CHECK(ga::inverse_length(0.5) == 2.0);
  CHECK(ga::inverse_length(1.0) == 1.0);
}

TEST_CASE("cin2021.eq26: a f1 + b f2 with each weight on its own term", "[cin2021][mutants]") {
  // 2 * 0.5 + 3 * 0.25 + 0 * 7 = 1 + 0.75 = 1.75 (every product and sum exact in binary)
  CHECK(ga::weighted_fitness(0.5, 0.25, 7.0, ga::FitnessWeights{2.0, 3.0, 0.0}) == 1.75);
  // b = 0: f2 has no influence
  CHECK(ga::weighted_fitness(0.5, 100.0, 0.0, ga::FitnessWeights{1.0, 0.0, 0.0}) == 0.5);
}

TEST_CASE("cin2021.eq27: probabilities are the weights over their plain sum", "[cin2021][mutants]") {
  const std::vector<double> w{1.0, 3.0};
  const std::vector<double> p = equations::proportional_probabilities(w);
  REQUIRE(p.size() == 2);
  CHECK(p[0] == 0.25);  // 1 / (1 + 3)
  CHECK(p[1] == 0.75);  // 3 / (1 + 3)
  const std::vector<double> w3{2.0, 2.0, 4.0};
  const std::vector<double> p3 = equations::proportional_probabilities(w3);
  CHECK(p3[0] == 0.25);
  CHECK(p3[2] == 0.5);
}

TEST_CASE("cin2021.eq29: the weight is tau^alpha times eta^beta", "[cin2021][mutants]") {
  const std::vector<double> tau{2.0, 0.5};
  const std::vector<double> eta{3.0, 4.0};
  // alpha 1, beta 2: 2 * 9 = 18, 0.5 * 16 = 8
  const std::vector<double> w = aco::transition_weights(tau, eta, 1.0, 2.0);
  REQUIRE(w.size() == 2);
  CHECK(w[0] == 18.0);
  CHECK(w[1] == 8.0);
  // alpha 2, beta 1: 4 * 3 = 12, 0.25 * 4 = 1
  const std::vector<double> v = aco::transition_weights(tau, eta, 2.0, 1.0);
  CHECK(v[0] == 12.0);
  CHECK(v[1] == 1.0);
}

TEST_CASE("cin2021.eq30: eta is the inverse centre distance, the goal's own value at the goal", "[cin2021][mutants]") {
  // |(3,4) - (0,0)| = 5: eta = 1/5
  CHECK(aco::eta_goal_inverse(Cell{3, 4}, Cell{0, 0}, 2.0) == 1.0 / 5.0);
  CHECK(aco::eta_goal_inverse(Cell{0, 2}, Cell{0, 0}, 2.0) == 0.5);
  CHECK(aco::eta_goal_inverse(Cell{0, 0}, Cell{0, 0}, 2.0) == 2.0);
  CHECK(aco::eta_inverse_distance(Cell{0, 0}, Cell{1, 0}) == 1.0);
  CHECK(aco::eta_inverse_distance(Cell{0, 0}, Cell{1, 1}) == 1.0 / std::sqrt(2.0));
}

TEST_CASE("cin2021.eq31: tau' = (1 - rho) tau + delta", "[cin2021][mutants]") {
  CHECK(aco::pheromone_update(2.0, 0.25, 1.0) == 2.5);   // 0.75 * 2 + 1
  CHECK(aco::pheromone_update(4.0, 0.5, 0.25) == 2.25);  // 0.5 * 4 + 0.25
  CHECK(aco::pheromone_update(1.0, 0.5, 0.0) == 0.5);
}

TEST_CASE("cin2021.op.mutation: a greedy step tie goes to the first neighbour in cell order", "[cin2021][mutants]") {
  // 3 x 3, (1,1) blocked, policy always. From (1,0) towards (1,2) the candidates in neighbour
  // order (rows bottom to top, columns left to right) are (0,0) d2 = 5, (2,0) 5, (0,1) 2, (2,1) 2:
  // the nearest are (0,1) and (2,1), tied; the first, (0,1), is taken. From (0,1): (0,0) 5,
  // (0,2) 1, (1,2) 0 -> the target. The walk is (1,0) (0,1) (1,2).
  grid::Grid g(3, 3);
  g.set_blocked(Cell{1, 1}, true);
  rng::Stream st(1);
  const ga::Walk w = ga::research_walk(g, Cell{1, 0}, Cell{1, 2}, {}, grid::CornerPolicy::always,
                                       ga::Research::greedy, st);
  REQUIRE(w.ok);
  const std::vector<Cell> want{Cell{1, 0}, Cell{0, 1}, Cell{1, 2}};
  CHECK(w.cells == want);
  CHECK(st.doubles_drawn() == 0);
}

TEST_CASE("cin2021.srrt.steer: at d = delta the clip returns the target itself, not near + (target - near)", "[cin2021][mutants]") {
  // dx = fl(0.9 - 0.2) = 0.7 - 2^-53-ish, and 0.2 + dx rounds to 0.8999999999999999 != 0.9: only
  // the clip branch (d <= delta) gives the target bit for bit.
  const double dx = 0.9 - 0.2;
  const double d = std::sqrt(dx * dx + 0.0 * 0.0);
  REQUIRE(0.2 + (d / d) * dx != 0.9);  // the two readings differ at this input
  const continuous::Vec2 got = continuous::steer({0.2, 0.0}, {0.9, 0.0}, d, true);
  CHECK(got.x == 0.9);
  CHECK(got.y == 0.0);
}

TEST_CASE("cin2021.alg1: a goal exactly delta away is reached", "[cin2021][mutants]") {
  // |(1,3) - (1,1)|^2 = 4 = delta^2: the root already reaches the goal, no draw, no iteration.
  const geometry::ObstacleMap m = empty_world();
  continuous::RrtParams p;
  p.delta = 2.0;
  rng::Stream s(1);
  const continuous::RrtResult r = continuous::rrt(m, {1, 1}, {1, 3}, p, s);
  CHECK(r.found);
  CHECK(r.iterations == 0);
  CHECK(r.draws == 0);
  CHECK(r.path == std::vector<std::size_t>{0, 1});
}

TEST_CASE("cin2021.alg1: bias lt is strict, a draw equal to P_g samples", "[cin2021][mutants]") {
  // The paper variant draws x, y of x_rand, then p; goal iff p < P_g. Set P_g to the third draw of
  // seed 7 itself: p == P_g, so the step heads for x_rand = (10 u1, 10 u2), not for the goal.
  rng::Stream pre(7);
  const double u1 = pre.next_double();
  const double u2 = pre.next_double();
  const double u3 = pre.next_double();
  const geometry::ObstacleMap m = empty_world();
  continuous::RrtParams p;
  p.delta = 1.0;
  p.goal_probability = u3;
  p.max_iterations = 1;
  const continuous::Vec2 start{5, 5};
  const continuous::Vec2 goal{9.5, 0.5};
  rng::Stream s(7);
  const continuous::RrtResult r = continuous::rrt(m, start, goal, p, s);
  REQUIRE(r.iterations == 1);
  const continuous::Vec2 x_rand{0.0 + u1 * 10.0, 0.0 + u2 * 10.0};
  const continuous::Vec2 want = continuous::steer(start, x_rand, 1.0, true);
  REQUIRE(r.nodes.size() >= 2);
  CHECK(r.nodes[1] == want);
  CHECK_FALSE(r.nodes[1] == continuous::steer(start, goal, 1.0, true));
}

TEST_CASE("cin2021.srrt.metrics: turning adds the absolute heading change of right and left turns", "[cin2021][mutants]") {
  // right turn (0,0)-(1,0)-(1,-1): cross = -1, |.| -> pi/2; left turn (1,-1)-(2,-1): pi/2 again
  CHECK(continuous::total_turning({{0, 0}, {1, 0}, {1, -1}}) == std::atan2(1.0, 0.0));
  CHECK(continuous::total_turning({{0, 0}, {1, 0}, {1, -1}, {2, -1}}) == 2.0 * std::atan2(1.0, 0.0));
  CHECK(continuous::total_turning({{0, 0}, {1, 0}, {2, 0}}) == 0.0);
}

TEST_CASE("cin2021.srrt.curve: degree 1 is a valid request, 0 is not", "[cin2021][mutants]") {
  CHECK(continuous::curve_params(continuous::Json{{"degree", 1}}).degree == 1);
  CHECK(continuous::curve_params(continuous::Json{{"degree", 3}}).degree == 3);
  CHECK_THROWS_AS(continuous::curve_params(continuous::Json{{"degree", 0}}), DomainError);
}

TEST_CASE("cin2021.eq1: equal joint log-likelihoods go to the first class", "[cin2021][mutants]") {
  // class 0 at {0, 2}: mean 1, var 1; class 1 at {10, 12}: mean 11, var 1; equal priors. At x = 6
  // both (x - mu)^2 / var are 25 exactly, so the two jll are the same double: argmax_first -> 0.
  const ml::GaussianNb m = ml::fit_gaussian_nb(ml_data(1, {0, 2, 10, 12}, {0, 0, 1, 1}, 2), 0.0);
  const std::vector<double> x{6.0};
  const std::vector<double> jll = ml::joint_log_likelihood(m, x);
  REQUIRE(jll[0] == jll[1]);
  CHECK(ml::predict(m, x) == 0);
  CHECK(ml::argmax_first(std::vector<double>{1.0, 3.0, 3.0}) == 1);
}

TEST_CASE("cin2021.eq2: a zero decision value votes for the second class of the pair", "[cin2021][mutants]") {
  // x = 0.5: K(0.5, 0) = K(0.5, 1) = 2^-0.25, so pair (0,1) decides exactly 0 -> a vote for 1;
  // pair (0,2): 2^-0.25 - 2^-2.25 > 0 -> 0; pair (1,2): > 0 -> 1. Votes 0:1, 1:2 -> class 1
  // (with f >= 0 read as a vote for the first class it would be 2:1 -> class 0).
  const ml::SvmModel m = hand_svm();
  ml::validate(m);
  const std::vector<double> x{0.5};
  const auto dec = ml::svm_decision_values(m, x);
  REQUIRE(dec[0] == 0.0);
  CHECK(dec[1] > 0.0);
  CHECK(dec[2] > 0.0);
  CHECK(ml::predict(m, x) == 1);
}

TEST_CASE("cin2021.eq2: rho is subtracted from the kernel sum", "[cin2021][mutants]") {
  // x = 1: pair (0,1) sums K(1,0) - K(1,1) = 0.5 - 1 = -0.5; with rho = 0.25 the decision is -0.75
  ml::SvmModel m = hand_svm();
  m.rho = {0.25, -0.5, 0.0};
  ml::validate(m);
  const auto dec = ml::svm_decision_values(m, std::vector<double>{1.0});
  CHECK(dec[0] == Approx(-0.75).epsilon(1e-12));
  CHECK(dec[1] == Approx(0.5).epsilon(1e-12));  // 0.5 - 0.5 - (-0.5)
}

TEST_CASE("cin2021.eq6: averaged probabilities normalise each tree's counts", "[cin2021][mutants]") {
  // tree 1 {1, 0}: P = (1, 0); tree 2 {2, 4}: P = (1/3, 2/3). Mean P(0) = 2/3 -> class 0; the raw
  // count sums (3, 4) would say class 1.
  CHECK(ml::combine_votes(std::vector<double>{1, 0, 2, 4}, 2, ml::ForestVote::mean_proba) == 0);
  CHECK(ml::combine_votes(std::vector<double>{1, 0, 2, 4}, 2, ml::ForestVote::majority) == 0);  // 1 : 1
}

TEST_CASE("cin2021.eq6: a tree whose counts tie votes for its first class", "[cin2021][mutants]") {
  // tree 1 {2, 2} votes 0 (first of the tied), tree 2 {1, 3} votes 1: 1 : 1 -> class 0
  CHECK(ml::combine_votes(std::vector<double>{2, 2, 1, 3}, 2, ml::ForestVote::majority) == 0);
  // tree 1 {2, 2} -> 0, tree 2 {3, 1} -> 0: class 0 either way, tree 3 {0, 5} -> 1: 2 : 1
  CHECK(ml::combine_votes(std::vector<double>{2, 2, 3, 1, 0, 5}, 2, ml::ForestVote::majority) == 0);
}

TEST_CASE("cin2021.srrt.curve: the repair's nearest-node tie goes to the first raw index", "[cin2021][mutants]") {
  // World [0, 10] x [-4, 4], obstacle [4.5, 5.5] x [-0.5, 0.5], inflation 0. Degree 1 over
  // kept = {0, 3}: the curve is the segment (1, 0)-(9, 0); every sample has y = 0 exactly
  // (a combination of two zero coordinates) and crosses the square, so the verdict is `enters`.
  // Clamped knots {0, 0, 1, 1}: span_index gives k = 1 for every u, so the candidates are the raw
  // indices strictly between kept[0] = 0 and kept[1] = 3: 1 and 2. Nodes (5, 2) and (5, -2) are
  // mirror images in y = 0: for any sample (x, 0) both squared distances are (5 - x)^2 + 4, the
  // same double. The spec's tie rule (smallest index) re-inserts 1; a `<=` comparison would
  // take the later node, 2. After one insertion the polyline (1,0)-(5,+-2)-(9,0) keeps > 1 away
  // from the square (line x -+ 2y - 1 = 0 is 2.5 / sqrt(5) from the nearest corner): clear.
  const std::string text =
      "{\"format\": \"pathref-scene 1\", \"origin\": [0, -4], \"width\": 10, \"height\": 8, "
      "\"cell_size\": 1, \"radius\": 0, \"margin\": 0, "
      "\"polygons\": [{\"vertices\": [[4.5, -0.5], [5.5, -0.5], [5.5, 0.5], [4.5, 0.5]]}], "
      "\"start\": [0, 0], \"goal\": [1, 0]}";
  const auto m = geometry::ObstacleMap::from_scene(io::parse_scene_json(text, "t.json"));
  continuous::CurveParams p;
  p.degree = 1;
  const continuous::CurveParams no_repair = p;  // degree 1, repair off
  p.repair = true;
  const std::vector<std::size_t> kept = {0, 3};
  for (const double first_y : {2.0, -2.0}) {  // either node first: the first one wins
    const std::vector<continuous::Vec2> raw = {{1, 0}, {5, first_y}, {5, -first_y}, {9, 0}};
    const auto off = continuous::smooth_path(m, raw, kept, no_repair);
    REQUIRE(off.clearance.verdict == geometry::ClearanceVerdict::enters);
    const auto s = static_cast<std::size_t>(off.clearance.segment);
    REQUIRE(off.samples.points[s].y == 0.0);
    const auto r = continuous::smooth_path(m, raw, kept, p);
    CHECK(r.repair == "clear");
    CHECK(r.inserted == std::vector<std::size_t>{1});
    CHECK(r.kept == std::vector<std::size_t>{0, 1, 3});
    CHECK(r.degree == 1);
  }
}

TEST_CASE("cin2021.eq35: the dead-end penalty lowers the arc into the dead end, not the arc beyond", "[cin2021][mutants]") {
  // Map: one row of three free cells D = (0,0), S = (1,0), G = (2,0). aco-cin, 2 ants, 1 iteration,
  // dead_angle = penalise_only (D stays allowed after it is recorded), other defaults: alpha 1,
  // beta 2, tau0 0.1, lambda 0.5, eta = 1 / distance = 1 for both moves, proportional selection
  // (one roulette draw per step, also with a single candidate). At S the candidates in canonical
  // order are D (slot S*8+3, left) and G (slot S*8+4, right).
  // Seed 2's draws (res53 of init_genrand(2)): u0 = 0.43599..., u1 = 0.02592..., u2 = 0.54966...
  // Ant 0 at S: weights (0.1, 0.1), D iff 0.1 >= u0 * 0.2: D. At D: S is tabu, no move: a deadlock
  // point (one allowed move, into S, outside the table); Eq. 35 multiplies every arc INTO D by
  // lambda: tau(S -> D) = 0.5 * 0.1 = 0.05 (tau(S -> G) untouched). Back at S: only G, draw u1.
  // Ant 1 at S: weights (0.05, 0.1), D iff 0.05 >= u2 * 0.15 (u2 <= 1/3): no, G.
  // So deadlocks = 1, table [[0,0]], draws = 3, path S, G. Penalising slot S*8 + dir(D -> S) = S*8+4
  // instead (the arc S -> G, leading away from D) gives weights (0.1, 0.05): D iff u2 <= 2/3, a
  // second deadlock and a fourth draw.
  rng::Stream st(2);
  const double u0 = st.next_double();
  const double u1 = st.next_double();
  const double u2 = st.next_double();
  REQUIRE(u0 <= 0.5);
  REQUIRE(u1 < 1.0);
  REQUIRE(u2 > 1.0 / 3.0);
  REQUIRE(u2 < 2.0 / 3.0);
  // Eq. 35 written out for ant 1's choice, and the roulette it implies
  const double tau0 = 0.1;
  const double lambda = 0.5;
  CHECK(rng::roulette(std::vector<double>{tau0, tau0}, u0) == 0);                 // ant 0 -> D
  CHECK(rng::roulette(std::vector<double>{lambda * tau0, tau0}, u2) == 1);        // ant 1 -> G
  CHECK(rng::roulette(std::vector<double>{tau0, lambda * tau0}, u2) == 0);        // wrong slot -> D
  const grid::Grid g = grid::Grid::from_rows_top_first({"..."});
  planners::Request req;
  req.grid = &g;
  req.start = Cell{1, 0};
  req.goal = Cell{2, 0};
  req.seed = 2;
  req.params = planners::Json{{"ants", 2}, {"iterations", 1}, {"dead_angle", "penalise_only"}};
  const auto r = planners::find_planner("aco-cin")->run(req);
  REQUIRE(r.found);
  CHECK(r.path == std::vector<Cell>{{1, 0}, {2, 0}});
  CHECK(r.extra.at("deadlocks") == 1);
  CHECK(r.extra.at("dead_angle_table") == planners::Json::parse("[[0,0]]"));
  CHECK(r.extra.at("draws") == 3);
  CHECK(r.extra.at("dead_ants_per_iteration") == planners::Json::parse("[0]"));
}
