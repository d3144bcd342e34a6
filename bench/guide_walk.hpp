#pragma once
// The human loop as fast as it goes: a simulated operator ("experienced") walking a problem's whole
// guide in the measured time, each state's nearest obstacle and contact frame computed
// (OperatorModel::compute, what the operator thread does at each tick). Shared by the benchmarks.

#include <cstdint>
#include <memory>

#include "tandem/core/stopwatch.hpp"
#include "tandem/interaction/operator_model.hpp"
#include "tandem/operators/guide_follower.hpp"
#include "tandem/scene/problem.hpp"

namespace bench {

struct GuideWalk {
  std::uint64_t states = 0;
  std::uint64_t framed = 0;  ///< states with a contact frame
  double seconds = 0.0;
};

inline GuideWalk walk_guide(const tandem::Problem& problem, const tandem::CollisionChecker& checker,
                            double seconds) {
  const auto profile =
      tandem::operator_profile("experienced", problem.space, tandem::OperatorClock::seconds);
  auto source = std::make_shared<tandem::GuideFollower>(problem.space, problem.guide, profile, 1);
  tandem::OperatorModel model(checker, source);
  // Walk the whole guide in the measured time, so every part of the scene is queried.
  const double scale = source->end_time() / seconds;
  const tandem::Stopwatch watch;
  GuideWalk walk;
  while ((walk.seconds = watch.seconds()) < seconds) {
    const tandem::OperatorState s = model.compute(walk.seconds * scale, ++walk.states);
    walk.framed += s.frame.has_value();
  }
  return walk;
}

}  // namespace bench
