#pragma once
// Reading CAD assemblies (STEP and IGES) with Open CASCADE's XCAF document API.
//
// assimp reads no STEP, and an engineer's parts live in STEP (or IGES) assemblies. OCCT's
// STEPCAFControl_Reader / IGESCAFControl_Reader fill an XCAF document: the assembly tree with its
// product and instance names, placements and colours. Each leaf instance (a part placed in the
// assembly) becomes one CadPart: its name, its path in the tree, its placement in metres, its
// colour, and its shape tessellated by BRepMesh_IncrementalMesh.
//
// Units: OCCT converts the file's length unit to the document's (millimetres unless the file
// sets another); the loader converts the document's unit to metres, so every length a CadPart
// carries is in metres, whatever unit the file was written in.
//
// Tessellation: linear deflection (the largest distance between a face and its triangles) and
// angular deflection (the largest angle between neighbouring triangles' normals on a curved
// face). The linear deflection defaults to 0.1% of the assembly's bounding-box diagonal; both are
// settable (CadOptions). A part's triangles are its true surface to within the linear deflection,
// so seated neighbours may overlap by up to it.
//
// IGES has no assembly tree: each part of the file (a solid, a shell, or a group of faces) is a
// leaf of one root.
//
// Colours: a part's colour is its instance's or its product's (solid) colour; a part whose faces
// carry colours and whose solid does not takes the colour that covers most of its triangles
// (tandem draws a body in one colour); else the default grey.
//
// Threading: load_cad may be called from any thread; OCCT's readers keep global state, so calls
// are serialised inside.

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

#include "tandem/scene/geometry.hpp"

namespace tandem {

struct CadOptions {
  double linear_deflection = 0.0;   ///< metres; 0: 0.1% of the assembly's bounding-box diagonal
  double angular_deflection = 0.5;  ///< radians (OCCT's default)
};

/// One node of the assembly tree, in depth-first order: an assembly or a leaf part.
struct CadNode {
  std::string name;     ///< the instance's name, else its product's, else the product's entry
  std::string path;     ///< the names from the root, joined by '/', unique in the assembly
  std::string product;  ///< the product (shape definition) it instantiates
  int depth = 0;        ///< 0 for a root
  bool assembly = false;
  /// Leaf parts only: its placement in the world (metres) and its triangles in its own frame.
  Eigen::Isometry3d placement = Eigen::Isometry3d::Identity();
  TriangleMesh mesh;
  Color color;
  bool has_color = false;  ///< false: the default grey
};

struct CadAssembly {
  std::string format;        ///< "STEP" or "IGES"
  double unit_m = 1.0;       ///< the document's length unit, in metres
  double linear_deflection;  ///< metres, as used
  double angular_deflection;
  std::vector<CadNode> nodes;  ///< the tree, depth-first

  /// The leaf part whose name or path is `name`; throws InputError naming `source` otherwise (the
  /// message lists the parts).
  const CadNode& part(const std::string& name, const std::string& source) const;
  /// World-frame bounding box of the leaf parts' triangles.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> bounding_box() const;
};

/// Reads a STEP (.step, .stp) or IGES (.iges, .igs) file. Throws InputError naming the file when it
/// is missing, empty, truncated, not STEP or IGES, or has no geometry to tessellate.
CadAssembly load_cad(const std::filesystem::path& file, const CadOptions& options = {});

/// True for the file extensions load_cad accepts (case-insensitive).
bool is_cad_file(const std::filesystem::path& file);

}  // namespace tandem
