// The Python module `tandem` (pybind11): problems, every planner of the registry with its declared
// parameters, planning as `tandem plan` does (same seed, same path), path checks, and collision and
// distance queries, one configuration or a batch. Errors are tandem.InputError (a ValueError) with
// tandem's message. python/tandem.pyi describes the module for editors; the README shows its use.
//
// Threading: plan() releases the GIL while it plans; a Collision object is for one thread at a
// time (as CollisionChecker).

#include <pybind11/stl.h>

#include "conversions.hpp"
#include "module_parts.hpp"
#include "plan_run.hpp"
#include "tandem/core/error.hpp"
#include "tandem/io/json_codec.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/planning/planner_settings.hpp"
#include "tandem/runs/run_record.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem::python {

PyProblem load(const std::string& spec, const std::string& part,
               const std::vector<std::string>& allow_dirs) {
  ProblemLoadOptions options;
  options.take_out.part = part;
  for (const auto& d : allow_dirs)
    options.allowed_dirs.emplace_back(d);
  PyProblem p;
  p.problem = std::make_shared<const Problem>(load_problem(spec, options));
  p.spec = spec;
  p.take_out = options.take_out;
  return p;
}

const CollisionChecker& prepared_checker(const PyProblem& p) {
  if (!p.prepared->has_value()) {
    p.prepared->emplace(p.problem->scene);
    // The grid the planners' validators use (the default validation settings).
    const MotionValidator validator(p.problem->space, **p.prepared,
                                    validation_settings(PlannerSettings{}));
  }
  return **p.prepared;
}

PyProblem as_problem(const py::object& problem) {
  if (py::isinstance<py::str>(problem))
    return load(problem.cast<std::string>(), "", {});
  return problem.cast<PyProblem>();
}

namespace {

/// The planner's tunables with their defaults, names, ranges and help (as the tuning panel and
/// the command line declare them).
py::object parameters(const std::string& planner) {
  if (!find_planner(planner))
    throw InputError("planner", unknown_planner(planner));
  const RunSpec spec = default_spec(planner, {});
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [name, value] : used_tunables(spec))
    list.push_back(param_spec_json(find_param(run_tunables(), name)->spec, value));
  return to_python(list);
}

py::list planners() {
  py::list out;
  for (const PlannerEntry& e : planner_registry()) {
    py::dict d;
    d["name"] = std::string(e.name);
    d["description"] = std::string(e.description);
    d["citation"] = std::string(e.citation);
    d["uses_operator"] = e.uses_operator;
    d["parameters"] = parameters(std::string(e.name));
    out.append(d);
  }
  return out;
}

}  // namespace

/// A keyword argument as the command line would have typed it.
std::string option_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value))
    return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::float_>(value))
    return py::str(py::module_::import("builtins").attr("repr")(value));
  return py::str(value);
}

cli::RunArgs run_args(const std::optional<std::string>& planner, std::optional<std::uint64_t> seed,
                      std::optional<double> time_limit, const py::kwargs& params) {
  cli::RunArgs args;
  args.mode = planner;
  args.seed = seed;
  args.time_limit = time_limit;
  for (const auto& [key, value] : params) {
    const std::string name = py::str(key);
    if (find_param(run_tunables(), name) == nullptr)
      throw InputError(name, "unknown parameter (tandem.parameters(planner) lists them)");
    args.tunables[name] = option_text(value);
  }
  return args;
}

namespace {

py::dict plan(const py::object& what, const std::optional<std::string>& planner,
              std::optional<std::uint64_t> seed, std::optional<double> time_limit, bool simplify,
              const py::kwargs& params) {
  const cli::RunArgs args = run_args(planner, seed, time_limit, params);
  const PyProblem p = as_problem(what);
  const Problem& problem = *p.problem;
  const CollisionChecker& prepared = prepared_checker(p);
  cli::PlanRun r;
  {
    const py::gil_scoped_release release;
    r = cli::plan_run(problem, args, simplify, &prepared);
  }
  const bool solved = r.run.status == PlannerStatus::solved;
  py::dict out =
      to_python(record_json(make_record(problem.name, r.spec.mode, used_tunables(r.spec),
                                        r.spec.settings.seed, r.spec.time_limit, r.run, solved)));
  out["path"] = path_array(r.path, problem.space);
  out["path_length"] =
      solved ? py::object(py::float_(path_length(problem.space, r.path))) : py::object(py::none());
  out["mode"] = r.spec.mode;
  return out;
}

py::dict check(const py::object& what,
               const py::array_t<double, py::array::c_style | py::array::forcecast>& rows) {
  const PyProblem p = as_problem(what);
  const Problem& problem = *p.problem;
  const Path path = path_of(rows, problem.space, "path");
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker, validation_settings(PlannerSettings{}));
  const PathCheck c = check_path(path, validator);
  py::dict out;
  out["valid"] = c.valid;
  out["index"] = c.index;
  out["motion"] = c.motion;
  out["out_of_bounds"] = c.out_of_bounds;
  out["message"] = c.valid ? std::string("valid") : c.describe();
  return out;
}

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Collision and distance queries against a problem's obstacles (FCL, as the planners use it).
class Collision {
 public:
  /// The checker the planners use, distance grid included (it answers about half of Easy's
  /// queries without FCL, always as FCL would: see the collision tests).
  explicit Collision(const PyProblem& p)
      : problem_(p.problem), checker_(prepared_checker(p).clone()) {}

