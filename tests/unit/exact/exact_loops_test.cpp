// The exact path's loops turned into a layer's contours: open chains, areas, the kind decided at
// the smallest vertex, and depths by exact point-in-loop tests, touching loops included.

// The library is compiled with CGAL's configuration, CGAL_USE_GMPXX, under which the exact
// module's Rational is GMP's mpq_class; this file passes the module's own types across, so it
// must see the same type.
#ifndef CGAL_USE_GMPXX
#define CGAL_USE_GMPXX 1
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <type_traits>
#include <vector>

#include "exact/exact_loops_internal.hpp"

namespace strata::exact::detail {
namespace {

static_assert(std::is_same_v<Rational, mpq_class>, "the library's exact number type");

ExactLoop loop_of(const std::vector<Point2>& points, bool closed = true) {
  ExactLoop loop;
  loop.closed = closed;
  for (const Point2& p : points) {
    loop.points.push_back({RoundedRational(Rational(p.x)), RoundedRational(Rational(p.y))});
  }
  return loop;
}

/// The square [x0, x0 + side] x [y0, y0 + side], counter-clockwise from its lowest corner.
ExactLoop square(double x0, double y0, double side) {
  return loop_of({{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}});
}

ExactLoop reversed(ExactLoop loop) {
  std::reverse(loop.points.begin(), loop.points.end());
  return loop;
}

TEST(FinishContours, KeepsOpenChainsOpenAndOutOfTheArea) {
  const LayerContours c = finish_contours(
      3, 0.5, {loop_of({{0, 0}, {1, 0}, {1, 1}}, false), square(5, 5, 1), loop_of({})}, 1);
  EXPECT_EQ(c.layer, 3u);
  EXPECT_EQ(c.z_mm, 0.5);
  EXPECT_EQ(c.open_chains, 1u);
  ASSERT_EQ(c.loops.size(), 3u);
  EXPECT_FALSE(c.loops[0].is_closed);
  EXPECT_EQ(c.loops[0].kind, LoopKind::Open);
  EXPECT_EQ(c.loops[0].points, (std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}}));
  EXPECT_FALSE(c.loops[2].is_closed) << "a loop without points closes nothing";
  EXPECT_EQ(c.loops[2].kind, LoopKind::Open);
  EXPECT_EQ(c.area_mm2, 1.0);
}

TEST(FinishContours, GivesCounterClockwiseLoopsAsOuterAndClockwiseAsHoles) {
  const LayerContours c = finish_contours(0, 0, {square(0, 0, 4), reversed(square(1, 1, 2))}, 0);
  ASSERT_EQ(c.loops.size(), 2u);
  EXPECT_EQ(c.loops[0].kind, LoopKind::Outer);
  EXPECT_EQ(c.loops[0].signed_area_mm2, 16.0);
  EXPECT_EQ(c.loops[0].depth, 0);
  EXPECT_EQ(c.loops[1].kind, LoopKind::Hole);
  EXPECT_EQ(c.loops[1].signed_area_mm2, -4.0);
  EXPECT_EQ(c.loops[1].depth, 1);
  EXPECT_EQ(c.area_mm2, 12.0);
}

TEST(FinishContours, GivesALoopOfTwoPointsNoAreaAndNoDepth) {
  const LayerContours c = finish_contours(0, 0, {loop_of({{1, 1}, {2, 1}}), square(0, 0, 4)}, 0);
  EXPECT_TRUE(c.loops[0].is_closed);
  EXPECT_EQ(c.loops[0].signed_area_mm2, 0.0);
  EXPECT_EQ(c.loops[0].kind, LoopKind::Outer);
  EXPECT_EQ(c.loops[0].depth, 0) << "not tested against the square";
}

TEST(FinishContours, DecidesTheKindAtASmallestVertexRepeatedInARow) {
  // The smallest vertex twice in a row, once across the loop's start: one visit each time.
  const LayerContours c = finish_contours(
      0, 0, {loop_of({{0, 0}, {0, 0}, {2, 0}, {2, 2}}), loop_of({{5, 0}, {7, 0}, {7, 2}, {5, 0}})},
      0);
  EXPECT_EQ(c.loops[0].kind, LoopKind::Outer);
  EXPECT_EQ(c.loops[0].signed_area_mm2, 2.0);
  EXPECT_EQ(c.loops[1].kind, LoopKind::Outer);
  EXPECT_EQ(c.loops[1].signed_area_mm2, 2.0);
}

TEST(FinishContours, FallsBackToTheAreaWhenTheSmallestVertexDoesNotDecide) {
  // Through the smallest vertex twice: two lobes of areas 2 and 0.5, both counter-clockwise.
  const LayerContours lobes =
      finish_contours(0, 0, {loop_of({{0, 0}, {2, -1}, {2, 1}, {0, 0}, {1, 2}, {1, 3}})}, 0);
  EXPECT_EQ(lobes.loops[0].signed_area_mm2, 2.5);
  EXPECT_EQ(lobes.loops[0].kind, LoopKind::Outer);
  const LayerContours turned = finish_contours(
      0, 0, {reversed(loop_of({{0, 0}, {2, -1}, {2, 1}, {0, 0}, {1, 2}, {1, 3}}))}, 0);
  EXPECT_EQ(turned.loops[0].kind, LoopKind::Hole);
  // Every point the same: no turn at all, and no area.
  const LayerContours point = finish_contours(0, 0, {loop_of({{1, 1}, {1, 1}, {1, 1}})}, 0);
  EXPECT_EQ(point.loops[0].kind, LoopKind::Outer);
  EXPECT_EQ(point.loops[0].signed_area_mm2, 0.0);
}

TEST(FinishContours, CountsALoopWhoseProbeLiesOnAnotherLoopAsOutsideIt) {
  // Each inner loop's first edge lies on the outer square's boundary (bottom, right and left
  // sides): its probe, the middle of that edge, is on the square, so the square does not count.
  const LayerContours c = finish_contours(
      0, 0,
      {square(0, 0, 4), loop_of({{3, 0}, {1, 0}, {1, 1}, {3, 1}}),
       loop_of({{4, 1}, {4, 3}, {3, 3}, {3, 1}}), loop_of({{0, 3}, {0, 1}, {1, 1}, {1, 3}})},
      0);
  ASSERT_EQ(c.loops.size(), 4u);
  EXPECT_EQ(c.loops[1].depth, 0);
  EXPECT_EQ(c.loops[2].depth, 0);
  EXPECT_EQ(c.loops[3].depth, 0);
  EXPECT_EQ(c.loops[0].depth, 0) << "the square's probe (2, 0) is on the first inner loop";
}

}  // namespace
}  // namespace strata::exact::detail
