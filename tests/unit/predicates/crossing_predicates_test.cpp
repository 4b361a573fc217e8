// The exact signs of SPEC §2's inside rule: decided without arithmetic when the end points
// settle it, by the double filter when it can, by GMP on ties and near-ties.
#include "predicates/crossing_predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "support/exact_crossing.hpp"

namespace strata::detail {
namespace {

/// Sign and whether the exact fallback was needed.
template <class F>
std::pair<int, bool> sign_and_fallback(const F& f) {
  const std::uint64_t before = exact_fallback_counter();
  const int s = f();
  return {s, exact_fallback_counter() != before};
}

TEST(CrossingYSign, EndPointsOnOneSideDecideWithoutArithmetic) {
  const Vec3 lo{0, 2, 0}, hi{0, 3, 4};
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, 1.5); }),
            std::make_pair(1, false));
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, 3.5); }),
            std::make_pair(-1, false));
  const Vec3 flat_lo{0, 1, 0}, flat_hi{5, 1, 4};
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(flat_lo, flat_hi, 2, 1.0); }),
            std::make_pair(0, false));
}

TEST(CrossingYSign, ClearSignsAreDecidedByTheFilter) {
  // Crossing of (0,0,0)-(0,4,4) at z = 1 is y = 1.
  const Vec3 lo{0, 0, 0}, hi{0, 4, 4};
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, 0.5); }),
            std::make_pair(1, false));
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, 1.5); }),
            std::make_pair(-1, false));
}

TEST(CrossingYSign, AnExactTieIsZeroThroughTheExactFallback) {
  const Vec3 lo{0, 0, 0}, hi{0, 3, 3};
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, 1.0); }),
            std::make_pair(0, true));
}

TEST(CrossingYSign, ACrossingAHairAboveIsAboveWhereDoublesSayTie) {
  // The crossing is y = 1/3 exactly; the double 0.333...3 lies 1.9e-17 below it. In double,
  // -y * 3 + 1 rounds to 0; the exact sign is +1.
  const Vec3 lo{0, 0, 0}, hi{0, 1, 3};
  const double y = 1.0 / 3.0;
  ASSERT_EQ(-y * 3.0 + 1.0, 0.0);
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, y); }),
            std::make_pair(1, true));
}

/// Random edges crossing a random plane, their coordinates of magnitude around `scale`.
struct RandomCrossing {
  Vec3 lo, hi;
  double z;
};
RandomCrossing random_crossing(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> coordinate(-scale, scale);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  RandomCrossing c;
  do {
    c.lo = {coordinate(rng), coordinate(rng), coordinate(rng)};
    c.hi = {coordinate(rng), coordinate(rng), coordinate(rng)};
    if (c.lo.z > c.hi.z) std::swap(c.lo, c.hi);
    c.z = c.lo.z + fraction(rng) * (c.hi.z - c.lo.z);
  } while (!(c.lo.z < c.z && c.z <= c.hi.z));
  return c;
}

constexpr double kScales[] = {1e-310, 1e-300, 1e-3, 1.0, 250.0, 1e6, 1e300};

TEST(CrossingPointError, BoundsTheRoundedPointWithRoomToSpare) {
  // The bound claims a factor of two over the worst rounding; hold it to half of itself.
  std::mt19937_64 rng(20261129);
  for (const double scale : kScales) {
    for (int n = 0; n < 4000; ++n) {
      const RandomCrossing c = random_crossing(rng, scale);
      const Point2 p = crossing_point(c.lo, c.hi, c.z);
      for (const int axis : {0, 1}) {
        const double rounded = axis == 0 ? p.x : p.y;
        const double bound =
            axis == 0 ? crossing_point_error(c.lo.x, c.hi.x) : crossing_point_error(c.lo.y, c.hi.y);
        const mpq_class error = abs(test::crossing_as_written(c.lo, c.hi, c.z, axis) - rounded);
        ASSERT_LE(error, mpq_class(bound) / 2) << "scale " << scale << " axis " << axis;
      }
    }
  }
}

