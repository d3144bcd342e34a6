#pragma once
// Operator traces: q_device over time, as a session recorder writes them and as the trace player
// replays them.
//
// File format (text, one sample per line, like OMPL's path format with a time column in front):
//
//   # tandem operator trace 1
//   # clock: ticks                 (or: seconds)
//   # t x y z qx qy qz qw buttons
//   0 -2 0 0.6 0 0 0.7071067811865476 0.7071067811865476 0
//   ...
//
// t is operator time (planner iterations for "ticks", seconds for "seconds") and never decreases;
// the pose is the object's (x y z and a unit quaternion); buttons is a bit mask. Numbers are
// written with 17 significant digits so that a replay sees exactly the recorded values. Lines
// starting with '#' are comments, except the two header lines, which are required.

#include <filesystem>
#include <string>
#include <vector>

#include "tandem/interaction/operator_source.hpp"
#include "tandem/operators/operator_profile.hpp"

namespace tandem {

struct TraceSample {
  double t = 0.0;
  Config q;
  std::uint32_t buttons = 0;
};

struct Trace {
  OperatorClock clock = OperatorClock::ticks;
  std::vector<TraceSample> samples;
};

std::string format_trace(const Trace& trace);
/// Throws InputError naming `source` and the line for a missing header, a wrong number of fields, a
/// non-finite number, a zero quaternion, a decreasing time, or no samples.
Trace parse_trace(const std::string& text, const std::string& source);
Trace read_trace_file(const std::filesystem::path& file);
void write_trace_file(const std::filesystem::path& file, const Trace& trace);

/// Replays a trace: the pose at t is the geodesic interpolation between the samples around t (the
/// last sample after the end); buttons are those of the last sample at or before t.
class TracePlayer final : public OperatorSource {
 public:
  TracePlayer(const SE3Space& space, Trace trace);

  DeviceReading read(double t) const override;
  double end_time() const override { return trace_.samples.back().t; }
  std::string describe() const override;
  OperatorClock clock() const { return trace_.clock; }

 private:
  Config pose(double t) const;

  const SE3Space& space_;
  Trace trace_;
};

}  // namespace tandem
