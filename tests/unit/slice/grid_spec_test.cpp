// The grid of SPEC §2 built from a model's bounding box: sizes, origin and the refusals.
#include "strata/slice/grid_spec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace strata {
namespace {

Bbox3 box(Vec3 lo, Vec3 hi) {
  Bbox3 b;
  b.add(lo);
  b.add(hi);
  return b;
}

GridOptions cells(double dx, double dy, double dz) {
  GridOptions o;
  o.dx_mm = dx;
  o.dy_mm = dy;
  o.dz_mm = dz;
  return o;
}

TEST(MakeGrid, CountsCellsAsTheCeilingOfSpanOverSize) {
  // 1.0 / 0.25 = 4 exactly; 1.1 / 0.5 = 2.2 rounds up to 3; 0.3 / 0.1 is 2.9999999999999996.
  const auto g = make_grid(box({0, 0, 0}, {1.0, 1.1, 0.3}), cells(0.25, 0.5, 0.1));
  ASSERT_TRUE(g.has_value()) << g.error().to_string();
  EXPECT_EQ(g->nx, 4u);
  EXPECT_EQ(g->ny, 3u);
  EXPECT_EQ(g->nz, 3u);
  EXPECT_EQ(g->x0, 0.0);
  EXPECT_EQ(g->dy, 0.5);
  EXPECT_EQ(g->cells_per_layer(), 12u);
  EXPECT_EQ(g->cell_count(), 36u);
}

TEST(MakeGrid, CentresAndPlanesAreHalfACellFromTheOrigin) {
  const auto g = make_grid(box({-1, -2, 3}, {1, 2, 5}), cells(0.5, 0.25, 0.125));
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->xc(0), -0.75);
  EXPECT_EQ(g->yc(3), -1.125);
  EXPECT_EQ(g->zk(15), 4.9375);
}

TEST(MakeGrid, FlatModelGetsOneCellAlongItsFlatAxis) {
  const auto g = make_grid(box({0, 0, 2}, {4, 4, 2}), cells(1, 1, 1));
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->nz, 1u);
  EXPECT_EQ(g->z0, 2.0);
}

TEST(MakeGrid, OriginBeyondTheModelStillGivesOneCell) {
  GridOptions o = cells(1, 1, 1);
  o.origin = Vec3{10, 10, 10};
  const auto g = make_grid(box({0, 0, 0}, {4, 4, 4}), o);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->nx, 1u);
  EXPECT_EQ(g->ny, 1u);
  EXPECT_EQ(g->nz, 1u);
  EXPECT_EQ(g->x0, 10.0);
}

TEST(MakeGrid, GivenOriginBelowTheModelAddsTheCellsBetween) {
  GridOptions o = cells(1, 1, 1);
  o.origin = Vec3{-2, 0, -0.5};
  const auto g = make_grid(box({0, 0, 0}, {4, 4, 4}), o);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->nx, 6u);
  EXPECT_EQ(g->ny, 4u);
  EXPECT_EQ(g->nz, 5u);
}

TEST(MakeGrid, RefusesAModelWithoutVertices) {
  const auto g = make_grid(Bbox3{}, cells(1, 1, 1));
  ASSERT_FALSE(g.has_value());
  EXPECT_EQ(g.error().code, ErrorCode::BadInput);
  EXPECT_EQ(g.error().message, "the model has no vertices");
}

TEST(MakeGrid, RefusesANonFiniteOrigin) {
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    for (int axis = 0; axis < 3; ++axis) {
      GridOptions o = cells(1, 1, 1);
      Vec3 origin{0, 0, 0};
      (axis == 0 ? origin.x : axis == 1 ? origin.y : origin.z) = bad;
      o.origin = origin;
      const auto g = make_grid(box({0, 0, 0}, {1, 1, 1}), o);
      ASSERT_FALSE(g.has_value()) << axis;
      EXPECT_EQ(g.error().code, ErrorCode::Usage);
      EXPECT_EQ(g.error().message, "the grid origin must be finite");
    }
  }
}

TEST(MakeGrid, RefusesZeroNegativeAndNonFiniteCellSizesNamingTheAxis) {
  const Bbox3 b = box({0, 0, 0}, {1, 1, 1});
  struct Case {
    GridOptions options;
    const char* message;
  };
  const Case cases[] = {
      {cells(0, 1, 1), "cell size along x must be a positive number, got 0"},
      {cells(1, -0.5, 1), "cell size along y must be a positive number, got -0.5"},
      {cells(1, 1, std::numeric_limits<double>::quiet_NaN()),
       "cell size along z must be a positive number, got nan"},
      {cells(std::numeric_limits<double>::infinity(), 1, 1),
       "cell size along x must be a positive number, got inf"},
  };
  for (const Case& c : cases) {
    const auto g = make_grid(b, c.options);
    ASSERT_FALSE(g.has_value()) << c.message;
    EXPECT_EQ(g.error().code, ErrorCode::Usage);
    EXPECT_EQ(g.error().message, c.message);
  }
}

TEST(MakeGrid, AcceptsTheLargestAxisAndRefusesOneCellMore) {
  // 2^31 - 1 cells of 1 mm is the most an axis indexes; one more is refused with the span.
  const auto most = make_grid(box({0, 0, 0}, {2147483647.0, 1, 1}), cells(1, 1, 1));
  ASSERT_TRUE(most.has_value()) << most.error().to_string();
  EXPECT_EQ(most->nx, 2147483647u);
  const auto over = make_grid(box({0, 0, 0}, {1, 2147483648.0, 1}), cells(1, 1, 1));
  ASSERT_FALSE(over.has_value());
  EXPECT_EQ(over.error().code, ErrorCode::Usage);
  EXPECT_EQ(over.error().message,
            "the model spans 2147483648 mm along y: 2147483648 cells of 1 mm are more than the "
            "grid can index; use larger cells");
}

TEST(MakeGrid, RefusesASpanTooLargeForADouble) {
  const auto g = make_grid(box({-1.7e308, 0, 0}, {1.7e308, 1, 1}), cells(1, 1, 1));
  ASSERT_FALSE(g.has_value());
  EXPECT_EQ(g.error().code, ErrorCode::Usage);
  EXPECT_NE(g.error().message.find("along x: inf cells of 1 mm"), std::string::npos)
      << g.error().message;
}

TEST(MakeGrid, RefusesALayerOfMoreThanTwoToTheThirtyFourCells) {
  // 2^17 x 2^17 = 2^34 cells is the limit; 2^17 x (2^17 + 1) is over it.
  const auto most = make_grid(box({0, 0, 0}, {131072, 131072, 1}), cells(1, 1, 1));
  ASSERT_TRUE(most.has_value()) << most.error().to_string();
  const auto over = make_grid(box({0, 0, 0}, {131072, 131073, 1}), cells(1, 1, 1));
  ASSERT_FALSE(over.has_value());
  EXPECT_EQ(over.error().code, ErrorCode::Usage);
  EXPECT_EQ(over.error().message,
            "a layer of 131072 x 131073 cells is larger than strata holds in memory (2^34 "
            "cells); use larger cells");
}

}  // namespace
}  // namespace strata