TEST(CrossingYSign, FromTheRoundedPointAgreesWithTheExactSignUlpsAround) {
  // Scanlines a few ulps from the rounded crossing, where the rounding may put it on the wrong
  // side: the rounded point decides only beyond its bound, the exact sign otherwise.
  std::mt19937_64 rng(7);
  std::uint64_t near_ties_seen = 0;
  for (const double scale : kScales) {
    for (int n = 0; n < 250; ++n) {
      const RandomCrossing c = random_crossing(rng, scale);
      const double approx = crossing_point(c.lo, c.hi, c.z).y;
      const mpq_class exact = test::crossing_as_written(c.lo, c.hi, c.z, 1);
      double y = approx;
      for (int k = 0; k < 24; ++k) y = std::nextafter(y, -INFINITY);
      for (int k = -24; k <= 24; ++k, y = std::nextafter(y, INFINITY)) {
        const int expected = sgn(exact - y);
        ASSERT_EQ(crossing_y_sign(c.lo, c.hi, c.z, y, approx), expected)
            << "scale " << scale << " ulps " << k;
        if (expected != (approx > y) - (approx < y)) ++near_ties_seen;
      }
    }
  }
  // The rounded point was on the wrong side of some scanline (or on it while the crossing was
  // not): the cases the bound is there for.
  EXPECT_GT(near_ties_seen, 1000U);
}

TEST(CrossingYSign, FromTheRoundedPointFarScanlinesNeedNoExactArithmetic) {
  const Vec3 lo{0, 0, 0}, hi{0, 1, 3};  // crosses z = 1 at y = 1/3
  const double approx = crossing_point(lo, hi, 1).y;
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, 0.3, approx); }),
            std::make_pair(1, false));
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, 0.4, approx); }),
            std::make_pair(-1, false));
  // On the rounded point itself, the exact sign: 1/3 lies above its double.
  EXPECT_EQ(sign_and_fallback([&] { return crossing_y_sign(lo, hi, 1, 1.0 / 3.0, approx); }),
            std::make_pair(1, true));
  // A tie stays a tie.
  const Vec3 tie_lo{0, 0, 0}, tie_hi{0, 3, 3};
  EXPECT_EQ(crossing_y_sign(tie_lo, tie_hi, 1, 1.0, crossing_point(tie_lo, tie_hi, 1).y), 0);
}

TEST(CrossingYSign, FromAnOverflowingRoundedPointTheExactPredicateDecides) {
  // hi.y - lo.y overflows: the rounded point is +inf, the crossing 0.35e308 at z = 0.5. The
  // bound overflows with it, so the rounded point decides nothing.
  const Vec3 lo{0, -1e308, 0}, hi{0, 1.7e308, 1};
  const double approx = crossing_point(lo, hi, 0.5).y;
  ASSERT_EQ(approx, INFINITY);
  EXPECT_EQ(crossing_y_sign(lo, hi, 0.5, 1e308, approx), -1);
  EXPECT_EQ(crossing_y_sign(lo, hi, 0.5, 0.0, approx), 1);
}

TEST(CrossingXSign, MirrorsTheYPredicate) {
  const Vec3 lo{0, 0, 0}, hi{1, 0, 3};
  EXPECT_EQ(crossing_x_sign(lo, hi, 1, 1.0 / 3.0), 1);
  EXPECT_EQ(crossing_x_sign(lo, hi, 1, 0.5), -1);
  EXPECT_EQ(crossing_x_sign({2, 0, 0}, {3, 0, 1}, 0.5, 1.0), 1);
  EXPECT_EQ(crossing_x_sign({2, 0, 0}, {3, 0, 1}, 0.5, 4.0), -1);
  EXPECT_EQ(crossing_x_sign({2, 0, 0}, {2, 5, 1}, 0.5, 2.0), 0);
  EXPECT_EQ(crossing_x_sign({0, 0, 0}, {4, 0, 4}, 1, 1.0), 0);
}

TEST(CrossingXSign, EndPointsOnBothSidesOfXNeedTheCrossing) {
  // lo right of x, hi left of it: the crossing at z = 1 is x = 1, on the line.
  EXPECT_EQ(sign_and_fallback([&] {
              return crossing_x_sign({2, 0, 0}, {0, 0, 2}, 1, 1.0);
            }),
            std::make_pair(0, true));
  // lo on x, hi right of it: the crossing at z = 1 is x = 2.
  EXPECT_EQ(sign_and_fallback([&] {
              return crossing_x_sign({1, 0, 0}, {3, 0, 2}, 1, 1.0);
            }),
            std::make_pair(1, false));
  // lo on x, hi left of it: the crossing at z = 1 is x = 0.
  EXPECT_EQ(sign_and_fallback([&] {
              return crossing_x_sign({1, 0, 0}, {-1, 0, 2}, 1, 1.0);
            }),
            std::make_pair(-1, false));
}

