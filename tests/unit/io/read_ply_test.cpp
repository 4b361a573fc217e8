// The PLY reader: header and body errors with the location and message each must give, the
// byte orders, triangle strips, and the warnings for odd but readable files.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "io/read_mesh_internal.hpp"

namespace strata::io {
namespace {

constexpr std::string_view kTriangleBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

std::string ascii_header(std::string_view elements) {
  return "ply\nformat ascii 1.0\n" + std::string(elements) + "end_header\n";
}

/// The header of three float vertices and one face, as most tests here use.
std::string triangle_header() {
  return ascii_header(
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\n");
}

Error read_error(std::string_view bytes, const ReadLimits& limits = {}) {
  const auto soup = detail::read_ply_bytes(bytes, "part.ply", limits);
  EXPECT_FALSE(soup.has_value());
  return soup ? Error{} : soup.error();
}

void expect_error(std::string_view bytes, std::string_view location, std::string_view message,
                  const ReadLimits& limits = {}) {
  const Error e = read_error(bytes, limits);
  EXPECT_EQ(e.code, ErrorCode::BadInput);
  EXPECT_EQ(e.location, location);
  EXPECT_EQ(e.message, message);
}

const Diagnostic* find_diagnostic(const TriangleSoup& soup, std::string_view code) {
  for (const Diagnostic& d : soup.diagnostics) {
    if (d.code == code) return &d;
  }
  return nullptr;
}

template <class T>
void append_raw(std::string& out, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

/// A binary PLY of the triangle (0,0,0) (1.5,0,0) (0,2,0): float vertices, uchar/int list.
std::string binary_triangle(bool big_endian) {
  std::string out = std::string("ply\nformat ") +
                    (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
                    "z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float xyz[] = {0, 0, 0, 1.5f, 0, 0, 0, 2, 0};
  for (const float v : xyz) append_raw(out, v, big_endian);
  out.push_back(3);
  for (const std::int32_t i : {0, 1, 2}) append_raw(out, i, big_endian);
  return out;
}

TEST(ReadPly, ReadsAnAsciiTriangle) {
  const auto soup =
      detail::read_ply_bytes(triangle_header() + std::string(kTriangleBody), "part.ply", {});
  ASSERT_TRUE(soup.has_value()) << soup.error().to_string();
  EXPECT_EQ(soup->format, "ply");
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0][1], (Vec3{1, 0, 0}));
  EXPECT_TRUE(soup->diagnostics.empty());
}

TEST(ReadPly, ReadsBothByteOrdersAlike) {
  for (const bool big_endian : {false, true}) {
    const auto soup = detail::read_ply_bytes(binary_triangle(big_endian), "part.ply", {});
    ASSERT_TRUE(soup.has_value()) << soup.error().to_string();
    ASSERT_EQ(soup->triangles.size(), 1u);
    EXPECT_EQ(soup->triangles[0][1], (Vec3{1.5, 0, 0})) << big_endian;
    EXPECT_EQ(soup->triangles[0][2], (Vec3{0, 2, 0})) << big_endian;
  }
}

TEST(ReadPly, HeaderWithoutEndHeaderIsAnError) {
  expect_error("ply\nformat ascii 1.0\nelement vertex 3\n", "part.ply:3",
               "PLY header has no end_header line");
}

TEST(ReadPly, FirstLineMustBePly) {
  expect_error("plyx\nformat ascii 1.0\nend_header\n", "part.ply:1",
               "not a PLY file: the first line is not 'ply'");
}

TEST(ReadPly, HeaderLineOverTheLimitIsAnError) {
  ReadLimits limits;
  limits.max_line_bytes = 16;
  // Built with append: GCC 12 warns (-Wrestrict, a false positive) on a chain of operator+.
  std::string header = "ply\nformat ascii 1.0\ncomment ";
  header.append(20, 'c');
  header.append("\nend_header\n");
  expect_error(header, "part.ply:3", "line longer than the limit of 16 bytes", limits);
}

TEST(ReadPly, UnknownFormatIsNamed) {
  expect_error("ply\nformat utf8 1.0\nend_header\n", "part.ply:2", "unknown PLY format 'utf8'");
}

TEST(ReadPly, HeaderWithoutFormatLineIsAnError) {
  expect_error("ply\nelement vertex 0\nend_header\n", "part.ply:3",
               "PLY header has no format line");
}

TEST(ReadPly, ElementNeedsANameAndACount) {
  expect_error(ascii_header("element vertex\n"), "part.ply:3",
               "PLY element line needs a name and a count");
}

TEST(ReadPly, ElementCountMustBeAWholeNumber) {
  const Error e = read_error(ascii_header("element vertex 3.0\n"));
  EXPECT_EQ(e.location, "part.ply:3");
  EXPECT_EQ(e.message.rfind("bad number '3.0'", 0), 0u) << e.message;
}

TEST(ReadPly, PropertyBeforeAnyElementIsAnError) {
  expect_error(ascii_header("property float x\n"), "part.ply:3", "PLY property before any element");
}

TEST(ReadPly, ListCountTypeMustBeAnInteger) {
  expect_error(ascii_header("element face 1\nproperty list float int vertex_indices\n"),
               "part.ply:4", "PLY list property needs an integer count type");
}

TEST(ReadPly, UnknownPropertyTypeIsNamed) {
  expect_error(ascii_header("element vertex 1\nproperty quad x\n"), "part.ply:4",
               "unknown PLY property type 'quad'");
}

TEST(ReadPly, VertexElementNeedsXYAndZ) {
  expect_error(ascii_header("element vertex 1\nproperty float x\nproperty float y\n") + "0 0\n",
               "part.ply", "PLY vertex element lacks an x, y or z property");
}

TEST(ReadPly, FaceElementNeedsAVertexIndexList) {
  expect_error(ascii_header("element vertex 0\nproperty float x\nproperty float y\nproperty "
                            "float z\nelement face 1\nproperty int material\n") +
                   "0\n",
               "part.ply", "PLY face element has no vertex_indices list");
}

TEST(ReadPly, TruncatedAsciiBodyNamesTheItemAndLine) {
  expect_error(triangle_header() + "0 0 0\n1 0 0\n", "part.ply:12",
               "PLY vertex 2 of 3: file ends early (truncated?)");
}

TEST(ReadPly, TruncatedBinaryBodyNamesTheItemAndByte) {
  std::string bytes = binary_triangle(false);
  const std::size_t header = bytes.size() - 9 * 4 - 1 - 3 * 4;
  bytes.resize(header + 4 * 4);  // vertex 0 and x of vertex 1
  expect_error(bytes, "part.ply: byte " + std::to_string(header + 16),
               "PLY vertex 1 of 3: file ends early (truncated?)");
}

TEST(ReadPly, ListLongerThanTheFileIsAnError) {
  expect_error(triangle_header() + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n", "part.ply:13",
               "PLY face 0: list of 200 entries, more than the file holds");
}

TEST(ReadPly, NegativeFaceIndexIsAnError) {
  expect_error(triangle_header() + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "part.ply:13",
               "PLY face 0 uses the negative vertex index -1");
}

TEST(ReadPly, BadNumberInTheBodyGivesTheNumberMessage) {
  const Error e = read_error(triangle_header() + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(e.location, "part.ply:11");
  EXPECT_EQ(e.message.rfind("bad number 'nan'", 0), 0u) << e.message;
}

TEST(ReadPly, FacetsOverTheLimitAreAnError) {
  ReadLimits limits;
  limits.max_triangles = 1;
  const std::string bytes =
      ascii_header(
          "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
          "element face 2\nproperty list uchar int vertex_indices\n") +
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n";
  expect_error(bytes, "part.ply:14", "more than the limit of 1 facets", limits);
}

std::string strip_file(std::string_view strip) {
  return ascii_header(
             "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
             "element tristrips 1\nproperty list int int vertex_indices\n") +
         "0 0 0\n1 0 0\n0 1 0\n1 1 0\n" + std::string(strip) + "\n";
}

TEST(ReadPly, TriangleStripsAlternateOrientation) {
  const auto soup = detail::read_ply_bytes(strip_file("4 0 1 2 3"), "part.ply", {});
  ASSERT_TRUE(soup.has_value()) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 2u);
  // (0 1 2), then (1 2 3) turned over to (2 1 3) to keep the strip's orientation: both face +z.
  EXPECT_EQ(soup->triangles[0][0], (Vec3{0, 0, 0}));
  EXPECT_EQ(soup->triangles[0][1], (Vec3{1, 0, 0}));
  EXPECT_EQ(soup->triangles[1][0], (Vec3{0, 1, 0}));
  EXPECT_EQ(soup->triangles[1][1], (Vec3{1, 0, 0}));
  EXPECT_EQ(soup->triangles[1][2], (Vec3{1, 1, 0}));
}

TEST(ReadPly, StripJoinsAreSkippedWithANote) {
  // -1 separates two strips; 1 1 repeats a vertex (a join), which is no facet.
  const auto soup = detail::read_ply_bytes(strip_file("8 0 1 2 -1 1 1 3 2"), "part.ply", {});
  ASSERT_TRUE(soup.has_value()) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 2u);
  const Diagnostic* d = find_diagnostic(*soup, "ply.strip_joins");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->message,
            "part.ply: 1 triangles of the strips repeat a vertex (strip joins); not faces, "
            "skipped");
}

TEST(ReadPly, StripIndexBelowMinusOneIsAnError) {
  expect_error(strip_file("4 0 1 -2 3"), "part.ply:14",
               "PLY strip uses the negative vertex index -2");
}

TEST(ReadPly, BytesAfterTheLastBinaryElementAreAWarning) {
  const auto soup = detail::read_ply_bytes(binary_triangle(false) + "xyz", "part.ply", {});
  ASSERT_TRUE(soup.has_value()) << soup.error().to_string();
  const Diagnostic* d = find_diagnostic(*soup, "ply.trailing_bytes");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->message, "part.ply: 3 bytes after the last element ignored");
}

TEST(ReadPly, OtherElementsAndASecondVertexElementAreSkipped) {
  const std::string bytes =
      ascii_header(
          "comment made by hand\nobj_info none\n"
          "element vertices 3\nproperty double x\nproperty double y\nproperty double z\n"
          "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
          "element material 2\nproperty uchar red\nproperty list uchar uchar tags\n"
          "element faces 1\nproperty uchar flags\nproperty list uchar uint vertex_index\n") +
      "0 0 0\n2 0 0\n0 2 0\n9 9 9\n255 1 7\n0 0\n5 3 0 1 2\n";
  const auto soup = detail::read_ply_bytes(bytes, "part.ply", {});
  ASSERT_TRUE(soup.has_value()) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0][1], (Vec3{2, 0, 0}));
}

}  // namespace
}  // namespace strata::io
