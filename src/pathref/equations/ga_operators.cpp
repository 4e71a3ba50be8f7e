#include "pathref/equations/ga_operators.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"

namespace pathref::ga {

InitReject parse_init_reject(std::string_view name) {
  if (name == "blocked") return InitReject::blocked;
  if (name == "near_obstacle") return InitReject::near_obstacle;
  if (name == "shift") return InitReject::shift;
  throw UsageError("unknown init_reject '" + std::string(name) +
                   "' (expected blocked, near_obstacle or shift)");
}

std::string_view to_string(InitReject v) noexcept {
  switch (v) {
    case InitReject::blocked: return "blocked";
    case InitReject::near_obstacle: return "near_obstacle";
    case InitReject::shift: return "shift";
  }
  return "?";
}

IllegalStep parse_illegal_step(std::string_view name) {
  if (name == "repair") return IllegalStep::repair;
  if (name == "reject") return IllegalStep::reject;
  throw UsageError("unknown illegal_step '" + std::string(name) + "' (expected repair or reject)");
}

std::string_view to_string(IllegalStep v) noexcept {
  return v == IllegalStep::repair ? "repair" : "reject";
}

namespace {

/// Hash of a cell for crossover_points' table (splitmix64 finaliser of x, mixed with y).
struct CellHash {
  std::size_t operator()(const grid::Cell& c) const noexcept {
    std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ULL ^
                      static_cast<std::uint64_t>(c.y);
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ULL;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBULL;
    h ^= h >> 31;
    return static_cast<std::size_t>(h);
  }
};

bool has_blocked_neighbour(const grid::Grid& g, grid::Cell c) {
  for (std::int64_t dy = -1; dy <= 1; ++dy)
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const grid::Cell n{c.x + dx, c.y + dy};
      if (g.in_bounds(n) && g.blocked(n)) return true;
    }
  return false;
}

}  // namespace

std::string_view connect_chain_into(const grid::Grid& g, std::span<const grid::Cell> genes,
                                   grid::CornerPolicy policy, MidRounding rounding, InitReject rej,
                                   IllegalStep illegal, std::vector<grid::Cell>& p) {
  std::int64_t shifts = 0;
  return connect_chain_into(g, genes, policy, rounding, rej, illegal, p, shifts);
}

std::string_view connect_chain_into(const grid::Grid& g, std::span<const grid::Cell> genes,
                                   grid::CornerPolicy policy, MidRounding rounding, InitReject rej,
                                   IllegalStep illegal, std::vector<grid::Cell>& p,
                                   std::int64_t& inserted) {
  inserted = 0;
  require(genes.size() >= 2, "a chain needs at least two genes (start and goal)");
  for (const grid::Cell c : genes) require(g.in_bounds(c), "a gene lies outside the grid");
  for (const grid::Cell c : genes)
    if (g.blocked(c)) return "blocked_gene";
  p.assign(genes.begin(), genes.end());
  std::size_t k = 0;
  while (k + 1 < p.size()) {
    const grid::Cell a = p[k];
    const grid::Cell b = p[k + 1];
    const std::int64_t d = continuity_delta(a, b);
    if (d == 0) {  // duplicate_gene = drop
      p.erase(p.begin() + static_cast<std::ptrdiff_t>(k + 1));
      continue;
    }
    if (d == 1) {
      if (grid::step_allowed(g, a, b, policy)) {
        ++k;
        continue;
      }
      // Not an allowed move: only a diagonal can be (a and b are free 8-neighbours). Under
      // `repair` it is "not continuous" (Sec. 4.2 step 2): insert the first free orthogonal
      // cell, (b.x, a.y) then (a.x, b.y) (o_1, o_2 of grid.corner-policy); a -> o and o -> b are
      // orthogonal steps between free cells, allowed under every policy.
      if (illegal == IllegalStep::reject || a.x == b.x || a.y == b.y) return "illegal_step";
      const grid::Cell o1{b.x, a.y};
      const grid::Cell o2{a.x, b.y};
      const grid::Cell* o = g.free(o1) ? &o1 : (g.free(o2) ? &o2 : nullptr);
      if (o == nullptr) return "illegal_step";
      p.insert(p.begin() + static_cast<std::ptrdiff_t>(k + 1), *o);
      continue;
    }
    grid::Cell m = insertion_cell(a, b, rounding);
    if (g.blocked(m) && rej == InitReject::shift) {
      // The first free orthogonal neighbour of m other than a and b, in the order of the
      // MATLAB code: left, right, then y + 1, y - 1.
      bool moved = false;
      for (const grid::Cell off : {grid::Cell{-1, 0}, grid::Cell{1, 0}, grid::Cell{0, 1}, grid::Cell{0, -1}}) {
        const grid::Cell q{m.x + off.x, m.y + off.y};
        if (g.free(q) && !(q == a) && !(q == b)) {
          m = q;
          moved = true;
          break;
        }
      }
      if (!moved) return "blocked_insert";
      if (++inserted > g.cell_count()) return "insert_limit";
    }
    if (g.blocked(m)) return "blocked_insert";
    if (rej == InitReject::near_obstacle && has_blocked_neighbour(g, m)) return "near_obstacle";
    p.insert(p.begin() + static_cast<std::ptrdiff_t>(k + 1), m);
  }
  return "ok";
}

