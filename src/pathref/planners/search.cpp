#include "pathref/planners/search.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>
#include <limits>
#include <optional>
#include <type_traits>

#include <fmt/core.h>

#include "pathref/core/error.hpp"
#include "pathref/core/memory.hpp"

namespace pathref::search {

namespace core {

/// One open-list entry: the key of a cell at the time it was put in OPEN. When a cell's g improves, a
/// new entry is pushed and the old one stays (lazy deletion). An old entry has a larger g, hence
/// a key that does not precede the new one (f = fl(g + h) is monotone in g; h and index are the
/// same), so the first entry of a cell to surface carries the cell's current key (or an equal
/// one): expanding the cell then with its current g is exactly the selection of spec/search.md,
/// and every later entry of the cell finds it closed and is skipped (not an expansion).
struct Entry {
  std::uint64_t f;      // order_bits(f)
  std::uint64_t h;      // order_bits(h)
  std::uint32_t index;  // cell index (W * H <= 2^28)
};

/// The entry of a search with h = 0 for every cell (Dijkstra): the key (g, 0, index) of
/// search.order with its constant middle part left out (equal h never decide), 16 bytes.
struct GEntry {
  std::uint64_t f;      // order_bits(f) = order_bits(g)
  std::uint32_t index;  // cell index
};

/// An unsigned integer whose order is the order of the doubles (for every non-NaN double, with
/// -0 mapped to +0, which compare equal as doubles): the sign-magnitude bits turned into an
/// offset binary. Exact: a < b as doubles iff order_bits(a) < order_bits(b), a == b iff equal.
[[nodiscard]] inline std::uint64_t order_bits(double x) noexcept {
  const auto b = std::bit_cast<std::uint64_t>(x + 0.0);  // -0 + 0 = +0; any other x unchanged
  return (b >> 63) != 0 ? ~b : b | (std::uint64_t{1} << 63);
}

__extension__ using u128 = unsigned __int128;  // GCC / Clang

/// a is selected before b: search.order (precedes) on (f, h, index), as one 128-bit comparison of
/// (f, h) followed by the index.
[[nodiscard]] inline bool first(const Entry& a, const Entry& b) noexcept {
  const u128 ka = (static_cast<u128>(a.f) << 64) | a.h;
  const u128 kb = (static_cast<u128>(b.f) << 64) | b.h;
  return ka < kb || (ka == kb && a.index < b.index);
}

/// search.order on (g, 0, index): one 128-bit comparison of (g, index).
[[nodiscard]] inline bool first(const GEntry& a, const GEntry& b) noexcept {
  return ((static_cast<u128>(a.f) << 64) | a.index) < ((static_cast<u128>(b.f) << 64) | b.index);
}

/// A growable array whose append is inlined (std::vector::push_back is not, in the inner loop):
/// the storage only grows, `n` counts the elements in use.
template <class E>
class Stack {
 public:
  [[gnu::always_inline]] void push_back(const E& e) {
    if (n_ == v_.size()) [[unlikely]] grow();
    v_[n_++] = e;
  }
  void pop_back() noexcept { --n_; }
  void clear() noexcept { n_ = 0; }
  [[nodiscard]] std::size_t size() const noexcept { return n_; }
  [[nodiscard]] bool empty() const noexcept { return n_ == 0; }
  [[nodiscard]] E& operator[](std::size_t i) noexcept { return v_[i]; }
  [[nodiscard]] const E& operator[](std::size_t i) const noexcept { return v_[i]; }
  [[nodiscard]] const E& front() const noexcept { return v_[0]; }
  [[nodiscard]] const E& back() const noexcept { return v_[n_ - 1]; }
  [[nodiscard]] const E* begin() const noexcept { return v_.data(); }
  [[nodiscard]] const E* end() const noexcept { return v_.data() + n_; }
  [[nodiscard]] std::size_t capacity() const noexcept { return v_.size(); }

