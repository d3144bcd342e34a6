// The workspace-guided sampler on Twistycool (a part that must pass a wall's hole): its guide
// crosses the wall through the hole, its samples follow the guide for the share asked, it retires
// as long after the trees cover the guide as they took to, and before its warm-up (the hole is
// narrower than the part lengthwise), or with a share of 0, it draws exactly the uniform samples.
// On Easy, whose route the part fits lengthwise, it guides from the first iteration, and half of
// its guided samples turn the part's longest axis along the route. The checker's
// guide blocks, built once with its grid, are those of the grid inside the space's bounds.

#include "tandem/sampling/guided_sampler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "support/test_support.hpp"
#include "tandem/collision/distance_grid.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/collision/workspace_guide.hpp"
#include "tandem/scene/ompl_app_problem.hpp"

namespace tandem {
namespace {

class GuidedSamplerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    TANDEM_REQUIRE_SHARED_DATA();
    problem_.emplace(load_ompl_app_problem(test::shared_dir() / "benchmarks" / "omplapp" / "3D" /
                                           "Twistycool.cfg"));
    checker_.emplace(problem_->scene);
    validator_.emplace(problem_->space, *checker_);
    validator_->configure({MotionValidation::exact, 0.0, true});
  }
  GuidedSampler sampler(double share) const {
    return GuidedSampler(problem_->space, *checker_, problem_->start, problem_->goal, share);
  }
  /// One sample at `iteration` from `rng`.
  static Config draw(GuidedSampler& s, std::uint64_t iteration, Rng& rng) {
    std::vector<Target> out;
    s.sample({iteration, nullptr, &rng}, out);
    EXPECT_EQ(out.size(), 1u);
    return out.front().q;
  }
  /// The distance from p to the guide's polyline.
  static double off_guide(const std::vector<GuidePoint>& g, const Eigen::Vector3d& p) {
    double best = 1e300;
    for (std::size_t k = 1; k < g.size(); ++k) {
      const Eigen::Vector3d a = g[k - 1].point, d = g[k].point - a;
      const double u = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
      best = std::min(best, (a + u * d - p).norm());
    }
    return best;
  }

  std::optional<Problem> problem_;
  std::optional<CollisionChecker> checker_;
  std::optional<MotionValidator> validator_;
};

TEST_F(GuidedSamplerTest, TheGuideCrossesTheWallThroughTheHole) {
  GuidedSampler s = sampler(0.75);
  Rng rng(3);
  draw(s, GuidedSampler::kGuideWarmup, rng);
  const std::vector<GuidePoint>& guide = s.guide();
  ASSERT_GE(guide.size(), 3u);
  EXPECT_TRUE(guide.front().point.isApprox(problem_->start.t));
  EXPECT_TRUE(guide.back().point.isApprox(problem_->goal.t));
  // Every point between the ends is free space as the grid bounds it, so where the route crosses
  // the wall between the start and the goal (z from -200 to -400) it is in the hole.
  const DistanceGrid& grid = *checker_->distance_grid();
  for (std::size_t k = 1; k + 1 < guide.size(); ++k) {
    EXPECT_GT(guide[k].clearance, 0.0);
    EXPECT_GT(grid.lower_bound(guide[k].point), 0.0) << guide[k].point.transpose();
    EXPECT_TRUE(problem_->space.bounds().contains(guide[k].point));
  }
}

TEST_F(GuidedSamplerTest, SamplesFollowTheGuideForTheShareAsked) {
  GuidedSampler s = sampler(1.0);
  Rng rng(5);
  draw(s, GuidedSampler::kGuideWarmup, rng);
  double widest = 0.0;
  for (const GuidePoint& g : s.guide())
    widest = std::max(widest, g.clearance);
  widest = std::max(widest, 0.1 * checker_->object_extent().half_extents.maxCoeff());
  int near = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const Config q = draw(s, GuidedSampler::kGuideWarmup + 1, rng);
    EXPECT_TRUE(problem_->space.bounds().contains(q.t));
    EXPECT_NEAR(q.q.norm(), 1.0, 1e-9);
    near += off_guide(s.guide(), q.t) < 4.0 * widest ? 1 : 0;
  }
  EXPECT_GT(near, 0.99 * n) << "a Gaussian of the guide's clearance stays within 4 of its sigmas";
  // Uniform samples spread over the bounds: far fewer are that near a route of one corridor.
  Rng uniform_rng(5);
  int uniform_near = 0;
  for (int i = 0; i < n; ++i)
    uniform_near += off_guide(s.guide(), problem_->space.sample_uniform(uniform_rng).t) < widest;
  int guided_near = 0;
  for (int i = 0; i < n; ++i)
    guided_near += off_guide(s.guide(), draw(s, GuidedSampler::kGuideWarmup + 1, rng).t) < widest;
  EXPECT_GT(guided_near, 2 * uniform_near);
}

