#include "tandem/interaction/operator_feed.hpp"

#include <cmath>
#include <stdexcept>

namespace tandem {

VirtualTimeFeed::VirtualTimeFeed(OperatorModel model, std::uint64_t period)
    : model_(std::move(model)), period_(period), pacer_(model_.source().lead()) {
  if (period_ == 0)
    throw std::invalid_argument("the operator's period must be at least one iteration");
}

const OperatorState* VirtualTimeFeed::at(std::uint64_t iteration, const RoadmapView* roadmap) {
  const std::uint64_t tick = iteration - iteration % period_;
  if (!have_ || current_.time != static_cast<double>(tick)) {
    const Stopwatch watch;
    // The operator looks at the roadmap around the object where it last held it.
    const double seen = have_ && roadmap != nullptr && std::isfinite(pacer_.lead())
                            ? roadmap->distance_to_roadmap(current_.device.q_device)
                            : 0.0;
    const double pace = pacer_.advance(static_cast<double>(tick), seen);
    current_ = model_.compute(static_cast<double>(tick), pace, tick / period_ + 1);
    operator_seconds_ += watch.seconds();
    have_ = true;
  }
  return &current_;
}

const OperatorState* LiveFeed::at(std::uint64_t iteration, const RoadmapView* roadmap) {
  const OperatorState* s = channel_.latest();
  if (s != nullptr && s->sequence != last_sequence_) {
    last_sequence_ = s->sequence;
    if (keep_record_)
      record_.push_back({iteration, *s});
    if (roadmap_distance_ != nullptr && roadmap != nullptr)
      roadmap_distance_->publish(roadmap->distance_to_roadmap(s->device.q_device));
  }
  return s;
}

const OperatorState* ReplayFeed::at(std::uint64_t iteration, const RoadmapView* /*roadmap*/) {
  while (next_ < record_.size() && record_[next_].iteration <= iteration)
    current_ = &record_[next_++].state;
  return current_;
}

}  // namespace tandem
