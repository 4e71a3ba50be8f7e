// Boost Graph Library as the peer of pathref's grid search (issue 18; docs/performance.md "BGL as
// the peer"): on the MovingAI scenarios of ../shared/data/movingai (the six maps; every Nth
// scenario), pathref's A* (octile) and Dijkstra with a reused search::Workspace against BGL's
// astar_search (octile heuristic) and dijkstra_shortest_paths on a compressed_sparse_row_graph of
// the same map (policy strict: an edge for every allowed step, weight 1 or sqrt2). Each query
// stops at the goal on both sides (BGL: a visitor that throws when the goal is examined). The
// graphs and BGL's property maps are built once per map, untimed; BGL's per-query initialisation
// of its maps is part of astar_search / dijkstra_shortest_paths and so of its time.
//
// Every query is checked: both lengths agree with the scenario file (spec/formats.md#scen-agreement)
// and with each other to 1e-9 relative (the two searches may return different shortest paths whose
// sums round differently, spec/search.md guarantee 2). Any disagreement: exit 1.
//
// Timing: process CPU time (user + system, getrusage) per batch of all queries of one map, R
// repetitions interleaved (pathref then BGL in odd repetitions, BGL then pathref in even ones);
// reported: the median over repetitions of the CPU time per query, its min-max, and the median of
// the per-repetition ratios pathref / BGL (both sides measured in the same repetition).
//
// Opt-in, never in CI: tools/deps-bgl.sh installs libboost-graph-dev and prints the configure line
// (-DPATHREF_BGL_PEER=ON). The pathref library never depends on Boost.
// Usage: astar_bgl_peer [--reps R] [--every N] [--every-small N] [--algo astar|dijkstra|both]
//                       [--side both|pathref|bgl] [--maps a,b,...] [--data DIR]
// (--side pathref|bgl runs one side only, for callgrind instruction counts.)
#include <fmt/core.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <boost/graph/astar_search.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include "pathref/grid/grid.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/movingai.hpp"
#include "pathref/planners/search.hpp"

namespace {

using pathref::grid::Cell;
using pathref::grid::CornerPolicy;
using pathref::grid::Grid;

struct EdgeProp {
  double w;
};
using CsrGraph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, EdgeProp>;
using Vertex = boost::graph_traits<CsrGraph>::vertex_descriptor;

/// CSR graph of the grid: vertex = cell index (grid.index), an edge a -> b for every allowed step
/// under `strict` (grid::step_allowed), weight grid::step_cost. Edges sorted by source.
CsrGraph make_graph(const Grid& g) {
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<EdgeProp> props;
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    const Cell c = g.cell(i);
    if (!g.free(c)) continue;
    for (const auto& mv : pathref::grid::neighbours(g, c, CornerPolicy::strict)) {
      edges.emplace_back(static_cast<std::size_t>(i), static_cast<std::size_t>(g.index(mv.to)));
      props.push_back(EdgeProp{mv.cost});
    }
  }
  return CsrGraph(boost::edges_are_sorted, edges.begin(), edges.end(), props.begin(),
                  static_cast<std::size_t>(g.cell_count()));
}

struct FoundGoal {};

/// Stops the search when the goal is taken from the queue (the same moment pathref stops).
template <class Base>
struct GoalVisitor : Base {
  Vertex goal;
  explicit GoalVisitor(Vertex g) : goal(g) {}
  void examine_vertex(Vertex u, const CsrGraph&) {
    if (u == goal) throw FoundGoal{};
  }
};

/// The octile distance to the goal, as BGL users write it (same formula as search.h.octile).
struct OctileH : boost::astar_heuristic<CsrGraph, double> {
  std::int64_t width;
  std::int64_t gx;
  std::int64_t gy;
  double operator()(Vertex v) const {
    const auto i = static_cast<std::int64_t>(v);
    const std::int64_t dx = std::llabs(i % width - gx);
    const std::int64_t dy = std::llabs(i / width - gy);
    const std::int64_t big = std::max(dx, dy);
    const std::int64_t small = std::min(dx, dy);
    return static_cast<double>(big - small) + std::numbers::sqrt2 * static_cast<double>(small);
  }
};

/// BGL's per-graph property storage, allocated once per map.
struct BglMaps {
  std::vector<Vertex> pred;
  std::vector<double> dist;
  std::vector<double> cost;
  std::vector<boost::default_color_type> color;
  explicit BglMaps(std::size_t n) : pred(n), dist(n), cost(n), color(n) {}
  [[nodiscard]] std::size_t bytes() const {
    return pred.size() * sizeof(Vertex) + (dist.size() + cost.size()) * sizeof(double) +
           color.size() * sizeof(boost::default_color_type);
  }
};

