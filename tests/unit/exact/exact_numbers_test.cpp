// The one rounding of the exact path: to the nearest double, ties to even, below the normal range
// too; and the comparisons that fall back to the exact value when the doubles tie.

// The library is compiled with CGAL's configuration, CGAL_USE_GMPXX, under which the exact
// module's Rational is GMP's mpq_class; this file passes the module's own types across, so it
// must see the same type.
#ifndef CGAL_USE_GMPXX
#define CGAL_USE_GMPXX 1
#endif

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

#include "exact/exact_numbers_internal.hpp"
#include "support/exact_crossing.hpp"
#include "support/nearest_double.hpp"

namespace strata::exact::detail {
namespace {

static_assert(std::is_same_v<Rational, mpq_class>, "the library's exact number type");

constexpr double kMinSubnormal = std::numeric_limits<double>::denorm_min();  // 2^-1074

/// n * 2^-e, exactly.
mpq_class scaled(long n, unsigned long e) {
  mpq_class q(n);
  mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), e);
  return q;
}

double rounded(const mpq_class& q) { return round_to_double(q.get_mpq_t()); }

TEST(RoundToDouble, GivesZeroForZero) { EXPECT_EQ(rounded(mpq_class(0)), 0.0); }

TEST(RoundToDouble, RoundsOneThirdToNearest) {
  EXPECT_EQ(rounded(mpq_class(1, 3)), 1.0 / 3.0);
  EXPECT_EQ(rounded(mpq_class(-2, 3)), -2.0 / 3.0);
}

TEST(RoundToDouble, KeepsASubnormalThatIsADouble) {
  EXPECT_EQ(rounded(scaled(1, 1074)), kMinSubnormal);
  EXPECT_EQ(rounded(scaled(-5, 1074)), -5 * kMinSubnormal);
}

TEST(RoundToDouble, RoundsBelowTheNormalRangeToTheNearestSubnormal) {
  // 1.25 and 1.75 times the smallest subnormal: down to 1, up to 2 of them.
  EXPECT_EQ(rounded(scaled(5, 1076)), kMinSubnormal);
  EXPECT_EQ(rounded(scaled(7, 1076)), 2 * kMinSubnormal);
  EXPECT_EQ(rounded(scaled(-5, 1076)), -kMinSubnormal);
  EXPECT_EQ(rounded(scaled(-7, 1076)), -2 * kMinSubnormal);
}

TEST(RoundToDouble, BreaksTiesBelowTheNormalRangeToEven) {
  // 1.5 of the smallest subnormal lies between 1 (odd) and 2 (even) of them; 2.5 between 2 and 3.
  EXPECT_EQ(rounded(scaled(3, 1075)), 2 * kMinSubnormal);
  EXPECT_EQ(rounded(scaled(5, 1075)), 2 * kMinSubnormal);
  EXPECT_EQ(rounded(scaled(-3, 1075)), -2 * kMinSubnormal);
  // Half the smallest subnormal ties between 0 (even) and it.
  EXPECT_EQ(rounded(scaled(1, 1075)), 0.0);
}

TEST(RoundToDouble, RoundsJustAboveTheNormalRangesLowerEndOnce) {
  const double smallest_normal = std::numeric_limits<double>::min();  // 2^-1022
  EXPECT_EQ(rounded(scaled(1, 1022)), smallest_normal);
  // 2^-1022 (1 + 2^-53): a tie between 2^-1022 (even) and its successor.
  mpq_class tie = scaled(1, 1022) + scaled(1, 1075);
  EXPECT_EQ(rounded(tie), smallest_normal);
}

/// A random integer of 1 to `max_bits` bits, of either sign.
mpz_class random_integer(std::mt19937_64& random, int max_bits) {
  const int bits = std::uniform_int_distribution<int>(1, max_bits)(random);
  mpz_class n = 1;
  for (int b = 1; b < bits; ++b) n = 2 * n + static_cast<int>(random() & 1);
  return (random() & 1) != 0 ? mpz_class(-n) : n;
}

