// lac quadratic: a polyline point that fails does not shift the others.
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"

namespace lac {
namespace {

// The reproducer: s = 0.27, 0.655 and 1.04 were all printed at (−0.1147, 0.0072), the coordinates
// of s = −0.115, after the first piece (0 → −0.5) exhausted the evaluation budget.
TEST(CliQuadratic, FailedPointDoesNotShiftTheOthers) {
  const auto run = test::run_lac(
      "quadratic --alpha 2.612227706329021 --gamma 0.23347280458415112 --lambda 1.92314224068905 --samples 5 "
      "--s-from -0.5 --s-to 1.04 --format csv");
  // s = −0.5 turns 15810 rad from the reference point: beyond the evaluation budget, flagged
  // (exit 3); the other points keep their own positions.
  ASSERT_EQ(run.status, 3) << run.out;
  std::istringstream in(run.out);
  std::string line;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("s,", 0) == 0) continue;  // summary comments, header
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  ASSERT_EQ(rows.size(), 5u) << run.out;
  EXPECT_NE(run.out.find("\n# max_iterations,"), std::string::npos) << run.out;
  EXPECT_TRUE(rows[0].size() < 2 || rows[0][1].empty()) << run.out;  // the failed point has no position
  std::set<std::string> positions;
  for (size_t k = 1; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 5u) << run.out;  // s,x,y,theta,kappa; a failed point would have empty x, y
    EXPECT_FALSE(rows[k][1].empty()) << run.out;
    positions.insert(rows[k][1] + "," + rows[k][2]);
  }
  EXPECT_EQ(positions.size(), 4u) << run.out;  // four different points
  EXPECT_NEAR(std::stod(rows[4][1]), 0.94995896720813, 1e-12) << run.out;  // = the end point of --s-to 1.04
}

}  // namespace
}  // namespace lac
