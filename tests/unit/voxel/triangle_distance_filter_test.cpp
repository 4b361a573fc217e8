#include <gtest/gtest.h>

#include <random>

#include "voxel/triangle_distance_filter_internal.hpp"

namespace strata::detail {
namespace {

using Filter = TriangleDistanceFilter;

// Narrows [lo, hi] on the row (y, z) by the filter's row bounds, as the shell does.
bool row_range(const Filter& filter, double y, double z, double& lo, double& hi) {
  Filter::RowBound bounds[Filter::kMaxRowBounds];
  const int count = filter.row_bounds(z, y, y, lo, hi, bounds);
  for (int q = 0; q < count; ++q) bounds[q].clip(y, lo, hi);
  return lo <= hi;
}

// Whatever the filter decides must be what the exact predicate says.
void expect_consistent(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p, double t,
                       int* decided = nullptr) {
  const Filter filter(a, b, c, t);
  const int quick = filter.decide(p);
  const bool exact = triangle_closer_than(p, a, b, c, t);
  if (quick != Filter::kUndecided) {
    ASSERT_EQ(quick == Filter::kCloser, exact)
        << "p=(" << p.x << "," << p.y << "," << p.z << ") t=" << t;
    if (decided) ++*decided;
  }
  EXPECT_EQ(filter.closer_than(p), exact);
  // The row range the shell scans may leave out only points that are not closer.
  if (exact) {
    for (const double reach : {0.0, 1.0, 1e3}) {
      double lo = p.x - reach;
      double hi = p.x + reach;
      ASSERT_TRUE(row_range(filter, p.y, p.z, lo, hi))
          << "p=(" << p.x << "," << p.y << "," << p.z << ") t=" << t << " reach " << reach;
      ASSERT_TRUE(lo <= p.x && p.x <= hi)
          << "p=(" << p.x << "," << p.y << "," << p.z << ") t=" << t << " reach " << reach;
    }
  }
}

TEST(TriangleDistanceFilter, AgreesWithExactPredicateOnRandomTriangles) {
  const std::uint64_t seed = 20261122;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  int decided = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Vec3 a{coord(rng), coord(rng), coord(rng)};
    const Vec3 b{coord(rng), coord(rng), coord(rng)};
    const Vec3 c{coord(rng), coord(rng), coord(rng)};
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    expect_consistent(a, b, c, p, std::fabs(coord(rng)) + 0.01, &decided);
    if (HasFatalFailure()) FAIL() << "seed " << seed << " case " << i;
  }
  // The filter is only worth having if it decides nearly everything.
  EXPECT_GT(decided, n * 95 / 100);
}

TEST(TriangleDistanceFilter, AgreesOnExactTiesAtTheThickness) {
  // Axis-aligned facet z = 0 over [0,4]^2; centres at distance exactly t above it, beside an edge
  // and beside a corner.
  const Vec3 a{0, 0, 0}, b{4, 0, 0}, c{0, 4, 0};
  for (const Vec3& p : {Vec3{1, 1, 1.5}, Vec3{2, -1.5, 0}, Vec3{-1.5, 2, 0}, Vec3{-0.9, -1.2, 0},
                        Vec3{1, 1, -1.5}, Vec3{3.5, 3.5, 0}}) {
    expect_consistent(a, b, c, p, 1.5);
    // Exactly at t is not closer than t.
  }
  EXPECT_FALSE(Filter(a, b, c, 1.5).closer_than({1, 1, 1.5}));
  // Beside the corner at distance exactly 1.25 (0.75^2 + 1^2 = 1.25^2, all dyadic).
  expect_consistent(a, b, c, {-0.75, -1.0, 0}, 1.25);
  EXPECT_FALSE(Filter(a, b, c, 1.25).closer_than({-0.75, -1.0, 0}));
  EXPECT_TRUE(Filter(a, b, c, 1.25).closer_than({-0.75, -0.9999999999, 0}));
  EXPECT_TRUE(Filter(a, b, c, 1.5).closer_than({1, 1, 1.4999999999}));
}

TEST(TriangleDistanceFilter, AgreesOnDegenerateAndSliverTriangles) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  for (int i = 0; i < 3000; ++i) {
    const Vec3 a{coord(rng), coord(rng), coord(rng)};
    const Vec3 b{coord(rng), coord(rng), coord(rng)};
    const double s = coord(rng);
    // Collinear (zero-area), coincident corners, and slivers a hair off the line.
    const Vec3 on_line{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)};
    const Vec3 sliver{on_line.x + 1e-12, on_line.y, on_line.z - 1e-13};
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    const double t = std::fabs(coord(rng)) + 0.05;
    expect_consistent(a, b, on_line, p, t);
    expect_consistent(a, a, b, p, t);
    expect_consistent(a, a, a, p, t);
    expect_consistent(a, b, sliver, p, t);
    if (HasFatalFailure()) FAIL() << "case " << i;
  }
}