TEST(RoundToDouble, RoundsBeyondTheLargestDoubleToInfinity) {
  const double largest = std::numeric_limits<double>::max();  // (2^53 - 1) 2^971
  mpq_class two_to_1024(1);
  mpq_mul_2exp(two_to_1024.get_mpq_t(), two_to_1024.get_mpq_t(), 1024);
  EXPECT_EQ(rounded(two_to_1024), HUGE_VAL);
  EXPECT_EQ(rounded(-two_to_1024), -HUGE_VAL);
  // Halfway between the largest double and 2^1024 rounds to even, up; a hair less, down.
  mpq_class half_ulp(1);
  mpq_mul_2exp(half_ulp.get_mpq_t(), half_ulp.get_mpq_t(), 970);
  EXPECT_EQ(rounded(mpq_class(largest) + half_ulp), HUGE_VAL);
  EXPECT_EQ(rounded(mpq_class(largest) + half_ulp - 1), largest);
  EXPECT_EQ(rounded(-(mpq_class(largest) + half_ulp - 1)), -largest);
}

TEST(RoundToDouble, AgreesWithMpfrOnRandomQuotients) {
  std::mt19937_64 random(20261127);
  for (int i = 0; i < 20000; ++i) {
    const mpz_class num = random_integer(random, 1 + i % 200);
    mpz_class den = abs(random_integer(random, 1 + (i / 7) % 150));
    mpq_class q(num, den);
    q.canonicalize();
    ASSERT_EQ(rounded(q), test::nearest_double(q)) << q.get_str();
  }
}

TEST(RoundToDouble, BreaksExactTiesToEvenAndRoundsNearTiesAway) {
  std::mt19937_64 random(7);
  for (int i = 0; i < 5000; ++i) {
    // A 53-bit mantissa m and the midpoint (m + 1/2) 2^k between it and its successor.
    const std::uint64_t m = (std::uint64_t{1} << 52) | (random() >> 12);
    const int k = static_cast<int>(random() % 200) - 100;
    mpq_class tie = mpq_class(mpz_class(std::to_string(2 * m + 1)), 2);
    if (k >= 0) mpq_mul_2exp(tie.get_mpq_t(), tie.get_mpq_t(), static_cast<mp_bitcnt_t>(k));
    if (k < 0) mpq_div_2exp(tie.get_mpq_t(), tie.get_mpq_t(), static_cast<mp_bitcnt_t>(-k));
    const double down = std::ldexp(static_cast<double>(m), k);
    const double up = std::ldexp(static_cast<double>(m + 1), k);
    ASSERT_EQ(rounded(tie), (m & 1) == 0 ? down : up);
    ASSERT_EQ(rounded(-tie), (m & 1) == 0 ? -down : -up);
    // A hair either side of the tie: one part in 2^300 of it.
    mpq_class hair = tie;
    mpq_div_2exp(hair.get_mpq_t(), hair.get_mpq_t(), 300);
    ASSERT_EQ(rounded(tie + hair), up);
    ASSERT_EQ(rounded(tie - hair), down);
    ASSERT_EQ(rounded(tie + hair / 3), up);
    ASSERT_EQ(rounded(tie - hair / 3), down);
  }
}

