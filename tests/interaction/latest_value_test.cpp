#include "tandem/interaction/latest_value.hpp"

#include <gtest/gtest.h>

#include <array>
#include <thread>

namespace tandem {
namespace {

TEST(LatestValue, GivesNothingBeforeTheFirstValueThenTheNewest) {
  LatestValue<int> v;
  EXPECT_EQ(v.latest(), nullptr);
  v.publish(1);
  v.publish(2);
  ASSERT_NE(v.latest(), nullptr);
  EXPECT_EQ(*v.latest(), 2);
  EXPECT_EQ(*v.latest(), 2);  // no new value: the same
  v.publish(3);
  EXPECT_EQ(*v.latest(), 3);
}

/// A value whose fields must all agree: a torn read would show.
struct Payload {
  std::uint64_t sequence = 0;
  std::array<std::uint64_t, 32> copies{};
};

TEST(LatestValue, HandsOverWholeValuesBetweenThreadsWithoutWaiting) {
  LatestValue<Payload> channel;
  constexpr std::uint64_t kCount = 200000;
  std::thread writer([&] {
    for (std::uint64_t i = 1; i <= kCount; ++i) {
      Payload p;
      p.sequence = i;
      p.copies.fill(i);
      channel.publish(p);
    }
  });
  std::uint64_t last = 0, reads = 0, changes = 0;
  while (last < kCount) {
    const Payload* p = channel.latest();
    ++reads;
    if (p == nullptr)
      continue;
    for (std::uint64_t c : p->copies)
      ASSERT_EQ(c, p->sequence);
    ASSERT_GE(p->sequence, last);  // never older than what was seen
    if (p->sequence != last)
      ++changes;
    last = p->sequence;
  }
  writer.join();
  EXPECT_EQ(last, kCount);
  EXPECT_GT(changes, 0u);
  EXPECT_GT(reads, 0u);
}

}  // namespace
}  // namespace tandem
