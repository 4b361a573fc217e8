// PLY header lines that are no PLY keyword (free text without `comment`, as Blender 2.47 wrote)
// are skipped with a warning naming the file and the line, as assimp and MeshLab do.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "strata/io/read_mesh.hpp"

namespace strata::io {
namespace {

/// A triangle as Blender 2.47's PLY exporter wrote it: a bare line after the format line.
std::string blender_triangle(std::string_view format, std::string_view body) {
  return "ply\nformat " + std::string(format) +
         " 1.0\nCreated by Blender3D 247 - www.blender.org, source file: 'part.blend'\n"
         "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar uint vertex_indices\nend_header\n" +
         std::string(body);
}

std::vector<const Diagnostic*> diagnostics_of(const TriangleSoup& soup, std::string_view code) {
  std::vector<const Diagnostic*> found;
  for (const Diagnostic& d : soup.diagnostics) {
    if (d.code == code) found.push_back(&d);
  }
  return found;
}

TEST(PlyHeaderLeniency, BareCreatedByLineIsSkippedWithAWarningNamingTheLine) {
  const auto soup =
      read_mesh_bytes(blender_triangle("ascii", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "blender.ply");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0], (std::array<Vec3, 3>{Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  const auto skipped = diagnostics_of(*soup, "ply.header_line_skipped");
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0]->severity, Severity::Warning);
  EXPECT_EQ(skipped[0]->message,
            "blender.ply:3: PLY header line 'Created by Blender3D 247 - www.blender.o...' "
            "skipped: it is not an element, property, format, comment, obj_info or end_header "
            "line");
}

TEST(PlyHeaderLeniency, BinaryBodyAfterASkippedLineIsRead) {
  std::string body;
  auto put = [&](const auto value) {
    body.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  for (const float v : {0.f, 0.f, 0.f, 2.f, 0.f, 0.f, 0.f, 2.f, 0.f}) put(v);
  put(static_cast<unsigned char>(3));
  for (const unsigned i : {0u, 1u, 2u}) put(i);
  const auto soup = read_mesh_bytes(blender_triangle("binary_little_endian", body), "b.ply");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0][2], (Vec3{0, 2, 0}));
  EXPECT_EQ(diagnostics_of(*soup, "ply.header_line_skipped").size(), 1u);
}

TEST(PlyHeaderLeniency, SeveralSkippedLinesGiveOneWarningWithEveryLine) {
  const std::string text =
      "ply\nformat ascii 1.0\nbogus one\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nbogus two\nelement face 1\nproperty list uchar int vertex_indices\n"
      "\tbogus\x01three\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto soup = read_mesh_bytes(text, "part.ply");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
  const auto skipped = diagnostics_of(*soup, "ply.header_line_skipped");
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0]->message,
            "part.ply:3: PLY header line 'bogus one' skipped: it is not an element, property, "
            "format, comment, obj_info or end_header line (3 times in all; also at line 8, 11)");
}

TEST(PlyHeaderLeniency, ControlBytesOfASkippedLineAreEscaped) {
  const std::string text =
      "ply\nformat ascii 1.0\n\tbad\x01line\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int "
      "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto soup = read_mesh_bytes(text, "part.ply");
  ASSERT_TRUE(soup) << soup.error().to_string();
  const auto skipped = diagnostics_of(*soup, "ply.header_line_skipped");
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0]->message,
            "part.ply:3: PLY header line '\\x09bad\\x01line' skipped: it is not an element, "
            "property, format, comment, obj_info or end_header line");
}

TEST(PlyHeaderLeniency, KnownKeywordsWithBadArgumentsAreStillErrors) {
  // Leniency covers unknown lines only: a format, element or property line that is wrong stays
  // an error at its line.
  const auto soup = read_mesh_bytes(
      "ply\nformat ascii 1.0\nCreated by Blender3D\nelement vertex\nend_header\n", "part.ply");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "part.ply:4");
  EXPECT_EQ(soup.error().message, "PLY element line needs a name and a count");
}

TEST(PlyHeaderLeniency, HeaderOfOnlySkippedLinesStillNeedsItsEnd) {
  const auto soup = read_mesh_bytes("ply\nformat ascii 1.0\nCreated by Blender3D\n", "part.ply");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "part.ply:3");
  EXPECT_EQ(soup.error().message, "PLY header has no end_header line");
}

}  // namespace
}  // namespace strata::io
