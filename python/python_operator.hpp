#pragma once
// An operator written in Python: a callable view -> q_device, where the view (a dict) holds the
// operator time, the trees' state as the session shows it, and the operator's previous state:
// its q_device, the nearest obstacle there and the contact frame (computed here, as the human
// loop computes them). It drives a session in virtual time (called every operator_period planner
// iterations, on the planner's thread) or a live one (called on the operator thread, at its rate).
//
// Threading: read() runs on one thread at a time (the planner's or the operator thread) and takes
// the GIL for the call.

#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "tandem/interaction/operator_model.hpp"
#include "tandem/interaction/operator_source.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem::python {

namespace py = pybind11;

/// An operator state as Python sees it: time, q_device, nearest (dict), contact_frame (dict or
/// None); None for no state.
py::object state_dict(const OperatorState* s, const Problem& problem);

class PythonOperator final : public OperatorSource {
 public:
  /// Adds the trees' state to the view (called with the GIL held, on read()'s thread).
  using TreesView = std::function<void(py::dict& view)>;

  /// Throws InputError if `callable` is not callable.
  PythonOperator(py::object callable, std::shared_ptr<const Problem> problem);
  ~PythonOperator() override;
  PythonOperator(const PythonOperator&) = delete;
  PythonOperator& operator=(const PythonOperator&) = delete;

  /// Set before the session first reads the operator.
  void show_trees(TreesView trees) { trees_ = std::move(trees); }
  /// On the operator thread of a live session an exception cannot go up: read() keeps the first
  /// one, calls `stop` (to end the session), and holds the part where it was. rethrow() raises
  /// it afterwards on the caller's thread.
  void catch_errors(std::function<void()> stop) { stop_ = std::move(stop); }
  void rethrow() const;

  DeviceReading read(double t) const override;
  /// The callable's reading, with its state observed.
  DeviceReading call(double t) const;
  double end_time() const override;
  std::string describe() const override { return "Python operator " + name_; }

 private:
  py::object callable_;
  std::shared_ptr<const Problem> problem_;
  TreesView trees_;
  std::string name_;
  mutable OperatorModel model_;
  mutable std::optional<OperatorState> previous_;
  mutable std::uint64_t calls_ = 0;
  std::function<void()> stop_;
  mutable std::exception_ptr error_;
};

}  // namespace tandem::python