TEST(TriangleDistanceFilter, AgreesAtMetreScaleCoordinates) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> local(-0.3, 0.3);
  const Vec3 base{1812.25, 987.5, 640.125};
  const auto near_base = [&] {
    return Vec3{base.x + local(rng), base.y + local(rng), base.z + local(rng)};
  };
  for (int i = 0; i < 5000; ++i) {
    expect_consistent(near_base(), near_base(), near_base(), near_base(),
                      0.1 + std::fabs(local(rng)));
    if (HasFatalFailure()) FAIL() << "case " << i;
  }
}

TEST(TriangleDistanceFilter, DecidesPointsBesideACornerWithoutTheExactTest) {
  // Beside a corner the facet's nearest point is the corner itself, farther than the line of
  // either edge: points just beyond t of the corner must still be rejected by the double
  // bounds, since the shell meets them around every vertex of a fine mesh.
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto unit_vector = [](const Vec3& v) {
    const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return Vec3{v.x / len, v.y / len, v.z / len};
  };
  int rejected = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const Vec3 a{coord(rng), coord(rng), coord(rng)};
    const Vec3 b{coord(rng), coord(rng), coord(rng)};
    const Vec3 c{coord(rng), coord(rng), coord(rng)};
    // Away from both edges at a (the corner's region), tilted out of the plane at random.
    const Vec3 ub = unit_vector({b.x - a.x, b.y - a.y, b.z - a.z});
    const Vec3 uc = unit_vector({c.x - a.x, c.y - a.y, c.z - a.z});
    const Vec3 n_ = unit_vector(
        {ub.y * uc.z - ub.z * uc.y, ub.z * uc.x - ub.x * uc.z, ub.x * uc.y - ub.y * uc.x});
    const double tilt = 2.0 * unit(rng) - 1.0;
    const Vec3 away = unit_vector(
        {-(ub.x + uc.x) + tilt * n_.x, -(ub.y + uc.y) + tilt * n_.y, -(ub.z + uc.z) + tilt * n_.z});
    const double t = 0.05 + unit(rng);
    const double step = std::pow(10.0, -6.0 + 5.0 * unit(rng));
    const double reach = t * (1.0 + step);
    const Vec3 p{a.x + reach * away.x, a.y + reach * away.y, a.z + reach * away.z};
    expect_consistent(a, b, c, p, t);
    // And as near inside t: closer, whatever decides it.
    const double inside = t * (1.0 - step);
    expect_consistent(a, b, c,
                      {a.x + inside * away.x, a.y + inside * away.y, a.z + inside * away.z}, t);
    if (HasFatalFailure()) FAIL() << "case " << i;
    rejected += Filter(a, b, c, t).decide(p) == Filter::kFarther ? 1 : 0;
  }
  EXPECT_GT(rejected, n * 99 / 100);
}

