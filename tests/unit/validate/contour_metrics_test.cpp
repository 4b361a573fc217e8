#include "strata/validate/contour_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace strata::validate {
namespace {

/// A closed loop through the points in order; Outer when counter-clockwise.
Contour loop(std::vector<Point2> points) {
  Contour c;
  c.points = std::move(points);
  c.is_closed = true;
  double twice = 0.0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const Point2& p = c.points[i];
    const Point2& q = c.points[(i + 1) % c.points.size()];
    twice += p.x * q.y - q.x * p.y;
  }
  c.signed_area_mm2 = twice / 2;
  c.kind = twice > 0 ? LoopKind::Outer : LoopKind::Hole;
  return c;
}

Contour square(double x0, double y0, double side) {
  return loop({{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}});
}

Contour clockwise_square(double x0, double y0, double side) {
  return loop({{x0, y0}, {x0, y0 + side}, {x0 + side, y0 + side}, {x0 + side, y0}});
}

Contour points(std::vector<Point2> pts) {
  Contour c;
  c.points = std::move(pts);
  c.is_closed = false;
  return c;
}

TEST(SymmetricDifference, OfTwoOffsetSquaresIsTheirNonOverlap) {
  // Squares of side 2, one moved by 0.5 in x: they overlap in 1.5 x 2, so each has 1 mm2 alone.
  const std::vector<Contour> a = {square(0, 0, 2)};
  const std::vector<Contour> b = {square(0.5, 0, 2)};
  const SymmetricDifference d = symmetric_difference(a, b, FillRule::NonZero);
  EXPECT_EQ(d.method, AreaMethod::Arrangement);
  EXPECT_DOUBLE_EQ(d.area_mm2, 2.0);
  EXPECT_DOUBLE_EQ(d.area_a_mm2, 4.0);
  EXPECT_DOUBLE_EQ(d.area_b_mm2, 4.0);
}

TEST(SymmetricDifference, OfAFrameAndItsFilledSquareIsTheHole) {
  const std::vector<Contour> frame = {square(0, 0, 4), clockwise_square(1, 1, 2)};
  const std::vector<Contour> full = {square(0, 0, 4)};
  const SymmetricDifference d = symmetric_difference(frame, full, FillRule::NonZero);
  EXPECT_DOUBLE_EQ(d.area_mm2, 4.0);
  EXPECT_DOUBLE_EQ(d.area_a_mm2, 12.0);
  EXPECT_DOUBLE_EQ(d.area_b_mm2, 16.0);
}

TEST(SymmetricDifference, OfTwoFramesWithShiftedHolesCountsBothHoleParts) {
  // The holes (2 x 2) are 0.25 apart in y: 2 x 0.25 on each side differ.
  const std::vector<Contour> a = {square(0, 0, 4), clockwise_square(1, 1, 2)};
  const std::vector<Contour> b = {square(0, 0, 4), clockwise_square(1, 1.25, 2)};
  EXPECT_DOUBLE_EQ(symmetric_difference(a, b, FillRule::EvenOdd).area_mm2, 1.0);
}

TEST(SymmetricDifference, IsZeroWithoutOverlayForTheSameLoopsStartedElsewhere) {
  const std::vector<Contour> a = {square(0, 0, 2)};
  const std::vector<Contour> b = {loop({{2, 2}, {0, 2}, {0, 0}, {2, 0}})};
  const SymmetricDifference d = symmetric_difference(a, b, FillRule::NonZero);
  EXPECT_EQ(d.method, AreaMethod::Identical);
  EXPECT_EQ(d.area_mm2, 0.0);
}

