#pragma once
// An animation anyone can open: the scene and the part moving along a path, as a glTF 2.0 binary
// (.glb) that three.js, Blender, Windows' 3D Viewer and the web's model viewers play.
//
// Content: a root node "tandem-z-up" turning tandem's z-up world into glTF's y-up one; under it
// one node per obstacle (its parts tessellated and posed in the world, its colour as the
// material's base colour), the node "object" (the moving part in its object frame) and, when
// given, the node "envelope" (translucent). One animation, "path": the object node's translation
// and rotation keyed at every state of the path, LINEAR (glTF's linear translation and shortest-
// arc slerp, which is the space's geodesic motion between states), at constant speed in the
// space's metric over `duration` seconds. Units: metres, glTF's own.
//
// Threading: pure functions.

#include <string>

#include "tandem/planning/path.hpp"
#include "tandem/scene/scene.hpp"

namespace tandem {

struct AnimationOptions {
  double duration = 10.0;                  ///< seconds, > 0
  const TriangleMesh* envelope = nullptr;  ///< world frame; optional
  std::string title = "tandem path";       ///< the asset's and the page's title
};

/// Keyframe times: 0 at the first state, `duration` at the last, proportional to the distance
/// travelled in the space's metric (equal steps for a path that does not move).
std::vector<double> keyframe_times(const Path& path, const SE3Space& space, double duration);

/// The .glb file's bytes. Throws InputError ("--duration") for a duration that is not positive and
/// finite, or ("path") for an empty path.
std::string path_animation_glb(const Scene& scene, const Path& path, const SE3Space& space,
                               const AnimationOptions& options);

}  // namespace tandem