TEST(TriangleDistanceFilter, AgreesForPointsPlacedNearTheThreshold) {
  // Points at t(1 +- 1e-13) from a slanted facet: the filter must hand these to the exact test.
  const Vec3 a{0.1, 0.2, 0.3}, b{3.7, 0.9, 1.3}, c{1.1, 2.9, -0.7};
  const Vec3 e1{b.x - a.x, b.y - a.y, b.z - a.z}, e2{c.x - a.x, c.y - a.y, c.z - a.z};
  Vec3 n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
  const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  n = {n.x / len, n.y / len, n.z / len};
  const Vec3 centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
  for (const double f : {1 - 1e-13, 1 - 1e-15, 1.0, 1 + 1e-15, 1 + 1e-13}) {
    const double t = 0.5;
    const Vec3 p{centroid.x + n.x * t * f, centroid.y + n.y * t * f, centroid.z + n.z * t * f};
    expect_consistent(a, b, c, p, t);
  }
}

TEST(TriangleDistanceFilter, RowRangeKeepsTheStretchOfARowNearASteepFacet) {
  // The facet x = 2 (normal along x), t = 0.5: along any row through its footprint only
  // x in (1.5, 2.5) can be closer, give or take the margin of 1e-6.
  const Filter filter({2, 0, 0}, {2, 10, 0}, {2, 0, 10}, 0.5);
  double lo = -100.0;
  double hi = 100.0;
  ASSERT_TRUE(row_range(filter, 3.0, 4.0, lo, hi));
  EXPECT_NEAR(lo, 1.5, 1e-3);
  EXPECT_NEAR(hi, 2.5, 1e-3);
  // Its edges' planes all contain the x direction: a row beyond an edge keeps the slab's
  // stretch (the shell's box and the cell tests leave it out).
  lo = -100.0;
  hi = 100.0;
  EXPECT_TRUE(row_range(filter, 13.0, 4.0, lo, hi));
  EXPECT_NEAR(lo, 1.5, 1e-3);
  EXPECT_NEAR(hi, 2.5, 1e-3);
}

TEST(TriangleDistanceFilter, RowRangeIsBoundedByTheEdgesOfAFlatFacet) {
  // The facet z = 0 with corners (0,0), (4,0), (0,4); t = 0.5, the row y = 1 at z = 0.2. Its
  // plane and the edge along x run along the row and bound nothing; the edge x = 0 keeps
  // x > -0.5 and the edge x + y = 4 keeps x < 3 + 0.5 sqrt(2).
  const Vec3 a{0, 0, 0}, b{4, 0, 0}, c{0, 4, 0};
  const Filter filter(a, b, c, 0.5);
  double lo = -100.0;
  double hi = 100.0;
  ASSERT_TRUE(row_range(filter, 1.0, 0.2, lo, hi));
  EXPECT_NEAR(lo, -0.5, 1e-3);
  EXPECT_NEAR(hi, 3.0 + 0.5 * std::sqrt(2.0), 1e-3);
  // The bounds are the true reach of the facet there only where a side is nearest: beyond the
  // edge x = 0 at height 0.2 the reach is sqrt(0.25 - 0.04), inside the kept range.
  EXPECT_TRUE(triangle_closer_than({-0.45, 1.0, 0.2}, a, b, c, 0.5));
  EXPECT_FALSE(triangle_closer_than({-0.47, 1.0, 0.2}, a, b, c, 0.5));
  EXPECT_LT(lo, -0.47);
  // A row of another layer beyond the edge x + y = 4 by more than t: nothing is kept.
  lo = -100.0;
  hi = 100.0;
  EXPECT_FALSE(row_range(filter, 5.5, 0.0, lo, hi));
  // A facet without a reliable plane (three points on a line) gives no bound.
  const Filter line({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, 0.5);
  Filter::RowBound bounds[Filter::kMaxRowBounds];
  EXPECT_EQ(line.row_bounds(0.0, 0.0, 0.0, -1.0, 1.0, bounds), 0);
}

}  // namespace
}  // namespace strata::detail
