// Writes examples/bracket.step, the STEP assembly of the README's workflow (scripts/make-example
// runs this). Millimetres, z up:
//   bracket              (assembly)
//     base               a 160 x 100 x 10 plate, z in [0, 10]; grey
//     walls              (a sub-assembly)
//       wall-left        a 10 x 100 x 70 wall on the plate, x in [-50, -40], with a bore of
//                        radius 6.5 along x at y = 0, z = 50; blue
//       wall-right       the same wall product, x in [40, 50]
//     pin                a cylinder of radius 6 and length 120 along x, centred at (0, 0, 50):
//                        through both bores (0.5 mm clear), 10 mm out of each; orange
//     block              a 40 x 40 x 30 block on the plate between the walls, under the pin; green
//     cap                a 100 x 20 x 10 bar across the walls' tops, z in [80, 90]; its top red
// Taking the pin out means sliding it 110 mm along its axis, in the bores, before it is free.

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Interface_Static.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax2.hxx>
#include <iostream>

namespace {

struct Document {
  Handle(TDocStd_Document) doc;
  Handle(XCAFDoc_ShapeTool) shapes;
  Handle(XCAFDoc_ColorTool) colors;

  /// A product: the shape, its name and its colour (sRGB).
  TDF_Label product(const TopoDS_Shape& shape, const char* name, double r, double g, double b) {
    const TDF_Label label = shapes->AddShape(shape, false);
    TDataStd_Name::Set(label, TCollection_ExtendedString(name));
    colors->SetColor(label, Quantity_Color(r, g, b, Quantity_TOC_sRGB), XCAFDoc_ColorSurf);
    return label;
  }

  /// An instance of `part` in `assembly`, moved by (x, y, z).
  void place(const TDF_Label& assembly, const TDF_Label& part, const char* name, double x, double y,
             double z) {
    gp_Trsf t;
    t.SetTranslation(gp_Vec(x, y, z));
    const TDF_Label instance = shapes->AddComponent(assembly, part, TopLoc_Location(t));
    TDataStd_Name::Set(instance, TCollection_ExtendedString(name));
  }

  TDF_Label assembly(const char* name) {
    const TDF_Label label = shapes->NewShape();
    TDataStd_Name::Set(label, TCollection_ExtendedString(name));
    return label;
  }
};

TopoDS_Shape box(double x0, double y0, double z0, double dx, double dy, double dz) {
  return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), dx, dy, dz).Shape();
}

/// A cylinder along x from x0, of radius r and length l, its axis at (y, z).
TopoDS_Shape rod(double x0, double y, double z, double r, double l) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x0, y, z), gp_Dir(1, 0, 0)), r, l).Shape();
}

Document bracket() {
  Document d;
  XCAFApp_Application::GetApplication()->NewDocument("XmlXCAF", d.doc);
  XCAFDoc_DocumentTool::SetLengthUnit(d.doc, 0.001);
  d.shapes = XCAFDoc_DocumentTool::ShapeTool(d.doc->Main());
  d.colors = XCAFDoc_DocumentTool::ColorTool(d.doc->Main());
  const TDF_Label base = d.product(box(-80, -50, 0, 160, 100, 10), "base-plate", 0.6, 0.6, 0.62);
  const TopoDS_Shape wall_shape =
      BRepAlgoAPI_Cut(box(0, -50, 0, 10, 100, 70), rod(-1, 0, 40, 6.5, 12)).Shape();
  const TDF_Label wall = d.product(wall_shape, "wall", 0.15, 0.3, 0.75);
  const TDF_Label pin = d.product(rod(-60, 0, 0, 6, 120), "pin-12x120", 0.95, 0.55, 0.1);
  const TDF_Label block = d.product(box(-20, -20, 0, 40, 40, 30), "spacer-block", 0.2, 0.65, 0.3);
  const TDF_Label cap = d.product(box(-50, -10, 0, 100, 20, 10), "cap-bar", 0.8, 0.15, 0.12);
  const TDF_Label walls = d.assembly("walls");
  d.place(walls, wall, "wall-left", -50, 0, 10);
  d.place(walls, wall, "wall-right", 40, 0, 10);
  const TDF_Label top = d.assembly("bracket");
  d.place(top, base, "base", 0, 0, 0);
  d.place(top, walls, "walls", 0, 0, 0);
  d.place(top, pin, "pin", 0, 0, 50);
  d.place(top, block, "block", 0, 0, 10);
  d.place(top, cap, "cap", 0, 0, 80);
  d.shapes->UpdateAssemblies();
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: tandem-make-bracket OUT.step\n";
    return 2;
  }
  const Document d = bracket();
  Interface_Static::SetCVal("write.step.unit", "MM");
  STEPCAFControl_Writer writer;
  writer.SetColorMode(true);
  writer.SetNameMode(true);
  if (!writer.Transfer(d.doc, STEPControl_AsIs) || writer.Write(argv[1]) != IFSelect_RetDone) {
    std::cerr << argv[1] << ": could not be written\n";
    return 2;
  }
  std::cout << "wrote " << argv[1] << '\n';
  return 0;
}
