#include "tandem/interaction/operator_thread.hpp"

#include <chrono>
#include <limits>

#include "tandem/core/stopwatch.hpp"

namespace tandem {

OperatorThread::OperatorThread(OperatorModel model, LatestValue<OperatorState>& channel,
                               double rate_hz, LatestValue<double>* roadmap)
    : model_(std::move(model)),
      channel_(channel),
      roadmap_(roadmap),
      period_s_(rate_hz > 0.0 ? 1.0 / rate_hz : 0.0) {
  thread_ = std::thread([this] { run(); });
}

OperatorThread::~OperatorThread() {
  stop();
}

void OperatorThread::stop() {
  stop_.store(true, std::memory_order_relaxed);
  if (thread_.joinable())
    thread_.join();
}

void OperatorThread::wait_for_first_state(const std::atomic<bool>* cancel) const {
  while (channel_.latest() == nullptr &&
         (cancel == nullptr || !cancel->load(std::memory_order_relaxed)))
    std::this_thread::sleep_for(std::chrono::microseconds(100));
}

double OperatorThread::achieved_rate() const {
  const double elapsed = elapsed_s_.load(std::memory_order_relaxed);
  return elapsed > 0.0 ? static_cast<double>(published()) / elapsed : 0.0;
}

void OperatorThread::run() {
  using Clock = std::chrono::steady_clock;
  const Stopwatch watch;
  auto next = Clock::now();
  std::uint64_t sequence = 0;
  Pacer pacer(
      roadmap_ != nullptr ? model_.source().lead() : std::numeric_limits<double>::infinity(),
      model_.source().reaction_delay());
  while (!stop_.load(std::memory_order_relaxed)) {
    const double t = watch.seconds();
    const double* seen = roadmap_ != nullptr ? roadmap_->latest() : nullptr;
    const double pace = pacer.advance(t, seen != nullptr ? *seen : 0.0);
    channel_.publish(model_.compute(t, pace, ++sequence));
    published_.store(sequence, std::memory_order_relaxed);
    elapsed_s_.store(watch.seconds(), std::memory_order_relaxed);
    waits_.store(pacer.waits(), std::memory_order_relaxed);
    waited_s_.store(pacer.waited(), std::memory_order_relaxed);
    next += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_s_));
    const auto now = Clock::now();
    if (next > now) {
      std::this_thread::sleep_until(next);
    } else {
      next = now;  // fell behind: do not try to catch up with a burst
    }
  }
}

}  // namespace tandem