ChainRepair connect_chain(const grid::Grid& g, std::span<const grid::Cell> genes,
                          grid::CornerPolicy policy, MidRounding rounding, InitReject rej,
                          IllegalStep illegal) {
  ChainRepair r;
  std::vector<grid::Cell> p;
  r.reason = std::string(connect_chain_into(g, genes, policy, rounding, rej, illegal, p));
  r.feasible = r.reason == "ok";
  if (r.feasible) r.path = std::move(p);
  return r;
}

std::vector<CrossPoint> crossover_points_any(std::span<const grid::Cell> a,
                                             std::span<const grid::Cell> b) {
  std::vector<CrossPoint> out;
  if (a.size() < 3) return out;
  std::unordered_map<grid::Cell, std::size_t, CellHash> first;  // b's first position of each cell
  first.reserve(b.size());
  for (std::size_t j = 0; j < b.size(); ++j) first.emplace(b[j], j);
  for (std::size_t k = 1; k + 1 < a.size(); ++k) {
    const auto it = first.find(a[k]);
    if (it != first.end()) out.push_back(CrossPoint{k, it->second});
  }
  return out;
}

std::size_t round_choice(double u, std::size_t n) {
  require(n >= 1, "round_choice needs at least one item");
  require(u >= 0.0 && u < 1.0, "round_choice needs u in [0, 1)");
  const double r = std::round(u * static_cast<double>(n - 1));  // half away from zero
  const auto c = static_cast<std::size_t>(r);
  return c < n ? c : n - 1;
}

std::optional<std::vector<grid::Cell>> segment_mutation(const grid::Grid& g,
                                                        std::span<const grid::Cell> path,
                                                        std::size_t lo, std::size_t hi,
                                                        grid::CornerPolicy policy,
                                                        MidRounding rounding, InitReject reject,
                                                        IllegalStep illegal) {
  require(lo >= 1 && lo <= hi && hi + 2 <= path.size(),
          "segment mutation needs interior positions 1 <= lo <= hi <= n - 2");
  const grid::Cell ends[2] = {path[lo - 1], path[hi + 1]};
  std::vector<grid::Cell> slice;
  if (connect_chain_into(g, ends, policy, rounding, reject, illegal, slice) != "ok")
    return std::nullopt;
  std::vector<grid::Cell> out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(lo));
  // slice = ends[0], interior..., ends[1]; a repeated end (Delta = 0) leaves slice = [ends[0]].
  if (slice.size() >= 2) out.insert(out.end(), slice.begin() + 1, slice.end() - 1);
  const std::size_t from = slice.size() >= 2 ? hi + 1 : hi + 2;
  out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(from), path.end());
  return out;
}

std::vector<CrossPoint> crossover_points(std::span<const grid::Cell> a,
                                         std::span<const grid::Cell> b) {
  std::vector<CrossPoint> out;
  if (a.size() < 3 || b.size() < 3) return out;
  const std::size_t na = a.size() - 2;
  const std::size_t nb = b.size() - 2;
  if (na <= crossover_scan_limit / nb) {  // na * nb <= limit: scan b for every a[k]
    for (std::size_t k = 1; k <= na; ++k)
      for (std::size_t j = 1; j <= nb; ++j)
        if (a[k] == b[j]) {
          out.push_back(CrossPoint{k, j});
          break;
        }
    return out;
  }
  // Long parents (loops = keep lets paths grow to 10^5 nodes and more): the first interior
  // position of every cell of b, then one lookup per a[k]; the same points as the scan.
  std::unordered_map<grid::Cell, std::size_t, CellHash> first;
  first.reserve(nb);
  for (std::size_t j = 1; j <= nb; ++j) first.try_emplace(b[j], j);  // keeps the first j
  for (std::size_t k = 1; k <= na; ++k) {
    const auto it = first.find(a[k]);
    if (it != first.end()) out.push_back(CrossPoint{k, it->second});
  }
  return out;
}

