#pragma once
// A memo of clearance bounds by configuration. The motions a tree planner checks start at its
// nodes, and a node's clearance was bounded when it was added (as the end of the motion that added
// it): the exact motion validation asks for it again at every motion from that node.
//
// Direct-mapped: one slot per hash of the configuration's bits, so it never grows and a query of
// another configuration in the same slot replaces the entry. Deterministic: what it holds depends
// only on the queries made, in order.
//
// Threading: one per MotionValidator (one thread).

#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

#include "tandem/space/config.hpp"

namespace tandem {

class ClearanceCache {
 public:
  /// A bound for q as good as a new query capped at `cap` would give: the bound stored for q when
  /// it was not capped (it is then the best the checker gives), or when it reaches `cap`.
  std::optional<double> find(const Config& q, double cap) const {
    if (slots_.empty())
      return std::nullopt;
    const Entry& e = slots_[slot(q)];
    if (!e.used || !(e.q == q))
      return std::nullopt;
    if (e.bound < e.cap || e.bound >= cap)
      return e.bound;
    return std::nullopt;
  }

  /// Records the bound of a query of q capped at `cap`.
  void store(const Config& q, double bound, double cap) {
    if (slots_.empty())
      slots_.resize(kSlots);
    slots_[slot(q)] = {q, bound, cap, true};
  }

  void clear() { slots_.clear(); }

 private:
  static constexpr std::size_t kSlots = 4096;  // a power of two

  struct Entry {
    Config q;
    double bound = 0.0;
    double cap = 0.0;
    bool used = false;
  };

  static std::size_t slot(const Config& q) {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    const auto mix = [&h](double v) {
      h ^= std::bit_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    };
    for (int i = 0; i < 3; ++i)
      mix(q.t[i]);
    for (int i = 0; i < 4; ++i)
      mix(q.q.coeffs()[i]);
    return static_cast<std::size_t>(h ^ (h >> 29)) & (kSlots - 1);
  }

  std::vector<Entry> slots_;  ///< kSlots once the first bound is stored
};

}  // namespace tandem
