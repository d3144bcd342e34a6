#pragma once
// What the parts of the Python module share: a loaded problem, and planner options given as
// keyword arguments, read as the command line reads them. Each part defines its classes and
// functions on the module.

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "run_options.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/scene/problem.hpp"
#include "tandem/scene/take_out.hpp"

namespace tandem::python {

namespace py = pybind11;

/// A loaded problem, shared by the objects made from it.
struct PyProblem {
  std::shared_ptr<const Problem> problem;
  /// A checker of the problem's scene with its distance grid, made at the first plan() and
  /// cloned by every plan() (the grid takes longer to build than an easy problem to plan). Made
  /// with the GIL held, then only cloned (a const read, safe from several threads).
  std::shared_ptr<std::optional<CollisionChecker>> prepared =
      std::make_shared<std::optional<CollisionChecker>>();
  std::string spec;  ///< as given: a file, a built-in scene's name (journals name it so)
  TakeOutOptions take_out;
};

PyProblem load(const std::string& spec, const std::string& part,
               const std::vector<std::string>& allow_dirs);
/// The problem's prepared checker (made at the first call; see PyProblem::prepared).
const CollisionChecker& prepared_checker(const PyProblem& p);
/// A Problem, or the spec of one (a file or a built-in scene's name), loaded.
PyProblem as_problem(const py::object& problem);

/// A keyword argument as the command line would have typed it.
std::string option_text(const py::handle& value);
/// The command line's options of a run: the planner, the seed, the time limit and the planner's
/// parameters by name. Throws InputError for an unknown parameter.
cli::RunArgs run_args(const std::optional<std::string>& planner, std::optional<std::uint64_t> seed,
                      std::optional<double> time_limit, const py::kwargs& params);

/// tandem.Session and the operators written in Python (session_binding.cpp).
void define_session(py::module_& m);
/// tandem.live: a live session with a Python operator (live_binding.cpp).
void define_live(py::module_& m);
/// tandem.bench: an experiment file run as `tandem bench` runs it (bench_binding.cpp).
void define_bench(py::module_& m);

}  // namespace tandem::python
