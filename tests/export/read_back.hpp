#pragma once
// The read-back of the export tests by independent readers: the one SPLINE of a DXF file
// evaluated by ezdxf (through tests/export/read_dxf.py), and with OpenCASCADE the one B-spline edge
// of a STEP or IGES file.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "lac/export/write.hpp"
#ifdef LAC_WITH_OCCT
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Curve.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#endif

namespace lac::test {

struct DxfReadBack {
  int degree = 0;
  size_t control_points = 0;
  std::vector<double> t;                     ///< parameters, uniform in the spline's range
  std::vector<std::array<double, 3>> point;  ///< the spline at t (z = 0 for dim 2)
};

/// The spline of `path` at n parameters by ezdxf, with `dim` (2 or 3) coordinates read. A failing
/// reader fails the test (and returns what was read).
inline DxfReadBack read_dxf(const std::string& path, int n, int dim) {
  const std::string cmd = std::string("/usr/bin/python3 ") + LAC_SOURCE_DIR + "/tests/export/read_dxf.py " + path +
                          " " + std::to_string(n) + " --dim " + std::to_string(dim);
  DxfReadBack r;
  FILE* pipe = popen(cmd.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  if (!pipe) return r;
  std::string out;
  char buf[4096];
  while (size_t k = fread(buf, 1, sizeof buf, pipe)) out.append(buf, k);
  EXPECT_EQ(pclose(pipe), 0) << out;
  std::istringstream in(out);
  in >> r.degree >> r.control_points;
  double t;
  std::array<double, 3> p{};
  while (in >> t >> p[0] >> p[1] && (dim == 2 || in >> p[2])) r.t.push_back(t), r.point.push_back(p);
  return r;
}

#ifdef LAC_WITH_OCCT
/// The B-spline of the one edge of a STEP or IGES file (`format`) read by OpenCASCADE, on its
/// parameter range [first, last]; expected: that degree and number of poles, the range [0, length].
/// A failed read fails the test and leaves `curve` null.
struct OcctReadBack {
  Handle(Geom_BSplineCurve) curve;
  double first = 0, last = 0;
};

inline OcctReadBack read_occt(const std::string& path, ExportFormat format, int degree, size_t poles, double length) {
  OcctReadBack r;
  TopoDS_Shape shape;
  if (format == ExportFormat::step) {
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || reader.TransferRoots() <= 0) {
      ADD_FAILURE() << "OpenCASCADE cannot read " << path;
      return r;
    }
    shape = reader.OneShape();
  } else {
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || reader.TransferRoots() <= 0) {
      ADD_FAILURE() << "OpenCASCADE cannot read " << path;
      return r;
    }
    shape = reader.OneShape();
  }
  int edges = 0;
  for (TopExp_Explorer ex(shape, TopAbs_EDGE); ex.More(); ex.Next()) {
    if (edges++ > 0) continue;
    const Handle(Geom_Curve) g = BRep_Tool::Curve(TopoDS::Edge(ex.Current()), r.first, r.last);
    if (g.IsNull()) continue;
    r.curve = Handle(Geom_BSplineCurve)::DownCast(g);
    EXPECT_FALSE(r.curve.IsNull()) << "not a B-spline: " << g->DynamicType()->Name();
  }
  EXPECT_EQ(edges, 1);
  if (r.curve.IsNull()) {
    ADD_FAILURE() << "no B-spline edge in " << path;
    return r;
  }
  EXPECT_EQ(r.curve->Degree(), degree);
  EXPECT_EQ(static_cast<size_t>(r.curve->NbPoles()), poles);
  EXPECT_NEAR(r.first, 0.0, 1e-12);
  EXPECT_NEAR(r.last, length, 1e-12);
  return r;
}
#endif

}  // namespace lac::test
