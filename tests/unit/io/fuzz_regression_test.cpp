// Inputs on which a fuzz target of fuzz/ failed (a sanitizer report, a hang, an
// allocation of gigabytes), each also kept as a seed of its target,
// fuzz/corpus/<target>/regress-*.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>

#include "strata/io/read_cells.hpp"
#include "strata/io/read_mesh.hpp"
#include "support/mesh_reading.hpp"
#include "support/temp_dir.hpp"
#include "support/text_meshes.hpp"

namespace strata::io {
namespace {

using test::contains;
/// An ASCII PLY of one triangle whose face list has the given type and third
/// index.
std::string ply_triangle(std::string_view list_type, std::string_view third_index) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty "
         "float y\n"
         "property float z\nelement face 1\nproperty list uchar " +
         std::string(list_type) + " vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 " +
         std::string(third_index) + "\n";
}

/// The header of an ASCII cells file with the given grid line, then one layer
/// of one cell.
std::string cells_header(std::string_view grid) {
  return "strata-cells 1\n" + std::string(grid) +
         "\norigin 0 0 0\nspacing 1 1 1\nshell 1\nlayer 0 z=0.5\n11\n";
}

// fuzz_obj: `-index > count` negated the smallest long long, which overflows.
TEST(ReadObjHostile, SmallestRelativeIndexIsAnErrorNamingIt) {
  const auto soup =
      read_mesh_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808\n", "t.obj");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.obj:4");
  EXPECT_TRUE(contains(soup.error().message, "relative vertex index -9223372036854775808"))
      << soup.error().message;
}

// fuzz_ply: an element without properties was walked item by item, 2^64 - 1
// times.
TEST(ReadPlyHostile, ElementWithoutPropertiesIsSkippedWhateverItsCount) {
  std::string text = ply_triangle("int", "2");
  text.insert(text.find("element vertex"), "element material 18446744073709551615\n");
  const auto soup = read_mesh_bytes(text, "t.ply");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
}

// fuzz_ply: a float index of 1e30 was converted to int64 (undefined behaviour).
TEST(ReadPlyHostile, FloatIndexBeyondTheIntegerRangeIsAnError) {
  const auto soup = read_mesh_bytes(ply_triangle("float", "1e30"), "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.ply:13");
  EXPECT_TRUE(contains(soup.error().message, "vertex index 1e+30 is not a whole number"))
      << soup.error().message;
}

// fuzz_ply: 2^63 - 1 became 2^63 as a double, one past the int64 range. An ASCII value is now
// checked against its declared type (here int32) as it is read.
TEST(ReadPlyHostile, IntegerIndexRoundedUpToTwoToThe63IsAnError) {
  const auto soup = read_mesh_bytes(ply_triangle("int", "9223372036854775807"), "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message,
                       "bad number '9223372036854775807': out of range for a 32-bit integer"))
      << soup.error().message;
}

TEST(ReadPlyHostile, FractionalFloatIndexIsAnError) {
  const auto soup = read_mesh_bytes(ply_triangle("float", "1.5"), "t.ply");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "vertex index 1.5 is not a whole number"))
      << soup.error().message;
}

TEST(ReadPlyHostile, WholeFloatIndicesAreRead) {
  const auto soup = read_mesh_bytes(ply_triangle("float", "2.0"), "t.ply");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0][2], (Vec3{0, 1, 0}));
}

// fuzz_cells: the ASCII reader sized its layer buffer from the header alone;
// 100000 x 100000 cells asked for 10 GB before the first row.
TEST(CellsReaderHostile, AsciiGridLargerThanTheFileIsAnErrorBeforeAllocating) {
  test::TempDir dir;
  const auto path =
      test::write_text_file(dir / "big.cells.txt", cells_header("grid 100000 100000 1"));
  const auto read = read_cells(path);
  ASSERT_FALSE(read);
  EXPECT_EQ(read.error().code, ErrorCode::BadInput);
  EXPECT_EQ(read.error().location, path.string() + ": header");
  EXPECT_TRUE(contains(read.error().message, "grid 100000 x 100000 x 1 has more cells than a file"))
      << read.error().message;
}

// fuzz_cells: 4294967295 x 4294967295 cells a layer threw std::length_error.
TEST(CellsReaderHostile, AsciiLargestGridIsAnErrorNotAnException) {
  test::TempDir dir;
  const auto path =
      test::write_text_file(dir / "max.cells.txt", cells_header("grid 4294967295 4294967295 1"));
  const auto summary = summarize_cells(path);
  ASSERT_FALSE(summary);
  EXPECT_EQ(summary.error().location, path.string() + ": header");
}

// fuzz_cells: 2e9 layers of one cell made summarize_cells reserve 48 GB after
// the first layer.
TEST(CellsReaderHostile, AsciiLayerCountLargerThanTheFileIsAnErrorBeforeTheFirstLayer) {
  test::TempDir dir;
  const auto path =
      test::write_text_file(dir / "deep.cells.txt", cells_header("grid 1 1 2000000000"));
  int layers_seen = 0;
  const auto header = read_cells_layers(
      path, [&](const CellsHeader&, std::uint32_t, std::span<const CellClass>) -> Result<void> {
        ++layers_seen;
        return {};
      });
  ASSERT_FALSE(header);
  EXPECT_EQ(header.error().location, path.string() + ": header");
  EXPECT_EQ(layers_seen, 0);
}

}  // namespace
}  // namespace strata::io
