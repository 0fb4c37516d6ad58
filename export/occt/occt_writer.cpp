#include "lac/export/occt/occt_writer.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <Geom_BSplineCurve.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Edge.hxx>

#include "lac/common/error.hpp"

namespace lac {

namespace {

Handle(Geom_BSplineCurve) make_curve(const BSpline& b) {
  b.validate();
  std::vector<double> values;
  std::vector<int> mults;
  b.distinct_knots(values, mults);
  const int n = static_cast<int>(b.control_points.size());
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) poles.SetValue(i + 1, gp_Pnt(b.control_points[i].real(), b.control_points[i].imag(), 0.0));
  TColStd_Array1OfReal knots(1, static_cast<int>(values.size()));
  TColStd_Array1OfInteger multiplicities(1, static_cast<int>(values.size()));
  for (size_t i = 0; i < values.size(); ++i) {
    knots.SetValue(static_cast<int>(i) + 1, values[i]);
    multiplicities.SetValue(static_cast<int>(i) + 1, mults[i]);
  }
  if (!b.rational()) return new Geom_BSplineCurve(poles, knots, multiplicities, b.degree);
  TColStd_Array1OfReal weights(1, n);
  for (int i = 0; i < n; ++i) weights.SetValue(i + 1, b.weights[i]);
  return new Geom_BSplineCurve(poles, weights, knots, multiplicities, b.degree);
}

}  // namespace

void write_step(const std::string& path, const BSpline& b) {
  try {
    const Handle(Geom_BSplineCurve) c = make_curve(b);
    const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(c);
    STEPControl_Writer writer;
    if (writer.Transfer(edge, STEPControl_AsIs) != IFSelect_RetDone)
      throw_input_error("export", "export", "'" + path + "': OpenCASCADE could not translate the curve to STEP");
    if (writer.Write(path.c_str()) != IFSelect_RetDone)
      throw_input_error("export", "export", "'" + path + "': cannot write the STEP file");
  } catch (const Standard_Failure& e) {
    throw_input_error("export", "export", "'" + path + "': OpenCASCADE: " + std::string(e.GetMessageString()));
  }
}

void write_iges(const std::string& path, const BSpline& b) {
  try {
    IGESControl_Controller::Init();
    const Handle(Geom_BSplineCurve) c = make_curve(b);
    IGESControl_Writer writer("MM", 0);
    if (!writer.AddGeom(c))
      throw_input_error("export", "export", "'" + path + "': OpenCASCADE could not translate the curve to IGES");
    writer.ComputeModel();
    if (!writer.Write(path.c_str()))
      throw_input_error("export", "export", "'" + path + "': cannot write the IGES file");
  } catch (const Standard_Failure& e) {
    throw_input_error("export", "export", "'" + path + "': OpenCASCADE: " + std::string(e.GetMessageString()));
  }
}

void write_any(const std::string& path, ExportFormat format, const BSpline& b) {
  if (format == ExportFormat::step) return write_step(path, b);
  if (format == ExportFormat::iges) return write_iges(path, b);
  write_file(path, format, b);
}

}  // namespace lac