TEST_F(GuidedSamplerTest, OnceTheTreesCoverTheGuideItGuidesAsLongAgainThenRetires) {
  GuidedSampler s = sampler(1.0);
  Rng rng(7);
  draw(s, GuidedSampler::kGuideWarmup, rng);
  ASSERT_GE(s.guide().size(), 3u);
  // Nodes far from the guide cover nothing; nodes on every point cover it all.
  s.cover(problem_->space.bounds().max);
  EXPECT_TRUE(s.covering());
  for (const GuidePoint& g : s.guide())
    s.cover(g.point);
  EXPECT_FALSE(s.covering());
  // Covered at iteration 1000: still guided up to 1999 (share 1: every sample near the guide)...
  draw(s, 1000, rng);
  double widest = 0.1 * checker_->object_extent().half_extents.maxCoeff();
  for (const GuidePoint& g : s.guide())
    widest = std::max(widest, g.clearance);
  for (std::uint64_t i = 1001; i < 1100; ++i)
    EXPECT_LT(off_guide(s.guide(), draw(s, i, rng).t), 6.0 * widest) << i;
  // ... and uniform from 2000 on.
  Rng same = rng;
  UniformSampler uniform(problem_->space);
  for (std::uint64_t i = 2000; i < 2100; ++i) {
    const Config q = draw(s, i, rng);
    std::vector<Target> out;
    uniform.sample({i, nullptr, &same}, out);
    ASSERT_TRUE(q.t == out.front().q.t && q.q.coeffs() == out.front().q.q.coeffs()) << i;
  }
}

TEST_F(GuidedSamplerTest, BeforeTheWarmUpOrWithoutAShareItDrawsTheUniformSamples) {
  for (double share : {0.0, 0.75}) {
    GuidedSampler s = sampler(share);
    UniformSampler uniform(problem_->space);
    Rng a(11), b(11);
    const std::uint64_t last =
        share == 0.0 ? 3 * GuidedSampler::kGuideWarmup : GuidedSampler::kGuideWarmup;
    for (std::uint64_t i = 0; i < last; ++i) {
      const Config q = draw(s, i, a);
      std::vector<Target> out;
      uniform.sample({i, nullptr, &b}, out);
      ASSERT_TRUE(q.t == out.front().q.t && q.q.coeffs() == out.front().q.q.coeffs()) << i;
    }
  }
}

/// Whether the part's longest axis (`axis`, in its frame) lies along a segment of the guide at q.
bool along_a_segment(const std::vector<GuidePoint>& g, const Eigen::Vector3d& axis,
                     const Config& q) {
  const Eigen::Vector3d world = q.q * axis;
  for (std::size_t k = 1; k < g.size(); ++k) {
    const Eigen::Vector3d d = g[k].point - g[k - 1].point;
    if (d.norm() > 0.0 && std::abs(world.dot(d.normalized())) > 1.0 - 1e-9)
      return true;
  }
  return false;
}

/// The narrowest clearance of a guide's points, its ends aside.
double narrowest(const std::vector<GuidePoint>& g) {
  double c = 1e300;
  for (std::size_t k = 1; k + 1 < g.size(); ++k)
    c = std::min(c, g[k].clearance);
  return c;
}

TEST_F(GuidedSamplerTest, WhereThePartFitsTheRouteLengthwiseItGuidesFromTheFirstIteration) {
  // Twistycool's hole is narrower than the part's second-largest half extent: a warm-up.
  GuidedSampler twisty = sampler(1.0);
  Rng rng(13);
  draw(twisty, 0, rng);
  ASSERT_GE(twisty.guide().size(), 3u);
  EXPECT_LT(narrowest(twisty.guide()), checker_->object_extent().half_extents(1));
  EXPECT_FALSE(twisty.covering()) << "no guiding before the warm-up";

  // Easy's route is wider than that: guided from iteration 0 (share 1: every sample near it).
  const Problem easy =
      load_ompl_app_problem(test::shared_dir() / "benchmarks" / "omplapp" / "3D" / "Easy.cfg");
  CollisionChecker checker(easy.scene);
  MotionValidator(easy.space, checker, {MotionValidation::exact, 0.0, true});
  GuidedSampler s(easy.space, checker, easy.start, easy.goal, 1.0);
  draw(s, 0, rng);
  ASSERT_GE(s.guide().size(), 3u);
  EXPECT_GE(narrowest(s.guide()), checker.object_extent().half_extents(1));
  EXPECT_TRUE(s.covering());
  double widest = 0.1 * checker.object_extent().half_extents.maxCoeff();
  for (const GuidePoint& g : s.guide())
    widest = std::max(widest, g.clearance);
  // Half of the guided samples turn the part's longest axis along the route; Twistycool's, whose
  // part does not fit its route lengthwise, keep uniform orientations.
  const Eigen::Vector3d axis = checker.object_extent().axes.col(0);
  // The turned ones lie near the route's centreline (a Gaussian a tenth as wide), the others
  // spread wider.
  int aligned = 0, others_off = 0;
  const int n = 400;
  for (int i = 1; i <= n; ++i) {
    const Config q = draw(s, static_cast<std::uint64_t>(i), rng);
    const double off = off_guide(s.guide(), q.t);
    EXPECT_LT(off, 6.0 * widest) << i;
    EXPECT_NEAR(q.q.norm(), 1.0, 1e-9);
    const bool turned = along_a_segment(s.guide(), axis, q);
    aligned += turned ? 1 : 0;
    if (turned)
      EXPECT_LT(off, 0.6 * widest) << i;
    else
      others_off += off >= 0.6 * widest ? 1 : 0;
  }
  EXPECT_GT(aligned, 0.4 * n);
  EXPECT_LT(aligned, 0.6 * n);
  EXPECT_GT(others_off, (n - aligned) / 10);
  const Eigen::Vector3d twisty_axis = checker_->object_extent().axes.col(0);
  int twisty_aligned = 0;
  for (int i = 0; i < n; ++i)
    twisty_aligned += along_a_segment(
        twisty.guide(), twisty_axis,
        draw(twisty, GuidedSampler::kGuideWarmup + static_cast<std::uint64_t>(i), rng));
  EXPECT_EQ(twisty_aligned, 0);
}

