// The OFF reader: its keyword variants, the line ends and comments of its tokens, and every
// refusal with the line and message it gives.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <string_view>

#include "io/read_mesh_internal.hpp"
#include "support/result_checks.hpp"

namespace strata::io {
namespace {

const Vec3 kA{0, 0, 0}, kB{1, 0, 0}, kC{0, 1, 0};

TriangleSoup read_off_ok(std::string_view text, const ReadLimits& limits = {}) {
  return test::value_of(detail::read_off_bytes(text, "m.off", limits), text);
}

void expect_off_error(std::string_view text, std::string_view location, std::string_view message,
                      const ReadLimits& limits = {}) {
  test::expect_bad_input(detail::read_off_bytes(text, "m.off", limits), location, message, text);
}

TEST(ReadOff, EveryKindOfLineEndAndCommentSeparatesTokens) {
  // A comment ended by CR, bare CR, a comment glued to a value, CRLF, a comment ending the file.
  const auto soup =
      read_off_ok("OFF # keyword\r3 1 0\r0 0 0#origin\n1 0 0 # x\r0 1 0\r\n3 0 1 2 # the face");
  ASSERT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.triangles[0], (std::array<Vec3, 3>{kA, kB, kC}));
}

TEST(ReadOff, TheKeywordIsOptional) {
  const auto soup = read_off_ok("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  ASSERT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.triangles[0][1], kB);
}

TEST(ReadOff, NOffReadsTheDimensionFirst) {
  // Four coordinates a vertex, of which x y z are used.
  const auto soup = read_off_ok("nOFF\n4\n3 1 0\n0 0 0 9\n1 0 0 9\n0 1 0 9\n3 0 1 2\n");
  ASSERT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.triangles[0][2], kC);
  // 4nOFF: the dimension, then a weight after the coordinates.
  const auto weighted = read_off_ok("4nOFF 3 3 1 0\n0 0 0 2\n4 0 0 4\n0 2 0 2\n3 0 1 2\n");
  ASSERT_EQ(weighted.triangles.size(), 1u);
  EXPECT_EQ(weighted.triangles[0][1], kB);
  EXPECT_EQ(weighted.triangles[0][2], kC);
}

TEST(ReadOff, NOffDimensionMustBeFromThreeToSixteen) {
  expect_off_error("nOFF\n2\n3 1 0\n", "m.off:2",
                   "nOFF dimension '2' is not an integer from 3 to 16");
  expect_off_error("nOFF\n17\n3 1 0\n", "m.off:2",
                   "nOFF dimension '17' is not an integer from 3 to 16");
  expect_off_error("nOFF", "m.off:1", "file ends where the dimension was expected (truncated?)");
  const auto soup = detail::read_off_bytes("nOFF\nthree\n", "m.off", {});
  ASSERT_FALSE(soup.has_value());
  EXPECT_EQ(soup.error().location, "m.off:2");
  EXPECT_EQ(soup.error().message.rfind("bad number 'three'", 0), 0u) << soup.error().message;
}

TEST(ReadOff, BinaryNOffIsUnsupported) {
  const auto soup = detail::read_off_bytes("nOFF BINARY\n", "m.off", {});
  ASSERT_FALSE(soup.has_value());
  EXPECT_EQ(soup.error().location, "m.off");
  EXPECT_EQ(soup.error().message, "unsupported format: binary OFF");
}

TEST(ReadOff, UnknownKeywordsAreNamedWithControlCharactersShown) {
  expect_off_error("XOFF\n3 1 0\n", "m.off:1", "unknown OFF keyword 'XOFF'");
  expect_off_error("C\x01\x7fOFF 3 1 0\n", "m.off:1", "unknown OFF keyword 'C??OFF'");
}

TEST(ReadOff, AnEmptyFileEndsWhereTheKeywordWasExpected) {
  expect_off_error("", "m.off:1", "file ends where the OFF keyword was expected (truncated?)");
  expect_off_error("# nothing\n\n", "m.off:3",
                   "file ends where the OFF keyword was expected (truncated?)");
  expect_off_error("OFF # counts follow", "m.off:1",
                   "file ends where the vertex count was expected (truncated?)");
}

TEST(ReadOff, TruncatedFilesNameWhatWasExpected) {
  expect_off_error("OFF\n3", "m.off:2", "file ends where the face count was expected (truncated?)");
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0", "m.off:4",
                   "file ends where vertex 1 was expected (truncated?)");
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1", "m.off:6",
                   "file ends where a corner of face 0 was expected (truncated?)");
}

