// tandem.Session: a planner stepped from Python, iteration by iteration, with its trees readable
// between steps; its operator (for the interactive planners) a simulated one, a trace, or a Python
// callable. Every session is a VirtualSession: in virtual time (the operator's clock counts planner
// iterations), journaled when asked, and `tandem replay JOURNAL` rebuilds its trees.
//
// Threading: a session belongs to the Python thread that made it. step() and run() release the
// GIL; a Python operator takes it back for each call, on the same thread.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>

#include "conversions.hpp"
#include "module_parts.hpp"
#include "python_operator.hpp"
#include "tandem/core/error.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/session/virtual_session.hpp"

namespace tandem::python {
namespace {

/// What a Python operator is shown of a session's trees: the iteration, the nodes, each tree's
/// size, and how far the tree it carries is from where it held the part (None at first).
void show_trees(py::dict& view, const VirtualSession& session) {
  const Planner& planner = session.planner();
  view["iteration"] = planner.stats().iterations;
  view["nodes"] = planner.stats().nodes;
  std::vector<std::size_t> sizes;
  for (const Tree* tree : planner.trees())
    sizes.push_back(tree->size());
  view["tree_sizes"] = sizes;
  const OperatorState* last = session.operator_state();
  view["distance_to_roadmap"] =
      last != nullptr ? py::object(py::float_(planner.distance_to_roadmap(last->device.q_device)))
                      : py::object(py::none());
}

class PySession {
 public:
  PySession(const py::object& what, const std::optional<std::string>& planner,
            std::optional<std::uint64_t> seed, std::optional<double> time_limit,
            const py::object& op, const std::string& journal, std::uint64_t digest_every,
            const py::kwargs& params)
      : problem_(as_problem(what)) {
    cli::RunArgs args = run_args(planner, seed, time_limit, params);
    if (py::isinstance<py::str>(op))
      args.tunables["operator"] = op.cast<std::string>();
    spec_ = cli::make_spec(args, *problem_.problem);
    std::shared_ptr<const OperatorSource> source;
    if (!op.is_none() && !py::isinstance<py::str>(op)) {
      python_op_ = std::make_shared<PythonOperator>(op, problem_.problem);
      source = python_op_;
    }
    VirtualSessionOptions options;
    options.problem_name = problem_.spec;
    options.take_out = problem_.take_out;
    options.journal = journal;
    options.digest_every = digest_every;
    session_ = std::make_unique<VirtualSession>(*problem_.problem, spec_, source, options);
    if (python_op_) {
      const VirtualSession* session = session_.get();
      python_op_->show_trees([session](py::dict& view) { show_trees(view, *session); });
    }
  }

  std::string step(std::uint64_t n) {
    return guarded([&] { return session().step(n); });
  }
  std::string run() {
    return guarded([&] { return session().run(); });
  }
  void close() {
    if (session_)
      session_->finish();
  }

  const VirtualSession& view() const { return *session_; }
  const Problem& problem() const { return *problem_.problem; }
  const RunSpec& spec() const { return spec_; }

 private:
  VirtualSession& session() {
    if (failed_)
      throw InputError("session", "ended when its operator raised an exception");
    return *session_;
  }

  /// Runs the planner without the GIL; an exception of the operator ends the session (the
  /// journal keeps what it recorded) and reaches Python.
  template <class F>
  std::string guarded(F&& f) {
    try {
      PlannerStatus s;
      {
        const py::gil_scoped_release release;
        s = f();
      }
      return std::string(to_string(s));
    } catch (...) {
      if (!failed_) {
        failed_ = true;
        session_->finish();
      }
      throw;
    }
  }

