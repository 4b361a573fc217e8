// The double filter of the exact predicates: what it can prove, and the GMP fallback for what it
// cannot.
#include "predicates/filtered_sign.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace strata::detail {
namespace {

TEST(CertainSign, AnExactValueBelowTheUnderflowSlackIsNotProven) {
  // 1e-302 is below 2^-1000: an exact value so small could be the rounding of a subnormal
  // product, so the filter declines even with no recorded error.
  ASSERT_LT(1e-302, kUnderflowSlack);
  EXPECT_EQ(certain_sign(ErrorBoundedDouble{1e-302, 0.0}), 2);
  EXPECT_EQ(certain_sign(ErrorBoundedDouble{-1e-302, 0.0}), 2);
  EXPECT_EQ(certain_sign(ErrorBoundedDouble{1e-290, 0.0}), 1);
}

TEST(FilteredSign, ATinyValueIsDecidedExactlyByTheFallback) {
  const std::uint64_t before = exact_fallback_counter();
  // 1e-151 squared is 1e-302 in double: the filter cannot decide it, GMP finds it positive.
  const int sign = filtered_sign([](auto tag) {
    using N = decltype(tag);
    N r = N(1e-151) * N(1e-151);
    return r;
  });
  EXPECT_EQ(sign, 1);
  EXPECT_EQ(exact_fallback_counter(), before + 1);
}

TEST(FilteredSign, AClearSignNeedsNoFallback) {
  const std::uint64_t before = exact_fallback_counter();
  const int sign = filtered_sign([](auto tag) {
    using N = decltype(tag);
    N r = N(2.0) * N(3.0) - N(7.0);
    return r;
  });
  EXPECT_EQ(sign, -1);
  EXPECT_EQ(exact_fallback_counter(), before);
}

}  // namespace
}  // namespace strata::detail
