#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "support/mesh_reading.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"

namespace strata::io {
namespace {

using test::adversarial;
using test::contains;
using test::corpus_file;
using test::expect_read_with_diagnostic;
using test::expect_refused;
using test::find_diagnostic;

using Triangle = std::array<Vec3, 3>;

/// The tetrahedron of data/adversarial/generate.py, facets in file order.
std::vector<Triangle> tetrahedron() {
  const Vec3 v[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  return {{v[0], v[2], v[1]}, {v[0], v[1], v[3]}, {v[0], v[3], v[2]}, {v[1], v[2], v[3]}};
}

// ---------------------------------------------------------------------------------------------
// Files: opening, gzip, dispatch

TEST(ReadMeshFile, MissingFileIsErrorNamingThePath) {
  const auto path = adversarial("does_not_exist.stl");
  const auto soup = read_mesh(path);
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().code, ErrorCode::BadInput);
  EXPECT_EQ(soup.error().location, path.string());
  EXPECT_TRUE(contains(soup.error().message, "no such file")) << soup.error().message;
}

TEST(ReadMeshFile, DirectoryIsError) {
  expect_refused(std::filesystem::path(STRATA_DATA_DIR) / "adversarial", "directory");
}

TEST(ReadMeshFile, ZeroByteFileIsError) {
  expect_refused(adversarial("empty.stl"), "empty file (0 bytes)");
}

TEST(ReadMeshFile, ReadsAFileWrittenInATemporaryFolder) {
  const test::TempDir dir("read-mesh");
  {
    std::ofstream out(dir / "tri.stl", std::ios::binary);
    out << "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
           "endloop\nendfacet\nendsolid t\n";
  }
  const auto soup = read_mesh(dir / "tri.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
}

TEST(ReadMeshGzip, AsciiStlInsideGzip) {
  const auto soup = read_mesh(adversarial("tetra_ascii.stl.gz"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-ascii+gz");
  EXPECT_EQ(soup->triangles, tetrahedron());
}

TEST(ReadMeshGzip, BinaryStlInsideGzip) {
  const auto soup = read_mesh(adversarial("tetra_binary.stl.gz"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary+gz");
  EXPECT_EQ(soup->triangles, tetrahedron());
}

TEST(ReadMeshGzip, DetectedByMagicBytesNotByExtension) {
  const auto soup = read_mesh(adversarial("gzip_without_gz_extension.stl"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-ascii+gz");
  EXPECT_EQ(soup->triangles.size(), 4u);
}

TEST(ReadMeshGzip, TruncatedGzipIsError) {
  const auto path = adversarial("truncated.stl.gz");
  const auto soup = read_mesh(path);
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, path.string());
  EXPECT_TRUE(contains(soup.error().message, "truncated")) << soup.error().message;
}

TEST(ReadMeshGzip, DecompressedSizeLimitHolds) {
  ReadLimits limits;
  limits.max_decompressed_bytes = 100;
  const auto soup = read_mesh(adversarial("tetra_ascii.stl.gz"), limits);
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "limit")) << soup.error().message;
}

TEST(ReadMeshGzip, CorpusObjInsideGzip) {
  const auto soup =
      read_mesh(corpus_file("openfoam-examples/resources/geometry/building_wtc2.obj.gz"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "obj+gz");
  EXPECT_EQ(soup->triangles.size(), 198u);
}

TEST(ReadMeshGzip, CorpusStlWithSeveralSolidsInsideGzip) {
  const auto soup = read_mesh(corpus_file("openfoam-examples/resources/geometry/flange.stl.gz"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-ascii+gz");
  EXPECT_EQ(soup->triangles.size(), 6468u);
  EXPECT_NE(find_diagnostic(*soup, "stl.multiple_solids"), nullptr);
}

TEST(ReadMeshDispatch, ZipAndAmfAreUnsupported) {
  for (const auto& path : {corpus_file("trimesh/models/ascii.stl.zip"),
                           corpus_file("openscad/tests/data/amf/amf_broken.amf")}) {
    const auto soup = read_mesh(path);
    ASSERT_FALSE(soup) << path;
    EXPECT_EQ(soup.error().location, path.string());
    EXPECT_TRUE(contains(soup.error().message, "unsupported format")) << soup.error().message;
  }
}

TEST(ReadMeshDispatch, ThreeMfGoesToTheThreeMfReader) {
  const auto moon = read_mesh(corpus_file("numpy-stl/tests/3mf/Moon.3mf"));
  ASSERT_TRUE(moon) << moon.error().to_string();
  EXPECT_EQ(moon->format, "3mf");
  EXPECT_EQ(moon->triangles.size(), 184u);
  // A zip local-file header and nothing else.
  expect_refused(adversarial("not_a_mesh.3mf"), "not a 3MF file: not a zip archive", "");
}

TEST(ReadMeshDispatch, StlContentWinsOverAWrongExtension) {
  const std::string binary = test::read_file(adversarial("stray_byte_binary.stl"));
  const auto as_obj = read_mesh_bytes(binary, "model.obj");
  ASSERT_TRUE(as_obj) << as_obj.error().to_string();
  EXPECT_EQ(as_obj->format, "stl-binary");
  const auto as_off = read_mesh_bytes(test::read_file(adversarial("tetra_ascii.stl")), "model.off");
  ASSERT_TRUE(as_off) << as_off.error().to_string();
  EXPECT_EQ(as_off->format, "stl-ascii");
}

TEST(ReadMeshDispatch, FilesWithoutExtensionAreRecognisedByContent) {
  const auto ply =
      read_mesh_bytes(test::read_file(adversarial("tetra_binary_big_endian.ply")), "m");
  ASSERT_TRUE(ply) << ply.error().to_string();
  EXPECT_EQ(ply->format, "ply");
  const auto off = read_mesh_bytes("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "m");
  ASSERT_TRUE(off) << off.error().to_string();
  EXPECT_EQ(off->format, "off");
  const auto obj = read_mesh_bytes("# a triangle\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "m");
  ASSERT_TRUE(obj) << obj.error().to_string();
  EXPECT_EQ(obj->format, "obj");
}

TEST(ReadMeshDispatch, UnknownContentIsUnsupported) {
  const auto soup = read_mesh_bytes(std::string(200, 'z'), "mystery.bin");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "unsupported format")) << soup.error().message;
}

// ---------------------------------------------------------------------------------------------
// OBJ

TEST(ReadObj, ReadsCoordinatesAsDouble) {
  const auto soup = read_mesh_bytes("v 0.1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "obj");
  EXPECT_EQ(soup->triangles[0][0].x, 0.1);  // SPEC §2: only STL is rounded to float32
  EXPECT_TRUE(soup->stored_normals.empty());
}

TEST(ReadObj, PolygonsAreFanTriangulated) {
  const auto soup =
      read_mesh_bytes("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 1 0\nf 1 2 3 4 5\n", "t.obj");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 3u);
  EXPECT_EQ(soup->triangles[2], (Triangle{Vec3{0, 0, 0}, {0, 1, 0}, {-1, 1, 0}}));
  const Diagnostic* info = find_diagnostic(*soup, "mesh.polygon_face");
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->severity, Severity::Info);
  EXPECT_TRUE(contains(info->message, "t.obj:6")) << info->message;
}

TEST(ReadObj, CornersWithTextureAndNormalIndices) {
  const auto soup = read_mesh_bytes(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
      "f 1/1/1 2/1/1 3/1/1\nf 1//1 2//1 3//1\nf 1/1 2/1 3/1\n",
      "t.obj");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 3u);
  EXPECT_EQ(soup->triangles[0], soup->triangles[1]);
  EXPECT_EQ(soup->triangles[0], soup->triangles[2]);
}

TEST(ReadObj, NegativeIndicesCountBackFromTheLastVertex) {
  const auto soup = read_mesh_bytes("v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n", "t.obj");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles[0], (Triangle{Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
}

TEST(ReadObj, TabSeparatedCornersAreAllRead) {
  const auto soup =
      read_mesh_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf\t1/1\t2/2\t4/4\t3/3\n", "t.obj");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 2u);
}

TEST(ReadObj, BackslashContinuesALine) {
  const auto soup =
      read_mesh_bytes("v 0 0 0\nv 1 0 0\nv 1 1 0\r\nv 0 1 0\nf 1 2 \\\r\n 3 4\nf 1 2 3\n", "t.obj");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 3u);
}

TEST(ReadObj, IndexZeroIsErrorNamingTheLine) {
  expect_refused(adversarial("index_zero.obj"), "index 0", ":5");
}

TEST(ReadObj, IndexOutOfRangeIsErrorNamingTheLine) {
  expect_refused(adversarial("index_out_of_range.obj"), "vertex 9", ":6");
}

TEST(ReadObj, RelativeIndexBeforeItsVertexIsError) {
  const auto soup = read_mesh_bytes("v 0 0 0\nf -1 -2 -3\n", "t.obj");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.obj:2");
}

TEST(ReadObj, NonFiniteVertexIsErrorNamingTheLine) {
  const auto path = adversarial("nan_vertex.obj");
  const auto soup = read_mesh(path);
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, path.string() + ":2");
}

TEST(ReadObj, UnparseableNumberIsErrorNamingTheLine) {
  const auto soup = read_mesh(corpus_file("assimp-testmodels/models/OBJ/number_formats.obj"));
  ASSERT_FALSE(soup);
  EXPECT_TRUE(soup.error().location.ends_with("number_formats.obj:11")) << soup.error().location;
  EXPECT_TRUE(contains(soup.error().message, "'3.1+e2'")) << soup.error().message;
}

TEST(ReadObj, TwoCornerFaceIsSkippedWithWarning) {
  const auto soup = read_mesh(corpus_file("trimesh/models/notenoughindices.obj"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
  const Diagnostic* warning = find_diagnostic(*soup, "mesh.short_face");
  ASSERT_NE(warning, nullptr);
  EXPECT_TRUE(contains(warning->message, "notenoughindices.obj:9")) << warning->message;
}

TEST(ReadObj, NoFacesIsError) {
  expect_refused(corpus_file("trimesh/models/empty.obj"), "no facets");
}

TEST(ReadObj, UnknownStatementIsAWarning) {
  const auto soup = read_mesh_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nbogus 1 2\nf 1 2 3\n", "t.obj");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_NE(find_diagnostic(*soup, "obj.unknown_statement"), nullptr);
}

TEST(ReadObj, CorpusLineContinuationsAndNegativeIndices) {
  // wallhole.obj continues long faces with '\'; CGAL's OBJ reader rejects it.
  const auto wall = read_mesh(corpus_file("trimesh/models/wallhole.obj"));
  ASSERT_TRUE(wall) << wall.error().to_string();
  EXPECT_EQ(wall->triangles.size(), 66u);
  const auto negative = read_mesh(corpus_file("trimesh/models/negative_indices.obj"));
  ASSERT_TRUE(negative) << negative.error().to_string();
  EXPECT_EQ(negative->triangles.size(), 12u);
}

// ---------------------------------------------------------------------------------------------
// OFF

TEST(ReadOff, ReadsPolygonsAsFansInDouble) {
  const auto soup =
      read_mesh_bytes("OFF\n# a square\n4 1 0\n0.1 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", "t.off");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "off");
  ASSERT_EQ(soup->triangles.size(), 2u);
  EXPECT_EQ(soup->triangles[0][0].x, 0.1);
  EXPECT_EQ(soup->triangles[1], (Triangle{Vec3{0.1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
}

TEST(ReadOff, CountsGluedToTheKeywordAreReadWithWarning) {
  expect_read_with_diagnostic(corpus_file("trimesh/models/whitespace.off"), 12u,
                              "off.glued_counts");
}

TEST(ReadOff, HostileCountsFailBeforeAllocating) {
  expect_refused(adversarial("hostile_counts.off"), "4000000000 vertices");
}

TEST(ReadOff, TruncatedFileIsErrorNamingTheLine) {
  expect_refused(adversarial("truncated.off"), "truncated", ":9");
}

TEST(ReadOff, CorpusShortFaceRecordIsError) {
  expect_refused(corpus_file("assimp-testmodels/models/OFF/invalid.off"), "face 2");
}

TEST(ReadOff, IndexOutOfRangeIsErrorNamingTheLine) {
  const auto soup = read_mesh_bytes("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "t.off");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.off:6");
  EXPECT_TRUE(contains(soup.error().message, "vertex 7")) << soup.error().message;
}

TEST(ReadOff, NonFiniteCoordinateIsErrorNamingTheLine) {
  const auto soup = read_mesh_bytes("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "t.off");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.off:4");
}

TEST(ReadOff, HugeCornerCountFailsBeforeAllocating) {
  const auto soup = read_mesh_bytes("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n", "t.off");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.off:6");
  EXPECT_TRUE(contains(soup.error().message, "4000000000 corners")) << soup.error().message;
}

TEST(ReadOff, ColoursCommentsAndNormalsAreSkipped) {
  const auto soup = read_mesh_bytes(
      "# leading comment\nCNOFF 3 1 0 # counts\n0 0 0  0 0 1  1 0 0 1\n1 0 0 0 0 1 0 1 0 1\n"
      "# between\n0 1 0 0 0 1 0 0 1 1\n3 0 1 2  255 0 0\n",
      "t.off");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0], (Triangle{Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
}

TEST(ReadOff, HomogeneousCoordinatesAreDividedByW) {
  const auto soup = read_mesh_bytes("4OFF\n3 1 0\n0 0 0 2\n2 0 0 2\n0 4 0 2\n3 0 1 2\n", "t.off");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles[0], (Triangle{Vec3{0, 0, 0}, {1, 0, 0}, {0, 2, 0}}));
}

TEST(ReadOff, BinaryOffIsUnsupported) {
  const auto soup = read_mesh_bytes(std::string("OFF BINARY\n\0\0\0\3", 15), "t.off");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "unsupported format")) << soup.error().message;
}

TEST(ReadOff, CorpusModelReads) {
  const auto soup = read_mesh(corpus_file("admesh/test/block/basic.off"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 12u);
}

// ---------------------------------------------------------------------------------------------
// PLY

const std::string kAsciiPly =
    "ply\n"
    "format ascii 1.0\n"
    "comment made by hand\n"
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "property uchar red\n"
    "property list uchar float extra\n"
    "element face 1\n"
    "property uchar flags\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 0 255 0\n"
    "1 0 0 255 2 0.5 0.5\n"
    "1 1 0 255 0\n"
    "0 1 0 255 1 7\n"
    "9 4 0 1 2 3\n";

TEST(ReadPly, AsciiWithExtraPropertiesIsFanTriangulated) {
  const auto soup = read_mesh_bytes(kAsciiPly, "t.ply");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "ply");
  ASSERT_EQ(soup->triangles.size(), 2u);
  EXPECT_EQ(soup->triangles[0], (Triangle{Vec3{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}));
  EXPECT_EQ(soup->triangles[1], (Triangle{Vec3{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
}

TEST(ReadPly, BinaryLittleAndBigEndianReadTheSame) {
  const auto little = read_mesh(adversarial("tetra_binary_little_endian.ply"));
  const auto big = read_mesh(adversarial("tetra_binary_big_endian.ply"));
  ASSERT_TRUE(little) << little.error().to_string();
  ASSERT_TRUE(big) << big.error().to_string();
  EXPECT_EQ(little->triangles, tetrahedron());
  EXPECT_EQ(big->triangles, tetrahedron());
}

TEST(ReadPly, TriangleStripsAreExpandedKeepingOrientation) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 2 0\n"
      "8 0 1 2 3 -1 1 3 4\n";
  const auto soup = read_mesh_bytes(text, "t.ply");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 3u);
  EXPECT_EQ(soup->triangles[0], (Triangle{Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(soup->triangles[1], (Triangle{Vec3{0, 1, 0}, {1, 0, 0}, {1, 1, 0}}));
  EXPECT_EQ(soup->triangles[2], (Triangle{Vec3{1, 0, 0}, {1, 1, 0}, {2, 2, 0}}));
}

TEST(ReadPly, CorpusTriangleStrips) {
  const auto soup = read_mesh(corpus_file("common-3d-test-models/data/igea.ply"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 268686u);
}

TEST(ReadPly, TruncatedBinaryIsErrorNamingTheByte) {
  const auto path = adversarial("truncated_binary.ply");
  const auto soup = read_mesh(path);
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().location, ": byte ")) << soup.error().location;
  EXPECT_TRUE(contains(soup.error().message, "truncated")) << soup.error().message;
}

TEST(ReadPly, IndexOutOfRangeIsErrorNamingTheLine) {
  std::string text = kAsciiPly;
  text.replace(text.find("9 4 0 1 2 3"), 11, "9 4 0 1 2 8");
  const auto soup = read_mesh_bytes(text, "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.ply:18");
  EXPECT_TRUE(contains(soup.error().message, "vertex 8")) << soup.error().message;
}

TEST(ReadPly, NegativeIndexIsError) {
  std::string text = kAsciiPly;
  text.replace(text.find("9 4 0 1 2 3"), 11, "9 4 0 1 2 -3");
  const auto soup = read_mesh_bytes(text, "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "negative")) << soup.error().message;
}

TEST(ReadPly, NonFiniteVertexIsError) {
  std::string text = kAsciiPly;
  text.replace(text.find("1 1 0 255"), 9, "1 nan 0 255");
  const auto soup = read_mesh_bytes(text, "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "'nan': not a number (inf and nan are not accepted)"))
      << soup.error().message;
}

TEST(ReadPly, UnknownPropertyTypeIsErrorNamingTheLine) {
  std::string text = kAsciiPly;
  text.replace(text.find("property uchar red"), 18, "property quad red");
  const auto soup = read_mesh_bytes(text, "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.ply:8");
}

TEST(ReadPly, ListLongerThanTheFileIsError) {
  std::string text = kAsciiPly;
  text.replace(text.find("9 4 0 1 2 3"), 11, "9 200 0 1 2 3");
  const auto soup = read_mesh_bytes(text, "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_FALSE(soup.error().location.empty());
}

TEST(ReadPly, HugeElementCountFailsWithoutAllocating) {
  std::string text = kAsciiPly;
  text.replace(text.find("element vertex 4"), 16, "element vertex 4000000000000");
  const auto soup = read_mesh_bytes(text, "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "truncated")) << soup.error().message;
}

TEST(ReadPly, NoFacesIsError) {
  expect_refused(corpus_file("trimesh/models/empty.ply"), "no facets");
}

}  // namespace
}  // namespace strata::io
