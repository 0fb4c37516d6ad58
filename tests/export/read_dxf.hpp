#pragma once
// The DXF read-back of the export tests: the one SPLINE of a file evaluated by ezdxf, an
// independent reader, through tests/export/read_dxf.py.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

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

}  // namespace lac::test
