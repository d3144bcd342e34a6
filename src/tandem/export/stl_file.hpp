#pragma once
// Binary STL: an 80-byte header, the triangle count, then per triangle its normal, its three
// corners (little-endian float32) and a zero attribute word. Read by every CAD and mesh tool.

#include <ostream>
#include <string>

#include "tandem/scene/mesh.hpp"

namespace tandem {

/// Writes `mesh` (scene units) to `file`; `header` fills the header (cut to 80 bytes). Throws
/// InputError naming the file when it cannot be written.
void write_stl(const TriangleMesh& mesh, const std::string& file, const std::string& header);
/// The same bytes, to a stream.
void write_stl(const TriangleMesh& mesh, std::ostream& out, const std::string& header);

}  // namespace tandem
