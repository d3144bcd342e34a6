// The text formats read whole: experiments, path files and operator traces. A path or trace that
// parses must also come back the same from its formatted text (the formats promise exact
// round trips), and a trace must replay at any time of it.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_target.hpp"
#include "scratch_folder.hpp"
#include "tandem/core/error.hpp"
#include "tandem/experiments/experiment.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/operators/trace.hpp"

namespace tandem::fuzz {
namespace {

const SE3Space& fuzz_space(SpaceKind kind = SpaceKind::se3) {
  static const Bounds bounds{Eigen::Vector3d::Constant(-10.0), Eigen::Vector3d::Constant(10.0)};
  static const SE3Space se3(SpaceKind::se3, bounds);
  static const SE3Space planar(SpaceKind::planar, bounds);
  return kind == SpaceKind::se3 ? se3 : planar;
}

bool same_config(const Config& a, const Config& b) {
  return a.t == b.t && a.q.coeffs() == b.q.coeffs();
}

/// Planar path files hold the yaw, not the quaternion: a pose comes back from its formatted text
/// to within rounding of the angle (1e-12), not bit for bit.
bool same_planar_config(const Config& a, const Config& b) {
  return a.t == b.t && SE3Space::rotation_angle(a.q, b.q) <= 1e-12;
}

/// A finding: the property `what` does not hold.
[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz: %s\n", what);
  std::abort();
}

}  // namespace

bool experiment(std::string_view input) {
  try {
    (void)parse_experiment(std::string(input), "experiment.toml", fresh_scratch_folder());
    return true;
  } catch (const InputError&) {
    return false;
  }
}

/// A path file is read for a problem's space: as SE(3) poses, else as planar ones (x y theta).
bool path(std::string_view input) {
  Path parsed;
  const SE3Space* space = nullptr;
  for (const SpaceKind kind : {SpaceKind::se3, SpaceKind::planar}) {
    try {
      parsed = parse_path(std::string(input), fuzz_space(kind), "fuzzed.path");
      space = &fuzz_space(kind);
      break;
    } catch (const InputError&) {
    }
  }
  if (space == nullptr)
    return false;
  const Path again = parse_path(format_path(parsed, *space), *space, "formatted path");
  if (again.size() != parsed.size())
    broken("a formatted path reads back with another number of waypoints");
  for (std::size_t i = 0; i < parsed.size(); ++i) {
    if (space->planar() ? !same_planar_config(again[i], parsed[i])
                        : !same_config(again[i], parsed[i]))
      broken("a formatted path reads back with other waypoints");
  }
  return true;
}

bool trace(std::string_view input) {
  Trace parsed;
  try {
    parsed = parse_trace(std::string(input), "fuzzed trace");
  } catch (const InputError&) {
    return false;
  }
  const Trace again = parse_trace(format_trace(parsed), "formatted trace");
  if (again.samples.size() != parsed.samples.size() || again.clock != parsed.clock)
    broken("a formatted trace reads back with another number of samples or clock");
  for (std::size_t i = 0; i < parsed.samples.size(); ++i) {
    const TraceSample& a = again.samples[i];
    const TraceSample& p = parsed.samples[i];
    if (a.t != p.t || a.buttons != p.buttons || !same_config(a.q, p.q))
      broken("a formatted trace reads back with other samples");
  }
  const TracePlayer player(fuzz_space(), parsed);
  const double end = player.end_time();
  for (const double t :
       {parsed.samples.front().t - 1.0, 0.5 * (parsed.samples.front().t + end), end, end + 1.0}) {
    const DeviceReading r = player.read(t);
    if (!r.q_device.t.allFinite() || std::abs(r.q_device.q.norm() - 1.0) > 1e-6)
      broken("a trace replays to a pose that is not finite or not a unit quaternion");
  }
  return true;
}

}  // namespace tandem::fuzz
