#pragma once
// One random number generator per planner run, seeded explicitly.
//
// Determinism: the same seed gives the same sequence on every platform with a 64-bit mt19937 (the
// engine is fully specified by the C++ standard). The distributions are written here rather than
// taken from <random>, whose distribution algorithms are implementation-defined, so a recorded seed
// replays identically whatever the standard library. Not thread-safe: one Rng per thread.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace tandem {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : seed_(seed), engine_(seed) {}

  std::uint64_t seed() const { return seed_; }

  /// Uniform in [0, 1), 53 bits of randomness.
  double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

  /// Uniform integer in [0, n), n > 0 (Lemire's nearly-divisionless method is unnecessary here;
  /// rejection keeps it unbiased).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t x;
    do {
      x = engine_();
    } while (x >= limit);
    return x % n;
  }

  /// Standard normal deviate (Marsaglia's polar method).
  double gaussian() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u, v, s;
    do {
      u = uniform(-1.0, 1.0);
      v = uniform(-1.0, 1.0);
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double f = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * f;
    has_spare_ = true;
    return u * f;
  }

  /// A seed for a child generator (e.g. one per benchmark run), derived deterministically.
  std::uint64_t split() { return engine_(); }

 private:
  std::uint64_t seed_;
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace tandem