TEST(SymmetricDifference, FollowsTheFillRuleOnOverlappingLoops) {
  // Two overlapping squares (winding 2 in the 1 x 2 overlap) against the outline of their union.
  const std::vector<Contour> overlapping = {square(0, 0, 2), square(1, 0, 2)};
  const std::vector<Contour> union_outline = {loop({{0, 0}, {3, 0}, {3, 2}, {0, 2}})};
  EXPECT_DOUBLE_EQ(symmetric_difference(overlapping, union_outline, FillRule::NonZero).area_mm2,
                   0.0);
  EXPECT_DOUBLE_EQ(symmetric_difference(overlapping, union_outline, FillRule::EvenOdd).area_mm2,
                   2.0);
}

TEST(SymmetricDifference, IgnoresOpenChains) {
  const std::vector<Contour> a = {square(0, 0, 2), points({{5, 5}, {6, 6}})};
  const std::vector<Contour> b = {square(0, 0, 2)};
  EXPECT_EQ(symmetric_difference(a, b, FillRule::NonZero).area_mm2, 0.0);
}

TEST(HausdorffDistance, OfTwoPointsIsTheirDistance) {
  const std::vector<Contour> a = {points({{0, 0}})};
  const std::vector<Contour> b = {points({{3, 4}})};
  EXPECT_DOUBLE_EQ(hausdorff_distance(a, b), 5.0);
}

TEST(HausdorffDistance, TakesTheWorseOfBothDirections) {
  // From a: (10, 0) is 10 from b's only point; from b: (0, 0) is on a. So 10, not 0.
  const std::vector<Contour> a = {points({{0, 0}}), points({{10, 0}})};
  const std::vector<Contour> b = {points({{0, 0}})};
  EXPECT_DOUBLE_EQ(hausdorff_distance(a, b), 10.0);
  EXPECT_DOUBLE_EQ(hausdorff_distance(b, a), 10.0);
}

TEST(HausdorffDistance, MeasuresVerticesToSegments) {
  // b is a taller by 0.5: its top vertices are 0.5 above a's top edge, and every vertex of a
  // lies on an edge of b.
  const std::vector<Contour> a = {square(0, 0, 1)};
  const std::vector<Contour> b = {loop({{0, 0}, {1, 0}, {1, 1.5}, {0, 1.5}})};
  EXPECT_DOUBLE_EQ(hausdorff_distance(a, b), 0.5);
}

TEST(HausdorffDistance, OfManyPointsOnAGridIsTheLargestGap) {
  // 100 x 100 points 1 apart against the same grid without its point (37, 52): the missing
  // point's neighbours are 1 away.
  std::vector<Contour> a, b;
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) {
      a.push_back(points({{double(i), double(j)}}));
      if (!(i == 37 && j == 52)) b.push_back(points({{double(i), double(j)}}));
    }
  }
  EXPECT_DOUBLE_EQ(hausdorff_distance(a, b), 1.0);
}

TEST(HausdorffDistance, IsZeroForTwoEmptySetsAndInfiniteForOne) {
  const std::vector<Contour> none;
  const std::vector<Contour> one = {square(0, 0, 1)};
  EXPECT_EQ(hausdorff_distance(none, none), 0.0);
  EXPECT_EQ(hausdorff_distance(one, none), std::numeric_limits<double>::infinity());
  EXPECT_EQ(hausdorff_distance(none, one), std::numeric_limits<double>::infinity());
}

TEST(SameLoopEdges, LeavesOutClosedLoopsOfOnePointAndZeroLengthEdges) {
  const std::vector<Contour> a = {square(0, 0, 2), loop({{5, 5}})};
  const std::vector<Contour> b = {loop({{0, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}})};
  EXPECT_TRUE(same_loop_edges(a, b));
  const SymmetricDifference d = symmetric_difference(a, b, FillRule::NonZero);
  EXPECT_EQ(d.method, AreaMethod::Identical);
  EXPECT_EQ(d.area_mm2, 0.0);
  EXPECT_EQ(d.area_a_mm2, 4.0);
  EXPECT_EQ(d.area_b_mm2, 4.0);
}

}  // namespace
}  // namespace strata::validate