TEST(ScanlineCrossingXSign, BoundsOfTheEndPointsDecideFarCentres) {
  // P = (0, 0), Q = (2, 2) at z = 1 (edges from z = 0 to z = 2); the line y = 1 meets PQ at x = 1.
  const Vec3 p_lo{0, 0, 0}, p_hi{0, 0, 2}, q_lo{2, 2, 0}, q_hi{2, 2, 2};
  EXPECT_EQ(scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, 1, 1, -1), 1);
  EXPECT_EQ(scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, 1, 1, 3), -1);
}

TEST(ScanlineCrossingXSign, CentreOnEitherSideOrOnTheCrossing) {
  const Vec3 p_lo{0, 0, 0}, p_hi{0, 0, 2}, q_lo{2, 2, 0}, q_hi{2, 2, 2};
  EXPECT_EQ(scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, 1, 1, 0.5), 1);
  EXPECT_EQ(scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, 1, 1, 1.5), -1);
  EXPECT_EQ(sign_and_fallback(
                [&] { return scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, 1, 1, 1.0); }),
            std::make_pair(0, true));
}

/// An edge crossing the plane z, its coordinates of magnitude around `scale`.
RandomCrossing random_crossing_at(std::mt19937_64& rng, double scale, double z) {
  std::uniform_real_distribution<double> coordinate(-scale, scale);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  RandomCrossing c;
  c.z = z;
  do {
    c.lo = {coordinate(rng), coordinate(rng), z - fraction(rng) * scale};
    c.hi = {coordinate(rng), coordinate(rng), z + fraction(rng) * scale};
  } while (!(c.lo.z < z && z <= c.hi.z));
  return c;
}

TEST(ScanlineCrossingXSign, FromTheRoundedPointsAgreesWithTheExactSignUlpsAround) {
  // Segments PQ between two edges' crossings, a scanline between P and Q, and centres up to a
  // hundred ulps of the coordinates' scale either side of where it meets PQ: the rounded end
  // points decide only what their errors leave certain, the exact sign the rest.
  std::mt19937_64 rng(20261130);
  std::uint64_t decided_near = 0;
  std::uint64_t wrong_side_in_doubles = 0;
  for (const double scale : kScales) {
    for (int n = 0; n < 250; ++n) {
      RandomCrossing p = random_crossing(rng, scale);
      RandomCrossing q = random_crossing_at(rng, scale, p.z);
      mpq_class py = test::crossing_as_written(p.lo, p.hi, p.z, 1);
      mpq_class qy = test::crossing_as_written(q.lo, q.hi, q.z, 1);
      if (py > qy) {
        std::swap(p, q);
        std::swap(py, qy);
      }
      const double yr = mpq_class((py + qy) / 2).get_d();
      if (!(py < yr && yr <= qy)) continue;  // P strictly below the scanline, Q on or above
      const mpq_class px = test::crossing_as_written(p.lo, p.hi, p.z, 0);
      const mpq_class qx = test::crossing_as_written(q.lo, q.hi, q.z, 0);
      const mpq_class x = px + (yr - py) * (qx - px) / (qy - py);
      const Point2 below = crossing_point(p.lo, p.hi, p.z);
      const Point2 above = crossing_point(q.lo, q.hi, q.z);
      const RoundedScanlineCrossing rounded(p.lo, p.hi, below, q.lo, q.hi, above, yr);
      // Where the rows' code would guess the crossing from the rounded points.
      const double guess = below.x + (yr - below.y) * (above.x - below.x) / (above.y - below.y);
      // Steps of two ulps of the coordinates' scale, where the rounded points' errors lie.
      const double step = 2.0 * std::ldexp(1.0, std::ilogb(scale) - 52);
      for (int k = -48; k <= 48; ++k) {
        const double xc = x.get_d() + k * step;
        const int expected = sgn(x - xc);
        ASSERT_EQ(scanline_crossing_x_sign(p.lo, p.hi, q.lo, q.hi, p.z, yr, xc, rounded), expected)
            << "scale " << scale << " steps " << k;
        if (rounded.x_sign(xc) != 2) ++decided_near;
        if (expected != (guess > xc) - (guess < xc)) ++wrong_side_in_doubles;
      }
    }
  }
  // The rounded points decided centres a few dozen ulps from the crossing, where the doubles
  // alone put many others on the wrong side: the cases the errors are carried for. The test
  // fails with the end points' errors taken as zero, or as 1/128 of crossing_point_error().
  EXPECT_GT(decided_near, 10000U);
  EXPECT_GT(wrong_side_in_doubles, 1000U);
}

