#pragma once
// The papers' device: a 3Dconnexion SpaceMouse, read through spacenavd with libspnav.
//
// libspnav keeps one global connection to the daemon, so there is at most one SpaceNav at a time.
// A held cap sends no repeats: the last motion holds until a zero event arrives (we keep it).
//
// Threading: one thread (the operator thread) polls; construction and destruction anywhere.

#include <array>
#include <memory>
#include <string>

namespace tandem {

/// The cap's deflection, each axis in [-1, 1] (x y z translation, rx ry rz rotation, in the
/// device's frame as spacenavd reports it: x right, y up, z toward the user).
using SpaceNavMotion = std::array<double, 6>;

class SpaceNav {
 public:
  /// Connects to spacenavd. Returns null and sets *why when the daemon is not running (or the
  /// library cannot reach it).
  static std::unique_ptr<SpaceNav> open(std::string* why);
  ~SpaceNav();
  SpaceNav(const SpaceNav&) = delete;
  SpaceNav& operator=(const SpaceNav&) = delete;

  /// Reads every pending event without waiting; returns the current deflection.
  const SpaceNavMotion& poll();
  std::uint32_t buttons() const { return buttons_; }
  const std::string& name() const { return name_; }

 private:
  SpaceNav() = default;
  SpaceNavMotion motion_{};
  std::uint32_t buttons_ = 0;
  std::string name_;
};

}  // namespace tandem
