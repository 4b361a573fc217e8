// The exact fill's crossings: each one the double nearest the exact crossing, down to the
// subnormal doubles, where the rounding takes the rational's own path.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "exact_test_support.hpp"

namespace strata::exact_test {
namespace {

TEST(ExactFill, ACrossingAmongTheSubnormalDoublesIsThatDoubleExactly) {
  const double tiny = 3e-310;  // subnormal
  ASSERT_LT(tiny, std::numeric_limits<double>::min());
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({tiny, 0.0, 0.0}, {1.0, 1.0, 1.0});
  GridSpec grid;
  grid.x0 = -0.5;
  grid.y0 = 0.0;
  grid.z0 = 0.0;
  grid.dx = grid.dy = grid.dz = 0.25;
  grid.nx = 8;
  grid.ny = 4;
  grid.nz = 4;
  SliceOptions options;
  const exact_test::Run run = run_exact(box, grid, options);
  ASSERT_TRUE(run.ok);
  for (std::uint32_t k = 0; k < grid.nz; ++k) {
    ASSERT_EQ(run.sink.hatches[k].size(), grid.ny) << "layer " << k;
    for (const HatchSegment& h : run.sink.hatches[k]) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(h.x_start), std::bit_cast<std::uint64_t>(tiny))
          << "layer " << k << " row " << h.row;
      EXPECT_EQ(h.x_end, 1.0);
    }
    for (std::uint32_t i = 0; i < grid.nx; ++i) {
      const double xc = grid.xc(i);
      EXPECT_EQ(run.sink.solid(i, 0, k), xc > tiny && xc < 1.0) << "cell " << i;
    }
  }
}

}  // namespace
}  // namespace strata::exact_test