TEST(ScanlineCrossingXSign, FromTheRoundedPointsFarCentresNeedNoExactArithmetic) {
  // P = (0, 0), Q = (2, 2) at z = 1; the line y = 1 meets PQ at x = 1.
  const Vec3 p_lo{0, 0, 0}, p_hi{0, 0, 2}, q_lo{2, 2, 0}, q_hi{2, 2, 2};
  const RoundedScanlineCrossing rounded(p_lo, p_hi, crossing_point(p_lo, p_hi, 1), q_lo, q_hi,
                                        crossing_point(q_lo, q_hi, 1), 1);
  const auto sign_at = [&](double xc) {
    return sign_and_fallback(
        [&] { return scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, 1, 1, xc, rounded); });
  };
  EXPECT_EQ(sign_at(0.5), std::make_pair(1, false));
  EXPECT_EQ(sign_at(1.5), std::make_pair(-1, false));
  // On the crossing: the rounding could hide either side, so the exact predicate says tie.
  EXPECT_EQ(sign_at(1.0), std::make_pair(0, true));
}

TEST(ScanlineCrossingXSign, FromAnOverflowingRoundedPointTheExactPredicateDecides) {
  // P's edge: hi.x - lo.x overflows, so P rounds to x = +inf (P = (0.35e308, 0) at z = 0.5); Q =
  // (0, 2). The scanline y = 1 meets PQ at x = 0.175e308.
  const Vec3 p_lo{-1e308, 0, 0}, p_hi{1.7e308, 0, 1}, q_lo{0, 2, 0}, q_hi{0, 2, 1};
  const Point2 below = crossing_point(p_lo, p_hi, 0.5);
  ASSERT_EQ(below.x, INFINITY);
  const RoundedScanlineCrossing rounded(p_lo, p_hi, below, q_lo, q_hi,
                                        crossing_point(q_lo, q_hi, 0.5), 1);
  EXPECT_EQ(rounded.x_sign(1e307), 2);
  EXPECT_EQ(scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, 0.5, 1, 1e307, rounded), 1);
  EXPECT_EQ(scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, 0.5, 1, 1e308, rounded), -1);
}

TEST(NormalXSign, SignOfTheNormalsXComponent) {
  // (b - a) x (c - a) for a facet in the plane x = 0 is along x.
  EXPECT_EQ(normal_x_sign({0, 0, 0}, {0, 1, 0}, {0, 0, 1}), 1);
  EXPECT_EQ(normal_x_sign({0, 0, 0}, {0, 0, 1}, {0, 1, 0}), -1);
  // A facet in a vertical plane containing x has no x component.
  EXPECT_EQ(normal_x_sign({0, 0, 0}, {1, 0, 0}, {0, 0, 1}), 0);
}

TEST(CertainSign, UndecidableBoundsReportTwo) {
  EXPECT_EQ(certain_sign(ErrorBoundedDouble{0.0, 0.0}), 0);
  EXPECT_EQ(certain_sign(ErrorBoundedDouble{1.0, 0.5}), 1);
  EXPECT_EQ(certain_sign(ErrorBoundedDouble{-1.0, 0.5}), -1);
  EXPECT_EQ(certain_sign(ErrorBoundedDouble{1.0, 1.0}), 2);
  EXPECT_EQ(certain_sign(ErrorBoundedDouble{0.0, 1e-300}), 2);
}

}  // namespace
}  // namespace strata::detail
