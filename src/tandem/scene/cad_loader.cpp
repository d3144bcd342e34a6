#include "tandem/scene/cad_loader.hpp"

#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <RWMesh_FaceIterator.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Iterator.hxx>
#include <UnitsMethods.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_Editor.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XCAFPrs_DocumentExplorer.hxx>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <gp_Quaternion.hxx>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <string_view>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"

namespace tandem {
namespace {

bool is_step(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  return ext == ".step" || ext == ".stp";
}

/// Every record of an IGES file (ASCII form): printable ASCII, 73 to 80 columns, its section
/// letter in column 73, the sections in their order (start, global, directory entry, parameter
/// data, terminate), the first a start record and the last the one terminate record (blank lines
/// may follow it). OCCT reads what it can of a truncated file without complaint, and its IGES
/// reader (a C parser) crashes on some files that are not so (fuzzing: binary bytes between a
/// start and a terminate record), so none reaches it.
void check_iges_records(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  constexpr std::string_view kSections = "SGDPT";
  std::size_t section = 0;
  bool global = false;      // a global record was read
  bool terminated = false;  // the terminate record was read: only blank lines may follow
  bool blank_only = true;   // no line but blank ones so far
  const auto truncated = [&] {
    return InputError(file.string(),
                      "truncated IGES file (its last record is no terminate record)");
  };
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    const bool blank = line.find_first_not_of(" \t") == std::string::npos;
    if (blank && (terminated || blank_only))
      continue;  // blank lines after the terminate record, or (refused next) before any record
    const auto bad = [&](const std::string& what) {
      if (in.peek() == EOF && !terminated)
        throw truncated();  // a record cut short at the file's end
      throw InputError(file.string(), "not an IGES file in ASCII form (record " +
                                          std::to_string(n) + " " + what + ")");
    };
    if (blank_only && (n != 1 || line.size() < 73 || line[72] != 'S'))
      throw InputError(file.string(), "not an IGES file (its first record is no start record)");
    blank_only = false;
    if (line.size() < 73 || line.size() > 80)
      bad("is not 73 to 80 columns long");
    for (const char c : line) {
      if (c < ' ' || c > '~')
        bad("has a character that is not printable ASCII");
    }
    const std::size_t at = kSections.find(line[72]);
    if (at == std::string_view::npos || at < section || terminated)
      bad("has no section letter S, G, D, P or T in column 73 in the sections' order");
    section = at;
    global = global || at == 1;
    terminated = at == 4;
  }
  if (blank_only)
    throw InputError(file.string(), "the file is empty");
  if (!terminated)
    throw truncated();
  if (!global)
    throw InputError(file.string(), "not an IGES file (it has no global section)");
}

/// The file's own framing, checked before OCCT reads it. A STEP file opens with ISO-10303-21; and
/// closes with END-ISO-10303-21; (ISO 10303-21): only its ends are read (OCCT reads the whole of
/// it next), since OCCT reads what it can of a truncated file without complaint. An IGES file's
/// every record is checked (check_iges_records).
void check_framing(const std::filesystem::path& file) {
  if (!is_step(file))
    return check_iges_records(file);
  const FileEnds ends = read_file_ends(file, 4096);
  const std::string head = trim(ends.head), tail = trim(ends.tail);
  if (head.empty() && tail.empty())
    throw InputError(file.string(), "the file is empty");
  if (head.rfind("ISO-10303-21;", 0) != 0)
    throw InputError(file.string(), "not a STEP file (it does not begin with ISO-10303-21;)");
  const std::string end = "END-ISO-10303-21;";
  if (tail.size() < end.size() || tail.substr(tail.size() - end.size()) != end)
    throw InputError(file.string(), "truncated STEP file (no END-ISO-10303-21; at its end)");
}

/// OCCT reports through its default messenger on stdout; tandem's output stays its own.
void quiet_occt() {
  for (Message_SequenceOfPrinters::Iterator p(Message::DefaultMessenger()->Printers()); p.More();
       p.Next())
    p.Value()->SetTraceLevel(Message_Fail);
}

/// IGES carries no assembly tree: OCCT reads a file as one compound of the parts (each a solid,
/// a shell or a compound of faces). Such a compound becomes an assembly, each child a part.
void split_parts(const Handle(TDocStd_Document) & doc) {
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence roots;
  shapes->GetFreeShapes(roots);
  for (const TDF_Label& root : roots) {
    const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(root);
    if (shape.ShapeType() != TopAbs_COMPOUND)
      continue;
    int parts = 0, others = 0;
    for (TopoDS_Iterator child(shape); child.More(); child.Next())
      ++(child.Value().ShapeType() <= TopAbs_SHELL ? parts : others);
    if (parts > 1 && others == 0)
      XCAFDoc_Editor::Expand(doc->Main(), root, false);
  }
}

Handle(TDocStd_Document) read_document(const std::filesystem::path& file) {
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("XmlXCAF", doc);
  auto read = [&](auto& reader) {
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    const IFSelect_ReturnStatus status = reader.ReadFile(file.c_str());
    if (status == IFSelect_RetVoid)
      throw InputError(file.string(), "no geometry (the file has no entities)");
    if (status != IFSelect_RetDone)
      throw InputError(file.string(), "OCCT cannot read it (malformed or not " +
                                          std::string(is_step(file) ? "STEP" : "IGES") + ")");
    if (reader.NbRootsForTransfer() == 0)
      throw InputError(file.string(), "no geometry (nothing in it is a shape or an assembly)");
    if (!reader.Transfer(doc))
      throw InputError(file.string(), "OCCT read it but could not transfer its shapes");
  };
  if (is_step(file)) {
    STEPCAFControl_Reader reader;
    read(reader);
  } else {
    IGESCAFControl_Reader reader;
    read(reader);
    split_parts(doc);
  }
  return doc;
}

/// The document's length unit in metres (OCCT's own default, millimetres, when it has none).
double document_unit(const Handle(TDocStd_Document) & doc) {
  double unit = 0.0;
  if (XCAFDoc_DocumentTool::GetLengthUnit(doc, unit) && unit > 0.0)
    return unit;
  return UnitsMethods::GetCasCadeLengthUnit(UnitsMethods_LengthUnit_Meter);
}

/// Tessellates every free shape (the instances share their products' triangulations); returns
/// the linear deflection used, in the document's unit.
double tessellate_shapes(const Handle(TDocStd_Document) & doc, const CadOptions& options,
                         double unit, const std::filesystem::path& file) {
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence roots;
  shapes->GetFreeShapes(roots);
  Bnd_Box box;
  for (const TDF_Label& root : roots)
    BRepBndLib::Add(XCAFDoc_ShapeTool::GetShape(root), box);
  if (box.IsVoid())
    throw InputError(file.string(), "no geometry (the file has no shapes)");
  double diagonal = std::sqrt(box.SquareExtent());
  double linear =
      options.linear_deflection > 0.0 ? options.linear_deflection / unit : 1e-3 * diagonal;
  if (!(linear > 0.0))
    throw InputError(file.string(), "no geometry (its shapes have no extent)");
  for (const TDF_Label& root : roots)
    BRepMesh_IncrementalMesh(XCAFDoc_ShapeTool::GetShape(root), linear, false,
                             options.angular_deflection, false);
  return linear;
}

std::string label_name(const TDF_Label& label) {
  Handle(TDataStd_Name) name;
  if (label.IsNull() || !label.FindAttribute(TDataStd_Name::GetID(), name))
    return {};
  return trim(TCollection_AsciiString(name->Get()).ToCString());
}

std::string entry(const TDF_Label& label) {
  TCollection_AsciiString e;
  TDF_Tool::Entry(label, e);
  return e.ToCString();
}

Color to_color(const Quantity_ColorRGBA& c) {
  double r = 0, g = 0, b = 0;
  c.GetRGB().Values(r, g, b, Quantity_TOC_sRGB);
  return {r, g, b, static_cast<double>(c.Alpha())};
}

/// A leaf part's triangles in its own frame, and the colour covering most of them.
void collect_part(const XCAFPrs_DocumentNode& node, double unit, CadNode& out) {
  std::map<std::array<int, 4>, std::pair<std::size_t, Color>> colours;
  for (RWMesh_FaceIterator face(node.RefLabel, TopLoc_Location(), true, node.Style); face.More();
       face.Next()) {
    if (face.IsEmptyMesh())
      continue;
    const auto base = static_cast<std::uint32_t>(out.mesh.vertices.size());
    for (int i = face.NodeLower(); i <= face.NodeUpper(); ++i) {
      const gp_Pnt p = face.NodeTransformed(i);
      out.mesh.vertices.emplace_back(unit * p.X(), unit * p.Y(), unit * p.Z());
    }
    for (int t = face.ElemLower(); t <= face.ElemUpper(); ++t) {
      const Poly_Triangle tri = face.TriangleOriented(t);
      out.mesh.triangles.push_back({base + static_cast<std::uint32_t>(tri.Value(1) - 1),
                                    base + static_cast<std::uint32_t>(tri.Value(2) - 1),
                                    base + static_cast<std::uint32_t>(tri.Value(3) - 1)});
    }
    if (face.HasFaceColor()) {
      const Color c = to_color(face.FaceColor());
      const std::array<int, 4> key{
          static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
          static_cast<int>(std::lround(c.b * 255)), static_cast<int>(std::lround(c.a * 255))};
      auto& [count, colour] = colours[key];
      count += static_cast<std::size_t>(face.NbTriangles());
      colour = c;
    }
  }
  const auto most = std::max_element(colours.begin(), colours.end(), [](auto& a, auto& b) {
    return a.second.first < b.second.first;
  });
  if (most != colours.end()) {
    out.color = most->second.second;
    out.has_color = true;
  }
}

Eigen::Isometry3d to_isometry(const TopLoc_Location& location, double unit,
                              const std::filesystem::path& file, const std::string& path) {
  const gp_Trsf trsf = location.Transformation();
  if (std::abs(trsf.ScaleFactor() - 1.0) > 1e-9)
    throw InputError(file.string(),
                     "the instance '" + path + "' is scaled; tandem takes rigid placements only");
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  const gp_Quaternion q = trsf.GetRotation();
  X.linear() = Eigen::Quaterniond(q.W(), q.X(), q.Y(), q.Z()).normalized().toRotationMatrix();
  const gp_XYZ t = trsf.TranslationPart();
  X.translation() = unit * Eigen::Vector3d(t.X(), t.Y(), t.Z());
  return X;
}

/// The tree, depth-first, with unique paths.
std::vector<CadNode> explore(const Handle(TDocStd_Document) & doc, double unit,
                             const std::filesystem::path& file) {
  std::vector<CadNode> nodes;
  std::vector<std::string> stack;  // the paths of the current node's ancestors
  std::set<std::string> paths;
  for (XCAFPrs_DocumentExplorer it(doc, XCAFPrs_DocumentExplorerFlags_None); it.More(); it.Next()) {
    const XCAFPrs_DocumentNode& node = it.Current();
    CadNode out;
    out.depth = it.CurrentDepth();
    out.assembly = node.IsAssembly;
    out.product = label_name(node.RefLabel);
    out.name = label_name(node.Label);
    if (out.name.empty())
      out.name = !out.product.empty() ? out.product : entry(node.RefLabel);
    stack.resize(static_cast<std::size_t>(out.depth));
    std::string path = stack.empty() ? out.name : stack.back() + "/" + out.name;
    for (int k = 2; !paths.insert(path).second; ++k)
      path = (stack.empty() ? out.name : stack.back() + "/" + out.name) + "#" + std::to_string(k);
    out.path = path;
    stack.push_back(path);
    if (!out.assembly) {
      out.placement = to_isometry(node.Location, unit, file, path);
      collect_part(node, unit, out);
      if (!out.mesh.triangles.empty())
        sanitize_mesh(out.mesh, file.string() + " (" + path + ")");
    }
    nodes.push_back(std::move(out));
  }
  return nodes;
}

}  // namespace

