#include "python_operator.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>

#include "conversions.hpp"
#include "tandem/core/error.hpp"

namespace tandem::python {
namespace {

std::vector<double> vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

py::object frame_dict(const std::optional<ContactFrame>& f) {
  if (!f)
    return py::none();
  py::dict d;
  d["P_o"] = vec(f->P_o);
  d["P_n"] = vec(f->P_n);
  d["P_c"] = vec(f->P_c);
  d["normal"] = vec(f->n);
  std::vector<std::vector<double>> r(3, std::vector<double>(3));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      r[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = f->R(i, j);
  }
  d["R"] = r;
  d["delta"] = f->delta;
  d["distance"] = f->distance;
  return d;
}

}  // namespace

py::object state_dict(const OperatorState* s, const Problem& problem) {
  if (s == nullptr)
    return py::none();
  py::dict d;
  d["time"] = s->time;
  d["q_device"] = config_array(s->device.q_device, problem.space);
  const std::size_t k = s->nearest.obstacle;
  d["nearest"] = nearest_dict(
      s->nearest, k < problem.scene.obstacles.size() ? problem.scene.obstacles[k].name : "");
  d["contact_frame"] = frame_dict(s->frame);
  return d;
}

PythonOperator::PythonOperator(py::object callable, std::shared_ptr<const Problem> problem)
    : callable_(std::move(callable)),
      problem_(std::move(problem)),
      model_(CollisionChecker(problem_->scene), nullptr) {
  if (!PyCallable_Check(callable_.ptr()))
    throw InputError("operator", "must be a callable, an operator's name or None");
  name_ = py::str(py::getattr(callable_, "__name__", py::type::of(callable_).attr("__name__")));
}

PythonOperator::~PythonOperator() {
  const py::gil_scoped_acquire gil;
  callable_ = py::object();
}

DeviceReading PythonOperator::read(double t) const {
  if (!stop_)
    return call(t);
  const Config held = previous_ ? previous_->device.q_device : problem_->start;
  if (error_)
    return {held};
  try {
    return call(t);
  } catch (...) {
    error_ = std::current_exception();
    stop_();
    return {held};
  }
}

void PythonOperator::rethrow() const {
  if (error_)
    std::rethrow_exception(error_);
}

DeviceReading PythonOperator::call(double t) const {
  const py::gil_scoped_acquire gil;
  py::dict view;
  view["time"] = t;
  view["previous"] = state_dict(previous_ ? &*previous_ : nullptr, *problem_);
  if (trees_)
    trees_(view);
  const py::object q = callable_(view);
  using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;
  Rows row;
  try {
    row = q.cast<Rows>();
  } catch (const py::cast_error&) {
    throw InputError("operator", "must return a configuration (an array of numbers), not " +
                                     std::string(py::str(py::repr(q))));
  }
  if (row.ndim() != 1)
    throw InputError("operator", "must return one configuration (a (7,) or (3,) array)");
  DeviceReading reading{configs_of(row, problem_->space, "the operator's q_device")[0]};
  previous_ = model_.observe(reading, t, t, ++calls_);
  return reading;
}

double PythonOperator::end_time() const {
  return std::numeric_limits<double>::infinity();
}

}  // namespace tandem::python
