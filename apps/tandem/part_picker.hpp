#pragma once
// Choosing the part to take out in the viewer. `tandem interactive FILE.step` without --part
// serves the whole assembly first: the page shows its tree, the user clicks a part (in the scene
// or the tree) and "take it out", the browser sends {"type":"take_out","part":PATH}; this server
// then gives way to the session's, on the same port with the same token, and the page reloads
// into the session.

#include <optional>
#include <string>

#include "cli_support.hpp"
#include "viewer_options.hpp"

namespace tandem::cli {

/// Serves the assembly of `problem` until a browser chooses a part (its path in the assembly
/// tree) or Ctrl-C (nullopt). Sets `viewer`'s port and token to the ones the page knows.
std::optional<std::string> pick_part_in_viewer(const ProblemArgs& problem, ViewerArgs& viewer);

}  // namespace tandem::cli
