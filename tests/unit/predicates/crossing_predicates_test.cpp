// The exact signs of SPEC §2's inside rule: decided without arithmetic when the end points
// settle it, by the double filter when it can, by GMP on ties and near-ties.
#include "predicates/crossing_predicates.hpp"

#include <gtest/gtest.h>

#include <cstdint>

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
