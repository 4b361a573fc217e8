// Vec3 and Point2: equality is coordinate by coordinate, as IEEE comparison of doubles has it.
#include "strata/mesh/vec3.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace strata {
namespace {

TEST(Vec3, EqualOnlyWhenEveryCoordinateIsEqual) {
  const Vec3 p{1, 2, 3};
  EXPECT_TRUE(p == (Vec3{1, 2, 3}));
  EXPECT_FALSE(p == (Vec3{9, 2, 3}));
  EXPECT_FALSE(p == (Vec3{1, 9, 3}));
  EXPECT_FALSE(p == (Vec3{1, 2, 9}));
  EXPECT_TRUE(p != (Vec3{1, 2, 9}));
}

TEST(Vec3, SignedZerosAreEqualAndNanIsNot) {
  EXPECT_TRUE((Vec3{0.0, -0.0, 0.0}) == (Vec3{-0.0, 0.0, 0.0}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE((Vec3{0, 0, nan}) == (Vec3{0, 0, nan}));
}

TEST(Point2, EqualOnlyWhenBothCoordinatesAreEqual) {
  const Point2 p{1, 2};
  EXPECT_TRUE(p == (Point2{1, 2}));
  EXPECT_FALSE(p == (Point2{9, 2}));
  EXPECT_FALSE(p == (Point2{1, 9}));
}

TEST(Bbox3, IsEmptyUntilAPointIsAddedThenSpansThePoints) {
  Bbox3 box;
  EXPECT_TRUE(box.empty());
  box.add({1, -2, 3});
  EXPECT_FALSE(box.empty());
  box.add({-1, 5, 2});
  EXPECT_EQ(box.min, (Vec3{-1, -2, 2}));
  EXPECT_EQ(box.max, (Vec3{1, 5, 3}));
}

}  // namespace
}  // namespace strata
