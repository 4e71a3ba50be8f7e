// pathref._pathref: the Python extension built from the same library as the CLI (issue 20,
// docs/python.md). No second implementation: every function below calls the library; values
// that are JSON in the library cross the boundary as JSON text and are decoded by the thin Python
// layer (python/pathref/__init__.py), arrays as NumPy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "pathref/io/json_text.hpp"
#include "pathref/core/error.hpp"
#include "pathref/core/version.hpp"
#include "geometry_cgal/scene_map.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/golden/runner.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/path_check.hpp"
#include "pathref/io/plan_json.hpp"
#include "pathref/planners/default_policy.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/rules/registry.hpp"

namespace py = pybind11;
using Json = nlohmann::json;

namespace {

using Blocked = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;

/// A grid from a (H, W) array whose row y is the map's row y (the Python layer flips MATLAB-style
/// top-first arrays before the call); nonzero = blocked.
pathref::grid::Grid grid_from(const Blocked& blocked) {
  if (blocked.ndim() != 2) throw pathref::UsageError("the grid must be a 2-D array (rows, columns)");
  const auto h = static_cast<std::int64_t>(blocked.shape(0));
  const auto w = static_cast<std::int64_t>(blocked.shape(1));
  pathref::grid::Grid g(w, h);  // DomainError for an empty or too large grid
  const auto a = blocked.unchecked<2>();
  for (std::int64_t y = 0; y < h; ++y)
    for (std::int64_t x = 0; x < w; ++x)
      if (a(y, x) != 0) g.set_blocked(pathref::grid::Cell{x, y}, true);
  return g;
}

/// The (H, W) uint8 array of a grid, row y = the map's row y, 1 = blocked.
py::array_t<std::uint8_t> array_from(const pathref::grid::Grid& g) {
  py::array_t<std::uint8_t> out({static_cast<py::ssize_t>(g.height()), static_cast<py::ssize_t>(g.width())});
  auto a = out.mutable_unchecked<2>();
  for (std::int64_t y = 0; y < g.height(); ++y)
    for (std::int64_t x = 0; x < g.width(); ++x) a(y, x) = g.free(pathref::grid::Cell{x, y}) ? 0 : 1;
  return out;
}

pathref::grid::Cell cell_from(const std::tuple<std::int64_t, std::int64_t>& c) {
  return pathref::grid::Cell{std::get<0>(c), std::get<1>(c)};
}

/// Asked at iteration boundaries with the GIL released: a pending Ctrl-C stops the run (the
/// translator below raises KeyboardInterrupt for pathref::Interrupted).
bool python_interrupted() {
  const py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() == 0) return false;
  PyErr_Clear();
  return true;
}

std::string eval_rule(const std::string& rule_id, const std::string& input_json) {
  const pathref::rules::Rule* rule = pathref::rules::registry().find(rule_id);
  if (rule == nullptr) throw pathref::UsageError("unknown rule '" + rule_id + "' (see pathref.rules())");
  const Json input = pathref::io::parse_json_text(input_json, "<input>", 1, pathref::io::cli_value_limits);
  return pathref::rules::evaluate(*rule, input).dump();
}

std::string plan(const Blocked& blocked, const std::tuple<std::int64_t, std::int64_t>& start,
                 const std::tuple<std::int64_t, std::int64_t>& goal, const std::string& algo, std::uint32_t seed,
                 const std::string& policy, const std::string& params_json, const std::string& map_name) {
  const pathref::planners::Planner* planner = pathref::planners::find_planner(algo);
  if (planner == nullptr) {
    std::string known;
    for (const auto& p : pathref::planners::planners()) known += (known.empty() ? "" : ", ") + p.name;
    throw pathref::UsageError("unknown algo '" + algo + "' (known: " + known + ")");
  }
  const pathref::grid::Grid g = grid_from(blocked);
  const Json overrides = pathref::io::parse_json_text(params_json, "<params>", 1, pathref::io::cli_value_limits);
  const Json merged = pathref::planners::merge_params(planner->defaults, overrides);  // UsageError for a bad key
  pathref::planners::Request req;
  req.grid = &g;
  req.start = cell_from(start);
  req.goal = cell_from(goal);
  req.policy = policy.empty() ? pathref::planners::default_policy(algo) : pathref::grid::parse_corner_policy(policy);
  req.seed = seed;
  req.params = overrides;
  req.interrupted = python_interrupted;
  pathref::io::PlanRecord rec{algo, seed, req.policy, pathref::io::MapSource{"python", map_name, std::nullopt},
                              req.start, req.goal, merged, {}};
  {
    const py::gil_scoped_release nogil;
    rec.result = planner->run(req);
  }
  if (!rec.result.params_used.empty()) rec.params = rec.result.params_used;
  Json j = pathref::io::plan_to_json(rec, g);
  j["pathref_version"] = std::string(pathref::version());
  j["golden_set_version"] = std::string(pathref::golden_set_version());
  return j.dump();
}

