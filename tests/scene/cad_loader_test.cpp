#include "tandem/scene/cad_loader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "support/cad_assembly.hpp"
#include "support/test_support.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using test::CadFormat;
using test::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const CadNode& node(const CadAssembly& a, const std::string& path) {
  for (const CadNode& n : a.nodes) {
    if (n.path == path)
      return n;
  }
  throw std::runtime_error("no node " + path);
}

/// The part's world-frame bounding box.
std::pair<Eigen::Vector3d, Eigen::Vector3d> world_box(const CadNode& n) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& v : n.mesh.vertices) {
    lo = lo.cwiseMin(n.placement * v);
    hi = hi.cwiseMax(n.placement * v);
  }
  return {lo, hi};
}

void expect_near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol) {
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), tol) << a.transpose() << " vs " << b.transpose();
}

class CadLoaderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    test::write_housing(dir_->path() / "housing.step");
    housing_ = new CadAssembly(load_cad(dir_->path() / "housing.step"));
  }
  static void TearDownTestSuite() {
    delete housing_;
    delete dir_;
  }
  static TempDir* dir_;
  static CadAssembly* housing_;
};
TempDir* CadLoaderTest::dir_ = nullptr;
CadAssembly* CadLoaderTest::housing_ = nullptr;

TEST_F(CadLoaderTest, ReadsTheAssemblyTreeWithInstanceAndProductNames) {
  std::vector<std::string> paths;
  for (const CadNode& n : housing_->nodes)
    paths.push_back(n.path + (n.assembly ? " (assembly)" : ""));
  EXPECT_THAT(paths, ElementsAre("housing (assembly)", "housing/base", "housing/lid-1 (assembly)",
                                 "housing/lid-1/lid", "housing/peg", "housing/peg-spare"));
  EXPECT_EQ(node(*housing_, "housing/base").product, "base-block");
  EXPECT_EQ(node(*housing_, "housing/peg-spare").product, "peg-pin");
  EXPECT_EQ(node(*housing_, "housing/lid-1/lid").depth, 2);
  EXPECT_EQ(housing_->format, "STEP");
}

TEST_F(CadLoaderTest, ConvertsMillimetresToMetresInPlacementsAndTriangles) {
  EXPECT_DOUBLE_EQ(housing_->unit_m, 0.001);
  const double tol = housing_->linear_deflection + 1e-9;
  auto [lo, hi] = world_box(node(*housing_, "housing/base"));
  expect_near(lo, {-0.05, -0.04, 0.0}, tol);
  expect_near(hi, {0.05, 0.04, 0.04}, tol);
  std::tie(lo, hi) = world_box(node(*housing_, "housing/lid-1/lid"));
  expect_near(lo, {-0.05, -0.04, 0.08}, tol);
  expect_near(hi, {0.05, 0.04, 0.09}, tol);
  const CadNode& peg = node(*housing_, "housing/peg");
  expect_near(peg.placement.translation(), {0, 0, 0.01}, 1e-12);
  std::tie(lo, hi) = world_box(peg);
  expect_near(lo, {-0.009, -0.009, 0.01}, tol);
  expect_near(hi, {0.009, 0.009, 0.04}, tol);
}

TEST_F(CadLoaderTest, SharedProductsKeepTheirOwnPlacements) {
  const CadNode& peg = node(*housing_, "housing/peg");
  const CadNode& spare = node(*housing_, "housing/peg-spare");
  ASSERT_EQ(peg.mesh.vertices.size(), spare.mesh.vertices.size());
  for (std::size_t i = 0; i < peg.mesh.vertices.size(); ++i)
    expect_near(peg.mesh.vertices[i], spare.mesh.vertices[i], 1e-12);  // the product's frame
  expect_near(spare.placement.translation(), {0.2, 0, 0}, 1e-12);
  // Turned 90 degrees about x: the cylinder's axis (z) lies along -y.
  expect_near(spare.placement.linear() * Eigen::Vector3d::UnitZ(), {0, -1, 0}, 1e-12);
}