TEST(SetScaled, GivesTheDoubleOverTheCommonPowerOfTwoExactly) {
  const double values[] = {1.0,
                           -1.0,
                           0.1,
                           -3.75e-9,
                           123456.789,
                           1e300,
                           -0.0,
                           0.0,
                           kMinSubnormal,
                           -7 * kMinSubnormal,
                           std::numeric_limits<double>::min()};
  int e = std::numeric_limits<int>::max();
  for (const double v : values) lower_to_last_bit(e, v);
  for (const double v : values) {
    mpz_class scaled_value;
    set_scaled(scaled_value, v, e);
    // scaled_value 2^e == v, with 2^e below every value's last bit.
    mpq_class back(scaled_value);
    mpq_div_2exp(back.get_mpq_t(), back.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    EXPECT_EQ(back, mpq_class(v)) << v;
  }
}

TEST(CompareWithDouble, DecidesByTheExactValueWhenTheRoundedOneTies) {
  const RoundedRational above(Rational(1) + Rational(scaled(1, 60)));
  const RoundedRational below(Rational(1) - Rational(scaled(1, 60)));
  ASSERT_EQ(above.rounded, 1.0);
  ASSERT_EQ(below.rounded, 1.0);
  EXPECT_EQ(compare_with_double(above, 1.0), 1);
  EXPECT_EQ(compare_with_double(below, 1.0), -1);
  EXPECT_EQ(compare_with_double(RoundedRational(Rational(1)), 1.0), 0);
  EXPECT_EQ(compare_with_double(above, 2.0), -1);
  EXPECT_EQ(compare_with_double(above, 0.5), 1);
}

TEST(CompareXy, ComparesXThenYExactly) {
  const auto point = [](const mpq_class& x, const mpq_class& y) {
    return ExactPoint2{RoundedRational(Rational(x)), RoundedRational(Rational(y))};
  };
  const mpq_class one(1);
  const mpq_class one_up = one + scaled(1, 60);  // rounds to 1, like `one`
  EXPECT_EQ(compare_xy(point(one, 0), point(2, 0)), -1);
  EXPECT_EQ(compare_xy(point(2, 0), point(one, 5)), 1);
  EXPECT_EQ(compare_xy(point(one, 0), point(one_up, 0)), -1);
  EXPECT_EQ(compare_xy(point(one_up, 0), point(one, 0)), 1);
  EXPECT_EQ(compare_xy(point(one, one), point(one, one_up)), -1);
  EXPECT_EQ(compare_xy(point(one, one_up), point(one, one)), 1);
  EXPECT_EQ(compare_xy(point(one, 3), point(one, 3)), 0);
}

TEST(Compare, DecidesTiesOfTheRoundedValuesExactly) {
  const RoundedRational one = RoundedRational::of_double(1.0);
  const RoundedRational one_up(Rational(1) + Rational(scaled(1, 60)));
  const RoundedRational one_down(Rational(1) - Rational(scaled(1, 60)));
  ASSERT_EQ(one_up.rounded, 1.0);
  ASSERT_EQ(one_down.rounded, 1.0);
  EXPECT_EQ(compare(one, one_up), -1);
  EXPECT_EQ(compare(one_up, one), 1);
  EXPECT_EQ(compare(one_down, one), -1);
  EXPECT_EQ(compare(one_down, one_up), -1);
  EXPECT_EQ(compare(one, RoundedRational(Rational(1))), 0);
  EXPECT_EQ(compare(one, RoundedRational::of_double(1.0)), 0);
  EXPECT_EQ(compare(RoundedRational::of_double(0.5), one_down), -1);
}

TEST(RoundedRational, KnowsWhenACrossingIsADouble) {
  // The upper end on the plane, or an edge that keeps its x: the crossing is that coordinate,
  // known to be a double without a rational.
  const Vec3 lo{0.1, 0.2, 0.0};
  const Vec3 on_plane{0.7, -0.3, 0.3};
  const Vec3 upright{0.1, 0.9, 0.9};
  const RoundedRational at_end = RoundedRational::crossing(lo, on_plane, 0.3, 0);
  EXPECT_TRUE(at_end.is_double());
  EXPECT_EQ(at_end.rounded, 0.7);
  EXPECT_EQ(at_end.exact(), Rational(0.7));
  const RoundedRational kept = RoundedRational::crossing(lo, upright, 0.3, 0);
  EXPECT_TRUE(kept.is_double());
  EXPECT_EQ(kept.exact(), Rational(0.1));
  // Its y changes along the edge: a rational, not a double.
  const RoundedRational moving = RoundedRational::crossing(lo, upright, 0.3, 1);
  EXPECT_FALSE(moving.is_double());
  EXPECT_EQ(moving.exact(), test::crossing_as_written(lo, upright, 0.3, 1));
  EXPECT_TRUE(RoundedRational::of_double(2.5).is_double());
  EXPECT_FALSE(RoundedRational(Rational(1, 3)).is_double());
  // Copies keep what they know; a value assigned over one takes the new value's.
  const RoundedRational copy = at_end;
  EXPECT_TRUE(copy.is_double());
  RoundedRational assigned = at_end;
  assigned = moving;
  EXPECT_FALSE(assigned.is_double());
  EXPECT_EQ(assigned.exact(), moving.exact());

  // Equal as doubles and both doubles: equal. A crossing that only rounds to a double is
  // decided by its rational.
  EXPECT_EQ(compare(at_end, RoundedRational::of_double(0.7)), 0);
  EXPECT_EQ(compare_with_double(kept, 0.1), 0);
  const Vec3 a{1.0, 0.0, 0.0};
  const Vec3 b{std::nextafter(1.0, 2.0), 0.0, 1.0};
  const RoundedRational near_one = RoundedRational::crossing(a, b, 0.25, 0);
  ASSERT_FALSE(near_one.is_double());
  ASSERT_EQ(near_one.rounded, 1.0);
  EXPECT_EQ(compare(near_one, RoundedRational::of_double(1.0)), 1);
  EXPECT_EQ(compare(RoundedRational::of_double(1.0), near_one), -1);
  EXPECT_EQ(compare_with_double(near_one, 1.0), 1);
}

/// Checks both axes of the crossing: its double is the rational's nearest (ties to even, below
/// the normal range too), and its exact value is the rational.
void expect_crossing(const Vec3& lo, const Vec3& hi, double z) {
  for (const int axis : {0, 1}) {
    const mpq_class expected = test::crossing_as_written(lo, hi, z, axis);
    const RoundedRational value = RoundedRational::crossing(lo, hi, z, axis);
    ASSERT_EQ(value.rounded, rounded(expected)) << expected.get_str() << " axis " << axis;
    if (value.rounded == 0.0) {
      ASSERT_FALSE(std::signbit(value.rounded)) << "zero is +0, as the rational holds it";
    }
    ASSERT_EQ(value.exact(), expected) << "axis " << axis;
  }
}

double random_float(std::mt19937_64& random, double scale) {
  return static_cast<float>(std::uniform_real_distribution<double>(-scale, scale)(random));
}

TEST(RoundedCrossing, IsTheNearestDoubleOfAFloatEdgeAndADoublePlane) {
  // A mesh's floats and a plane z0 + k dz: the machine-integer case, with coordinates near zero
  // beside large ones, and whole coordinates.
  std::mt19937_64 random(20261128);
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(random() % 24) - 8);
    Vec3 lo{random_float(random, scale), random_float(random, scale), random_float(random, scale)};
    Vec3 hi{random_float(random, scale), random_float(random, scale), random_float(random, scale)};
    if (i % 5 == 0) lo.x = static_cast<float>(lo.x * 1e-6);
    if (i % 7 == 0) hi.y = std::round(hi.y);
    if (lo.z == hi.z) continue;
    if (lo.z > hi.z) std::swap(lo, hi);
    const double z0 = -scale;
    const double dz = scale / 997.0;
    const double k = std::ceil((lo.z - z0) / dz);
    const double z = z0 + k * dz;
    if (!(z > lo.z && z <= hi.z)) continue;
    expect_crossing(lo, hi, z);
  }
}

