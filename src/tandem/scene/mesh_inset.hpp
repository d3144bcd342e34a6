#pragma once
// A closed mesh moved inward by a distance: how a part that sits in contact with its neighbours
// in a CAD assembly gets out of its seat.
//
// A seated part touches its neighbours, and tessellation (each face replaced by triangles within
// the linear deflection) makes touching curved faces overlap by up to the deflection. Planned as
// is, the part starts in collision. tandem plans with the part's surface moved inward by a seating
// tolerance instead: each face moves by the tolerance along its inward normal, and each vertex to
// where its faces' moved planes meet (the least-squares point when more than three meet). So the
// part may slide out of its seat along the faces it touches, and no motion takes it deeper than
// the tolerance into a neighbour. The tolerance is stated with every plan that uses it.
//
// The mesh must be closed and consistently oriented (outward normals), as OCCT's tessellation of
// a solid is. Vertices shared by several faces are welded first (OCCT gives each face its own).

#include "tandem/scene/mesh.hpp"

namespace tandem {

/// `mesh` with every face moved inward by `distance` (> 0). Throws std::invalid_argument for a
/// distance that is not positive and finite.
TriangleMesh inset_mesh(const TriangleMesh& mesh, double distance);

}  // namespace tandem
