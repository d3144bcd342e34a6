// CAD assemblies from the command line: `tandem parts`, and a scenario whose obstacles and object
// come from a STEP file (tests/support/cad_assembly.hpp's housing, written by the test).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cad_assembly.hpp"
#include "support/test_support.hpp"

namespace tandem {
namespace {

using test::run_tandem;
using test::TempDir;
using ::testing::HasSubstr;

class CadCliTest : public ::testing::Test {
 protected:
  void SetUp() override { test::write_housing(step_); }

  /// A scenario taking `part` of the housing out to the side, between the block and the lid.
  std::filesystem::path scenario(const std::string& part, const std::string& extra = "") {
    return dir_.write("peg-out.toml", R"(name = "peg-out"
[space]
min = [-0.2, -0.2, -0.05]
max = [0.2, 0.2, 0.15]
[assembly]
file = "housing.step"
part = ")" + part + R"("
)" + extra + R"(
[goal]
position = [0.1, 0.0, 0.046]
)");
  }

  std::filesystem::path path_file(const std::string& name, const std::string& states) {
    return dir_.write(name, states);
  }

  TempDir dir_;
  std::filesystem::path step_ = dir_.path() / "housing.step";
};

TEST_F(CadCliTest, PartsListsTheTreeWithSizesAndColours) {
  const auto r = run_tandem({"parts", step_.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("STEP, length unit 0.001 m"));
  EXPECT_THAT(r.out, HasSubstr("housing (assembly)\n  base [base-block]  0.1 x 0.08 x 0.04 m"));
  EXPECT_THAT(r.out, HasSubstr("  lid-1 [lid-assembly] (assembly)\n    lid [lid-plate]"));
  EXPECT_THAT(r.out, HasSubstr("#1933cc"));  // the base's blue (0.1, 0.2, 0.8)
}

TEST_F(CadCliTest, PartsAsJson) {
  const auto r = run_tandem({"parts", step_.string(), "--json", "--linear-deflection", "1e-5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["linear_deflection_m"].get<double>(), 1e-5);
  ASSERT_EQ(j["nodes"].size(), 6u);
  const auto& peg = j["nodes"][4];
  EXPECT_EQ(peg["path"], "housing/peg");
  EXPECT_NEAR(peg["position_m"][2].get<double>(), 0.011, 1e-12);
  EXPECT_NEAR(peg["size_m"][2].get<double>(), 0.03, 1e-9);
  EXPECT_EQ(peg["color"], "#19b333");  // (0.1, 0.7, 0.2)
}

TEST_F(CadCliTest, BadFilesAndOptionsExitWithCodeTwo) {
  const auto empty = dir_.write("empty.step", "");
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"parts", empty.string()},
           {"parts", (dir_.path() / "missing.igs").string()},
           {"parts", dir_.write("note.step", "just text\n").string()},
           {"parts", step_.string(), "--angular-deflection", "0"}}) {
    const auto r = run_tandem(args);
    EXPECT_EQ(r.exit_code, 2) << args[1] << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr("error"));
  }
  EXPECT_THAT(run_tandem({"parts", empty.string()}).err,
              HasSubstr(empty.string() + ": the file is empty"));
}

TEST_F(CadCliTest, AScenarioTakesThePartFromTheAssembly) {
  const auto problem = scenario("peg").string();
  // Straight up out of the pocket, then out sideways between the block and the lid: valid.
  const auto out =
      path_file("out.path", "0 0 0.011 0 0 0 1\n0 0 0.046 0 0 0 1\n0.1 0 0.046 0 0 0 1\n");
  const auto ok = run_tandem({"check-path", problem, out.string()});
  EXPECT_EQ(ok.exit_code, 0) << ok.out << ok.err;
  // Sideways at once: through the block's wall.
  const auto through = path_file("through.path", "0 0 0.011 0 0 0 1\n0.1 0 0.046 0 0 0 1\n");
  const auto bad = run_tandem({"check-path", problem, through.string()});
  EXPECT_EQ(bad.exit_code, 1) << bad.out << bad.err;
  EXPECT_THAT(bad.out, HasSubstr("the motion from state 0 to state 1 collides"));
  // Up too far: into the lid, a part of a sub-assembly.
  const auto lid = path_file("lid.path", "0 0 0.011 0 0 0 1\n0 0 0.07 0 0 0 1\n");
  const auto into_lid = run_tandem({"check-path", problem, lid.string()});
  EXPECT_EQ(into_lid.exit_code, 1);
  EXPECT_THAT(into_lid.out, HasSubstr("state 1 is in collision"));
}

TEST_F(CadCliTest, ThePlannerTakesThePegOutAndTheWayOutChecksValid) {
  const auto problem = scenario("peg").string();
  const auto path = (dir_.path() / "planned.path").string();
  const auto plan =
      run_tandem({"plan", problem, "--seed", "1", "--time-limit", "60", "--out", path});
  ASSERT_EQ(plan.exit_code, 0) << plan.out << plan.err;
  const auto check = run_tandem({"check-path", problem, path});
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_THAT(check.out, HasSubstr("starts at the start, ends at the goal"));
}

TEST_F(CadCliTest, AScenarioNamingNoSuchPartOrTwoObjectsExitsWithCodeTwo) {
  auto r = run_tandem(
      {"check-path", scenario("bolt").string(), path_file("p.path", "0 0 0 0 0 0 1\n").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("no part named 'bolt'"));
  EXPECT_THAT(r.err, HasSubstr("housing/peg-spare"));
  r = run_tandem({"check-path", scenario("peg", "[object]\nbox = [1, 1, 1]\n").string(),
                  path_file("p.path", "0 0 0 0 0 0 1\n").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("the object is given twice"));
}

}  // namespace
}  // namespace tandem
