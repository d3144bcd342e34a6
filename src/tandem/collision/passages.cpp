#include "tandem/collision/passages.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cstdint>

namespace tandem {
namespace {

/// A clearly curved ridge: the second difference across it is at least half of what a tube's
/// axis between two cells gives (-1/h; -2/h on a cell).
constexpr double kAcross = -0.5;
/// Along a tube the curvature is at most this share of the weaker curvature across it.
constexpr double kAlongShare = 0.25;

class Sampler {
 public:
  explicit Sampler(const DistanceGrid& grid) : grid_(grid) {}
  double at(const Eigen::Vector3i& i) const { return grid_.centre_bound(i); }
  /// The Hessian of the bound at cell i times the spacing (dimensionless: -2 across a tube's axis
  /// through the cell, -1 across one between two cells).
  Eigen::Matrix3d hessian(const Eigen::Vector3i& i, double f) const {
    Eigen::Matrix3d h;
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3i ea = Eigen::Vector3i::Unit(a);
      h(a, a) = at(i + ea) - 2.0 * f + at(i - ea);
      for (int b = a + 1; b < 3; ++b) {
        const Eigen::Vector3i eb = Eigen::Vector3i::Unit(b);
        h(a, b) = h(b, a) =
            0.25 * (at(i + ea + eb) - at(i + ea - eb) - at(i - ea + eb) + at(i - ea - eb));
      }
    }
    return h / grid_.spacing();
  }

 private:
  const DistanceGrid& grid_;
};

}  // namespace

std::vector<Passage> find_passages(const DistanceGrid& grid, double max_clearance) {
  const Sampler s(grid);
  std::vector<Passage> found;
  // The first pass reads the stored bytes (a bound is increasing in its byte): a positive bound
  // below max_clearance, at least its neighbours' along two axes.
  const std::vector<std::uint8_t>& v = grid.values();
  const double lowest = grid.slack() / grid.quantum();                     // bound 0
  const double highest = (max_clearance + grid.slack()) / grid.quantum();  // bound max_clearance
  const Eigen::Vector3i& n = grid.dims();
  const auto nx = static_cast<std::size_t>(n.x());
  const auto ny = static_cast<std::size_t>(n.y());
  const std::array<std::size_t, 3> stride{1, nx, nx * ny};
  for (int z = 1; z + 1 < n.z(); ++z) {
    for (int y = 1; y + 1 < n.y(); ++y) {
      const std::size_t row = (static_cast<std::size_t>(z) * ny + static_cast<std::size_t>(y)) * nx;
      for (int x = 1; x + 1 < n.x(); ++x) {
        const std::size_t c = row + static_cast<std::size_t>(x);
        const std::uint8_t f = v[c];
        if (!(f > lowest && f < highest))
          continue;
        int maxima = 0;  // at least both neighbours and above one (a plateau is no ridge)
        for (const std::size_t d : stride) {
          const std::uint8_t a = v[c + d], b = v[c - d];
          maxima += (f >= a && f >= b && f > std::min(a, b)) ? 1 : 0;
        }
        if (maxima < 2)
          continue;
        const Eigen::Vector3i i(x, y, z);
        const double bound = s.at(i);
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(s.hessian(i, bound));
        const Eigen::Vector3d& l = eig.eigenvalues();  // ascending
        if (l(1) < kAcross && l(2) > kAlongShare * l(1))
          found.push_back({grid.centre(i), eig.eigenvectors().col(2).normalized(), bound});
      }
    }
  }
  return found;
}

}  // namespace tandem
