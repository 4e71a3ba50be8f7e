// Boundary and tie cases of the comparison rules (issue 17), each checked against a value derived
// by hand in the comment beside it or a formula written out literally here, never against the
// function under test or the function a rule wraps. tools/mutate's catalogue names the mutants
// these cases kill (docs/testing.md).
// spec: han.collision.classify, han.eq3, han.eq4, han.eq5, han.eq7, shi2022.eq13, rng.roulette,
// mecanum.ik, mecanum.fk, shi2022.plan.ga, sensors2023.eq1, han.eq1, cin2021.eq24, han.sim.detour,
// han.sim.evade
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pathref/equations/aco.hpp"
#include "pathref/equations/aco_adaptive.hpp"
#include "pathref/equations/cin2021.hpp"
#include "pathref/equations/corner.hpp"
#include "pathref/equations/pseudo_random.hpp"
#include "pathref/equations/sensors2023.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/trace.hpp"
#include "pathref/sim/encounter.hpp"
#include "pathref/vehicle/mecanum.hpp"

using namespace pathref;

TEST_CASE("han.collision.classify: D = c exactly is no encounter and c just above it is one") {
  // Robot along the x axis from (0,0) to (4,0); the obstacle moves from (2,0.5) to (2,1), straight
  // away from it. D = 0.5 exactly (the vertical gap at x = 2), so with clearance 0.5 the spec's
  // "D >= c: none" applies; with the next double above 0.5 the obstacle is within the clearance.
  const std::vector<sim::Vec2> robot{{0.0, 0.0}, {4.0, 0.0}};
  const sim::Classification at = sim::classify(robot, {2.0, 0.5}, {2.0, 1.0}, 0.5);
  CHECK(at.distance == 0.5);
  CHECK(at.kind == sim::Encounter::none);
  const sim::Classification above = sim::classify(robot, {2.0, 0.5}, {2.0, 1.0}, std::nextafter(0.5, 1.0));
  // u = (4,0), v = (0,0.5): u.v = 0 > -cos(45 deg) |u||v|, so side, not frontal.
  CHECK(above.kind == sim::Encounter::side);
  // A static obstacle at distance exactly c: none; just inside: frontal (static is always frontal).
  CHECK(sim::classify(robot, {2.0, 0.5}, {2.0, 0.5}, 0.5).kind == sim::Encounter::none);
  CHECK(sim::classify(robot, {2.0, 0.5}, {2.0, 0.5}, 0.75).kind == sim::Encounter::frontal);
}

TEST_CASE("han.collision.classify: a tie between pieces goes to the first piece") {
  // Robot (0,0) -> (2,0) -> (2,2); obstacle (3,-1) -> (4,-3). Both pieces are nearest at their
  // shared point (2,0), at distance sqrt(2) from p = (3,-1): a tie. The spec takes the first piece
  // (piece 0, u = (2,0)): u.v = 2 for v = (1,-2), cos = 2/(2 sqrt 5) > -0.7071, so side. Piece 1
  // (u = (0,2)) would give u.v = -4, cos = -0.894 <= -0.7071: frontal.
  const std::vector<sim::Vec2> robot{{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}};
  const sim::Classification c = sim::classify(robot, {3.0, -1.0}, {4.0, -3.0}, 2.0);
  CHECK(c.distance == Approx(std::sqrt(2.0)).epsilon(1e-15));
  CHECK(c.piece == 0);
  CHECK(c.kind == sim::Encounter::side);
  // The frontal boundary itself: u = (1,0), v = (-1,0) moving head-on: cos = -1 <= frontal_cos.
  // With frontal_cos = -1 exactly, u.v = -1 == (-1 * 1) * 1: the spec's "<=" makes it frontal.
  const std::vector<sim::Vec2> line{{0.0, 0.0}, {1.0, 0.0}};
  CHECK(sim::classify(line, {3.0, 0.25}, {2.0, 0.25}, 2.0, -1.0).kind == sim::Encounter::frontal);
}

TEST_CASE("han.eq4: q = q0 takes the argmax and an argmax tie takes the first maximum") {
  const std::vector<double> w{1.0, 3.0, 3.0, 2.0};
  // q == q0: argmax (spec han.eq4, "q = q0 takes the argmax"), the first of the tied 3s.
  const aco::PseudoRandomChoice c = aco::pseudo_random_choice(w, 0.5, 0.5, 0.0);
  CHECK(c.mode == aco::ChoiceMode::argmax);
  CHECK(c.index == 1);
  // q just above q0: the roulette with u = 0: the first positive weight (index 0).
  const aco::PseudoRandomChoice r = aco::pseudo_random_choice(w, std::nextafter(0.5, 1.0), 0.5, 0.0);
  CHECK(r.mode == aco::ChoiceMode::roulette);
  CHECK(r.index == 0);
  CHECK(aco::argmax_weight(std::vector<double>{2.0, 2.0}) == 0);
}