 private:
  [[gnu::noinline]] void grow() { v_.resize(std::max<std::size_t>(64, 2 * v_.size())); }
  std::vector<E> v_;
  std::size_t n_ = 0;
};

/// The open list: an implicit d-ary min-heap under `first` (d = arity) over a vector the workspace
/// keeps. Pops a minimal entry; search.order is total, so which heap pops it does not matter.
constexpr std::size_t arity = 4;

template <class E>
[[gnu::always_inline]] inline void heap_push(Stack<E>& v, const E& e) {
  v.push_back(e);
  std::size_t i = v.size() - 1;
  while (i > 0) {
    const std::size_t p = (i - 1) / arity;
    if (!first(e, v[p])) break;
    v[i] = v[p];
    i = p;
  }
  v[i] = e;
}

template <class E>
inline E heap_pop(Stack<E>& v) {
  const E top = v.front();
  const E last = v.back();
  v.pop_back();
  const std::size_t n = v.size();
  if (n == 0) return top;
  std::size_t i = 0;
  for (;;) {
    const std::size_t c = arity * i + 1;
    if (c >= n) break;
    std::size_t best = c;
    const std::size_t end = std::min(c + arity, n);
    for (std::size_t j = c + 1; j < end; ++j)
      if (first(v[j], v[best])) best = j;
    if (!first(v[best], last)) break;
    v[i] = v[best];
    i = best;
  }
  v[i] = last;
  return top;
}

/// Per-cell state, 16 bytes (one cache line holds four cells): g, parent index and a mark
/// (generation << 2 | open / closed). A mark of another generation means "not looked at in this
/// search": neither open nor closed, g and parent meaningless.
struct CellState {
  double g;
  std::uint32_t parent;
  std::uint32_t mark;
};
constexpr std::uint32_t mark_open = 1;
constexpr std::uint32_t mark_closed = 2;
constexpr std::uint32_t no_parent = 0xFFFFFFFFu;
constexpr std::uint32_t max_generation = (std::uint32_t{1} << 30) - 1;

}  // namespace core

using core::CellState;
using core::Entry;
using core::GEntry;
using core::first;
using core::order_bits;
using core::heap_pop;
using core::heap_push;
using core::mark_closed;
using core::mark_open;
using core::max_generation;
using core::no_parent;

/// The open list: a radix heap on f (Ahuja, Mehlhorn, Orlin & Tarjan, "Faster algorithms for the
/// shortest path problem", J. ACM 37(2), 1990) over the order-preserving bits of f, with exact
/// ties. `last` is the f of the last entry taken from the buckets; the entries are partitioned
/// into
///   - `same`: the entries with f == last, a heap under search.order (so by (h, index));
///   - `bucket[i]` (i = 1..64): the entries with f > last whose highest bit differing from last
///     is bit i - 1, unordered;
///   - `below`: the entries with f < last (an f smaller than an earlier pop's: only an
///     inconsistent heuristic or rounding makes one), a heap under search.order.
/// A pop takes the top of `below` if any (its f is below every other entry's), else the top of
/// `same`, refilled when empty from the lowest non-empty bucket: its smallest f becomes `last`,
/// its entries of that f go to `same` and the others to lower buckets. So every pop returns the
/// first entry of the whole list under search.order, as a single heap would.
template <class E>
struct OpenList {
  core::Stack<E> same;
  core::Stack<E> below;
  std::array<core::Stack<E>, 65> bucket;
  std::uint64_t occupied = 0;  // bit i - 1 set iff bucket[i] is non-empty
  std::uint64_t last = 0;
  std::size_t size = 0;