  PyProblem problem_;
  RunSpec spec_;
  std::shared_ptr<PythonOperator> python_op_;
  std::unique_ptr<VirtualSession> session_;
  bool failed_ = false;
};

/// The trees: per tree its nodes (n, 7), parents (n,) (-1 for the root) and node sources.
py::list trees(const PySession& s) {
  py::list out;
  for (const Tree* tree : s.view().planner().trees()) {
    py::dict d;
    d["nodes"] = path_array(tree->nodes, s.problem().space);
    py::array_t<std::int64_t> parents(static_cast<py::ssize_t>(tree->size()));
    auto m = parents.mutable_unchecked<1>();
    std::vector<std::string> sources;
    for (std::size_t i = 0; i < tree->size(); ++i) {
      m(static_cast<py::ssize_t>(i)) =
          tree->parent[i] == Tree::kNoParent ? -1 : static_cast<std::int64_t>(tree->parent[i]);
      sources.emplace_back(to_string(tree->source[i]));
    }
    d["parents"] = parents;
    d["sources"] = sources;
    out.append(d);
  }
  return out;
}

py::dict stats(const PySession& s) {
  const PlannerStats& st = s.view().planner().stats();
  py::dict d;
  d["iterations"] = st.iterations;
  d["nodes"] = st.nodes;
  d["edges"] = st.edges;
  d["collision_checks"] = st.collision_checks;
  d["operator_iterations"] = st.operator_iterations;
  d["contact_entries"] = st.contact_entries;
  py::dict by_source;
  for (std::size_t k = 0; k < kNodeSources; ++k)
    by_source[py::str(std::string(to_string(static_cast<NodeSource>(k))))] = st.nodes_by_source[k];
  d["nodes_by_source"] = by_source;
  return d;
}

}  // namespace

void define_session(py::module_& m) {
  py::class_<PySession>(m, "Session",
                        "A planner stepped from Python, with its operator; journaled on request")
      .def(py::init<const py::object&, const std::optional<std::string>&,
                    std::optional<std::uint64_t>, std::optional<double>, const py::object&,
                    const std::string&, std::uint64_t, const py::kwargs&>(),
           py::arg("problem"), py::arg("planner") = py::none(), py::arg("seed") = py::none(),
           py::arg("time_limit") = py::none(), py::arg("operator") = py::none(),
           py::arg("journal") = "", py::arg("digest_every") = 10000,
           "planner: a registry name (tandem.planners()); operator: for the interactive planners, "
           "None (the planner's default), a simulated operator's name ('experienced', "
           "'inexperienced', 'trace:FILE') or a callable view -> q_device called every "
           "operator_period iterations; journal: a file for `tandem replay`. Keyword arguments "
           "set the planner's parameters by name")
      .def("step", &PySession::step, py::arg("n") = 1,
           "Up to n planner iterations (fewer if it ends); returns the status")
      .def("run", &PySession::run,
           "Steps until solved, the time limit or the iteration limit; returns the status")
      .def("close", &PySession::close, "Ends the session (writes the journal's end record)")
      .def("__enter__", [](PySession& s) -> PySession& { return s; })
      .def("__exit__", [](PySession& s, const py::args&) { s.close(); })
      .def_property_readonly(
          "status", [](const PySession& s) { return std::string(to_string(s.view().status())); })
      .def_property_readonly("steps", [](const PySession& s) { return s.view().steps(); })
      .def_property_readonly(
          "tree_digest",
          [](const PySession& s) { return format_digest(tree_digest(s.view().planner().trees())); })
      .def_property_readonly("stats", &stats)
      .def_property_readonly("mode", [](const PySession& s) { return s.spec().mode; })
      .def_property_readonly("seed", [](const PySession& s) { return s.spec().settings.seed; })
      .def("trees", &trees, "Per tree: nodes (n, 7), parents (n,) with -1 at the root, sources")
      .def_property_readonly("solution",
                             [](const PySession& s) {
                               return path_array(s.view().planner().solution(), s.problem().space);
                             })
      .def_property_readonly(
          "operator_state",
          [](const PySession& s) { return state_dict(s.view().operator_state(), s.problem()); })
      .def_property_readonly("journal", [](const PySession& s) -> py::object {
        const auto* f = s.view().journal_file();
        return f != nullptr ? py::object(py::str(f->string())) : py::object(py::none());
      });
}

}  // namespace tandem::python
