#pragma once
// A static picture of a problem and its solution: top (x-y) and side (x-z) orthographic views as
// SVG. It is how `tandem plan --svg` and the demo show a result without the live viewer.

#include <string>

#include "tandem/planning/path.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

struct SvgOptions {
  int panel_width = 720;      ///< pixels per view
  int object_snapshots = 10;  ///< object outlines drawn along the path (besides start and goal)
  std::size_t max_triangles =
      150000;  ///< obstacle triangles drawn at most (large meshes are thinned)
};

/// `path` may be empty (the problem alone).
std::string render_svg(const Problem& problem, const Path& path, const SvgOptions& options = {});

}  // namespace tandem