TEST(ReadOff, BadNumbersInFacesNameTheirLine) {
  for (const std::string_view face : {"x 0 1 2", "3 0 y 2"}) {
    const auto soup = detail::read_off_bytes(
        "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n" + std::string(face) + "\n", "m.off", {});
    ASSERT_FALSE(soup.has_value()) << face;
    EXPECT_EQ(soup.error().location, "m.off:6");
    EXPECT_EQ(soup.error().message.rfind("bad number '", 0), 0u) << soup.error().message;
  }
}

TEST(ReadOff, CountsAFileCannotHoldAreRefusedBeforeReading) {
  expect_off_error(
      "OFF\n3 900 0\n", "m.off:2",
      "header declares 3 vertices and 900 faces, more than a file of 12 bytes can hold "
      "(truncated?)");
}

TEST(ReadOff, FacesOverTheLimitAreRefusedFromTheHeader) {
  ReadLimits limits;
  limits.max_triangles = 1;
  expect_off_error("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n", "m.off:2",
                   "header declares 2 faces, more than the limit of 1", limits);
}

TEST(ReadOff, AHomogeneousWeightOfZeroIsAnError) {
  expect_off_error("4OFF\n3 1 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n3 0 1 2\n", "m.off:4",
                   "vertex 1 has the homogeneous weight 0");
}

TEST(ReadOff, ACoordinateOverflowingItsDivisionByTheWeightIsAnError) {
  for (const std::string_view vertex :
       {"1e300 0 0 1e-300", "0 1e300 0 1e-300", "0 0 -1e300 1e-300"}) {
    expect_off_error("4OFF\n3 1 0\n0 0 0 1\n" + std::string(vertex) + "\n0 1 0 1\n3 0 1 2\n",
                     "m.off:4",
                     "vertex 1 divided by its weight 1e-300 is too large for a double; NaN and "
                     "infinity cannot be sliced");
  }
}

TEST(ReadOff, LinesOverTheLimitAreRefused) {
  ReadLimits limits;
  limits.max_line_bytes = 16;
  // A token running past the limit, and a line whose ignored rest (colours) does.
  expect_off_error("OFF\n3 1 0\n0 0 0.000000000000000000001\n", "m.off:3",
                   "line longer than the limit of 16 bytes", limits);
  expect_off_error("OFF\n3 1 0\n0 0 0 255 255 255 255 255\n1 0 0\n0 1 0\n3 0 1 2\n", "m.off:3",
                   "line longer than the limit of 16 bytes", limits);
}

TEST(ReadOff, PolygonsBeyondTheFacetLimitAreAnErrorOnTheirLine) {
  ReadLimits limits;
  limits.max_triangles = 1;
  expect_off_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", "m.off:7",
                   "more than the limit of 1 facets", limits);
}

TEST(ReadOff, OnlyFacesOfFewerThanThreeCornersIsNoFacets) {
  const auto soup =
      detail::read_off_bytes("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0\n2 0 1\n", "m.off", {});
  ASSERT_FALSE(soup.has_value());
  EXPECT_EQ(soup.error().location, "m.off");
  EXPECT_EQ(soup.error().message, "no facets: all 2 OFF faces have fewer than 3 corners");
}

TEST(ReadOff, AOneCornerFaceIsSkippedWithAWarning) {
  const auto soup = read_off_ok("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n1 2\n3 0 1 2\n");
  ASSERT_EQ(soup.triangles.size(), 1u);
  ASSERT_EQ(soup.diagnostics.size(), 1u);
  EXPECT_EQ(soup.diagnostics[0].message, "m.off:6: OFF face has 1 corner, so no area; skipped");
}

}  // namespace
}  // namespace strata::io