  void clear() noexcept {
    same.clear();
    below.clear();
    for (std::uint64_t m = occupied; m != 0; m &= m - 1) bucket[static_cast<std::size_t>(__builtin_ctzll(m)) + 1].clear();
    occupied = 0;
    last = 0;
    size = 0;
  }
  [[nodiscard]] bool empty() const noexcept { return size == 0; }
  /// Puts e in the part its f belongs to, relative to `last`.
  [[gnu::always_inline]] void place(const E& e) {
    if (e.f == last) {
      heap_push(same, e);
    } else if (e.f > last) {
      const auto i = static_cast<std::size_t>(64 - __builtin_clzll(e.f ^ last));
      bucket[i].push_back(e);
      occupied |= std::uint64_t{1} << (i - 1);
    } else {
      heap_push(below, e);
    }
  }
  void push(const E& e) {
    place(e);
    ++size;
  }
  /// Pre: !empty().
  E pop() {
    --size;
    if (!below.empty()) return heap_pop(below);
    if (same.empty()) {
      const auto i = static_cast<std::size_t>(__builtin_ctzll(occupied)) + 1;
      core::Stack<E>& from = bucket[i];
      std::uint64_t m = from.front().f;
      for (const E& e : from) m = std::min(m, e.f);
      last = m;
      occupied &= ~(std::uint64_t{1} << (i - 1));
      for (const E& e : from) place(e);  // every f here is >= m: none goes to `below` or back to bucket i
      from.clear();
    }
    return heap_pop(same);
  }
  [[nodiscard]] std::size_t bytes() const noexcept {
    std::size_t n = same.capacity() + below.capacity();
    for (const auto& v : bucket) n += v.capacity();
    return n * sizeof(E);
  }
};

struct Workspace::Impl {
  std::vector<CellState> cells;
  OpenList<Entry> open;    // searches with a heuristic
  OpenList<GEntry> gopen;  // searches with h = 0 (Dijkstra)
  std::uint32_t generation = 0;
  // Move masks of the grid and policy last searched (spec/search.md "Reusing the search state"):
  // masks[i] = 0x100 | allowed_moves(cell i) once computed, 0 before; valid while the grid equals
  // mask_grid (same size and cells) and the policy is mask_policy, recomputed lazily otherwise.
  std::optional<grid::Grid> mask_grid;
  grid::CornerPolicy mask_policy = grid::CornerPolicy::strict;
  std::vector<std::uint16_t> masks;

  /// Starts a search on `count` cells: grows the arrays if needed, then a new generation (every
  /// mark of an earlier search becomes stale). On wrap-around of the generation counter (after
  /// 2^30 - 1 searches) the marks are cleared once.
  std::uint32_t begin(std::size_t count) {
    if (cells.size() < count) {
      cells.assign(count, CellState{0.0, no_parent, 0});
      generation = 0;
    }
    if (generation == max_generation) {
      for (CellState& c : cells) c.mark = 0;
      generation = 0;
    }
    ++generation;
    open.clear();
    gopen.clear();
    return generation << 2;
  }

