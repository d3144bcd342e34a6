// tandem.live: a live session, in human time, whose operator is a Python callable (or a simulated
// operator): the papers' two loops on two threads, as `tandem interactive` runs them, journaled,
// so that `tandem replay JOURNAL` rebuilds the same trees.
//
// Threading: the planner runs on the calling thread with the GIL released; the operator thread
// takes the GIL for each call of the Python operator (at rate_hz).

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "conversions.hpp"
#include "module_parts.hpp"
#include "python_operator.hpp"
#include "tandem/core/error.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/session/live_session.hpp"

namespace tandem::python {
namespace {

/// What the operator is shown of a live session's trees (its progress, updated a few tens of
/// times a second).
void show_progress(py::dict& view, const LiveSession& session) {
  const LiveProgress p = session.progress();
  view["iteration"] = p.stats.iterations;
  view["nodes"] = p.stats.nodes;
  view["elapsed_s"] = p.elapsed_s;
  view["iterations_per_s"] = p.iterations_per_s;
}

py::dict outcome(const LiveSession& session, PlannerStatus status, const Problem& problem) {
  const Planner& planner = session.planner();
  py::dict d;
  d["status"] = std::string(to_string(status));
  d["steps"] = session.steps();
  d["iterations"] = planner.stats().iterations;
  d["nodes"] = planner.stats().nodes;
  d["tree_digest"] = format_digest(tree_digest(planner.trees()));
  d["solution"] = path_array(planner.solution(), problem.space);
  d["journal"] = session.journal_file().string();
  return d;
}

py::dict live(const py::object& what, const std::optional<std::string>& planner,
              std::optional<std::uint64_t> seed, std::optional<double> time_limit,
              const py::object& op, const std::string& journal, double rate_hz,
              const py::kwargs& params) {
  const PyProblem p = as_problem(what);
  cli::RunArgs args = run_args(planner, seed, time_limit, params);
  if (py::isinstance<py::str>(op))
    args.tunables["operator"] = op.cast<std::string>();
  const RunSpec spec = cli::make_spec(args, *p.problem);
  if (journal.empty())
    throw InputError("journal", "a live session is journaled: give journal=FILE");
  if (!(rate_hz > 0.0 && rate_hz <= 10000.0))
    throw InputError("rate_hz", "must be in (0, 10000], not " + std::to_string(rate_hz));
  LiveOptions options;
  options.problem_name = p.spec;
  options.take_out = p.take_out;
  options.journal = journal;
  options.operator_rate_hz = rate_hz;
  options.spacemouse = false;
  std::shared_ptr<PythonOperator> python_op;
  if (!op.is_none() && !py::isinstance<py::str>(op)) {
    python_op = std::make_shared<PythonOperator>(op, p.problem);
    options.operator_source = python_op;
  }
  LiveSession session(*p.problem, spec, options);
  if (python_op) {
    python_op->show_trees([&session](py::dict& view) { show_progress(view, session); });
    python_op->catch_errors([&session] { session.stop(); });
  }
  PlannerStatus status = PlannerStatus::running;
  {
    const py::gil_scoped_release release;
    status = session.run();
  }
  if (python_op)
    python_op->rethrow();
  return outcome(session, status, *p.problem);
}

}  // namespace

void define_live(py::module_& m) {
  m.def("live", &live, py::arg("problem"), py::arg("planner") = py::none(),
        py::arg("seed") = py::none(), py::arg("time_limit") = py::none(),
        py::arg("operator") = py::none(), py::arg("journal") = "", py::arg("rate_hz") = 200.0,
        "A live session in human time, as `tandem interactive` runs one: the planner on this "
        "thread, the operator on its own, called rate_hz times a second with a view (time in "
        "seconds, iteration, nodes, elapsed_s, previous: its previous state) and returning "
        "q_device. Journaled to `journal`; `tandem replay` rebuilds the trees. Returns status, "
        "steps, iterations, nodes, tree_digest, solution, journal");
}

}  // namespace tandem::python
