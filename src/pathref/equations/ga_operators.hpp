#pragma once
/// \file ga_operators.hpp
/// The path operators of Shi et al. 2022's genetic algorithms as pure functions: the repair of a
/// chain of genes into a continuous path (population initialisation, Sec. 4.2 steps 2-3), the
/// crossover at a common node (Figure 3), the point mutation (Figure 4), the deletion operator
/// (Figure 6, Sec. 4.4.3) and elite retention (Sec. 4.4.3). Random choices are not made here:
/// the caller draws (rng::uniform_index) and passes the chosen index, so every operator is a
/// pure function of its arguments and golden vectors pin it without a generator.
/// The GA planners (planners/genetic.hpp) compose these with the equations of ga.hpp.
/// Spec: spec/shi2022-ga.md (shi2022.op.init, shi2022.op.crossover, shi2022.op.mutation,
/// shi2022.op.deletion, shi2022.op.elite)
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/equations/ga.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::ga {

/// When an initial chain is rejected (spec shi2022.op.init, option `init_reject`).
enum class InitReject {
  blocked,        ///< an inserted cell is blocked (the literal "eliminate"; the default before issue 11)
  near_obstacle,  ///< also when an inserted cell has a blocked cell among its 8 neighbours
  shift,          ///< a blocked mid-point is replaced by its first free orthogonal neighbour
                  ///< (x-1, y), (x+1, y), (x, y+1), (x, y-1) other than the pair's cells (the
                  ///< widely copied MATLAB generate_continuous_path); rejected if none (default)
};
/// "blocked" | "near_obstacle" | "shift" -> InitReject; UsageError otherwise. Spec: shi2022.op.init.
[[nodiscard]] InitReject parse_init_reject(std::string_view name);
[[nodiscard]] std::string_view to_string(InitReject v) noexcept;

/// What a continuous (Delta = 1) pair whose step is not an allowed move under the corner policy
/// is (spec shi2022.op.init, option `illegal_step`).
enum class IllegalStep {
  repair,  ///< "not continuous" (Sec. 4.2 step 2): the first free orthogonal cell of the diagonal,
           ///< (b.x, a.y) then (a.x, b.y), is inserted; rejected only when neither is free (default)
  reject,  ///< the chain is rejected ("illegal_step"), pathref's earlier default
};
/// "repair" | "reject" -> IllegalStep; UsageError otherwise. Spec: shi2022.op.init.
[[nodiscard]] IllegalStep parse_illegal_step(std::string_view name);
[[nodiscard]] std::string_view to_string(IllegalStep v) noexcept;

/// What connect_chain returns: the repaired path, or the reason the chain was rejected.
struct ChainRepair {
  bool feasible = false;
  std::vector<grid::Cell> path;  ///< start..goal when feasible, else empty
  std::string reason;            ///< "ok" | "blocked_gene" | "blocked_insert" | "near_obstacle" | "illegal_step" | "insert_limit"
};

/// Repairs a chain of genes g_0 (start), ..., g_m (goal) into a continuous path (Shi Sec. 4.2,
/// population initialisation steps 2-3): scanning k = 0, 1, ... left to right, a pair with
/// Delta = 0 (Eq. 8) drops the second gene; Delta = 1 advances k when grid::step_allowed, else
/// (a diagonal that cuts a corner, or any diagonal under `never`) under IllegalStep::repair the
/// first free orthogonal cell (b.x, a.y), (a.x, b.y) is inserted without advancing k (rejected,
/// "illegal_step", when neither is free) and under IllegalStep::reject the chain is rejected; Delta >= 2 inserts insertion_cell (Eq. 9) between them
/// without advancing k, rejected if the inserted cell is blocked ("blocked_insert") or, under
/// near_obstacle, has a blocked 8-neighbour inside the map ("near_obstacle"); under shift a
/// blocked mid-point is replaced by its first free orthogonal neighbour (InitReject::shift) and
/// the chain is rejected after more than W * H such shifts ("insert_limit"). A blocked gene is rejected
/// first ("blocked_gene").
/// Source: Shi et al. 2022, Sec. 4.2 "Population initialization", Eq. (8)-(9),
/// doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.op.init
/// Pre: >= 2 genes, every gene inside g (DomainError).
/// Post: feasible => path starts with genes.front(), ends with genes.back(), every step an
/// allowed move under policy (metrics::validate_path is valid); terminates (each insertion
/// strictly lowers the Chebyshev distance of the pair).
/// Golden: golden/shi2022-ga/shi2022.op.init.json
[[nodiscard]] ChainRepair connect_chain(const grid::Grid& g, std::span<const grid::Cell> genes,
                                        grid::CornerPolicy policy,
                                        MidRounding rounding = MidRounding::floor,
                                        InitReject reject = InitReject::shift,
                                        IllegalStep illegal = IllegalStep::repair);

/// connect_chain writing the repaired path into `path` (overwritten; no allocation once its
/// capacity suffices) and returning the reason ("ok" when feasible; `path` is then the repaired
/// path, else unspecified). connect_chain is this function plus the copy; the GA initialisation
/// calls it once per drawn chain. Spec: shi2022.op.init. Pre: as connect_chain.
[[nodiscard]] std::string_view connect_chain_into(const grid::Grid& g, std::span<const grid::Cell> genes,
                                                  grid::CornerPolicy policy, MidRounding rounding,
                                                  InitReject reject, IllegalStep illegal,
                                                  std::vector<grid::Cell>& path);

/// connect_chain_into that also sets `shifts` to the number of shifted mid-points it made
/// (InitReject::shift; always 0 otherwise), the count that the W * H bound ("insert_limit")
/// applies to. The GA initialisation uses it to decide a chain pair by pair (spec
/// shi2022.plan.ga, "Evaluation"). Spec: shi2022.op.init. Pre: as connect_chain.
[[nodiscard]] std::string_view connect_chain_into(const grid::Grid& g, std::span<const grid::Cell> genes,
                                                  grid::CornerPolicy policy, MidRounding rounding,
                                                  InitReject reject, IllegalStep illegal,
                                                  std::vector<grid::Cell>& path, std::int64_t& shifts);

/// One crossover point: position k in parent a and position j in parent b with a[k] == b[j].
struct CrossPoint {
  std::size_t k = 0;
  std::size_t j = 0;
  friend constexpr bool operator==(const CrossPoint&, const CrossPoint&) = default;
};

/// Above this many pairs (n_a - 2) * (n_b - 2) of interior nodes, crossover_points finds the
/// common nodes through a table of b's first positions instead of scanning b for every node of
/// a; the points are the same.
inline constexpr std::size_t crossover_scan_limit = 4096;

/// The common nodes of two paths (Figure 3: "find out all identical points on both paths"): for
/// each interior position k = 1..n_a-2 of a, ascending, such that a[k] occurs among the interior
/// positions 1..n_b-2 of b, the point (k, j) with j the FIRST such position in b.
/// Source: Shi et al. 2022, Sec. 4.2 "Crossover", Figure 3, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.op.crossover
/// Pre: none. Post: k ascending; a[k] == b[j]; 1 <= k <= n_a - 2, 1 <= j <= n_b - 2.
/// Golden: golden/shi2022-ga/shi2022.op.crossover.json
[[nodiscard]] std::vector<CrossPoint> crossover_points(std::span<const grid::Cell> a,
                                                       std::span<const grid::Cell> b);

/// The two children of a single-point crossover at (k, j): c1 = a[0..k] ++ b[j+1..],
/// c2 = b[0..j] ++ a[k+1..].
/// Source: Shi et al. 2022, Sec. 4.2 "Crossover", Figure 3, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.op.crossover
/// Pre: k < n_a, j < n_b, a[k] == b[j] (DomainError).
/// Post: |c1| + |c2| == |a| + |b|; if a and b are valid paths from S to T under a policy, so are
/// c1 and c2 (every step of a child is a step of a parent).
/// Golden: golden/shi2022-ga/shi2022.op.crossover.json
struct Children {
  std::vector<grid::Cell> first;
  std::vector<grid::Cell> second;
};
[[nodiscard]] Children crossover_at(std::span<const grid::Cell> a, std::span<const grid::Cell> b,
                                    CrossPoint point);

/// The common nodes as the classic MATLAB GA script finds them (`ismember` over the whole of b):
/// for each interior position k = 1..n_a-2 of a, ascending, such that a[k] occurs ANYWHERE in b,
/// the point (k, j) with j its first position in b (0 <= j <= n_b - 1). Differs from
/// crossover_points only when a[k] equals b's first or last cell or occurs in b only there.
/// Source: the classic GA grid script (../shared/data/matlab-maps/README.txt, crossover.m).
/// Spec: classic.plan.ga
/// Pre: none. Post: k ascending; a[k] == b[j]; j the smallest such index.
/// Golden: golden/classic/classic.plan.ga.json (through the planner)
[[nodiscard]] std::vector<CrossPoint> crossover_points_any(std::span<const grid::Cell> a,
                                                           std::span<const grid::Cell> b);

/// The classic script's choice of one of n >= 1 items from a draw u in [0, 1):
/// round(u * (n - 1)) with round half away from zero (MATLAB round; std::round), the product in
/// binary64. Not uniform: the first and last item have half the probability of the others.
/// Source: the classic GA grid script (crossover.m, mutation.m: round(rand * (m - 3)) + 2).
/// Spec: classic.plan.ga
/// Pre: n >= 1, 0 <= u < 1 (DomainError). Post: in [0, n - 1].
[[nodiscard]] std::size_t round_choice(double u, std::size_t n);

/// The classic script's segment mutation of path p (0-based interior positions 1 <= lo <= hi <=
/// n - 2): the genes p[lo..hi] are replaced by the interior of connect_chain([p[lo-1], p[hi+1]])
/// under the given readings; when p[lo-1] == p[hi+1] the segment and one copy of that cell are
/// removed. nullopt when the repair rejects the pair.
/// Source: the classic GA grid script (mutation.m with generate_continuous_path.m).
/// Spec: classic.plan.ga
/// Pre: 1 <= lo <= hi <= n - 2, cells inside g (DomainError).
/// Post: a valid path stays valid (every new step comes from connect_chain); same first and last
/// cell.
[[nodiscard]] std::optional<std::vector<grid::Cell>> segment_mutation(
    const grid::Grid& g, std::span<const grid::Cell> path, std::size_t lo, std::size_t hi,
    grid::CornerPolicy policy, MidRounding rounding, InitReject reject, IllegalStep illegal);

/// The replacement candidates for gene k of a path (Figure 4, point mutation): the cells c of the
/// 8-neighbourhood of path[k-1], in increasing cell index (grid.neighbour-order), with c !=
/// path[k], c != path[k+1], grid::step_allowed(path[k-1], c) and grid::step_allowed(c, path[k+1]).
/// Source: Shi et al. 2022, Sec. 4.2 "Mutation", Figure 4, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.op.mutation
/// Pre: 1 <= k <= n - 2 (DomainError).
/// Post: replacing path[k] by any candidate keeps every step of a valid path allowed.
/// Golden: golden/shi2022-ga/shi2022.op.mutation.json
[[nodiscard]] std::vector<grid::Cell> mutation_candidates(const grid::Grid& g,
                                                          std::span<const grid::Cell> path,
                                                          std::size_t k, grid::CornerPolicy policy);

/// The deletion operator (Figure 6): scanning i = 1, 2, ... while i <= n - 2 of the current path,
/// if path[i-1] -> path[i+1] is an allowed single move (grid::step_allowed), path[i] is deleted
/// and the scan steps back to i - 1 (if i > 1; the deletion changed that node's successor);
/// otherwise i advances. The result has no deletable node left.
/// Source: Shi et al. 2022, Sec. 4.4.3 "Adding a deletion operator", Figure 6,
/// doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.op.deletion
/// Pre: none (any sequence of cells; a node is removed only where the shortcut is a move).
/// Post: a subsequence of the input with the same first and last node; if the input is a valid
/// path, so is the output, and metrics::path_length(output) <= path_length(input) (each deletion
/// replaces two steps by one: strictly shorter); idempotent.
/// Golden: golden/shi2022-ga/shi2022.op.deletion.json
[[nodiscard]] std::vector<grid::Cell> delete_redundant(const grid::Grid& g,
                                                       std::span<const grid::Cell> path,
                                                       grid::CornerPolicy policy);

/// Loop removal (planner option `loops = cut`, spec shi2022.op.loops): scanning the path left to
/// right, when a cell already kept at output position q occurs again, the output is cut back to
/// position q (the closed loop between the two visits is dropped) and the scan goes on.
/// Source: pathref (the paper is silent about the loops a crossover at a common node can create;
/// Shi et al. 2022, Sec. 4.2, Figure 3, doi:10.3389/fbioe.2022.905983).
/// Spec: shi2022.op.loops
/// Pre: none. Post: no cell occurs twice; same first and last cell; a valid path stays valid and
/// metrics::path_length never increases; a path without repeated cells is returned unchanged.
/// Golden: golden/shi2022-ga/shi2022.op.loops.json
[[nodiscard]] std::vector<grid::Cell> remove_loops(std::span<const grid::Cell> path);

/// Elite retention (Sec. 4.4.3, "retains the top 50% of the individuals with a large fitness
/// value"): the indices of the `count` largest fitness values, ordered by fitness descending,
/// ties by the smaller index (a stable sort).
/// Source: Shi et al. 2022, Sec. 4.4.3 steps 5 and 7, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.op.elite
/// Pre: count <= fitness.size(); every fitness finite (DomainError).
/// Post: result.size() == count; distinct indices; fitness[result[0]] is the maximum whenever
/// count >= 1 (the best is never lost).
/// Golden: golden/shi2022-ga/shi2022.op.elite.json
[[nodiscard]] std::vector<std::size_t> elite_indices(std::span<const double> fitness,
                                                     std::size_t count);

/// The number kept by "the top fraction": ceil(fraction * n) evaluated in binary64, at least 1
/// when n >= 1. Spec: shi2022.op.elite. Pre: 0 < fraction <= 1 (DomainError).
[[nodiscard]] std::size_t elite_count(std::size_t n, double fraction);

/// What crossover_cut returns: the two repaired children, or feasible = false when a repair was
/// rejected (the crossover of the pair is then void).
struct CutChildren {
  bool feasible = false;
  Children children;
};

/// Single-point crossover at random cut genes of parents without a common gene (cin2021
/// Figure 8a): the chains c1 = a[0..k] ++ b[j+1..] and c2 = b[0..j] ++ a[k+1..], each repaired
/// by connect_chain (the GA's own repair: Eq. 8 continuity, Eq. 9 mid-points) with `rounding`,
/// `reject` and `illegal`; feasible iff both repairs are. The defaults (blocked, reject) are
/// ga-cin's (cin2021.plan.ga pins them), not the Shi planners' (shift, repair).
/// Source: cin2021 Sec. 5.3.2, Figure 8(a), doi:10.1155/2021/8025730; repair of Shi et al. 2022
/// Sec. 4.2 (shi2022.op.init).
/// Spec: cin2021.op.crossover
/// Pre: 1 <= k <= n_a - 2, 1 <= j <= n_b - 2; every cell inside g (DomainError).
/// Post: feasible => both children start at a[0] (resp. b[0]), end at b.back() (resp. a.back())
/// and every step is allowed under policy when the parents' are.
/// Golden: golden/cin2021-hga-aco/cin2021.op.crossover.json
[[nodiscard]] CutChildren crossover_cut(const grid::Grid& g, std::span<const grid::Cell> a,
                                        std::span<const grid::Cell> b, std::size_t k, std::size_t j,
                                        grid::CornerPolicy policy,
                                        MidRounding rounding = MidRounding::floor,
                                        InitReject reject = InitReject::blocked,
                                        IllegalStep illegal = IllegalStep::reject);

/// How the multidirectional mutation re-searches (option `research`, spec cin2021.op.mutation).
enum class Research {
  greedy,  ///< the candidate nearest the target (squared centre distance), first on ties; no draw
  random,  ///< a uniformly drawn candidate (rng::uniform_index), one draw per step
};
[[nodiscard]] Research parse_research(std::string_view name);
[[nodiscard]] std::string_view to_string(Research v) noexcept;

/// A re-search walk from `from` to `to`: at each cell the candidates are its allowed moves
/// (grid::neighbours, canonical order) into cells neither in `avoid` nor already on the walk
/// (`to` is never avoided); greedy takes the nearest to `to`, random draws one (this is the one
/// operator here that draws: one res53 double per step, from `stream`). Stops on `to`. At a cell
/// without candidates the walk fails (ok = false), or, with `backtrack`, steps back (the cell stays
/// closed; no draw) and fails only when it backtracks out of `from` (a randomised depth-first
/// search: it reaches `to` whenever `to` is reachable avoiding `avoid`).
/// Source: cin2021 Sec. 5.3.2, Figure 9 ("reverse search"), doi:10.1155/2021/8025730.
/// Spec: cin2021.op.mutation
/// Pre: from, to in bounds and free (DomainError). Post: ok => cells run from `from` to `to`, a
/// valid simple path under policy avoiding `avoid`.
struct Walk {
  bool ok = false;
  std::vector<grid::Cell> cells;
};
[[nodiscard]] Walk research_walk(const grid::Grid& g, grid::Cell from, grid::Cell to,
                                 std::span<const grid::Cell> avoid, grid::CornerPolicy policy,
                                 Research mode, rng::Stream& stream, bool backtrack = false);

/// The two mutants of the multidirectional mutation at interior point k of `path` (cin2021
/// Figure 9): A = reverse(research_walk(path[k] -> path[0], avoiding path[k+1..])) ++ path[k+1..];
/// B = path[0..k-1] ++ reverse(research_walk(path[n-1] -> path[k], avoiding path[0..k-1])).
/// A's walk draws first. An empty vector marks a failed walk.
/// Source: cin2021 Sec. 5.3.2, Figure 9, doi:10.1155/2021/8025730.
/// Spec: cin2021.op.mutation
/// Pre: 1 <= k <= n - 2; path valid and simple (not checked beyond bounds: DomainError).
/// Post: each non-empty mutant is a valid simple path from path[0] to path[n-1].
/// Golden: golden/cin2021-hga-aco/cin2021.op.mutation.json
struct Mutants {
  std::vector<grid::Cell> a;
  std::vector<grid::Cell> b;
};
[[nodiscard]] Mutants multidirectional_mutants(const grid::Grid& g, std::span<const grid::Cell> path,
                                               std::size_t k, grid::CornerPolicy policy,
                                               Research mode, rng::Stream& stream);

}  // namespace pathref::ga