TEST_CASE("rng.roulette: an exact cumulative-sum tie stops at the piece it completes") {
  // Integer weights: every product u * total and every partial sum is exact. The spec returns the
  // first k with cumsum_k >= u * total, so at u * total == cumsum_k exactly it returns k.
  const std::vector<double> w{1.0, 1.0, 2.0};  // total 4, cumulative 1, 2, 4
  CHECK(rng::roulette(w, 0.25) == 0);  // target 1 == cumsum_0
  CHECK(rng::roulette(w, 0.5) == 1);   // target 2 == cumsum_1
  CHECK(rng::roulette(w, std::nextafter(0.25, 1.0)) == 1);
  CHECK(rng::roulette(w, 0.0) == 0);
  // A zero weight never wins, even when the target equals the sum before it.
  const std::vector<double> z{2.0, 0.0, 2.0};
  CHECK(rng::roulette(z, 0.5) == 0);                          // target 2 == cumsum_0
  CHECK(rng::roulette(z, std::nextafter(0.5, 1.0)) == 2);     // past it: skips the 0
}

TEST_CASE("han.eq7: the stepped factor at d = a and d = b exactly") {
  // f = 0.9 for d > b, 0.8 for a < d <= b, 0.7 for d <= a (spec han.eq7); rho = max(f rho, rho_min).
  const auto ref = aco::SpreadReference::iteration_worst;
  CHECK(aco::stepped_rho(0.5, 10.0, 6.0, 2.0, 4.0, 0.01, ref) == 0.8 * 0.5);  // d = 4 = b
  CHECK(aco::stepped_rho(0.5, 8.0, 6.0, 2.0, 4.0, 0.01, ref) == 0.7 * 0.5);   // d = 2 = a
  CHECK(aco::stepped_rho(0.5, 11.0, 6.0, 2.0, 4.0, 0.01, ref) == 0.9 * 0.5);  // d = 5 > b
  CHECK(aco::stepped_rho(0.5, 9.0, 6.0, 2.0, 4.0, 0.01, ref) == 0.8 * 0.5);   // a < d = 3 < b
  CHECK(aco::stepped_rho(0.5, 10.0, 6.0, 2.0, 4.0, 0.45, ref) == 0.45);       // the floor
}

TEST_CASE("han.eq5 and shi2022.eq13: the formulas written out at hand-computed points") {
  // han.eq5: q0 = eps (0.2 + 0.7 (N_max - N_c)/N_max). At N_c = 0: 0.2 + 0.7 = 0.8999999999999999
  // in binary64 (spec/han.md); at N_c = N_max: 0.2; at N_c = 25 of 50: 0.2 + 0.35 = 0.55.
  CHECK(aco::adaptive_q0(1.0, 0, 50) == 0.8999999999999999);
  CHECK(aco::adaptive_q0(1.0, 50, 50) == 0.2);
  CHECK(aco::adaptive_q0(1.0, 25, 50) == Approx(0.55).epsilon(1e-15));
  CHECK(aco::adaptive_q0(0.5, 25, 50) == Approx(0.275).epsilon(1e-15));
  // shi2022.eq13 (factor reading): rho(t) = max(T/(T+t) * e^-(1-rho) * rho, rho_min).
  // rho = 0.9, t = 1, T = 100: 100/101 * e^-0.1 * 0.9 = 0.806290768546... (e^-0.1 = 0.904837418036).
  CHECK(aco::adaptive_rho(0.9, 1, 100, 0.1, aco::RhoReading::factor) ==
        Approx(0.80629076854689).epsilon(1e-12));
  // rho = 0.5, t = 0: e^-0.5 * 0.5 = 0.303265329856...
  CHECK(aco::adaptive_rho(0.5, 0, 100, 0.1, aco::RhoReading::factor) ==
        Approx(0.30326532985631671).epsilon(1e-12));
  CHECK(aco::adaptive_rho(0.2, 0, 100, 0.1, aco::RhoReading::factor) == 0.1);  // 0.0898... < rho_min
}

TEST_CASE("han.eq3: the 90 degree turn under both readings") {
  const grid::Cell prev{0, 0}, cur{1, 0};
  // A 90 degree turn (dot of the two steps = 0): T = 2 under at90 = two, T = 1 under at90 = one.
  CHECK(corner::turning_cost(prev, cur, grid::Cell{1, 1}, corner::OmegaForm::multiply, corner::At90::two) == 2);
  CHECK(corner::turning_cost(prev, cur, grid::Cell{1, 1}, corner::OmegaForm::multiply, corner::At90::one) == 1);
  CHECK(corner::turning_cost(prev, cur, grid::Cell{2, 0}, corner::OmegaForm::multiply, corner::At90::one) == 2);
  CHECK(corner::turning_cost(prev, cur, grid::Cell{0, 1}, corner::OmegaForm::multiply, corner::At90::one) == 1);
}