TEST_F(CadLoaderTest, KeepsSolidAndFaceColours) {
  auto rgb = [](const CadNode& n) { return Eigen::Vector3d(n.color.r, n.color.g, n.color.b); };
  const CadNode& base = node(*housing_, "housing/base");
  ASSERT_TRUE(base.has_color);
  expect_near(rgb(base), {0.1, 0.2, 0.8}, 0.01);
  ASSERT_TRUE(node(*housing_, "housing/peg").has_color);
  expect_near(rgb(node(*housing_, "housing/peg")), {0.1, 0.7, 0.2}, 0.01);
  // The lid's solid has no colour; its one coloured face gives its colour.
  const CadNode& lid = node(*housing_, "housing/lid-1/lid");
  ASSERT_TRUE(lid.has_color);
  expect_near(rgb(lid), {0.9, 0.1, 0.1}, 0.01);
}

TEST_F(CadLoaderTest, TheFilesUnitDoesNotChangeTheMetres) {
  test::write_housing(dir_->path() / "housing-m.step", CadFormat::step, "M");
  const CadAssembly metres = load_cad(dir_->path() / "housing-m.step");
  for (const char* path : {"housing/base", "housing/peg-spare"}) {
    auto [lo, hi] = world_box(node(metres, path));
    auto [lo_mm, hi_mm] = world_box(node(*housing_, path));
    expect_near(lo, lo_mm, 1e-6);
    expect_near(hi, hi_mm, 1e-6);
  }
}

TEST_F(CadLoaderTest, ReadsIges) {
  test::write_housing(dir_->path() / "housing.igs", CadFormat::iges);
  const CadAssembly iges = load_cad(dir_->path() / "housing.igs");
  EXPECT_EQ(iges.format, "IGES");
  std::size_t parts = 0;
  for (const CadNode& n : iges.nodes)
    parts += (!n.assembly && !n.mesh.triangles.empty()) ? 1u : 0u;
  EXPECT_EQ(parts, 4u);  // IGES keeps no assembly tree, but each part
  auto [lo, hi] = iges.bounding_box();
  auto [lo_step, hi_step] = housing_->bounding_box();
  expect_near(lo, lo_step, 2 * housing_->linear_deflection);
  expect_near(hi, hi_step, 2 * housing_->linear_deflection);
}

TEST_F(CadLoaderTest, TheLinearDeflectionIsSettableAndBoundsTheSurfaceError) {
  const double fine = 1e-5;  // metres
  const CadAssembly a = load_cad(dir_->path() / "housing.step", {fine, 0.5});
  EXPECT_DOUBLE_EQ(a.linear_deflection, fine);
  const CadNode& peg = node(a, "housing/peg");
  EXPECT_GT(peg.mesh.triangle_count(), node(*housing_, "housing/peg").mesh.triangle_count());
  // Every triangle's midpoint lies within the deflection of the cylinder's side or caps.
  for (const auto& t : peg.mesh.triangles) {
    const Eigen::Vector3d m =
        (peg.mesh.vertices[t[0]] + peg.mesh.vertices[t[1]] + peg.mesh.vertices[t[2]]) / 3.0;
    const double r = m.head<2>().norm();
    const bool cap = std::abs(m.z()) < 1e-9 || std::abs(m.z() - 0.03) < 1e-9;
    if (!cap) {
      EXPECT_NEAR(r, 0.009, fine + 1e-9);
    }
  }
}

TEST_F(CadLoaderTest, FindsAPartByNameOrPathAndListsThePartsOtherwise) {
  EXPECT_EQ(housing_->part("peg", "x").path, "housing/peg");
  EXPECT_EQ(housing_->part("housing/lid-1/lid", "x").name, "lid");
  const std::string e = test::error_message<InputError>([] { housing_->part("bolt", "--part"); });
  EXPECT_THAT(e, HasSubstr("--part: no part named 'bolt'"));
  EXPECT_THAT(e, HasSubstr("housing/peg-spare"));
}

