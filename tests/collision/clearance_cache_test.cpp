#include "tandem/collision/clearance_cache.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace tandem {
namespace {

using test::at;

TEST(ClearanceCache, ServesABoundAsGoodAsANewQueryWouldGive) {
  ClearanceCache cache;
  const Config q = at(1, 2, 3), other = at(1, 2, 3.5);
  EXPECT_FALSE(cache.find(q, 0.1).has_value());
  // Not capped (below its cap): the checker's best bound, good for any cap.
  cache.store(q, 0.05, 0.2);
  EXPECT_EQ(cache.find(q, 0.01), 0.05);
  EXPECT_EQ(cache.find(q, 10.0), 0.05);
  EXPECT_FALSE(cache.find(other, 0.01).has_value());
  // Capped at 0.2: it says "at least 0.2", enough for caps up to 0.2, not beyond.
  cache.store(q, 0.2, 0.2);
  EXPECT_EQ(cache.find(q, 0.2), 0.2);
  EXPECT_EQ(cache.find(q, 0.1), 0.2);
  EXPECT_FALSE(cache.find(q, 0.3).has_value());
  cache.clear();
  EXPECT_FALSE(cache.find(q, 0.1).has_value());
}

TEST(ClearanceCache, TellsConfigurationsApartBitForBit) {
  ClearanceCache cache;
  Config q = at(0.1, 0.2, 0.3);
  cache.store(q, 0.5, 1.0);
  Config nudged = q;
  nudged.t.x() = std::nextafter(q.t.x(), 1.0);
  EXPECT_FALSE(cache.find(nudged, 0.1).has_value());
  EXPECT_TRUE(cache.find(q, 0.1).has_value());
}

}  // namespace
}  // namespace tandem