TEST(RoundedCrossing, BreaksTiesToEvenAndRoundsNearTiesEitherWay) {
  // Halfway up an edge between two neighbouring doubles, the crossing is their midpoint; a
  // plane a little lower or higher moves it a hair off the midpoint.
  std::mt19937_64 random(11);
  for (int i = 0; i < 5000; ++i) {
    // Mantissas of 53 bits from 2^-1 to 2^8 (on machine integers beside the planes near 1),
    // and smaller ones (not).
    const int k =
        i % 2 == 0 ? static_cast<int>(random() % 10) - 53 : static_cast<int>(random() % 80) - 140;
    const double a =
        std::ldexp(static_cast<double>((std::uint64_t{1} << 52) | (random() >> 12)), k);
    const double b = std::nextafter(a, HUGE_VAL);
    const Vec3 lo{a, -b, 0.0};
    const Vec3 hi{b, -a, 2.0};
    expect_crossing(lo, hi, 1.0);
    expect_crossing(lo, hi, std::nextafter(1.0, 0.0));
    expect_crossing(lo, hi, std::nextafter(1.0, 2.0));
  }
}

TEST(RoundedCrossing, IsTheNearestDoubleOverAnyRangeOfExponents) {
  // Coordinates of very different sizes (integers too wide for the machine's), and crossings
  // that fall below the normal range, where the rational rounds them.
  std::mt19937_64 random(5);
  const auto any = [&] {
    const double m = std::uniform_real_distribution<double>(-1.0, 1.0)(random);
    return std::ldexp(m, static_cast<int>(random() % 2090) - 1070);  // finite
  };
  for (int i = 0; i < 20000; ++i) {
    Vec3 lo{any(), any(), any()};
    Vec3 hi{any(), any(), any()};
    if (i % 3 == 0) {
      // Both ends below the normal range on one axis.
      lo.x = std::ldexp(lo.x, -60);
      hi.x = std::ldexp(hi.x, -60);
    }
    if (lo.z == hi.z) continue;
    if (lo.z > hi.z) std::swap(lo, hi);
    const double z = i % 2 == 0 ? hi.z : lo.z + (hi.z - lo.z) * 0.375;
    if (!(z > lo.z && z <= hi.z)) continue;
    expect_crossing(lo, hi, z);
  }
  expect_crossing({kMinSubnormal, 0.0, 0.0}, {4 * kMinSubnormal, 1.0, 3.0}, 1.0);
  expect_crossing({-kMinSubnormal, 0.0, -1.0}, {kMinSubnormal, 1e300, 1.0}, 0.0);
}

