#include "pathref/planners/search.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "pathref/core/error.hpp"

namespace pathref::search {

bool precedes(const OpenKey& a, const OpenKey& b) noexcept {
  if (a.f < b.f) return true;
  if (b.f < a.f) return false;
  if (a.h < b.h) return true;
  if (b.h < a.h) return false;
  return a.index < b.index;
}

namespace {

/// One heap entry. An entry is current iff its g equals the cell's best g and the cell is not
/// closed; older entries of the same cell (larger g) are skipped when they surface. This lazy
/// deletion realises exactly the abstract OPEN set of spec/search.md: each open cell has one
/// current entry, keyed by its current g.
struct Entry {
  double f;
  double h;
  double g;
  std::int64_t index;
};

/// std::push_heap/pop_heap build a max-heap; "a is later than b" puts the first key on top.
bool later(const Entry& a, const Entry& b) noexcept {
  return precedes(OpenKey{b.f, b.h, b.index}, OpenKey{a.f, a.h, a.index});
}

enum : std::uint8_t { unseen = 0, open = 1, closed = 2 };

}  // namespace

Outcome astar(const grid::Grid& g, grid::Cell start, grid::Cell goal, grid::CornerPolicy policy,
              heuristics::Heuristic h) {
  require(g.in_bounds(start), "search: start cell outside the grid");
  require(g.in_bounds(goal), "search: goal cell outside the grid");
  require(g.free(start), "search: start cell is blocked");
  require(g.free(goal), "search: goal cell is blocked");

  const auto cells = static_cast<std::size_t>(g.cell_count());
  const std::int64_t goal_index = g.index(goal);
  std::vector<double> best_g(cells, std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> parent(cells, -1);
  std::vector<std::uint8_t> state(cells, unseen);
  std::vector<Entry> heap;

  Outcome out;
  const std::int64_t start_index = g.index(start);
  const double h_start = heuristics::evaluate(h, start, goal);
  best_g[static_cast<std::size_t>(start_index)] = 0.0;
  state[static_cast<std::size_t>(start_index)] = open;
  heap.push_back(Entry{0.0 + h_start, h_start, 0.0, start_index});

  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const Entry e = heap.back();
    heap.pop_back();
    const auto ei = static_cast<std::size_t>(e.index);
    if (state[ei] == closed || e.g != best_g[ei]) continue;  // stale entry: not an expansion
    state[ei] = closed;
    ++out.expansions;

    if (e.index == goal_index) {
      out.found = true;
      out.length = e.g;
      for (std::int64_t i = e.index; i != -1; i = parent[static_cast<std::size_t>(i)])
        out.path.push_back(g.cell(i));
      std::reverse(out.path.begin(), out.path.end());
      return out;
    }

    const grid::Cell c = g.cell(e.index);
    // Canonical neighbour order (grid.neighbour-order); the order cannot change the result
    // (spec/search.md: each neighbour is relaxed once per expansion, independently).
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const grid::Cell m{c.x + dx, c.y + dy};
        if (!grid::step_allowed(g, c, m, policy)) continue;
        const std::int64_t mi = g.index(m);
        const auto ui = static_cast<std::size_t>(mi);
        if (state[ui] == closed) continue;  // no reopening
        const double g_new = e.g + grid::step_cost(c, m);
        if (state[ui] == unseen || g_new < best_g[ui]) {  // parent changes on strictly smaller g
          best_g[ui] = g_new;
          parent[ui] = e.index;
          state[ui] = open;
          const double h_m = heuristics::evaluate(h, m, goal);
          heap.push_back(Entry{g_new + h_m, h_m, g_new, mi});
          std::push_heap(heap.begin(), heap.end(), later);
        }
      }
    }
  }
  return out;  // OPEN exhausted: goal unreachable
}

Outcome dijkstra(const grid::Grid& g, grid::Cell start, grid::Cell goal, grid::CornerPolicy policy) {
  return astar(g, start, goal, policy, heuristics::Heuristic::zero);
}

StepCounts step_counts(std::span<const grid::Cell> path) {
  StepCounts s;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const std::int64_t dx = std::llabs(path[k].x - path[k - 1].x);
    const std::int64_t dy = std::llabs(path[k].y - path[k - 1].y);
    require(dx <= 1 && dy <= 1 && dx + dy >= 1,
            "step_counts: consecutive cells must be distinct 8-neighbours");
    if (dx + dy == 2) {
      ++s.diagonal;
    } else {
      ++s.orthogonal;
    }
  }
  return s;
}

}  // namespace pathref::search

namespace pathref::planners {

namespace {

Result to_result(search::Outcome o, Json params_used, Json extra) {
  Result r;
  r.found = o.found;
  r.path = std::move(o.path);
  r.length = o.length;
  r.expansions = o.expansions;
  r.params_used = std::move(params_used);
  r.extra = std::move(extra);
  return r;
}

const grid::Grid& grid_of(const Request& req) {
  if (req.grid == nullptr) throw UsageError("plan request without a grid");
  return *req.grid;
}

}  // namespace

Planner make_astar_planner() {
  Planner p;
  p.name = "astar";
  p.description =
      "A* (Hart, Nilsson & Raphael 1968; Han Eq. 8 with heuristic=chebyshev), tie-break (f, h, "
      "cell index), spec/search.md";
  p.defaults = Json{{"heuristic", "octile"}};
  p.run = [defaults = p.defaults](const Request& req) {
    const grid::Grid& g = grid_of(req);
    Json params = merge_params(defaults, req.params);
    const auto h = heuristics::parse_heuristic(params.at("heuristic").get<std::string>());
    Json extra = {{"admissible", heuristics::admissible(h, req.policy)},
                  {"consistent", heuristics::consistent(h, req.policy)}};
    return to_result(search::astar(g, req.start, req.goal, req.policy, h), std::move(params),
                     std::move(extra));
  };
  return p;
}

Planner make_dijkstra_planner() {
  Planner p;
  p.name = "dijkstra";
  p.description = "Dijkstra (1959): A* with h = 0, tie-break (g, cell index), spec/search.md";
  p.defaults = Json::object();
  p.run = [defaults = p.defaults](const Request& req) {
    const grid::Grid& g = grid_of(req);
    Json params = merge_params(defaults, req.params);
    return to_result(search::dijkstra(g, req.start, req.goal, req.policy), std::move(params),
                     Json::object());
  };
  return p;
}

}  // namespace pathref::planners
