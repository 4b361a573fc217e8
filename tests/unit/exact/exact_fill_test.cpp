// The exact fill's crossings: each one the double nearest the exact crossing, down to the
// subnormal doubles, where the rounding takes the rational's own path.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "exact_test_support.hpp"

namespace strata::exact_test {
namespace {

/// The box [lo, hi] with double corners, outward facets.
IndexedMesh double_box(const Vec3& lo, const Vec3& hi) {
  IndexedMesh m;
  for (int k = 0; k < 8; ++k) {
    m.vertices.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  }
  add_quad(m, 0, 2, 3, 1);  // z = lo
  add_quad(m, 4, 5, 7, 6);  // z = hi
  add_quad(m, 0, 1, 5, 4);  // y = lo
  add_quad(m, 2, 6, 7, 3);  // y = hi
  add_quad(m, 0, 4, 6, 2);  // x = lo
  add_quad(m, 1, 3, 7, 5);  // x = hi
  return m;
}

TEST(ExactFill, ACrossingAmongTheSubnormalDoublesIsThatDoubleExactly) {
  const double tiny = 3e-310;  // subnormal
  ASSERT_LT(tiny, std::numeric_limits<double>::min());
  const IndexedMesh box = double_box({tiny, 0.0, 0.0}, {1.0, 1.0, 1.0});
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