std::string check(const Blocked& blocked, const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& path,
                  const std::tuple<std::int64_t, std::int64_t>& start, const std::tuple<std::int64_t, std::int64_t>& goal,
                  const std::string& policy) {
  const pathref::grid::Grid g = grid_from(blocked);
  if (path.ndim() != 2 || (path.shape(0) > 0 && path.shape(1) != 2))
    throw pathref::UsageError("the path must be an (N, 2) array of (x, y) cells");
  const auto p = path.unchecked<2>();
  std::vector<pathref::grid::Cell> cells;
  for (py::ssize_t k = 0; k < path.shape(0); ++k) cells.push_back(pathref::grid::Cell{p(k, 0), p(k, 1)});
  const pathref::grid::CornerPolicy pol = pathref::grid::parse_corner_policy(policy);
  const auto s = cell_from(start), t = cell_from(goal);
  const auto report = pathref::io::check_path(g, cells, s, t, pol, pathref::io::optimum_length(g, s, t, pol));
  Json j = pathref::io::path_report_json(report, cells);
  j["nodes"] = cells.size();
  j["policy"] = std::string(pathref::grid::to_string(pol));
  return j.dump();
}

py::tuple load_map(const std::string& file) {
  pathref::io::MapReadOptions o;
  o.scene_to_map = pathref::geometry::scene_map;  // polygon scenes, inflated exactly (as the CLI)
  const pathref::io::LoadedMapFile m = pathref::io::load_map_file(file, o);
  const auto cell = [](const std::optional<pathref::grid::Cell>& c) -> py::object {
    return c ? py::object(py::make_tuple(c->x, c->y)) : py::object(py::none());
  };
  return py::make_tuple(array_from(m.map.grid), cell(m.map.start), cell(m.map.goal), m.map.name,
                        std::string(pathref::io::to_string(m.format)));
}

std::string golden_check(const std::string& dir) {
  const pathref::golden::Report r = pathref::golden::check_directory(dir);
  Json failures = Json::array();
  for (const auto& c : r.cases)
    if (c.status == pathref::golden::Status::fail)
      failures.push_back(Json{{"file", c.file}, {"rule", c.rule}, {"tcId", c.tc_id}, {"message", c.message}});
  return Json{{"pass", r.count(pathref::golden::Status::pass)},
              {"fail", r.count(pathref::golden::Status::fail)},
              {"skipped", r.count(pathref::golden::Status::skipped)},
              {"failures", failures}}
      .dump();
}

}  // namespace

PYBIND11_MODULE(_pathref, m) {
  m.doc() = "pathref's library (the reference implementation's C++ core); use the package `pathref`.";
  pathref::geometry::install_inflation_rules();  // the same registry as the CLI
  pathref::geometry::install_srrt_rules();

  static py::exception<pathref::ParseError> parse_error(m, "ParseError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const pathref::ParseError& e) {
      py::object err = py::reinterpret_borrow<py::object>(parse_error.ptr())(e.what());
      err.attr("file") = e.file();
      err.attr("line") = e.line();
      err.attr("column") = e.column();
      PyErr_SetObject(parse_error.ptr(), err.ptr());
    } catch (const pathref::Interrupted&) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const pathref::Error& e) {  // DomainError, UsageError: the input is wrong
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const nlohmann::json::exception& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  py::class_<pathref::rng::Stream>(m, "Stream", "MT19937 init_genrand(seed) + genrand_res53 (spec/rng.md)")
      .def(py::init<std::uint32_t>(), py::arg("seed"))
      .def("next_double", [](pathref::rng::Stream& s) { return s.next_double(); }, "one draw in [0, 1)")
      .def(
          "random_sample",
          [](pathref::rng::Stream& s, py::object n) -> py::object {
            if (n.is_none()) return py::float_(s.next_double());
            const auto k = n.cast<py::ssize_t>();
            if (k < 0) throw pathref::DomainError("random_sample: n must be >= 0");
            py::array_t<double> out(k);
            auto a = out.mutable_unchecked<1>();
            for (py::ssize_t i = 0; i < k; ++i) a(i) = s.next_double();
            return out;
          },
          py::arg("n") = py::none(), "NumPy RandomState(seed).random_sample(n): n draws (a float when n is None)")
      .def("uniform_index", [](pathref::rng::Stream& s, std::size_t n) { return pathref::rng::uniform_index(s.next_double(), n); },
           py::arg("n"), "one draw -> rng.index: floor(u n)")
      .def("roulette", [](pathref::rng::Stream& s, const std::vector<double>& w) { return pathref::rng::roulette(w, s.next_double()); },
           py::arg("weights"), "one draw -> rng.roulette over the weights")
      .def("bernoulli", [](pathref::rng::Stream& s, double p) { return pathref::rng::bernoulli(s.next_double(), p); },
           py::arg("p"), "one draw -> rng.bernoulli: u < p")
      .def_property_readonly("seed", &pathref::rng::Stream::seed)
      .def_property_readonly("doubles_drawn", &pathref::rng::Stream::doubles_drawn);
  m.def("uniform_index", [](double u, std::size_t n) { return pathref::rng::uniform_index(u, n); }, py::arg("u"), py::arg("n"));
  m.def("roulette", [](const std::vector<double>& w, double u) { return pathref::rng::roulette(w, u); }, py::arg("weights"), py::arg("u"));
  m.def("bernoulli", [](double u, double p) { return pathref::rng::bernoulli(u, p); }, py::arg("u"), py::arg("p"));

  m.def("version", [] { return std::string(pathref::version()); });
  m.def("golden_set_version", [] { return std::string(pathref::golden_set_version()); });
  m.def("_eval", &eval_rule);
  m.def("_rules", [] { return pathref::rules::rule_list_json().dump(); });
  m.def("_plan", &plan);
  m.def("_check", &check);
  m.def("_load_map", &load_map);
  m.def("_golden_check", [](const std::string& dir) {
    const py::gil_scoped_release nogil;
    return golden_check(dir);
  });
}
