#pragma once
// Latest-value hand-over from one writer thread to one reader thread: a triple buffer.
//
// The writer publishes whole values; the reader gets the newest one published so far. Neither side
// ever waits for the other: publish() and latest() are wait-free (one atomic exchange each), so the
// operator thread can publish at its own rate and the planner thread reads without ever blocking.
// Values the reader did not pick up in time are overwritten: only the latest matters.
//
// Threading: exactly one thread calls publish() and exactly one thread calls latest() (they may be
// different threads, and either may change over time only with external synchronisation). The three
// slots are handed over through one atomic index with acquire/release ordering, which is what makes
// a published value's contents visible to the reader (and keeps ThreadSanitizer quiet without
// suppressions).

#include <array>
#include <atomic>
#include <cstdint>

namespace tandem {

template <class T>
class LatestValue {
 public:
  LatestValue() = default;
  LatestValue(const LatestValue&) = delete;
  LatestValue& operator=(const LatestValue&) = delete;

  /// Writer thread: makes `value` the latest.
  void publish(const T& value) {
    slots_[back_] = value;
    const std::uint8_t previous =
        middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel);
    back_ = previous & kIndex;
  }

  /// Reader thread: the latest value published, or nullptr before the first. The pointer stays
  /// valid (and its value unchanged) until this reader's next call.
  const T* latest() {
    if ((middle_.load(std::memory_order_relaxed) & kFresh) != 0) {
      const std::uint8_t previous = middle_.exchange(front_, std::memory_order_acq_rel);
      front_ = previous & kIndex;
      seen_ = true;
    }
    return seen_ ? &slots_[front_] : nullptr;
  }

 private:
  static constexpr std::uint8_t kIndex = 3;
  static constexpr std::uint8_t kFresh = 4;

  std::array<T, 3> slots_{};
  std::atomic<std::uint8_t> middle_{
      1};                   // slot index, plus kFresh when the writer put a new value there
  std::uint8_t back_ = 0;   // writer's slot
  std::uint8_t front_ = 2;  // reader's slot
  bool seen_ = false;       // reader: something was published
};

}  // namespace tandem