/// Length of the shortest path by BGL (A* when astar, else Dijkstra); -1 when unreachable.
double bgl_query(const CsrGraph& graph, BglMaps& m, std::int64_t width, Cell start, Cell goal, bool astar) {
  const auto s = static_cast<Vertex>(start.y * width + start.x);
  const auto t = static_cast<Vertex>(goal.y * width + goal.x);
  auto index = get(boost::vertex_index, graph);
  auto pred = boost::make_iterator_property_map(m.pred.begin(), index);
  auto dist = boost::make_iterator_property_map(m.dist.begin(), index);
  auto color = boost::make_iterator_property_map(m.color.begin(), index);
  auto weight = get(&EdgeProp::w, graph);
  try {
    if (astar) {
      auto cost = boost::make_iterator_property_map(m.cost.begin(), index);
      boost::astar_search(graph, s, OctileH{{}, width, goal.x, goal.y},
                          boost::visitor(GoalVisitor<boost::default_astar_visitor>(t))
                              .predecessor_map(pred)
                              .distance_map(dist)
                              .rank_map(cost)
                              .color_map(color)
                              .weight_map(weight));
    } else {
      boost::dijkstra_shortest_paths(graph, s,
                                     boost::visitor(GoalVisitor<boost::default_dijkstra_visitor>(t))
                                         .predecessor_map(pred)
                                         .distance_map(dist)
                                         .color_map(color)
                                         .weight_map(weight));
    }
  } catch (const FoundGoal&) {
    return m.dist[t];
  }
  return -1.0;
}

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

