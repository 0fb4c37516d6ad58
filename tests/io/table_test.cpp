// Result tables and data files write −0 as 0: the sign of a zero is rounding, and a regenerated
// table must not differ from the committed one by it.
#include "io/table.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace lac::io {
namespace {

TEST(Numbers, NegativeZeroIsWrittenAsZero) {
  EXPECT_EQ(fmt(-0.0), "0");
  EXPECT_EQ(sci(-0.0, 2), "0.0e+00");
  EXPECT_EQ(fmt(-1e-300), "-1e-300");  // a negative number keeps its sign
  std::ostringstream os;
  os.precision(9);
  write_numbers_plainly(os);
  os << -0.0 << "," << -1.5 << "," << 0.25;
  EXPECT_EQ(os.str(), "0,-1.5,0.25");
}

}  // namespace
}  // namespace lac::io
