// count_prefix: the exact prefix length of a monotone predicate whatever the first guess.
#include "predicates/grid_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace strata::detail {
namespace {

struct CountingBelow {
  std::uint32_t boundary;
  mutable int calls = 0;
  bool operator()(std::uint32_t k) const {
    ++calls;
    return k < boundary;
  }
};

TEST(CountPrefix, AnyGuessGivesTheExactCount) {
  const double guesses[] = {std::numeric_limits<double>::quiet_NaN(),
                            -std::numeric_limits<double>::infinity(),
                            -5.0,
                            0.0,
                            0.5,
                            36.9,
                            37.0,
                            37.5,
                            99.99,
                            100.0,
                            1e300,
                            std::numeric_limits<double>::infinity()};
  for (const std::uint32_t boundary : {0u, 1u, 37u, 99u, 100u}) {
    for (const double guess : guesses) {
      EXPECT_EQ(count_prefix(guess, 100, CountingBelow{boundary}), boundary)
          << "boundary " << boundary << ", guess " << guess;
    }
  }
}

TEST(CountPrefix, AOneElementRangeCountsZeroOrOneAndEvaluatesOnlyItsElement) {
  for (const std::uint32_t boundary : {0u, 1u}) {
    for (const double guess : {-1.0, 0.0, 0.5, 1.0, 7.0}) {
      const auto below = [&](std::uint32_t k) {
        EXPECT_EQ(k, 0u);
        return k < boundary;
      };
      EXPECT_EQ(count_prefix(guess, 1, below), boundary) << "guess " << guess;
    }
  }
}

TEST(CountPrefix, ARightGuessCostsTwoEvaluations) {
  CountingBelow below{37};
  EXPECT_EQ(count_prefix(37.2, 100, below), 37u);
  EXPECT_EQ(below.calls, 2);
}

TEST(CountPrefix, AFarGuessCostsLogarithmicallyManyEvaluations) {
  // A guess off by a million steps gallops and bisects: about 2 log2(10^6) = 40 evaluations.
  const std::uint32_t n = 2000000;
  CountingBelow low{1000};
  EXPECT_EQ(count_prefix(1001000.0, n, low), 1000u);
  EXPECT_LE(low.calls, 45);
  CountingBelow high{1001000};
  EXPECT_EQ(count_prefix(1000.0, n, high), 1001000u);
  EXPECT_LE(high.calls, 45);
}

TEST(ClampGuess, NaNAndNegativesGiveZeroAndGuessesPastTheEndGiveN) {
  EXPECT_EQ(clamp_guess(std::numeric_limits<double>::quiet_NaN(), 10), 0u);
  EXPECT_EQ(clamp_guess(-0.5, 10), 0u);
  EXPECT_EQ(clamp_guess(0.0, 10), 0u);
  EXPECT_EQ(clamp_guess(0.999, 10), 0u);
  EXPECT_EQ(clamp_guess(9.999, 10), 9u);
  EXPECT_EQ(clamp_guess(10.0, 10), 10u);
  EXPECT_EQ(clamp_guess(std::numeric_limits<double>::infinity(), 10), 10u);
  EXPECT_EQ(clamp_guess(5.0, 0), 0u);
}

TEST(SearchPrefix, FindsTheAnswerOnEitherSideOfEveryWrongGuess) {
  // Every wrong guess k0 of every answer in every small range, both directions: the gallop's
  // clamping at 0 and at n and the bisection's both outcomes.
  for (std::uint32_t n = 1; n <= 40; ++n) {
    for (std::uint32_t boundary = 0; boundary <= n; ++boundary) {
      for (std::uint32_t k0 = 0; k0 <= n; ++k0) {
        if (k0 == boundary) continue;
        const CountingBelow below{boundary};
        EXPECT_EQ(search_prefix(k0, n, boundary > k0, IndexPredicate(below)), boundary)
            << "n " << n << ", boundary " << boundary << ", guess " << k0;
      }
    }
  }
}

TEST(SearchPrefix, EvaluatesOnlyIndicesInsideTheRange) {
  const std::uint32_t n = 17;
  for (std::uint32_t boundary = 0; boundary <= n; ++boundary) {
    for (std::uint32_t k0 = 0; k0 <= n; ++k0) {
      if (k0 == boundary) continue;
      const auto below = [&](std::uint32_t k) {
        EXPECT_LT(k, n);
        return k < boundary;
      };
      EXPECT_EQ(search_prefix(k0, n, boundary > k0, IndexPredicate(below)), boundary);
    }
  }
}

}  // namespace
}  // namespace strata::detail