  /// Whether the object is clear of every obstacle: a bool for one row, a bool array for many.
  py::object is_free(const Rows& rows) {
    const std::vector<Config> qs = configs_of(rows, problem_->space, "q");
    py::array_t<bool> out(static_cast<py::ssize_t>(qs.size()));
    auto m = out.mutable_unchecked<1>();
    {
      const py::gil_scoped_release release;
      for (std::size_t i = 0; i < qs.size(); ++i)
        m(static_cast<py::ssize_t>(i)) = checker_.is_collision_free(qs[i]);
    }
    if (rows.ndim() == 1)
      return py::bool_(m(0));
    return out;
  }

  /// The nearest obstacle to one configuration: its name, the distance and the nearest points.
  py::dict nearest(const Rows& row) {
    if (row.ndim() != 1)
      throw InputError("q", "nearest() takes one configuration; distances() takes many");
    const NearestObstacle n = checker_.nearest_obstacle(configs_of(row, problem_->space, "q")[0]);
    return nearest_dict(n, checker_.obstacle_name(n.obstacle));
  }

  /// For many configurations: the distances (0 in collision) and the nearest obstacles' names.
  py::tuple distances(const Rows& rows) {
    const std::vector<Config> qs = configs_of(rows, problem_->space, "qs");
    py::array_t<double> d(static_cast<py::ssize_t>(qs.size()));
    auto m = d.mutable_unchecked<1>();
    std::vector<std::size_t> nearest(qs.size());
    {
      const py::gil_scoped_release release;
      for (std::size_t i = 0; i < qs.size(); ++i) {
        const NearestObstacle n = checker_.nearest_obstacle(qs[i]);
        m(static_cast<py::ssize_t>(i)) = n.distance;
        nearest[i] = n.obstacle;
      }
    }
    py::list names;
    for (const std::size_t k : nearest)
      names.append(checker_.obstacle_name(k));
    return py::make_tuple(d, names);
  }

 private:
  std::shared_ptr<const Problem> problem_;
  CollisionChecker checker_;
};

py::array_t<double> bounds_array(const Problem& p) {
  const Bounds& b = p.space.bounds();
  py::array_t<double> out({2, 3});
  auto m = out.mutable_unchecked<2>();
  for (py::ssize_t k = 0; k < 3; ++k) {
    m(0, k) = b.min[k];
    m(1, k) = b.max[k];
  }
  return out;
}

void define_problem(py::module_& m) {
  py::class_<PyProblem>(m, "Problem", "A motion-planning problem, loaded as `tandem plan` loads it")
      .def(py::init(&load), py::arg("spec"), py::arg("part") = "",
           py::arg("allow_dirs") = std::vector<std::string>{},
           "An OMPL.app .cfg, a tandem scenario (.toml), a built-in scene's name, or a STEP or "
           "IGES assembly with `part` (the part to take out)")
      .def_property_readonly("name", [](const PyProblem& p) { return p.problem->name; })
      .def_property_readonly("source", [](const PyProblem& p) { return p.problem->source; })
      .def_property_readonly("planar", [](const PyProblem& p) { return p.problem->space.planar(); })
      .def_property_readonly("bounds", [](const PyProblem& p) { return bounds_array(*p.problem); })
      .def_property_readonly(
          "start",
          [](const PyProblem& p) { return config_array(p.problem->start, p.problem->space); })
      .def_property_readonly(
          "goal",
          [](const PyProblem& p) { return config_array(p.problem->goal, p.problem->space); })
      .def_property_readonly("obstacles",
                             [](const PyProblem& p) {
                               std::vector<std::string> names;
                               for (const Body& b : p.problem->scene.obstacles)
                                 names.push_back(b.name);
                               return names;
                             })
      .def("__repr__",
           [](const PyProblem& p) { return "<tandem.Problem '" + p.problem->name + "'>"; });
}

void define_functions(py::module_& m) {
  m.def("planners", &planners, "Every planner of the registry, with its parameters");
  m.def("parameters", &parameters, py::arg("planner"),
        "The parameters a planner reads: name, default, range, help (as the command line's)");
  m.def("plan", &plan, py::arg("problem"), py::arg("planner") = py::none(),
        py::arg("seed") = py::none(), py::arg("time_limit") = py::none(),
        py::arg("simplify") = true,
        "Plans as `tandem plan` does (same seed and threads, same path). Keyword arguments set "
        "the planner's parameters by name (tandem.parameters(planner)). Returns the run's record "
        "(status, solved, time_s, iterations, nodes, collision_checks, ...) with `path`, an (n, 7) "
        "array (planar: (n, 3)), empty unless solved");
  m.def("check_path", &check, py::arg("problem"), py::arg("path"),
        "Checks every state and every motion of a path (exact validation), as `tandem check-path`");
  py::class_<Collision>(m, "Collision", "Collision and distance queries (FCL) for a problem")
      .def(py::init<const PyProblem&>(), py::arg("problem"))
      .def("is_free", &Collision::is_free, py::arg("q"),
           "True where the object touches no obstacle: one configuration or an (n, 7) batch")
      .def("nearest", &Collision::nearest, py::arg("q"),
           "The nearest obstacle to one configuration, with the nearest points")
      .def("distances", &Collision::distances, py::arg("qs"),
           "For an (n, 7) batch: the distances (0 in collision) and the nearest obstacles");
}

}  // namespace
}  // namespace tandem::python

PYBIND11_MODULE(tandem, m) {
  using namespace tandem::python;
  m.doc() = "tandem: interactive motion planning with contact (see the README)";
  static py::exception<tandem::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr e) {
    try {
      if (e)
        std::rethrow_exception(e);
    } catch (const tandem::InputError& error) {
      PyErr_SetString(input_error.ptr(), error.what());
    }
  });
  define_problem(m);
  define_functions(m);
  define_session(m);
  define_live(m);
  define_bench(m);
}
