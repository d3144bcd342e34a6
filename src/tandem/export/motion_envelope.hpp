#pragma once
// The motion envelope: the volume the moving part sweeps along a path, as a closed triangle mesh
// that contains every pose of the part along the whole motion (not only at the path's states).
//
// Built with OpenVDB: the part (every part of the object body, tessellated) is rasterised at poses
// along the path into a narrow-band level set of voxel size h, the level sets are united (minimum
// of the signed distances), and the union is meshed back at the iso-value
//   iso = s / 2 + sqrt(3) h + g,
// where s is the largest displacement of any point of the part between two neighbouring poses (a
// point moves at most |dt| + angle x radius over a motion; the poses are at equal shares of that
// bound summed along the path, at most s = h apart), and g is how far the tessellation of a curved
// primitive lies inside it. Why that contains the part: a point x of the part at any pose along
// the motion is within s / 2 of the same point at the nearest rasterised pose, so every corner c
// of the voxel cell of x has a signed distance of at most s / 2 + sqrt(3) h + g to that pose's
// surface (distances are exact in the narrow band: renormalisation is off). The mesher's surface
// only crosses cells whose corners lie on both sides of iso, so x is inside the mesh. The envelope
// lies within iso + h of the swept volume: `offset` states it.
//
// Threading: a pure function; OpenVDB runs its loops on TBB's threads.

#include <cstddef>
#include <stop_token>

#include "tandem/planning/path.hpp"
#include "tandem/scene/geometry.hpp"

namespace tandem {

struct MotionEnvelope {
  TriangleMesh mesh;      ///< closed, outward-facing triangles, world frame
  double voxel = 0.0;     ///< h
  double offset = 0.0;    ///< the mesh lies within this distance outside the swept volume
  std::size_t poses = 0;  ///< part poses rasterised
};

/// A voxel size for an object body: its largest extent / 48 (a few seconds of work for a path a
/// few times the part's size).
double default_envelope_voxel(const Body& object);

/// The envelope of `object` moved along `path` (one state or more). Throws InputError ("--voxel")
/// when the voxel is not positive and finite, or the path would need more than 20 000 poses or
/// more than 4096 voxels across. When `stop` is requested it returns early, with an empty mesh.
MotionEnvelope motion_envelope(const Body& object, const Path& path, const SE3Space& space,
                               double voxel, const std::stop_token& stop = {});

}  // namespace tandem
