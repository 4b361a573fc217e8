// The writers' numbers: the shortest text that reads back to the same double, exactly as
// fmt::format("{}") writes it (SPEC's number grammar), however the text is produced.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "export/sink_support_internal.hpp"

namespace strata::io::detail {
namespace {

std::string appended(double v) {
  std::string out = "x";  // appends, never replaces
  append_number(out, v);
  return out.substr(1);
}

TEST(AppendNumber, WritesWhatFmtWritesForTheEdgesOfEveryForm) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> edges = {0.0,
                                     -0.0,
                                     1.0,
                                     -1.5,
                                     0.1,
                                     1e-4,
                                     1e-5,
                                     9.999999999999999e15,
                                     1e16,
                                     123456789012345680.0,
                                     std::numeric_limits<double>::min(),
                                     std::numeric_limits<double>::denorm_min(),
                                     -std::numeric_limits<double>::max(),
                                     -2.2250738585072014e-308,
                                     inf,
                                     -inf,
                                     std::numeric_limits<double>::quiet_NaN()};
  for (const double v : edges) EXPECT_EQ(appended(v), fmt::format("{}", v)) << v;
  EXPECT_EQ(appended(1e16), "1e+16");
  EXPECT_EQ(appended(1e-5), "1e-05");
  EXPECT_EQ(appended(-0.0), "-0");
  EXPECT_EQ(appended(-2.2250738585072014e-308), "-2.2250738585072014e-308");
}

TEST(AppendNumber, WritesWhatFmtWritesForRandomDoublesOfEveryMagnitude) {
  std::mt19937_64 random(20261125);
  std::uniform_real_distribution<double> millimetres(-500.0, 500.0);
  for (int i = 0; i < 200000; ++i) {
    const auto bits = random();
    const double any = std::bit_cast<double>(bits);  // every exponent, NaNs and infinities too
    const double coordinate = millimetres(random);
    const double rounded = static_cast<double>(static_cast<std::int64_t>(coordinate * 1000)) / 1000;
    for (const double v : {any, coordinate, rounded}) {
      ASSERT_EQ(appended(v), fmt::format("{}", v)) << std::bit_cast<std::uint64_t>(v);
    }
  }
}

TEST(AppendNumber, WritesWhatFmtWritesAroundEveryPowerOfTenAndItsLayouts) {
  // Where the layout changes: every power of ten and its neighbours either side (the switch
  // between fixed and exponent notation, the number of exponent digits, zeros before and after
  // the digits), times short and long significands, both signs.
  for (int e = -324; e <= 308; ++e) {
    const double p = std::pow(10.0, e);
    for (const double m : {1.0, 1.5, 9.999999999999998, 1.2345678901234567, 3.0}) {
      const double v = p * m;
      for (const double w : {v, std::nextafter(v, 0.0), std::nextafter(v, HUGE_VAL)}) {
        for (const double x : {w, -w}) ASSERT_EQ(appended(x), fmt::format("{}", x)) << x;
      }
    }
  }
  for (std::uint64_t n = 1; n < 2'000'000; n = n * 3 + 1) {
    const auto v = static_cast<double>(n);
    ASSERT_EQ(appended(v), fmt::format("{}", v));
    ASSERT_EQ(appended(v / 1024), fmt::format("{}", v / 1024));
  }
}

TEST(AppendNumber, WritesEveryDigitInEveryPlaceOfTheSignificand) {
  // The digits are made eight at a time: every digit 0-9 in each of the 16 places of an
  // integer significand (leading, inner and trailing zeros), and every integer of up to five
  // digits; as integers and, divided by powers of ten, with the point between the digits.
  std::vector<double> values;
  for (std::int64_t n = 0; n < 100000; ++n) values.push_back(static_cast<double>(n));
  std::int64_t place = 1;
  for (int p = 0; p < 16; ++p, place *= 10) {
    for (const std::int64_t base : {std::int64_t{1234567890123456}, std::int64_t{9999999999999999},
                                    std::int64_t{1000000000000000}, std::int64_t{0}}) {
      for (std::int64_t d = 0; d <= 9; ++d) {
        const std::int64_t n = base - (base / place % 10) * place + d * place;
        if (n > 0) values.push_back(static_cast<double>(n));
      }
    }
  }
  for (const double v : values) {
    for (const double x : {v, v / 1e3, v / 1e9, v * 1e-20}) {
      ASSERT_EQ(appended(x), fmt::format("{}", x)) << x;
    }
  }
}

TEST(AppendText, WritesItsNumbersAsAppendNumberDoesAndItsCharactersBetween) {
  // The longest texts first (their digits are copied in fixed-size pieces past their ends, which
  // must stay in the text's room), then random pairs of every magnitude; a repeated number too.
  const std::vector<double> longest = {-2.2250738585072014e-308, -1.2345678901234567e-100,
                                       -0.00012345678901234567,  -1234567890123456.8,
                                       -9007199254740991.0,      5e-324};
  std::mt19937_64 random(20261127);
  std::vector<std::pair<double, double>> pairs;
  for (const double a : longest) {
    for (const double b : longest) pairs.emplace_back(a, b);
  }
  for (int i = 0; i < 20000; ++i) {
    pairs.emplace_back(std::bit_cast<double>(random()), std::bit_cast<double>(random()));
  }
  RepeatedNumber repeated;
  for (const auto& [a, b] : pairs) {
    std::string out = "x";  // appends, never replaces
    append_text(out, a, ' ', b, ',', RepeatedValue{repeated, a}, ';');
    std::string expected = "x";
    append_number(expected, a);
    expected += ' ';
    append_number(expected, b);
    expected += ',';
    append_number(expected, a);
    expected += ';';
    ASSERT_EQ(out, expected) << a << " " << b;
  }
}

TEST(RepeatedNumber, WritesWhatAppendNumberWritesWhetherTheNumberRepeatsOrChanges) {
  // Runs of one value, values that compare equal but print differently (0 and -0), a NaN (which
  // equals nothing), and a return to a value seen before.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = {-41.15, -41.15, -41.15, -41.05, 0.0,   -0.0,  -0.0,
                                      0.0,    nan,    nan,    1e-05,  1e-05, -41.15};
  RepeatedNumber repeated;
  std::string written;
  std::string expected;
  for (const double v : values) {
    append_text(written, RepeatedValue{repeated, v}, ',');
    append_number(expected, v);
    expected += ',';
  }
  EXPECT_EQ(written, expected);
  EXPECT_EQ(written, "-41.15,-41.15,-41.15,-41.05,0,-0,-0,0,nan,nan,1e-05,1e-05,-41.15,");
}

TEST(RepeatedNumber, WritesInPlaceWhatAppendNumberWritesTheLongestTextIncluded) {
  // Into a buffer as write_shortest writes: room for the longest text and as much again after
  // each number, the characters past its end not part of the text.
  const std::vector<double> values = {-2.2250738585072014e-308,
                                      -2.2250738585072014e-308,
                                      -41.15,
                                      -41.15,
                                      0.1 + 0.2,
                                      -0.0,
                                      1e300,
                                      1e300};
  RepeatedNumber in_place;
  std::vector<char> buffer(values.size() * kShortestNumberChars + kShortestNumberChars, 'x');
  char* end = buffer.data();
  std::string expected;
  for (const double v : values) {
    end = in_place.write(end, v);
    *end++ = ',';
    append_number(expected, v);
    expected += ',';
  }
  EXPECT_EQ(std::string(buffer.data(), end), expected);
  EXPECT_EQ(expected.substr(0, 26), "-2.2250738585072014e-308,-");
}

}  // namespace
}  // namespace strata::io::detail
