#include "tandem/operators/spacenav.hpp"

#include <spnav.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace tandem {
namespace {

/// spacenavd reports about +-350 at full deflection (3Dconnexion's range; the SpaceNavigator's).
constexpr double kFullScale = 350.0;

double axis(int value) {
  return std::clamp(static_cast<double>(value) / kFullScale, -1.0, 1.0);
}

}  // namespace

std::unique_ptr<SpaceNav> SpaceNav::open(std::string* why) {
  if (spnav_open() == -1) {
    if (why != nullptr) {
      *why =
          "no SpaceMouse: spacenavd is not running (start it with 'spacenavd' or 'systemctl start "
          "spacenavd'; the browser's inputs keep working)";
    }
    return nullptr;
  }
  std::unique_ptr<SpaceNav> nav(new SpaceNav());
  spnav_client_name("tandem");
  char name[128] = {};
  if (spnav_dev_name(name, sizeof name) > 0)
    nav->name_ = name;
  else
    nav->name_ = "SpaceMouse (spacenavd)";
  return nav;
}

SpaceNav::~SpaceNav() {
  spnav_close();
}

const SpaceNavMotion& SpaceNav::poll() {
  spnav_event event;
  while (spnav_poll_event(&event) != 0) {
    if (event.type == SPNAV_EVENT_MOTION) {
      motion_ = {axis(event.motion.x),  axis(event.motion.y),  axis(event.motion.z),
                 axis(event.motion.rx), axis(event.motion.ry), axis(event.motion.rz)};
    } else if (event.type == SPNAV_EVENT_BUTTON && event.button.bnum >= 0 &&
               event.button.bnum < 32) {
      const std::uint32_t bit = 1u << static_cast<unsigned>(event.button.bnum);
      buttons_ = event.button.press != 0 ? (buttons_ | bit) : (buttons_ & ~bit);
    }
  }
  return motion_;
}

}  // namespace tandem