bool is_cad_file(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

CadAssembly load_cad(const std::filesystem::path& file, const CadOptions& options) {
  check_file_name(file.string());
  if (!is_cad_file(file))
    throw InputError(file.string(), "not a STEP or IGES file name (.step, .stp, .iges, .igs)");
  if (!(options.linear_deflection >= 0.0) || !(options.angular_deflection > 0.0) ||
      !std::isfinite(options.linear_deflection) || !std::isfinite(options.angular_deflection))
    throw InputError(file.string(), "the tessellation's deflections must be positive numbers");
  check_framing(file);
  static std::mutex occt;  // OCCT's readers keep global state (Interface_Static, the messenger)
  const std::lock_guard<std::mutex> lock(occt);
  quiet_occt();
  try {
    CadAssembly assembly;
    assembly.format = is_step(file) ? "STEP" : "IGES";
    const Handle(TDocStd_Document) doc = read_document(file);
    assembly.unit_m = document_unit(doc);
    assembly.linear_deflection =
        assembly.unit_m * tessellate_shapes(doc, options, assembly.unit_m, file);
    assembly.angular_deflection = options.angular_deflection;
    assembly.nodes = explore(doc, assembly.unit_m, file);
    const bool any = std::any_of(assembly.nodes.begin(), assembly.nodes.end(),
                                 [](const CadNode& n) { return !n.mesh.triangles.empty(); });
    if (!any)
      throw InputError(file.string(), "no geometry to tessellate (no faces or solids)");
    return assembly;
  } catch (const Standard_Failure& e) {
    throw InputError(file.string(), std::string("OCCT failed reading it: ") + e.GetMessageString());
  }
}

const CadNode& CadAssembly::part(const std::string& name, const std::string& source) const {
  std::vector<const CadNode*> found;
  std::string listed;
  for (const CadNode& n : nodes) {
    if (n.assembly || n.mesh.triangles.empty())
      continue;
    if (n.path == name || n.name == name)
      found.push_back(&n);
    listed += (listed.empty() ? "" : ", ") + n.path;
  }
  if (found.size() == 1)
    return *found.front();
  if (found.empty())
    throw InputError(source, "no part named '" + name + "' (the parts: " + listed + ")");
  throw InputError(source, "several parts are named '" + name +
                               "'; name one by its path (the parts: " + listed + ")");
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> CadAssembly::bounding_box() const {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const CadNode& n : nodes) {
    for (const Eigen::Vector3d& v : n.mesh.vertices) {
      const Eigen::Vector3d w = n.placement * v;
      lo = lo.cwiseMin(w);
      hi = hi.cwiseMax(w);
    }
  }
  return {lo, hi};
}

}  // namespace tandem
