// EXTEND (LaValle and Kuffner): toward a target, at most the range, classic or up to the last
// valid configuration.

#include "tandem/planning/extend.hpp"

#include <gtest/gtest.h>

#include "support/problems.hpp"

namespace tandem {
namespace {

using Fixture = test::ProblemFixture;

TEST(Extend, StopsAtTheRangeAndReportsWhatItDid) {
  Fixture f;
  Tree tree(f.problem.space, "kdtree", f.problem.start);
  Config far = f.problem.start;
  far.t.y() = 2.0;
  const Extension e = extend(tree, far, 0.5, f.validator, ExtendMode::classic);
  ASSERT_EQ(e.status, ExtendStatus::advanced);
  EXPECT_NEAR(f.problem.space.distance(tree.nodes[e.node], f.problem.start), 0.5, 1e-12);
  Config near = tree.nodes[e.node];
  near.t.y() += 0.2;
  EXPECT_EQ(extend(tree, near, 0.5, f.validator, ExtendMode::classic).status,
            ExtendStatus::reached);
  // Toward the wall: classic adds nothing, last_valid stops at it.
  Config beyond = f.problem.start;
  beyond.t = {0.5, 1.0, 0};
  Tree t2(f.problem.space, "kdtree",
          Config{Eigen::Vector3d(-1, 1, 0), Eigen::Quaterniond::Identity()});
  EXPECT_EQ(extend(t2, beyond, 5.0, f.validator, ExtendMode::classic).status,
            ExtendStatus::trapped);
  const Extension stopped = extend(t2, beyond, 5.0, f.validator, ExtendMode::last_valid);
  ASSERT_EQ(stopped.status, ExtendStatus::stopped);
  EXPECT_LT(t2.nodes[stopped.node].t.x(), -0.5);
  EXPECT_GT(t2.nodes[stopped.node].t.x(), -0.6);
}

TEST(Extend, AddsNothingTowardANodeOfTheTree) {
  // An operator who holds the part still is the same target iteration after iteration: once the
  // tree has reached it, it must not fill up with copies of it.
  Fixture f;
  for (const ExtendMode mode : {ExtendMode::classic, ExtendMode::last_valid}) {
    Tree tree(f.problem.space, "kdtree", f.problem.start);
    Config target = f.problem.start;
    target.t.y() += 0.3;
    const Extension first = extend(tree, target, 0.5, f.validator, mode, NodeSource::operator_);
    ASSERT_EQ(first.status, ExtendStatus::reached);
    EXPECT_TRUE(first.added);
    for (int k = 0; k < 5; ++k) {
      const Extension again = extend(tree, target, 0.5, f.validator, mode, NodeSource::operator_);
      EXPECT_EQ(again.status, ExtendStatus::reached);
      EXPECT_FALSE(again.added);
      EXPECT_EQ(again.node, first.node);
    }
    EXPECT_EQ(tree.size(), 2u);
  }
}

}  // namespace
}  // namespace tandem
