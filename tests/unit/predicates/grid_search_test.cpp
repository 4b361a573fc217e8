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

TEST(CountPrefix, EmptyRangeCountsZero) { EXPECT_EQ(count_prefix(3.0, 0, CountingBelow{0}), 0u); }

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

}  // namespace
}  // namespace strata::detail