TEST_CASE("sensors2023.eq1: a bearing on a sector boundary belongs to the sector it opens") {
  // Sector s covers [22.5 + 45(s-1), 22.5 + 45 s) (spec/sensors2023.md): 22.5 opens sector 1,
  // 337.5 opens sector 0, and the double just below 22.5 is still sector 0.
  CHECK(sensors2023::bearing_sector(22.5) == 1);
  CHECK(sensors2023::bearing_sector(std::nextafter(22.5, 0.0)) == 0);
  CHECK(sensors2023::bearing_sector(67.5) == 2);
  CHECK(sensors2023::bearing_sector(337.5) == 0);
  CHECK(sensors2023::bearing_sector(std::nextafter(337.5, 0.0)) == 7);
}

TEST_CASE("mecanum.ik and mecanum.fk: the closed forms of spec/mecanum.md at exact inputs") {
  // r = 0.5, k = lx + ly = 0.25 (binary-exact), t = (1, 2, 4):
  //   w_FL = (vx - vy - k w)/r = (1 - 2 - 1)/0.5 = -4    w_FR = (vx + vy + k w)/r = 8
  //   w_RL = (vx + vy - k w)/r = 4                       w_RR = (vx - vy + k w)/r = 0
  const vehicle::Geometry g{0.5, 0.125, 0.125};
  const vehicle::WheelSpeeds w = vehicle::inverse_kinematics(vehicle::Twist{1.0, 2.0, 4.0}, g);
  CHECK(w(0) == -4.0);
  CHECK(w(1) == 8.0);
  CHECK(w(2) == 4.0);
  CHECK(w(3) == 0.0);
  // FK (spec): vx = r/4 (w1+w2+w3+w4) = 1, vy = r/4 (-w1+w2+w3-w4) = 2,
  // omega = r/(4k) (-w1+w2-w3+w4) = 0.5 * 8 = 4 — here for wheels not produced by IK as well:
  // (1, 0, 0, 0): vx = 0.125, vy = -0.125, omega = -0.5 (least squares of the same 4x3 system).
  const vehicle::Twist t = vehicle::forward_kinematics(w, g);
  CHECK(t.vx == Approx(1.0).epsilon(1e-14));
  CHECK(t.vy == Approx(2.0).epsilon(1e-14));
  CHECK(t.omega == Approx(4.0).epsilon(1e-14));
  const vehicle::Twist e = vehicle::forward_kinematics(vehicle::WheelSpeeds(1.0, 0.0, 0.0, 0.0), g);
  CHECK(e.vx == Approx(0.125).epsilon(1e-14));
  CHECK(e.vy == Approx(-0.125).epsilon(1e-14));
  CHECK(e.omega == Approx(-0.5).epsilon(1e-14));
}

TEST_CASE("shi2022.plan.ga: with pm = 1 every individual of a 3-node path draws a mutation gene") {
  // 3x3 open map from (0,0) to (2,0): every path has at least one interior gene (Chebyshev
  // distance 2), so under pm = 1 every "mutation test" draw (u < 1 always) must be followed by a
  // "mutation gene" draw (shi2022.plan.ga step 4) — the same number of each, and at least one.
  const grid::Grid g(3, 3);
  const planners::Planner* p = planners::find_planner("ga");
  REQUIRE(p != nullptr);
  planners::Request req;
  req.grid = &g;
  req.start = grid::Cell{0, 0};
  req.goal = grid::Cell{2, 0};
  req.seed = 1;
  req.params = planners::Json{{"population", 6}, {"generations", 3}, {"pm", 1.0}};
  rng::Trace trace;
  req.trace = &trace;
  const planners::Result r = p->run(req);
  REQUIRE(r.found);
  std::int64_t tests = 0, genes = 0;
  for (const rng::Draw& d : trace.draws()) {
    if (d.purpose.find("mutation test") != std::string::npos) ++tests;
    if (d.purpose.find("mutation gene") != std::string::npos) ++genes;
  }
  CHECK(tests > 0);
  CHECK(genes == tests);
}

