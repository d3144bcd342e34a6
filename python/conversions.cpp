#include "conversions.hpp"

#include <pybind11/stl.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/space/unit_quaternion.hpp"

namespace tandem::python {

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

std::size_t config_columns(const SE3Space& space) {
  return space.planar() ? 3 : 7;
}

py::array_t<double> path_array(const Path& path, const SE3Space& space) {
  const std::size_t cols = config_columns(space);
  py::array_t<double> out({path.size(), cols});
  auto m = out.mutable_unchecked<2>();
  std::istringstream text(format_path(path, space));
  for (py::ssize_t i = 0; i < m.shape(0); ++i)
    for (py::ssize_t k = 0; k < m.shape(1); ++k)
      text >> m(i, k);
  return out;
}

namespace {

/// The rows' count and columns; throws when the shape is not (cols,) or (n, cols).
py::ssize_t row_count(const py::array& rows, py::ssize_t cols, const std::string& what) {
  const bool one = rows.ndim() == 1;
  if (!((one && rows.shape(0) == cols) || (rows.ndim() == 2 && rows.shape(1) == cols)))
    throw InputError(what, "must be an array of shape (" + std::to_string(cols) + ",) or (n, " +
                               std::to_string(cols) + ")");
  return one ? 1 : rows.shape(0);
}

Config config_of(const double* v, bool planar, const std::string& where) {
  for (int k = 0; k < (planar ? 3 : 7); ++k)
    if (!std::isfinite(v[k]))
      throw InputError(where, "has a number that is not finite");
  Config q;
  if (planar) {
    q.t = {v[0], v[1], 0.0};
    q.q = Eigen::Quaterniond(Eigen::AngleAxisd(v[2], Eigen::Vector3d::UnitZ()));
    return q;
  }
  q.t = {v[0], v[1], v[2]};
  // Any four finite numbers but zero: 1e200 as a component reads as the direction it gives.
  const std::optional<Eigen::Quaterniond> unit = unit_quaternion(v[6], v[3], v[4], v[5]);
  if (!unit)
    throw InputError(where, "has a zero quaternion");
  q.q = *unit;
  return q;
}

}  // namespace

std::vector<Config> configs_of(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& rows,
    const SE3Space& space, const std::string& what) {
  const auto cols = static_cast<py::ssize_t>(config_columns(space));
  const py::ssize_t n = row_count(rows, cols, what);
  std::vector<Config> out;
  out.reserve(static_cast<std::size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i)
    out.push_back(
        config_of(rows.data() + i * cols, space.planar(), what + ", row " + std::to_string(i)));
  return out;
}

Path path_of(const py::array_t<double, py::array::c_style | py::array::forcecast>& rows,
             const SE3Space& space, const std::string& what) {
  const auto cols = static_cast<py::ssize_t>(config_columns(space));
  const py::ssize_t n = row_count(rows, cols, what);
  const double* data = rows.data();
  std::ostringstream text;
  text << std::setprecision(17);
  for (py::ssize_t i = 0; i < n; ++i) {
    for (py::ssize_t k = 0; k < cols; ++k)
      text << (k ? " " : "") << data[i * cols + k];
    text << '\n';
  }
  return parse_path(text.str(), space, what);
}

py::array_t<double> config_array(const Config& q, const SE3Space& space) {
  const py::array_t<double> rows = path_array({q}, space);
  py::array_t<double> out(rows.shape(1));
  std::copy(rows.data(), rows.data() + rows.shape(1), out.mutable_data());
  return out;
}

py::dict nearest_dict(const NearestObstacle& n, const std::string& obstacle_name) {
  py::dict out;
  out["in_collision"] = n.in_collision;
  out["distance"] = n.distance;
  out["obstacle"] = obstacle_name;
  out["point_on_object"] = std::vector<double>{n.point_on_object.begin(), n.point_on_object.end()};
  out["point_on_obstacle"] =
      std::vector<double>{n.point_on_obstacle.begin(), n.point_on_obstacle.end()};
  return out;
}

}  // namespace tandem::python
