#pragma once
// The human loop's computations for one instant (Blin et al. 2016, section IV-A): read the device,
// find the nearest obstacle (FCL distance: P_o, P_n, which obstacle), and compute the contact frame
// (n, delta, R by Gram-Schmidt).
//
// compute(t) is a pure function of t (the source is), so the state of any instant can be computed
// on any thread with the same result.
//
// Threading: not thread-safe (it owns a CollisionChecker); one model per thread. clone() gives
// another.

#include <memory>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/interaction/operator_source.hpp"
#include "tandem/interaction/operator_state.hpp"

namespace tandem {

class OperatorModel {
 public:
  /// `checker` is cloned: the model has its own FCL objects. `source` may be null for a model
  /// that only observes given readings (observe()).
  OperatorModel(const CollisionChecker& checker, std::shared_ptr<const OperatorSource> source);

  OperatorModel clone() const { return OperatorModel(checker_, source_); }

  OperatorState compute(double t, std::uint64_t sequence) { return compute(t, t, sequence); }
  /// The state at time t of an operator at `pace` along its way (see Pacer).
  OperatorState compute(double t, double pace, std::uint64_t sequence);
  /// The state for a given device reading: the nearest obstacle and the contact frame at its
  /// q_device (what a replay recomputes from a journal).
  OperatorState observe(const DeviceReading& reading, double t, double pace,
                        std::uint64_t sequence);

  const OperatorSource& source() const { return *source_; }
  const CollisionCounters& counters() const { return checker_.counters(); }

 private:
  CollisionChecker checker_;
  std::shared_ptr<const OperatorSource> source_;
};

}  // namespace tandem
