// The OBJ reader: the statements it reads and skips, its line ends and continuations, and every
// refusal with the line and message it gives.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "io/read_mesh_internal.hpp"
#include "support/result_checks.hpp"

namespace strata::io {
namespace {

constexpr std::string_view kVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TriangleSoup read_obj_ok(std::string_view text, const ReadLimits& limits = {}) {
  return test::value_of(detail::read_obj_bytes(text, "m.obj", limits), text);
}

void expect_obj_error(std::string_view text, std::string_view location, std::string_view message,
                      const ReadLimits& limits = {}) {
  test::expect_bad_input(detail::read_obj_bytes(text, "m.obj", limits), location, message, text);
}

TEST(ReadObj, StatementsThatAreNotGeometryAreSkippedSilently) {
  const auto soup =
      read_obj_ok("mtllib m.mtl\no part\ng group\ns 1\nusemtl steel\nvt 0 0\nvn 0 0 1\nvp 0.5\n" +
                  std::string(kVertices) + "l 1 2\np 3\nfo 1 2 3\n");
  ASSERT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.triangles[0][2], (Vec3{0, 1, 0}));
  EXPECT_TRUE(soup.diagnostics.empty());
}

TEST(ReadObj, UnknownStatementsAreQuotedShortAndVisible) {
  const std::string name(50, 'w');
  const auto soup = read_obj_ok(std::string(kVertices) + name + " 1\nbad\x01\x7f 2\nf 1 2 3\n");
  ASSERT_EQ(soup.diagnostics.size(), 1u);
  EXPECT_EQ(soup.diagnostics[0].message,
            "m.obj:4: statement '" + std::string(40, 'w') +
                "...' ignored (only v and f are read) (2 times in all; also at line 5)");
  const auto control = read_obj_ok(std::string(kVertices) + "bad\x01\x7f 2\nf 1 2 3\n");
  ASSERT_EQ(control.diagnostics.size(), 1u);
  EXPECT_EQ(control.diagnostics[0].message,
            "m.obj:4: statement 'bad\\x01\\x7f' ignored (only v and f are read)");
}

TEST(ReadObj, EveryKindOfLineEndEndsAStatement) {
  const auto soup = read_obj_ok("v 0 0 0\r\nv 1 0 0\rv 0 1 0\nf 1 2 3");
  ASSERT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.triangles[0][1], (Vec3{1, 0, 0}));
}

TEST(ReadObj, ContinuationsJoinLinesWhateverFollowsTheBackslash) {
  // A backslash followed by blanks, then a line of a backslash alone: lines 4 to 6 are one
  // face. A continuation onto an empty line (7) and one at the end of the file (9) end their
  // faces after two corners.
  const auto soup = read_obj_ok(std::string(kVertices) + "f 1 \\  \n\\\n2 3\nf 3 2 \\\n\nf 2 3 \\");
  ASSERT_EQ(soup.triangles.size(), 1u);
  EXPECT_EQ(soup.triangles[0][1], (Vec3{1, 0, 0}));
  ASSERT_EQ(soup.diagnostics.size(), 1u);
  EXPECT_EQ(soup.diagnostics[0].message,
            "m.obj:7: OBJ face has 2 corners, so no area; skipped (2 times in all; also at line "
            "9)");
}

TEST(ReadObj, AVertexWithTooFewCoordinatesSaysHowMany) {
  expect_obj_error("v\n", "m.obj:1", "vertex has 0 coordinates, expected 3");
  expect_obj_error("v 1\n", "m.obj:1", "vertex has 1 coordinate, expected 3");
}

TEST(ReadObj, ACornerWithoutAVertexIndexIsAnError) {
  expect_obj_error(std::string(kVertices) + "f 1 /2 3\n", "m.obj:4",
                   "face corner '/2' has no vertex index");
}

TEST(ReadObj, FacetsOverTheLimitAreAnErrorOnTheirLine) {
  ReadLimits limits;
  limits.max_triangles = 2;
  expect_obj_error(std::string(kVertices) + "v 1 1 0\nf 1 2 3\nf 1 2 3 4\n", "m.obj:6",
                   "more than the limit of 2 facets", limits);
}

TEST(ReadObj, LinesOverTheLimitAreRefused) {
  ReadLimits limits;
  limits.max_line_bytes = 16;
  expect_obj_error(std::string(kVertices) + "f 1 2 3 # a comment longer than that\n", "m.obj:4",
                   "line longer than the limit of 16 bytes", limits);
  // Continued lines that are short each but long together.
  expect_obj_error(std::string(kVertices) + "f 1 2 \\\n3 1 2 \\\n3 1 2 \\\n3\n", "m.obj:6",
                   "line longer than the limit of 16 bytes", limits);
}

}  // namespace
}  // namespace strata::io
