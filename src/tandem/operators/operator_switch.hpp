#pragma once
// The live operator of an interactive session: whichever input has the part now.
//
// The papers' operator holds a 6D device; in tandem the part can be held by a simulated operator
// or a recorded trace (a pure function of time, see OperatorSource), by the browser (the viewer's
// drag gizmo, keyboard, gamepad or WebHID SpaceMouse send poses), or by a SpaceMouse through
// spacenavd (velocities, integrated here on the operator thread). Inputs can be switched at any
// time; a person takes over from the simulated operator by moving the part, from where it is.
//
// Unlike the other sources, a live input is not a function of time: what the planner saw of it is
// recorded by the session's journal (the operator states, with the iteration that used them), which
// is what makes a session replayable.
//
// Threading: read()/read_paced() on the operator thread only; the setters and snapshot() from any
// thread (a mutex guards the shared part; the operator thread holds it for a few copies).

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

#include "tandem/interaction/operator_source.hpp"
#include "tandem/operators/spacenav.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

enum class OperatorInput : std::uint8_t { simulated, browser, spacemouse };
std::string_view to_string(OperatorInput input);
std::optional<OperatorInput> parse_operator_input(std::string_view name);

class OperatorSwitch final : public OperatorSource {
 public:
  /// `simulated` may be null (no simulated operator: the part starts held at `start`, still).
  /// `spacenav` may be null (no SpaceMouse daemon); `no_spacenav` then says why.
  OperatorSwitch(const SE3Space& space, std::shared_ptr<const OperatorSource> simulated,
                 const Config& start, std::unique_ptr<SpaceNav> spacenav = nullptr,
                 std::string no_spacenav = "no SpaceMouse");

  DeviceReading read(double t) const override { return read_paced(t, t); }
  DeviceReading read_paced(double t, double pace) const override;
  double lead() const override;
  double reaction_delay() const override;
  double end_time() const override;
  std::string describe() const override;

  /// Hands the part to an input; the new input starts from where the part is. Returns false (and
  /// changes nothing) for an input that is not available here (no simulated operator, no
  /// SpaceMouse), with the reason in *why.
  bool select(OperatorInput input, std::string* why = nullptr);
  /// A pose from the browser; the browser takes over. Clamped to the bounds, normalised.
  /// `input_id` identifies the event (0: none), for measuring its latency to the tree.
  void set_pose(const Config& q, std::uint64_t input_id);
  /// When the browser event `input_id` arrived, if it is the latest one.
  std::optional<std::chrono::steady_clock::time_point> input_time(std::uint64_t input_id) const;
  /// Scale of a SpaceMouse at full deflection: scene units per second, radians per second.
  void set_spacemouse_speed(double linear, double angular);

  struct Snapshot {
    OperatorInput input = OperatorInput::simulated;
    bool simulated_available = false;
    bool spacemouse_available = false;
    std::string spacemouse_status;  ///< why not, or the device's name
  };
  Snapshot snapshot() const;

 private:
  const SE3Space& space_;
  std::shared_ptr<const OperatorSource> simulated_;
  std::unique_ptr<SpaceNav> spacenav_;  ///< used on the operator thread only
  std::string no_spacenav_;
  mutable std::mutex mutex_;
  // Guarded by mutex_.
  OperatorInput input_;
  mutable Config held_;           ///< where the part is (the operator thread updates it)
  std::uint64_t held_input_ = 0;  ///< the browser event the held pose came from
  std::chrono::steady_clock::time_point held_input_time_;
  double linear_speed_, angular_speed_;
  // Operator thread only.
  mutable double last_t_ = 0.0;
};

}  // namespace tandem
