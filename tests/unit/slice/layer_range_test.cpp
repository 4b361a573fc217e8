#include "strata/slice/layer_range.hpp"

#include <gtest/gtest.h>

namespace strata {
namespace {

TEST(ParseLayerRange, ReadsTheThreeForms) {
  const auto half_open = parse_layer_range("3:7");
  ASSERT_TRUE(half_open);
  EXPECT_EQ(half_open->first, 3u);
  EXPECT_EQ(half_open->end, 7u);
  const auto to_last = parse_layer_range("12:");
  ASSERT_TRUE(to_last);
  EXPECT_EQ(to_last->first, 12u);
  EXPECT_FALSE(to_last->end.has_value());
  const auto single = parse_layer_range("5");
  ASSERT_TRUE(single);
  EXPECT_EQ(single->first, 5u);
  EXPECT_EQ(single->end, 6u);
}

TEST(ParseLayerRange, RefusesOtherTextAndEmptyRanges) {
  for (const char* text : {"", ":", ":4", "a:b", "3:x", "-1:4", "3-7", "3:7:9", " 3:7", "1.5",
                           "4294967295", "99999999999:"}) {
    const auto range = parse_layer_range(text);
    ASSERT_FALSE(range) << text;
    EXPECT_EQ(range.error().code, ErrorCode::Usage) << text;
  }
  const auto empty = parse_layer_range("7:7");
  ASSERT_FALSE(empty);
  EXPECT_NE(empty.error().message.find("empty"), std::string::npos);
  EXPECT_FALSE(parse_layer_range("8:7"));
}

TEST(ResolveLayerRange, FitsTheRangeToTheGrid) {
  EXPECT_EQ(resolve_layer_range({}, 10).value(), (LayerSpan{0, 10}));
  EXPECT_EQ(resolve_layer_range({4, std::nullopt}, 10).value(), (LayerSpan{4, 10}));
  EXPECT_EQ(resolve_layer_range({9, 10}, 10).value(), (LayerSpan{9, 10}));
  EXPECT_EQ(resolve_layer_range({2, 5}, 10)->count(), 3u);
}

TEST(ResolveLayerRange, RefusesRangesBeyondTheGrid) {
  for (const LayerRange range :
       {LayerRange{10, std::nullopt}, LayerRange{8, 11}, LayerRange{5, 5}}) {
    const auto span = resolve_layer_range(range, 10);
    ASSERT_FALSE(span);
    EXPECT_EQ(span.error().code, ErrorCode::Usage);
  }
  EXPECT_NE(resolve_layer_range({8, 11}, 10).error().message.find("10 layers"), std::string::npos);
}

}  // namespace
}  // namespace strata