struct Query {
  Cell start;
  Cell goal;
  const pathref::io::Scenario* scenario;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t a = 0;
  while (a <= s.size()) {
    const std::size_t b = s.find(',', a);
    out.push_back(s.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) break;
    a = b + 1;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 5;
  std::size_t every_big = 10;   // maps with more than 2^16 cells (the 512 x 512 ones)
  std::size_t every_small = 1;  // the others
  std::string algo = "both";
  std::string side = "both";
  std::string maps = "arena,den312d,lak303d,8room_000,maze512-1-0,random512-10-0";
  std::string data = std::string(PATHREF_SHARED_DIR) + "/data/movingai";
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string k = argv[a];
    const std::string v = argv[a + 1];
    if (k == "--reps") reps = std::max(1, std::atoi(v.c_str()));
    else if (k == "--every") every_big = static_cast<std::size_t>(std::max(1, std::atoi(v.c_str())));
    else if (k == "--every-small") every_small = static_cast<std::size_t>(std::max(1, std::atoi(v.c_str())));
    else if (k == "--algo") algo = v;
    else if (k == "--side") side = v;
    else if (k == "--maps") maps = v;
    else if (k == "--data") data = v;
    else {
      fmt::print(stderr, "unknown option {}\n", k);
      return 2;
    }
  }
  const bool run_pathref = side != "bgl";
  const bool run_bgl = side != "pathref";
  fmt::print("BGL peer: {} repetitions, every {} scenario(s) on maps > 65536 cells, every {} on the others, "
             "policy strict, CPU = user + system (getrusage)\n\n",
             reps, every_big, every_small);
  fmt::print("| map | algo | queries | pathref ms/query (median [min-max]) | BGL ms/query | ratio pathref/BGL "
             "(median [min-max]) | pathref expansions/s | pathref memory | BGL memory |\n");
  fmt::print("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  int bad = 0;
  for (const std::string& name : split(maps)) {
    const std::string map_path = data + "/" + name + ".map";
    const std::string scen_path = map_path + ".scen";
    pathref::io::MapReadOptions ro;
    const auto loaded = pathref::io::load_map_file(map_path, ro);
    const Grid& g = loaded.map.grid;
    const std::string text = pathref::io::read_text_file(scen_path, "scenario file");
    const pathref::io::ScenFile sf = pathref::io::parse_movingai_scen(text, scen_path, ro.limits);
    const std::size_t every = g.cell_count() > 65536 ? every_big : every_small;
    std::vector<Query> qs;
    for (std::size_t i = 0; i < sf.scenarios.size(); i += every) {
      const auto& s = sf.scenarios[i];
      qs.push_back(Query{pathref::io::from_movingai(s.start_x.value, s.start_y.value, g.height()),
                         pathref::io::from_movingai(s.goal_x.value, s.goal_y.value, g.height()), &s});
    }
    const CsrGraph graph = make_graph(g);
    BglMaps bm(static_cast<std::size_t>(g.cell_count()));
    const std::size_t graph_bytes = (boost::num_vertices(graph) + 1) * sizeof(std::size_t) +
                                    boost::num_edges(graph) * (sizeof(std::size_t) + sizeof(EdgeProp));
    for (const bool astar : {true, false}) {
      if ((astar && algo == "dijkstra") || (!astar && algo == "astar")) continue;
      pathref::search::Workspace ws;
      std::vector<double> tp, tb, ratio;
      std::vector<double> lp(qs.size()), lb(qs.size());
      std::int64_t expansions = 0;
      for (int r = 0; r < reps; ++r) {
        double p = 0.0, b = 0.0;
        const auto time_pathref = [&] {
          const double t0 = cpu_seconds();
          std::int64_t e = 0;
          for (std::size_t q = 0; q < qs.size(); ++q) {
            const auto o = astar ? pathref::search::astar(ws, g, qs[q].start, qs[q].goal, CornerPolicy::strict,
                                                          pathref::heuristics::Heuristic::octile)
                                 : pathref::search::dijkstra(ws, g, qs[q].start, qs[q].goal, CornerPolicy::strict);
            lp[q] = o.found ? o.length : -1.0;
            e += o.expansions;
          }
          p = cpu_seconds() - t0;
          expansions = e;
        };
        const auto time_bgl = [&] {
          const double t0 = cpu_seconds();
          for (std::size_t q = 0; q < qs.size(); ++q)
            lb[q] = bgl_query(graph, bm, g.width(), qs[q].start, qs[q].goal, astar);
          b = cpu_seconds() - t0;
        };
        if (r % 2 == 0) {
          if (run_pathref) time_pathref();
          if (run_bgl) time_bgl();
        } else {
          if (run_bgl) time_bgl();
          if (run_pathref) time_pathref();
        }
        const double n = static_cast<double>(qs.size());
        tp.push_back(p / n * 1e3);
        tb.push_back(b / n * 1e3);
        if (run_pathref && run_bgl) ratio.push_back(p / b);
      }
      // The checks (after the timing: they are not part of either side's time).
      for (std::size_t q = 0; q < qs.size(); ++q) {
        const auto& s = *qs[q].scenario;
        const double tol = pathref::io::agreement_tolerance(s.optimal, 6);
        const bool p_ok = !run_pathref || (lp[q] >= 0 && pathref::io::lengths_agree(lp[q], s.optimal, tol));
        const bool b_ok = !run_bgl || (lb[q] >= 0 && pathref::io::lengths_agree(lb[q], s.optimal, tol));
        const bool same = !(run_pathref && run_bgl) || std::fabs(lp[q] - lb[q]) <= 1e-9 * std::max(1.0, lp[q]);
        if (!p_ok || !b_ok || !same) {
          ++bad;
          fmt::print(stderr, "{} line {}: file {} pathref {} BGL {}\n", scen_path, s.line, s.optimal.text, lp[q], lb[q]);
        }
      }
      const auto range = [](const std::vector<double>& v) {
        return fmt::format("{:.4f} [{:.4f}-{:.4f}]", median(v), *std::min_element(v.begin(), v.end()),
                           *std::max_element(v.begin(), v.end()));
      };
      const double exp_rate = median(tp) > 0 ? static_cast<double>(expansions) / (median(tp) * 1e-3 * static_cast<double>(qs.size())) : 0.0;
      fmt::print("| {} | {} | {} | {} | {} | {} | {:.2f} M | {:.1f} MB | {:.1f} MB |\n", name, astar ? "A*" : "Dijkstra",
                 qs.size(), run_pathref ? range(tp) : "-", run_bgl ? range(tb) : "-",
                 ratio.empty() ? std::string("-")
                               : fmt::format("{:.3f} [{:.3f}-{:.3f}]", median(ratio),
                                             *std::min_element(ratio.begin(), ratio.end()),
                                             *std::max_element(ratio.begin(), ratio.end())),
                 exp_rate * 1e-6, static_cast<double>(ws.bytes()) / 1e6,
                 static_cast<double>(graph_bytes + bm.bytes()) / 1e6);
      std::fflush(stdout);
    }
  }
  if (bad != 0) {
    fmt::print(stderr, "{} queries disagree\n", bad);
    return 1;
  }
  fmt::print("\nall lengths agree with the scenario files and between pathref and BGL\n");
  return 0;
}