TEST_F(GuidedSamplerTest, WhereThePartFitsTheRouteLengthwiseItDrawsAlongTheGapTheTreesLeave) {
  const Problem easy =
      load_ompl_app_problem(test::shared_dir() / "benchmarks" / "omplapp" / "3D" / "Easy.cfg");
  CollisionChecker checker(easy.scene);
  MotionValidator(easy.space, checker, {MotionValidation::exact, 0.0, true});
  GuidedSampler covered(easy.space, checker, easy.start, easy.goal, 1.0);
  GuidedSampler fresh(easy.space, checker, easy.start, easy.goal, 1.0);
  Rng rng(31);
  draw(covered, 0, rng);
  draw(fresh, 0, rng);
  const std::vector<GuidePoint>& g = covered.guide();
  ASSERT_GE(g.size(), 8u);
  // Nodes on the first half of the guide: the trees have covered it.
  const std::size_t half = g.size() / 2;
  for (std::size_t k = 0; k < half; ++k)
    covered.cover(g[k].point);
  ASSERT_TRUE(covered.covering());
  const auto nearest_point = [&](const Eigen::Vector3d& p) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < g.size(); ++k)
      best = (g[k].point - p).norm() < (g[best].point - p).norm() ? k : best;
    return best;
  };
  // Samples nearest a point well inside the covered half: only the Gaussian's spill-over once the
  // trees cover it, a share like its share of the length before.
  const int n = 400;
  int behind = 0, behind_before = 0;
  for (int i = 1; i <= n; ++i) {
    behind += nearest_point(draw(covered, static_cast<std::uint64_t>(i), rng).t) + 2 < half;
    behind_before += nearest_point(draw(fresh, static_cast<std::uint64_t>(i), rng).t) + 2 < half;
  }
  EXPECT_LT(behind, n / 10);
  EXPECT_GT(behind_before, n / 5);
}

TEST_F(GuidedSamplerTest, GivenTheRunsRouteItDrawsWhatItWouldHaveFound) {
  const auto route = std::make_shared<const WorkspaceRoute>(
      workspace_route(problem_->space, *checker_, problem_->start.t, problem_->goal.t));
  ASSERT_GE(route->points.size(), 3u);
  EXPECT_FALSE(fits_lengthwise(*route));  // Twistycool's part turns to pass
  GuidedSampler finds = sampler(0.75);
  GuidedSampler given(problem_->space, *checker_, problem_->start, problem_->goal, 0.75, route);
  Rng a(29);
  Rng b(29);
  for (std::uint64_t i = 0; i < GuidedSampler::kGuideWarmup + 300; ++i) {
    const Config p = draw(finds, i, a);
    const Config q = draw(given, i, b);
    ASSERT_EQ(p.t, q.t) << i;
    ASSERT_EQ(p.q.coeffs(), q.q.coeffs()) << i;
  }
  ASSERT_EQ(finds.guide().size(), given.guide().size());
  for (std::size_t k = 0; k < given.guide().size(); ++k)
    EXPECT_EQ(finds.guide()[k].point, route->points[k].point);
}

TEST_F(GuidedSamplerTest, TheCheckersBlocksAreThoseOfItsGridInsideTheSpacesBounds) {
  const DistanceGrid& grid = *checker_->distance_grid();
  ASSERT_NE(checker_->guide_blocks(), nullptr);
  const GuideBlocks& kept = *checker_->guide_blocks();
  const GuideBlocks fresh(grid, problem_->space.bounds());
  ASSERT_EQ(kept.dims(), fresh.dims());
  int open = 0;
  for (int i = 0; i < fresh.size(); ++i) {
    ASSERT_EQ(kept.clearance(i), fresh.clearance(i)) << "block " << i;
    if (fresh.open(i)) {
      ASSERT_EQ(kept.centre(i), fresh.centre(i)) << "block " << i;
      ++open;
    }
  }
  EXPECT_GT(open, fresh.size() / 10) << "Twistycool's bounds are mostly free space";
  const double half = checker_->object_extent().half_extents.maxCoeff();
  EXPECT_GE(find_guide(grid, kept, problem_->start.t, problem_->goal.t, half).size(), 3u);
  checker_->drop_distance_grid();
  EXPECT_EQ(checker_->guide_blocks(), nullptr);
}

}  // namespace
}  // namespace tandem
