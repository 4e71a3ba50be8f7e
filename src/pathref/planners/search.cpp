#include "pathref/planners/search.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>

#include "pathref/core/error.hpp"

namespace pathref::search {

namespace {

/// One heap entry: the key of a cell at the time it was put in OPEN. When a cell's g improves, a
/// new entry is pushed and the old one stays (lazy deletion). An old entry has a larger g, hence
/// a key that does not precede the new one (f = fl(g + h) is monotone in g; h and index are the
/// same), so the first entry of a cell to surface carries the cell's current key (or an equal
/// one): expanding the cell then with its current g is exactly the selection of spec/search.md,
/// and every later entry of the cell finds it closed and is skipped (not an expansion).
struct Entry {
  double f;
  double h;
  std::int64_t index;
};

/// std::push_heap/pop_heap build a max-heap; "a is later than b" puts the first key on top.
/// A function object (not a function pointer) so that the comparison is inlined.
struct Later {
  bool operator()(const Entry& a, const Entry& b) const noexcept {
    return precedes(OpenKey{b.f, b.h, b.index}, OpenKey{a.f, a.h, a.index});
  }
};

/// Per-cell state. `unknown` = not looked at yet; the grid is asked once whether the cell is
/// free (Grid::free), and the answer is cached here together with the search state.
enum : std::uint8_t { unknown = 0, blocked = 1, unseen = 2, open = 3, closed = 4 };

struct Offset {
  std::int64_t dx;
  std::int64_t dy;
  double cost;  // grid::step_cost
};

/// The 8 moves in grid.neighbour-order with their costs from grid::step_cost.
std::array<Offset, 8> offsets() {
  std::array<Offset, 8> o{};
  std::size_t k = 0;
  for (std::int64_t dy = -1; dy <= 1; ++dy)
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      if (dx != 0 || dy != 0)
        o[k++] = Offset{dx, dy, grid::step_cost(grid::Cell{0, 0}, grid::Cell{dx, dy})};
  return o;
}

}  // namespace

Outcome astar(const grid::Grid& g, grid::Cell start, grid::Cell goal, grid::CornerPolicy policy,
              heuristics::Heuristic h) {
  require(g.in_bounds(start), "search: start cell outside the grid");
  require(g.in_bounds(goal), "search: goal cell outside the grid");
  require(g.free(start), "search: start cell is blocked");
  require(g.free(goal), "search: goal cell is blocked");

  const std::int64_t width = g.width();
  const std::int64_t height = g.height();
  const auto cells = static_cast<std::size_t>(g.cell_count());
  const std::int64_t goal_index = g.index(goal);
  const std::array<Offset, 8> moves = offsets();
  std::vector<double> best_g(cells, std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> parent(cells, -1);
  std::vector<std::uint8_t> state(cells, unknown);
  std::vector<Entry> heap;

  Outcome out;
  const std::int64_t start_index = g.index(start);
  const double h_start = heuristics::evaluate(h, start, goal);
  best_g[static_cast<std::size_t>(start_index)] = 0.0;
  state[static_cast<std::size_t>(start_index)] = open;
  heap.push_back(Entry{0.0 + h_start, h_start, start_index});

  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), Later{});
    const Entry e = heap.back();
    heap.pop_back();
    const auto ei = static_cast<std::size_t>(e.index);
    if (state[ei] == closed) continue;  // an older entry of a closed cell: not an expansion
    state[ei] = closed;
    ++out.expansions;
    const double g_here = best_g[ei];

    if (e.index == goal_index) {
      out.found = true;
      out.length = g_here;
      for (std::int64_t i = e.index; i != -1; i = parent[static_cast<std::size_t>(i)])
        out.path.push_back(g.cell(i));
      std::reverse(out.path.begin(), out.path.end());
      return out;
    }

    const grid::Cell c = g.cell(e.index);
    // Canonical neighbour order (grid.neighbour-order); the order cannot change the result
    // (spec/search.md: each neighbour is relaxed once per expansion, independently).
    for (const Offset& mv : moves) {
      const grid::Cell m{c.x + mv.dx, c.y + mv.dy};
      if (m.x < 0 || m.y < 0 || m.x >= width || m.y >= height) continue;
      const std::int64_t mi = m.y * width + m.x;  // grid.index
      const auto ui = static_cast<std::size_t>(mi);
      if (state[ui] == unknown) state[ui] = g.free(m) ? unseen : blocked;
      if (state[ui] == blocked || state[ui] == closed) continue;  // closed: no reopening
      // c and m are free: an orthogonal step is allowed under every policy; a diagonal one
      // depends on the policy and the two cells it passes between (grid.corner-policy).
      if (mv.dx != 0 && mv.dy != 0 && !grid::step_allowed(g, c, m, policy)) continue;
      const double g_new = g_here + mv.cost;
      if (state[ui] == unseen || g_new < best_g[ui]) {  // parent changes on strictly smaller g
        best_g[ui] = g_new;
        parent[ui] = e.index;
        state[ui] = open;
        const double h_m = heuristics::evaluate(h, m, goal);
        heap.push_back(Entry{g_new + h_m, h_m, mi});
        std::push_heap(heap.begin(), heap.end(), Later{});
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