  /// The move-mask cache for grid g under policy p: kept if g equals the grid of the cached masks
  /// (Grid::operator==: size and every cell) and p is the same policy, else reset to "none known".
  std::uint16_t* masks_for(const grid::Grid& g, grid::CornerPolicy p) {
    if (!mask_grid || mask_policy != p || !(*mask_grid == g)) {
      mask_grid = g;
      mask_policy = p;
      masks.assign(static_cast<std::size_t>(g.cell_count()), 0);
    }
    return masks.data();
  }
};

Workspace::Workspace() : impl_(std::make_unique<Impl>()) {}
Workspace::~Workspace() = default;
Workspace::Workspace(Workspace&&) noexcept = default;
Workspace& Workspace::operator=(Workspace&&) noexcept = default;
std::size_t Workspace::capacity() const noexcept { return impl_ ? impl_->cells.size() : 0; }
std::size_t Workspace::bytes() const noexcept {
  if (!impl_) return 0;
  const Impl& w = *impl_;
  return w.cells.capacity() * sizeof(CellState) + w.open.bytes() + w.gopen.bytes() +
         w.masks.capacity() * sizeof(std::uint16_t) +
         (w.mask_grid ? static_cast<std::size_t>(w.mask_grid->cell_count()) : 0);
}
Workspace::Impl& access(Workspace& w) noexcept { return *w.impl_; }

namespace {

/// The 8 moves in grid.neighbour-order (bit k of a move mask = move k).
constexpr std::array<std::int64_t, 8> move_dx{-1, 0, 1, -1, 1, -1, 0, 1};
constexpr std::array<std::int64_t, 8> move_dy{-1, -1, -1, 0, 0, 1, 1, 1};
constexpr std::uint32_t orthogonal_moves = 0b01011010;  // moves 1, 3, 4, 6

/// The moves of `c` allowed under `policy` (bit k = grid::step_allowed(g, c, c + move k, policy)),
/// for a free cell c: an orthogonal move needs its target free; a diagonal move its target free and
/// the policy's condition on the two orthogonal cells it passes between (grid.corner-policy). Equal
/// to step_allowed move by move (property prop_allowed_moves_is_step_allowed in tests).
std::uint32_t allowed_moves(const grid::Grid& g, grid::Cell c, grid::CornerPolicy policy) noexcept {
  std::uint32_t free = 0;
  for (std::size_t k = 0; k < 8; ++k)
    if (g.free(grid::Cell{c.x + move_dx[k], c.y + move_dy[k]})) free |= 1u << k;
  std::uint32_t allowed = free & orthogonal_moves;
  // Diagonal k and the orthogonal moves it passes between: 0:(3,1) 2:(4,1) 5:(3,6) 7:(4,6).
  const auto side = [free](int k) { return (free >> k) & 1u; };
  const std::uint32_t d0 = side(0), d2 = side(2), d5 = side(5), d7 = side(7);
  const std::uint32_t s1 = side(1), s3 = side(3), s4 = side(4), s6 = side(6);
  std::uint32_t pass0 = 0, pass2 = 0, pass5 = 0, pass7 = 0;
  switch (policy) {
    case grid::CornerPolicy::never: break;
    case grid::CornerPolicy::strict:
      pass0 = s3 & s1; pass2 = s4 & s1; pass5 = s3 & s6; pass7 = s4 & s6;
      break;
    case grid::CornerPolicy::one:
      pass0 = s3 | s1; pass2 = s4 | s1; pass5 = s3 | s6; pass7 = s4 | s6;
      break;
    case grid::CornerPolicy::always:
      pass0 = pass2 = pass5 = pass7 = 1;
      break;
  }
  allowed |= (d0 & pass0) << 0 | (d2 & pass2) << 2 | (d5 & pass5) << 5 | (d7 & pass7) << 7;
  return allowed;
}

/// The one best-first core. Rule: moves(cell) -> bitmask over the 8 moves, h(cell), f(g, h, cell);
/// Rule::zero_h: h = 0 and f = g for every cell (Dijkstra), which selects the 16-byte entries.
template <class Rule>
Outcome run_best_first(Workspace::Impl& ws, const grid::Grid& g, grid::Cell start, grid::Cell goal,
                       grid::CornerPolicy policy, Rule& rule) {
  require(g.in_bounds(start), "search: start cell outside the grid");
  require(g.in_bounds(goal), "search: goal cell outside the grid");
  require(g.free(start), "search: start cell is blocked");
  require(g.free(goal), "search: goal cell is blocked");

  constexpr bool zero_h = Rule::zero_h;
  using E = std::conditional_t<zero_h, GEntry, Entry>;
  const auto width = static_cast<std::uint32_t>(g.width());  // W * H <= 2^28: 32-bit arithmetic
  const std::uint32_t base = ws.begin(static_cast<std::size_t>(g.cell_count()));
  const std::uint32_t is_open = base | mark_open;
  const std::uint32_t is_closed = base | mark_closed;
  CellState* const cells = ws.cells.data();
  std::uint16_t* const masks = ws.masks_for(g, policy);
  OpenList<E>& open = [&ws]() -> OpenList<E>& {
    if constexpr (zero_h) return ws.gopen;
    else return ws.open;
  }();
  const auto key = [](std::uint32_t index, double f, double h) {
    if constexpr (zero_h) return GEntry{order_bits(f), index};
    else return Entry{order_bits(f), order_bits(h), index};
  };
  const auto cell_of = [width](std::uint32_t i) {
    return grid::Cell{static_cast<std::int64_t>(i % width), static_cast<std::int64_t>(i / width)};
  };
  const auto goal_index = static_cast<std::uint32_t>(g.index(goal));
  std::array<std::int32_t, 8> offset{};  // index difference of move k (grid.index)
  std::array<double, 8> cost{};          // grid::step_cost of move k
  for (std::size_t k = 0; k < 8; ++k) {
    offset[k] = static_cast<std::int32_t>(move_dy[k] * g.width() + move_dx[k]);
    cost[k] = grid::step_cost(grid::Cell{0, 0}, grid::Cell{move_dx[k], move_dy[k]});
  }

  Outcome out;
  const auto start_index = static_cast<std::uint32_t>(g.index(start));
  const double h_start = rule.h(start);
  cells[start_index] = CellState{0.0, no_parent, is_open};
  open.push(key(start_index, rule.f(0.0, h_start, start), h_start));

  while (!open.empty()) {
    const E e = open.pop();
    CellState& here = cells[e.index];
    if (here.mark == is_closed) continue;  // an older entry of a closed cell: not an expansion
    here.mark = is_closed;
    ++out.expansions;
    const double g_here = here.g;

    if (e.index == goal_index) {
      out.found = true;
      out.length = g_here;
      for (std::uint32_t i = e.index; i != no_parent; i = cells[i].parent) out.path.push_back(cell_of(i));
      std::reverse(out.path.begin(), out.path.end());
      return out;
    }

    // Generated moves: the rule's, restricted to the allowed steps (in bounds, free, policy),
    // whose mask is computed once per cell of the map and kept in the workspace.
    std::uint32_t allowed = masks[e.index];
    if (allowed == 0) {
      allowed = 0x100u | allowed_moves(g, cell_of(e.index), policy);
      masks[e.index] = static_cast<std::uint16_t>(allowed);
    }
    std::uint32_t todo = allowed & 0xFFu;
    grid::Cell c{};
    if constexpr (!zero_h) c = cell_of(e.index);
    if constexpr (!Rule::all_moves) todo &= rule.moves(cell_of(e.index));
    // Canonical neighbour order (grid.neighbour-order); the order cannot change the result
    // (spec/search.md: each neighbour is relaxed once per expansion, independently).
    while (todo != 0) {
      const auto k = static_cast<std::size_t>(__builtin_ctz(todo));
      todo &= todo - 1;
      const std::uint32_t mi = e.index + static_cast<std::uint32_t>(offset[k]);
      CellState& next = cells[mi];
      if (next.mark == is_closed) continue;  // no reopening
      ++out.generated;  // a child generation (spec/search.md "child counts")
      const double g_new = g_here + cost[k];
      const bool fresh = next.mark != is_open;
      if (fresh || g_new < next.g) {  // parent changes on strictly smaller g
        if (fresh) ++out.child_nodes;  // a new child node (spec/search.md "child counts")
        next = CellState{g_new, e.index, is_open};
        if constexpr (zero_h) {
          open.push(key(mi, g_new, 0.0));
        } else {
          const grid::Cell m{c.x + move_dx[k], c.y + move_dy[k]};
          const double h_m = rule.h(m);
          open.push(key(mi, rule.f(g_new, h_m, m), h_m));
        }
      }
    }
  }
  return out;  // OPEN exhausted: goal unreachable
}

/// astar's rule: every move, h from the heuristic H (fixed at compile time), f = g + h.
template <heuristics::Heuristic H>
struct PlainRule {
  grid::Cell goal;
  static constexpr bool zero_h = H == heuristics::Heuristic::zero;
  static constexpr bool all_moves = true;
  static constexpr std::uint32_t moves(grid::Cell) noexcept { return 0xFF; }
  double h(grid::Cell n) const {
    if constexpr (H == heuristics::Heuristic::octile) return heuristics::octile(n, goal);
    else if constexpr (H == heuristics::Heuristic::zero) return 0.0;  // n, goal in the grid: in the domain
    else return heuristics::evaluate(H, n, goal);
  }
  static double f(double g, double h_n, grid::Cell) noexcept { return g + h_n; }
};

template <heuristics::Heuristic H>
Outcome run_plain(Workspace::Impl& ws, const grid::Grid& g, grid::Cell start, grid::Cell goal,
                  grid::CornerPolicy policy) {
  PlainRule<H> rule{goal};
  return run_best_first(ws, g, start, goal, policy, rule);
}

/// A user rule behind std::function.
struct FunctionRule {
  const ExpansionRule& r;
  static constexpr bool zero_h = false;
  static constexpr bool all_moves = false;
  std::uint32_t moves(grid::Cell c) const { return r.moves ? r.moves(c) : std::uint8_t{0xFF}; }
  double h(grid::Cell n) const { return r.h(n); }
  double f(double g, double h_n, grid::Cell n) const { return r.f ? r.f(g, h_n, n) : g + h_n; }
};

}  // namespace

Outcome astar(Workspace& ws, const grid::Grid& g, grid::Cell start, grid::Cell goal,
              grid::CornerPolicy policy, heuristics::Heuristic h) {
  Workspace::Impl& w = access(ws);
  switch (h) {
    case heuristics::Heuristic::zero: return run_plain<heuristics::Heuristic::zero>(w, g, start, goal, policy);
    case heuristics::Heuristic::manhattan:
      return run_plain<heuristics::Heuristic::manhattan>(w, g, start, goal, policy);
    case heuristics::Heuristic::chebyshev:
      return run_plain<heuristics::Heuristic::chebyshev>(w, g, start, goal, policy);
    case heuristics::Heuristic::octile: return run_plain<heuristics::Heuristic::octile>(w, g, start, goal, policy);
    case heuristics::Heuristic::euclidean:
      return run_plain<heuristics::Heuristic::euclidean>(w, g, start, goal, policy);
  }
  throw UsageError("unknown heuristic");
}

Outcome astar(const grid::Grid& g, grid::Cell start, grid::Cell goal, grid::CornerPolicy policy,
              heuristics::Heuristic h) {
  Workspace ws;
  return astar(ws, g, start, goal, policy, h);
}

Outcome best_first(Workspace& ws, const grid::Grid& g, grid::Cell start, grid::Cell goal,
                   grid::CornerPolicy policy, const ExpansionRule& rule) {
  if (!rule.h) throw UsageError("best_first: the expansion rule needs a heuristic h");
  FunctionRule fr{rule};
  return run_best_first(access(ws), g, start, goal, policy, fr);
}

Outcome best_first(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                   grid::CornerPolicy policy, const ExpansionRule& rule) {
  Workspace ws;
  return best_first(ws, g, start, goal, policy, rule);
}

Outcome dijkstra(Workspace& ws, const grid::Grid& g, grid::Cell start, grid::Cell goal,
                 grid::CornerPolicy policy) {
  return astar(ws, g, start, goal, policy, heuristics::Heuristic::zero);
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

std::uint64_t memory_estimate(std::int64_t cells) noexcept {
  return memory::times(static_cast<std::uint64_t>(cells < 0 ? 0 : cells), bytes_per_cell);
}

/// Refuses a search whose per-cell arrays would exceed the request's memory limit (UsageError
/// naming the estimate and the limit), before they are allocated. Spec: search.astar ("Memory")
void require_memory(const planners::Request& req, const grid::Grid& g, std::string_view planner) {
  memory::require_within(memory_estimate(g.cell_count()), req.max_memory,
                         fmt::format("{} on a {}x{} grid ({} bytes per cell)", planner, g.width(), g.height(),
                                     bytes_per_cell));
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
  p.bytes_per_cell = search::bytes_per_cell;
  p.run = [defaults = p.defaults](const Request& req) {
    const grid::Grid& g = grid_of(req);
    Json params = merge_params(defaults, req.params);
    const auto h = heuristics::parse_heuristic(params.at("heuristic").get<std::string>());
    search::require_memory(req, g, "astar");
    Json extra = {{"admissible", heuristics::admissible(h, req.policy)},
                  {"consistent", heuristics::consistent(h, req.policy)}};
    search::Outcome o = req.workspace != nullptr
                            ? search::astar(*req.workspace, g, req.start, req.goal, req.policy, h)
                            : search::astar(g, req.start, req.goal, req.policy, h);
    return to_result(std::move(o), std::move(params), std::move(extra));
  };
  return p;
}

Planner make_dijkstra_planner() {
  Planner p;
  p.name = "dijkstra";
  p.description = "Dijkstra (1959): A* with h = 0, tie-break (g, cell index), spec/search.md";
  p.defaults = Json::object();
  p.bytes_per_cell = search::bytes_per_cell;
  p.run = [defaults = p.defaults](const Request& req) {
    const grid::Grid& g = grid_of(req);
    Json params = merge_params(defaults, req.params);
    search::require_memory(req, g, "dijkstra");
    search::Outcome o = req.workspace != nullptr
                            ? search::dijkstra(*req.workspace, g, req.start, req.goal, req.policy)
                            : search::dijkstra(g, req.start, req.goal, req.policy);
    return to_result(std::move(o), std::move(params), Json::object());
  };
  return p;
}

}  // namespace pathref::planners
