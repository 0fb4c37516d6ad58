#include "lac/export/occt/occt_writer.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <Geom_BSplineCurve.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESData_IGESWriter.hxx>
#include <IGESData_Protocol.hxx>
#include <IGESSelect_WorkLibrary.hxx>
#include <Interface_FloatWriter.hxx>
#include <fstream>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Writer.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <XSControl_Controller.hxx>
#include <XSControl_WorkSession.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Edge.hxx>

#include "lac/common/error.hpp"
#include "lac/export/write3.hpp"

namespace lac {

namespace {

/// OpenCASCADE's translators print statistics to stdout through the default messenger: silenced,
/// since the caller's stdout may be a report (the `lac` tool prints JSON there).
void quiet() {
  static const bool done = [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    return true;
  }();
  (void)done;
}

gp_Pnt pnt(const std::complex<double>& c) { return gp_Pnt(c.real(), c.imag(), 0.0); }
gp_Pnt pnt(const Eigen::Vector3d& c) { return gp_Pnt(c.x(), c.y(), c.z()); }

/// BSpline (in the plane z = 0) or BSpline3.
template <class B>
Handle(Geom_BSplineCurve) make_curve(const B& b) {
  b.validate();
  std::vector<double> values;
  std::vector<int> mults;
  b.distinct_knots(values, mults);
  const int n = static_cast<int>(b.control_points.size());
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) poles.SetValue(i + 1, pnt(b.control_points[i]));
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

template <class B>
void step_file(const std::string& path, const B& b) {
  quiet();
  try {
    const Handle(Geom_BSplineCurve) c = make_curve(b);
    const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(c);
    STEPControl_Writer writer;
    if (writer.Transfer(edge, STEPControl_AsIs) != IFSelect_RetDone)
      throw_input_error("write_step", "export", "'" + path + "': OpenCASCADE could not translate the curve to STEP");
    // STEPControl_Writer::Write prints reals with 12 to 13 significant digits; the same model
    // through StepData_StepWriter with 17 ("%.16E", round-trip exact).
    const Handle(StepData_Protocol) protocol =
        Handle(StepData_Protocol)::DownCast(writer.WS()->NormAdaptor()->Protocol());
    StepData_StepWriter out(writer.Model());
    out.FloatWriter().SetFormat("%.16E");
    out.FloatWriter().SetZeroSuppress(Standard_False);
    out.SendModel(protocol);
    std::ofstream file(path, std::ios::binary);
    if (protocol.IsNull() || !file || !out.Print(file) || !file.flush())
      throw_input_error("write_step", "export", "'" + path + "': cannot write the STEP file");
  } catch (const Standard_Failure& e) {
    throw_input_error("write_step", "export", "'" + path + "': OpenCASCADE: " + std::string(e.GetMessageString()));
  }
}

template <class B>
void iges_file(const std::string& path, const B& b) {
  quiet();
  try {
    IGESControl_Controller::Init();
    const Handle(Geom_BSplineCurve) c = make_curve(b);
    IGESControl_Writer writer("MM", 0);
    if (!writer.AddGeom(c))
      throw_input_error("write_iges", "export", "'" + path + "': OpenCASCADE could not translate the curve to IGES");
    writer.ComputeModel();
    // IGESControl_Writer::Write prints reals with 10 significant digits (1e-10 relative, above a
    // tight tolerance); the same model through IGESData_IGESWriter with 17 ("%.16E", round-trip).
    const Handle(IGESData_Protocol) protocol =
        Handle(IGESData_Protocol)::DownCast(IGESSelect_WorkLibrary::DefineProtocol());
    IGESData_IGESWriter out(writer.Model());
    out.FloatWriter().SetFormat("%.16E");
    out.FloatWriter().SetZeroSuppress(Standard_False);
    out.SendModel(protocol);
    std::ofstream file(path, std::ios::binary);
    if (!file || !out.Print(file) || !file.flush())
      throw_input_error("write_iges", "export", "'" + path + "': cannot write the IGES file");
  } catch (const Standard_Failure& e) {
    throw_input_error("write_iges", "export", "'" + path + "': OpenCASCADE: " + std::string(e.GetMessageString()));
  }
}

}  // namespace

void write_step(const std::string& path, const BSpline& b) { step_file(path, b); }
void write_iges(const std::string& path, const BSpline& b) { iges_file(path, b); }
void write_step(const std::string& path, const BSpline3& b) { step_file(path, b); }
void write_iges(const std::string& path, const BSpline3& b) { iges_file(path, b); }

void write_any(const std::string& path, ExportFormat format, const BSpline3& b) {
  if (format == ExportFormat::step) return write_step(path, b);
  if (format == ExportFormat::iges) return write_iges(path, b);
  write_file(path, format, b);
}

void write_any(const std::string& path, ExportFormat format, const BSpline& b, const SvgOptions& svg) {
  if (format == ExportFormat::step) return write_step(path, b);
  if (format == ExportFormat::iges) return write_iges(path, b);
  write_file(path, format, b, svg);
}

}  // namespace lac