TEST_CASE("han.eq1: the corner factor multiplies the weight, by hand") {
  // w_j = tau_j^alpha * eta_j^beta * omega_j^gamma (spec han.eq1) with alpha = 1, beta = 2,
  // gamma = 1: tau = (1, 2), eta = (0.5, 1), omega = (2, 4) -> w = (1 * 0.25 * 2, 2 * 1 * 4) = (0.5, 8);
  // with gamma = 2: (1 * 0.25 * 4, 2 * 1 * 16) = (1, 32).
  const std::vector<double> tau{1.0, 2.0}, eta{0.5, 1.0}, omega{2.0, 4.0};
  const std::vector<double> w = aco::transition_weights(tau, eta, 1.0, 2.0, aco::CornerFactor{omega, 1.0});
  REQUIRE(w.size() == 2);
  CHECK(w[0] == 0.5);
  CHECK(w[1] == 8.0);
  const std::vector<double> w2 = aco::transition_weights(tau, eta, 1.0, 2.0, aco::CornerFactor{omega, 2.0});
  CHECK(w2[0] == 1.0);
  CHECK(w2[1] == 32.0);
}

TEST_CASE("cin2021.eq24: each band opens at its lower edge minus eps, exactly") {
  // spec cin2021.eq24 with eps = 1e-3 degrees and the default penalties (c135, c90, c45) =
  // (5, 100, 1000): theta in [180 - eps, 180 + eps] -> 0, [135 - eps, 180 - eps) -> c135,
  // [90 - eps, 135 - eps) -> c90, below 90 - eps -> c45. At each edge the band above it applies;
  // one double below the edge, the band below.
  constexpr double eps = 1e-3;
  CHECK(cin::corner_penalty(180.0 - eps) == 0.0);
  CHECK(cin::corner_penalty(std::nextafter(180.0 - eps, 0.0)) == 5.0);
  CHECK(cin::corner_penalty(135.0 - eps) == 5.0);
  CHECK(cin::corner_penalty(std::nextafter(135.0 - eps, 0.0)) == 100.0);
  CHECK(cin::corner_penalty(90.0 - eps) == 100.0);
  CHECK(cin::corner_penalty(std::nextafter(90.0 - eps, 0.0)) == 1000.0);
}

TEST_CASE("han.sim.detour: a cell centre at exactly the reach is not swept") {
  // reach = clearance + sqrt(2)/2 (spec han.sim.detour). With clearance = 1 - sqrt(2)/2 (exact in
  // binary64: Sterbenz) the reach is exactly 1. The segment runs through the centres of the top
  // row of a 3x3 map, y = 2.5: the middle row's centres (y = 1.5) are exactly 1 away and are
  // not swept (strict <); the top row is (distance 0); the bottom row is 2 away.
  const grid::Grid g(3, 3);
  const double s = std::sqrt(2.0) / 2.0;
  const double clearance = 1.0 - s;
  REQUIRE(clearance + s == 1.0);
  const std::vector<grid::Cell> swept = sim::swept_cells(g, {0.5, 2.5}, {2.5, 2.5}, clearance);
  CHECK(swept == std::vector<grid::Cell>{{0, 2}, {1, 2}, {2, 2}});
  // clearance (1 + 2^-52) - sqrt(2)/2 (exact again): the reach is the next double above 1 and the
  // middle row's centres are now inside it
  const double wider_clearance = std::nextafter(1.0, 2.0) - s;
  REQUIRE(wider_clearance + s == std::nextafter(1.0, 2.0));
  const std::vector<grid::Cell> wider = sim::swept_cells(g, {0.5, 2.5}, {2.5, 2.5}, wider_clearance);
  CHECK(wider == std::vector<grid::Cell>{{0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}});
}

TEST_CASE("han.sim.evade: equal-cost routes keep the parent settled first") {
  // 3x1 free map; sources (0,0) and (2,0) both with cost 1; only the middle cell (1,0) is outside
  // the band. Both sources reach it at cost 1 + 1 = 2 (spec han.sim.evade: a parent is replaced
  // only on a strictly smaller g). The queue pops (1, index 0) first, so the refuge path starts at
  // source 0: [(0,0), (1,0)]; a "<=" relaxation would hand it to source 1, [(2,0), (1,0)].
  const grid::Grid g(3, 1);
  const std::vector<sim::RefugeSource> sources{{grid::Cell{0, 0}, 1.0}, {grid::Cell{2, 0}, 1.0}};
  const std::vector<std::uint8_t> band{1, 0, 1};
  for (const grid::CornerPolicy policy : {grid::CornerPolicy::never, grid::CornerPolicy::strict}) {
    const sim::Refuge r = sim::find_refuge(g, sources, band, policy);
    REQUIRE(r.found);
    CHECK(r.cost == 2.0);
    CHECK(r.source == 0);
    CHECK(r.path == std::vector<grid::Cell>{{0, 0}, {1, 0}});
  }
}