TEST(RoundedRational, KeepsACrossingsExactValueThroughCopiesAndMoves) {
  const Vec3 lo{0.1, 0.2, 0.0};
  const Vec3 hi{0.7, -0.3, 0.9};
  const mpq_class expected = test::crossing_as_written(lo, hi, 0.3, 0);
  std::vector<RoundedRational> values;
  for (int i = 0; i < 40; ++i) {
    values.push_back(RoundedRational::crossing(lo, hi, 0.3, 0));
    if (i % 2 == 0) {
      EXPECT_EQ(values.back().exact(), expected);  // computed before the moves
    }
  }
  RoundedRational assigned = RoundedRational::of_double(5.0);
  ASSERT_EQ(assigned.exact(), 5);
  assigned = values[1];
  RoundedRational moved_into = RoundedRational::of_double(-0.0);
  moved_into = std::move(values[2]);
  for (const RoundedRational& v : values) {
    if (&v == &values[2]) continue;
    EXPECT_EQ(v.exact(), expected);
    EXPECT_EQ(v.rounded, rounded(expected));
  }
  EXPECT_EQ(assigned.exact(), expected);
  EXPECT_EQ(moved_into.exact(), expected);
  EXPECT_EQ(RoundedRational::of_double(-0.0).exact(), 0);
  EXPECT_FALSE(std::signbit(RoundedRational::of_double(-0.0).rounded));
  EXPECT_EQ(RoundedRational().exact(), 0);
}

}  // namespace
}  // namespace strata::exact::detail
