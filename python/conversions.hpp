#pragma once
// Between tandem's values and Python's: configurations and paths as numpy arrays (rows of the
// path file's numbers: x y z qx qy qz qw, or x y theta in a planar space), JSON as Python objects.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/planning/path.hpp"

namespace tandem::python {

namespace py = pybind11;

/// json.loads of the JSON's text.
py::object to_python(const nlohmann::json& j);

/// The columns of a configuration's row: 7 in SE(3), 3 in a planar space.
std::size_t config_columns(const SE3Space& space);

/// A path as an (n, 7) or (n, 3) array, the numbers tandem writes to a path file.
py::array_t<double> path_array(const Path& path, const SE3Space& space);

/// One configuration as a (7,) or (3,) array.
py::array_t<double> config_array(const Config& q, const SE3Space& space);

/// A nearest obstacle as a dict: in_collision, distance, obstacle (its name), the nearest points.
py::dict nearest_dict(const NearestObstacle& n, const std::string& obstacle_name);

/// An (n, 7) or (n, 3) array (or one row) as a path, read as a path file is (finite numbers,
/// non-zero quaternions, normalised). Throws InputError naming `what` and the row.
Path path_of(const py::array_t<double, py::array::c_style | py::array::forcecast>& rows,
             const SE3Space& space, const std::string& what);

/// The same rows as configurations, converted directly (for batches of queries): finite numbers,
/// quaternions normalised (a zero one is an error), a planar row's theta a turn about z.
std::vector<Config> configs_of(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& rows,
    const SE3Space& space, const std::string& what);

}  // namespace tandem::python