Children crossover_at(std::span<const grid::Cell> a, std::span<const grid::Cell> b,
                      CrossPoint point) {
  require(point.k < a.size() && point.j < b.size(), "crossover point outside the parents");
  require(a[point.k] == b[point.j], "a crossover point must be a common node");
  Children c;
  const auto k = static_cast<std::ptrdiff_t>(point.k);
  const auto j = static_cast<std::ptrdiff_t>(point.j);
  c.first.assign(a.begin(), a.begin() + k + 1);
  c.first.insert(c.first.end(), b.begin() + j + 1, b.end());
  c.second.assign(b.begin(), b.begin() + j + 1);
  c.second.insert(c.second.end(), a.begin() + k + 1, a.end());
  return c;
}

std::vector<grid::Cell> mutation_candidates(const grid::Grid& g, std::span<const grid::Cell> path,
                                            std::size_t k, grid::CornerPolicy policy) {
  require(path.size() >= 3 && k >= 1 && k + 2 <= path.size(),
          "mutation position must be an interior gene 1 <= k <= n - 2");
  const grid::Cell prev = path[k - 1];
  const grid::Cell next = path[k + 1];
  std::vector<grid::Cell> out;
  // dy outer, dx inner: increasing cell index y * W + x (grid.neighbour-order).
  for (std::int64_t dy = -1; dy <= 1; ++dy)
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const grid::Cell c{prev.x + dx, prev.y + dy};
      if (c == path[k] || c == next) continue;
      if (grid::step_allowed(g, prev, c, policy) && grid::step_allowed(g, c, next, policy))
        out.push_back(c);
    }
  return out;
}

std::vector<grid::Cell> delete_redundant(const grid::Grid& g, std::span<const grid::Cell> path,
                                         grid::CornerPolicy policy) {
  std::vector<grid::Cell> p(path.begin(), path.end());
  std::size_t i = 1;
  while (i + 1 < p.size()) {
    if (grid::step_allowed(g, p[i - 1], p[i + 1], policy)) {
      p.erase(p.begin() + static_cast<std::ptrdiff_t>(i));
      if (i > 1) --i;  // the deletion changed the neighbourhood of node i - 1: test it again
    } else {
      ++i;
    }
  }
  return p;
}

std::vector<grid::Cell> remove_loops(std::span<const grid::Cell> path) {
  std::vector<grid::Cell> out;
  out.reserve(path.size());
  for (const grid::Cell c : path) {
    const auto it = std::find(out.begin(), out.end(), c);
    if (it != out.end()) {
      out.erase(it + 1, out.end());  // back to the first visit of c
    } else {
      out.push_back(c);
    }
  }
  return out;
}

