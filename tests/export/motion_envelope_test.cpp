// The motion envelope contains the part at every pose along the path (checked at random poses
// between the states, on points of the true primitives: a box's corners and faces, a cylinder's
// rims, a sphere's surface, and inside), with the generalised winding number of the closed mesh;
// it is not much larger than the swept volume; its STL file reads back.

#include "tandem/export/motion_envelope.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/export/stl_file.hpp"
#include "tandem/scene/mesh_loader.hpp"

namespace tandem {
namespace {

using Vec = Eigen::Vector3d;

/// The winding number of the closed mesh around p: 1 inside, 0 outside (Jacobson et al. 2013).
double winding_number(const TriangleMesh& mesh, const Vec& p) {
  double sum = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec a = mesh.vertices[t[0]] - p, b = mesh.vertices[t[1]] - p, c = mesh.vertices[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    sum += 2 * std::atan2(a.dot(b.cross(c)),
                          la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return sum / (4 * std::numbers::pi);
}

/// A box, a cylinder across its end and a sphere on its top: the three kinds of primitive.
Body object() {
  Body body;
  body.name = "object";
  body.parts.push_back({Box{{0.3, 0.1, 0.06}}, Eigen::Isometry3d::Identity()});
  Eigen::Isometry3d across = Eigen::Isometry3d::Identity();
  across.translate(Vec(0.15, 0, 0)).rotate(Eigen::AngleAxisd(std::numbers::pi / 2, Vec::UnitX()));
  body.parts.push_back({Cylinder{0.04, 0.2}, across});
  Eigen::Isometry3d top = Eigen::Isometry3d::Identity();
  top.translate(Vec(-0.1, 0, 0.06));
  body.parts.push_back({Sphere{0.05}, top});
  return body;
}

Config state(double x, double y, double z, double angle, const Vec& axis) {
  return {Vec(x, y, z), Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()))};
}

/// Points of the true geometry of each part (object frame): on its surface and inside.
std::vector<Vec> part_points(const Body& body, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec> points;
  const auto box = std::get<Box>(body.parts[0].geometry).size / 2;
  for (int k = 0; k < 8; ++k)
    points.emplace_back(k & 1 ? box.x() : -box.x(), k & 2 ? box.y() : -box.y(),
                        k & 4 ? box.z() : -box.z());
  for (int k = 0; k < 6; ++k)
    points.push_back(Vec(u(rng), u(rng), u(rng)).cwiseProduct(box));
  const auto cyl = std::get<Cylinder>(body.parts[1].geometry);
  for (int k = 0; k < 12; ++k) {
    const double a = std::numbers::pi * u(rng);
    const Vec rim(cyl.radius * std::cos(a), cyl.radius * std::sin(a),
                  cyl.length / 2 * (k % 2 ? 1 : -1));
    points.push_back(body.parts[1].pose * rim);
  }
  const double r = std::get<Sphere>(body.parts[2].geometry).radius;
  for (int k = 0; k < 12; ++k)
    points.push_back(body.parts[2].pose * (r * Vec(u(rng), u(rng), u(rng)).normalized()));
  return points;
}

class MotionEnvelopeTest : public ::testing::Test {
 protected:
  SE3Space space_{SpaceKind::se3, Bounds{{-2, -2, -2}, {2, 2, 2}}};
  Body body_ = object();
  // Translations and turns of up to 120 degrees, about different axes.
  Path path_{state(0, 0, 0, 0, Vec::UnitZ()), state(0.4, 0.1, 0, 2.0, Vec::UnitZ()),
             state(0.5, 0.4, 0.3, 2.2, Vec(1, 1, 0))};
};

TEST_F(MotionEnvelopeTest, ContainsThePartAtEveryCheckedPoseAlongTheMotion) {
  const double voxel = 0.02;
  const MotionEnvelope e = motion_envelope(body_, path_, space_, voxel);
  ASSERT_GT(e.mesh.triangle_count(), 100u);
  EXPECT_GT(e.poses, path_.size());
  EXPECT_GE(e.offset, 2.2 * voxel);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  int checked = 0;
  for (std::size_t i = 1; i < path_.size(); ++i)
    for (int k = 0; k < 12; ++k) {
      const double s = k == 0 ? 0.0 : k == 1 ? 1.0 : fraction(rng);
      const Eigen::Isometry3d X = space_.interpolate(path_[i - 1], path_[i], s).pose();
      for (const Vec& p : part_points(body_, rng)) {
        ++checked;
        ASSERT_GT(winding_number(e.mesh, X * p), 0.5)
            << "motion " << i << " at " << s << ", part point " << p.transpose();
      }
    }
  EXPECT_EQ(checked, 2 * 12 * 38);
}

TEST_F(MotionEnvelopeTest, IsNotMuchLargerThanTheSweptVolume) {
  const double voxel = 0.02;
  const MotionEnvelope e = motion_envelope(body_, path_, space_, voxel);
  // The swept volume's box, from dense poses of the part's tessellation (a slight underestimate).
  Vec lo = Vec::Constant(1e9), hi = -lo;
  std::mt19937 rng(1);
  for (std::size_t i = 1; i < path_.size(); ++i)
    for (int k = 0; k <= 400; ++k) {
      const Eigen::Isometry3d X = space_.interpolate(path_[i - 1], path_[i], k / 400.0).pose();
      for (const Vec& p : part_points(body_, rng)) {
        lo = lo.cwiseMin(X * p);
        hi = hi.cwiseMax(X * p);
      }
    }
  const auto [elo, ehi] = e.mesh.bounding_box();
  for (int d = 0; d < 3; ++d) {
    EXPECT_LT(elo[d], lo[d]) << "axis " << d;
    EXPECT_GT(ehi[d], hi[d]) << "axis " << d;
    EXPECT_GT(elo[d], lo[d] - e.offset - voxel) << "axis " << d;
    EXPECT_LT(ehi[d], hi[d] + e.offset + voxel) << "axis " << d;
  }
  // Far from the path (the first state's corner of the bounds) is outside.
  EXPECT_LT(winding_number(e.mesh, Vec(-1, -1, -1)), 0.5);
  EXPECT_LT(winding_number(e.mesh, Vec(0.0, 0.4, 0.0)), 0.5);
}

TEST_F(MotionEnvelopeTest, AFinerVoxelGivesATighterEnvelope) {
  const MotionEnvelope coarse = motion_envelope(body_, path_, space_, 0.04);
  const MotionEnvelope fine = motion_envelope(body_, path_, space_, 0.015);
  EXPECT_LT(fine.offset, coarse.offset);
  const auto [clo, chi] = coarse.mesh.bounding_box();
  const auto [flo, fhi] = fine.mesh.bounding_box();
  EXPECT_LT((fhi - flo).prod(), (chi - clo).prod());
}

TEST_F(MotionEnvelopeTest, OneStateIsThePartGrown) {
  const MotionEnvelope e = motion_envelope(body_, {path_.front()}, space_, 0.01);
  EXPECT_EQ(e.poses, 1u);
  EXPECT_GT(winding_number(e.mesh, Vec(0.149, 0.099, 0.0)), 0.5);  // the cylinder's end
  EXPECT_LT(winding_number(e.mesh, Vec(0.0, 0.0, 0.2)), 0.5);      // above the sphere
}

TEST_F(MotionEnvelopeTest, RejectsBadVoxelsNamingTheOption) {
  for (const double voxel : {0.0, -1.0, std::nan(""), 1e-7})
    try {
      motion_envelope(body_, path_, space_, voxel);
      FAIL() << "voxel " << voxel << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "--voxel");
    }
}

TEST_F(MotionEnvelopeTest, ItsStlFileReadsBackWithEveryTriangle) {
  const MotionEnvelope e = motion_envelope(body_, path_, space_, 0.04);
  test::TempDir dir;
  const auto file = dir.path() / "envelope.stl";
  write_stl(e.mesh, file.string(), "tandem test");
  const LoadedMesh back = load_mesh(file);
  EXPECT_EQ(back.mesh.triangle_count() + back.degenerate_removed, e.mesh.triangle_count());
  const auto [lo, hi] = e.mesh.bounding_box();
  const auto [blo, bhi] = back.mesh.bounding_box();
  EXPECT_LT((blo - lo).norm() + (bhi - hi).norm(), 1e-5);
  EXPECT_THROW(write_stl(e.mesh, (dir.path() / "no" / "such.stl").string(), ""), InputError);
}

}  // namespace
}  // namespace tandem