/// Expects load_cad to throw an InputError whose message names the file and contains `fault`.
void expect_rejected(const std::filesystem::path& file, const std::string& fault) {
  const std::string e = test::error_message<InputError>([&] { load_cad(file); });
  EXPECT_THAT(e, HasSubstr(file.string()));
  EXPECT_THAT(e, HasSubstr(fault));
}

TEST_F(CadLoaderTest, RejectsBadFilesWithOneClearError) {
  const TempDir dir;
  expect_rejected(dir.path() / "missing.step", "no such file");
  expect_rejected(dir.write("empty.step", ""), "empty");
  expect_rejected(dir.write("text.step", "solid t\nendsolid t\n"), "not a STEP file");
  std::ifstream in(dir_->path() / "housing.step");
  const std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  expect_rejected(dir.write("cut.step", whole.substr(0, whole.size() / 2)), "truncated");
  expect_rejected(dir.write("text.igs", "hello\n"), "not an IGES file");
  // An IGES file whose records break the form: each refused before OCCT reads it (its reader
  // crashed on such a file), while the file as written reads.
  test::write_housing(dir.path() / "good.igs", CadFormat::iges);
  std::ifstream good(dir.path() / "good.igs");
  std::vector<std::string> records;
  for (std::string line; std::getline(good, line);)
    records.push_back(line);
  ASSERT_GT(records.size(), 6u);
  const auto joined = [](const std::vector<std::string>& r) {
    std::string text;
    for (const auto& line : r)
      text += line + "\n";
    return text;
  };
  EXPECT_NO_THROW(load_cad(dir.write("same.igs", joined(records))));
  std::vector<std::string> binary = records;
  binary[2][10] = '\x8b';
  expect_rejected(dir.write("binary.igs", joined(binary)), "record 3 has a character");
  std::vector<std::string> order = records;
  std::swap(order[1], order[order.size() - 2]);  // a parameter record before the global section
  expect_rejected(dir.write("order.igs", joined(order)), "in the sections' order");
  std::vector<std::string> global;
  for (const auto& line : records) {
    if (line.size() < 73 || line[72] != 'G')
      global.push_back(line);
  }
  expect_rejected(dir.write("global.igs", joined(global)), "no global section");
  // Its ends: a start record first, a terminate record last, as a cut file has not.
  const std::string text = joined(records);
  expect_rejected(dir.write("cut.igs", text.substr(0, text.size() / 2)), "truncated IGES file");
  expect_rejected(dir.write("cut-record.igs", text.substr(0, text.size() - 20)),
                  "truncated IGES file");
  expect_rejected(dir.write("headless.igs", joined({records.begin() + 1, records.end()})),
                  "its first record is no start record");
  expect_rejected(dir.write("lead.igs", "\n" + text), "its first record is no start record");
  expect_rejected(dir.write("blank.igs", "  \n\n"), "the file is empty");
  test::write_empty_step(dir.path() / "nothing.step");
  expect_rejected(dir.path() / "nothing.step", "no geometry");
  expect_rejected(dir.write("part.stl", "solid t\nendsolid t\n"), "not a STEP or IGES");
  // Read only up to the NUL byte, "part.stl\0.step" would have OCCT read part.stl.
  EXPECT_THAT(test::error_message<InputError>(
                  [&] { load_cad((dir.path() / "part.stl").string() + '\0' + ".step"); }),
              HasSubstr("the file name '" + (dir.path() / "part.stl").string() +
                        "\\0...' holds a NUL byte"));
  const std::string e = test::error_message<InputError>([&] {
    load_cad(dir_->path() / "housing.step", {-1.0, 0.5});
  });
  EXPECT_THAT(e, HasSubstr("deflections"));
}

}  // namespace
}  // namespace tandem
