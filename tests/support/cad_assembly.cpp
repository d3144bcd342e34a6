#include "support/cad_assembly.hpp"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Bnd_Box.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <fstream>
#include <stdexcept>

namespace tandem::test {
namespace {

TopoDS_Shape box(double x0, double y0, double z0, double dx, double dy, double dz) {
  return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), dx, dy, dz).Shape();
}

TopLoc_Location moved(double x, double y, double z) {
  gp_Trsf t;
  t.SetTranslation(gp_Vec(x, y, z));
  return TopLoc_Location(t);
}

TDF_Label named(const TDF_Label& label, const char* name) {
  TDataStd_Name::Set(label, TCollection_ExtendedString(name));
  return label;
}

/// The face of `shape` whose outward normal is +z and which lies highest.
TopoDS_Face top_face(const TopoDS_Shape& shape) {
  TopoDS_Face top;
  double z = -1e300;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    Bnd_Box b;
    BRepBndLib::Add(e.Current(), b);
    double x0, y0, z0, x1, y1, z1;
    b.Get(x0, y0, z0, x1, y1, z1);
    if (z1 - z0 < 1e-3 && z0 > z) {  // flat (the box has a small tolerance gap)
      z = z0;
      top = TopoDS::Face(e.Current());
    }
  }
  return top;
}

Handle(TDocStd_Document) housing_document() {
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("XmlXCAF", doc);
  XCAFDoc_DocumentTool::SetLengthUnit(doc, 0.001);
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const Handle(XCAFDoc_ColorTool) colors = XCAFDoc_DocumentTool::ColorTool(doc->Main());

  const TopoDS_Shape base_shape =
      BRepAlgoAPI_Cut(box(-50, -40, 0, 100, 80, 40), box(-10, -10, 10, 20, 20, 31)).Shape();
  const TDF_Label base = named(shapes->AddShape(base_shape, false), "base-block");
  colors->SetColor(base, Quantity_Color(0.1, 0.2, 0.8, Quantity_TOC_sRGB), XCAFDoc_ColorSurf);

  const TopoDS_Shape lid_shape = box(-50, -40, 0, 100, 80, 10);
  const TDF_Label lid = named(shapes->AddShape(lid_shape, false), "lid-plate");
  const TDF_Label top = shapes->AddSubShape(lid, top_face(lid_shape));
  if (top.IsNull())
    throw std::logic_error("the lid's top face is not a sub-shape of the lid");
  colors->SetColor(top, Quantity_Color(0.9, 0.1, 0.1, Quantity_TOC_sRGB), XCAFDoc_ColorSurf);

  gp_Ax2 axis(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  const TDF_Label peg =
      named(shapes->AddShape(BRepPrimAPI_MakeCylinder(axis, 9, 30).Shape(), false), "peg-pin");
  colors->SetColor(peg, Quantity_Color(0.1, 0.7, 0.2, Quantity_TOC_sRGB), XCAFDoc_ColorSurf);

  const TDF_Label lid_assembly = named(shapes->NewShape(), "lid-assembly");
  named(shapes->AddComponent(lid_assembly, lid, TopLoc_Location()), "lid");
  const TDF_Label housing = named(shapes->NewShape(), "housing");
  named(shapes->AddComponent(housing, base, TopLoc_Location()), "base");
  named(shapes->AddComponent(housing, lid_assembly, moved(0, 0, 80)), "lid-1");
  named(shapes->AddComponent(housing, peg, moved(0, 0, 10)), "peg");
  gp_Trsf spare;
  spare.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), M_PI / 2);
  spare.SetTranslationPart(gp_Vec(200, 0, 0));
  named(shapes->AddComponent(housing, peg, TopLoc_Location(spare)), "peg-spare");
  shapes->UpdateAssemblies();
  return doc;
}

}  // namespace

void write_housing(const std::filesystem::path& file, CadFormat format, const std::string& unit) {
  const Handle(TDocStd_Document) doc = housing_document();
  if (format == CadFormat::step) {
    Interface_Static::SetCVal("write.step.unit", unit.c_str());
    STEPCAFControl_Writer writer;
    writer.SetColorMode(true);
    writer.SetNameMode(true);
    if (!writer.Transfer(doc, STEPControl_AsIs) || writer.Write(file.c_str()) != IFSelect_RetDone)
      throw std::runtime_error("could not write " + file.string());
    Interface_Static::SetCVal("write.step.unit", "MM");
    return;
  }
  IGESCAFControl_Writer writer;
  if (!writer.Transfer(doc) || !writer.Write(file.c_str()))
    throw std::runtime_error("could not write " + file.string());
}

void write_empty_step(const std::filesystem::path& file) {
  std::ofstream(file) << "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n"
                         "FILE_NAME('empty','2026-12-04T00:00:00',(''),(''),'','','');\n"
                         "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\n"
                         "ENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n";
}

}  // namespace tandem::test