std::vector<std::size_t> elite_indices(std::span<const double> fitness, std::size_t count) {
  require(count <= fitness.size(), "elite count exceeds the population");
  for (const double f : fitness) require(std::isfinite(f), "fitness values must be finite");
  std::vector<std::size_t> idx(fitness.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::stable_sort(idx.begin(), idx.end(),
                   [&](std::size_t x, std::size_t y) { return fitness[x] > fitness[y]; });
  idx.resize(count);
  return idx;
}

std::size_t elite_count(std::size_t n, double fraction) {
  require(std::isfinite(fraction) && fraction > 0.0 && fraction <= 1.0,
          "elite fraction must lie in (0, 1]");
  if (n == 0) return 0;
  const double v = std::ceil(fraction * static_cast<double>(n));
  const auto c = static_cast<std::size_t>(v);
  return std::clamp(c, std::size_t{1}, n);
}

CutChildren crossover_cut(const grid::Grid& g, std::span<const grid::Cell> a,
                          std::span<const grid::Cell> b, std::size_t k, std::size_t j,
                          grid::CornerPolicy policy, MidRounding rounding, InitReject reject,
                          IllegalStep illegal) {
  require(a.size() >= 3 && b.size() >= 3, "cut crossover needs parents of >= 3 nodes");
  require(k >= 1 && k + 2 <= a.size() && j >= 1 && j + 2 <= b.size(),
          "cut crossover: the cut genes must be interior");
  std::vector<grid::Cell> c1(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(k) + 1);
  c1.insert(c1.end(), b.begin() + static_cast<std::ptrdiff_t>(j) + 1, b.end());
  std::vector<grid::Cell> c2(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(j) + 1);
  c2.insert(c2.end(), a.begin() + static_cast<std::ptrdiff_t>(k) + 1, a.end());
  CutChildren out;
  ChainRepair r1 = connect_chain(g, c1, policy, rounding, reject, illegal);
  if (!r1.feasible) return out;
  ChainRepair r2 = connect_chain(g, c2, policy, rounding, reject, illegal);
  if (!r2.feasible) return out;
  out.feasible = true;
  out.children.first = std::move(r1.path);
  out.children.second = std::move(r2.path);
  return out;
}

Research parse_research(std::string_view name) {
  if (name == "greedy") return Research::greedy;
  if (name == "random") return Research::random;
  throw UsageError("research must be greedy or random, not '" + std::string(name) + "'");
}
std::string_view to_string(Research v) noexcept { return v == Research::greedy ? "greedy" : "random"; }

Walk research_walk(const grid::Grid& g, grid::Cell from, grid::Cell to,
                   std::span<const grid::Cell> avoid, grid::CornerPolicy policy, Research mode,
                   rng::Stream& stream, bool backtrack) {
  require(g.in_bounds(from) && g.in_bounds(to), "re-search: cells outside the grid");
  require(g.free(from) && g.free(to), "re-search: blocked end cell");
  std::vector<std::uint8_t> closed(static_cast<std::size_t>(g.cell_count()), 0);
  for (const grid::Cell c : avoid)
    if (g.in_bounds(c)) closed[static_cast<std::size_t>(g.index(c))] = 1;
  closed[static_cast<std::size_t>(g.index(to))] = 0;
  Walk w;
  w.cells.push_back(from);
  closed[static_cast<std::size_t>(g.index(from))] = 1;
  std::vector<grid::Cell> cand;
  while (!(w.cells.back() == to)) {
    cand.clear();
    for (const grid::Move& m : grid::neighbours(g, w.cells.back(), policy))
      if (closed[static_cast<std::size_t>(g.index(m.to))] == 0) cand.push_back(m.to);
    if (cand.empty()) {
      if (!backtrack) return Walk{};
      w.cells.pop_back();  // the dead end stays closed
      if (w.cells.empty()) return Walk{};
      continue;
    }
    std::size_t pick = 0;
    if (mode == Research::random) {
      pick = rng::uniform_index(stream.next_double("cin2021.op.mutation random re-search step (rng.index)"), cand.size());
    } else {
      std::int64_t best = -1;
      for (std::size_t i = 0; i < cand.size(); ++i) {
        const std::int64_t dx = cand[i].x - to.x;
        const std::int64_t dy = cand[i].y - to.y;
        const std::int64_t d = dx * dx + dy * dy;
        if (best < 0 || d < best) {
          best = d;
          pick = i;
        }
      }
    }
    w.cells.push_back(cand[pick]);
    closed[static_cast<std::size_t>(g.index(cand[pick]))] = 1;
  }
  w.ok = true;
  return w;
}

Mutants multidirectional_mutants(const grid::Grid& g, std::span<const grid::Cell> path,
                                 std::size_t k, grid::CornerPolicy policy, Research mode,
                                 rng::Stream& stream) {
  const std::size_t n = path.size();
  require(n >= 3 && k >= 1 && k + 2 <= n, "multidirectional mutation: k must be interior");
  Mutants out;
  {
    const Walk w = research_walk(g, path[k], path[0], path.subspan(k + 1), policy, mode, stream);
    if (w.ok) {
      out.a.assign(w.cells.rbegin(), w.cells.rend());
      out.a.insert(out.a.end(), path.begin() + static_cast<std::ptrdiff_t>(k) + 1, path.end());
    }
  }
  {
    const Walk w = research_walk(g, path[n - 1], path[k], path.subspan(0, k), policy, mode, stream);
    if (w.ok) {
      out.b.assign(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(k));
      out.b.insert(out.b.end(), w.cells.rbegin(), w.cells.rend());
    }
  }
  return out;
}

}  // namespace pathref::ga
