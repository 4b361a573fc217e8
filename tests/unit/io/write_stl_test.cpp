#include "strata/io/write_stl.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"

namespace strata::io {
namespace {

using strata::test::TempDir;

float f32_at(const std::string& bytes, std::size_t offset) {
  std::uint32_t bits = 0;
  for (int i = 3; i >= 0; --i) {
    bits = (bits << 8) | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(i)]);
  }
  return std::bit_cast<float>(bits);
}

std::uint32_t u32_at(const std::string& bytes, std::size_t offset) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) {
    v = (v << 8) | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(i)]);
  }
  return v;
}

/// The stored normal of binary facet f.
Vec3 binary_normal(const std::string& bytes, std::size_t f) {
  const std::size_t at = 84 + 50 * f;
  return {f32_at(bytes, at), f32_at(bytes, at + 4), f32_at(bytes, at + 8)};
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// "" when both soups hold the same triangles, corner for corner, bit for bit.
std::string bit_difference(const TriangleSoup& a, const TriangleSoup& b) {
  if (a.triangles.size() != b.triangles.size()) {
    return std::to_string(a.triangles.size()) + " vs " + std::to_string(b.triangles.size()) +
           " triangles";
  }
  for (std::size_t f = 0; f < a.triangles.size(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const Vec3& p = a.triangles[f][c];
      const Vec3& q = b.triangles[f][c];
      if (!same_bits(p.x, q.x) || !same_bits(p.y, q.y) || !same_bits(p.z, q.z)) {
        std::ostringstream out;
        out.precision(17);
        out << "facet " << f << " corner " << c << ": (" << p.x << ", " << p.y << ", " << p.z
            << ") vs (" << q.x << ", " << q.y << ", " << q.z << ")";
        return out.str();
      }
    }
  }
  return "";
}

TriangleSoup single_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  TriangleSoup soup;
  soup.triangles.push_back({a, b, c});
  return soup;
}

// --- stl_bytes, binary
// -----------------------------------------------------------------------

TEST(StlBytesBinary, HasHeaderCountAndFiftyBytesPerFacet) {
  const auto ring = mesh::make_ring(20, 12, 10, 16);
  const std::string bytes = stl_bytes(ring, StlEncoding::Binary);
  ASSERT_EQ(bytes.size(), 84 + 50 * ring.triangles.size());
  EXPECT_EQ(u32_at(bytes, 80), ring.triangles.size());
}

TEST(StlBytesBinary, HeaderNamesStrataAndDoesNotStartWithSolid) {
  const std::string bytes = stl_bytes(mesh::make_tetrahedron(), StlEncoding::Binary);
  EXPECT_EQ(bytes.substr(0, 6), "strata");
  EXPECT_NE(bytes.substr(0, 5), "solid");
}

TEST(StlBytesBinary, StoresCornersAsLittleEndianFloat32) {
  const std::string bytes =
      stl_bytes(single_triangle({1, 2, 3}, {-4, 0.5, 6}, {7, 8, -0.25}), StlEncoding::Binary);
  const std::vector<float> expected = {1, 2, 3, -4, 0.5F, 6, 7, 8, -0.25F};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(f32_at(bytes, 84 + 12 + 4 * i), expected[i]) << "value " << i;
  }
  EXPECT_EQ(bytes.substr(84 + 48, 2), std::string(2, '\0'));
}

TEST(StlBytesBinary, NormalFollowsTheVertexOrder) {
  const auto up = single_triangle({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
  const auto down = single_triangle({0, 0, 0}, {0, 2, 0}, {2, 0, 0});
  EXPECT_EQ(binary_normal(stl_bytes(up, StlEncoding::Binary), 0), (Vec3{0, 0, 1}));
  EXPECT_EQ(binary_normal(stl_bytes(down, StlEncoding::Binary), 0), (Vec3{0, 0, -1}));
}

TEST(StlBytesBinary, NormalIsNormalised) {
  const auto tilted = single_triangle({0, 0, 0}, {3, 0, 0}, {0, 1, 1});
  const Vec3 n = binary_normal(stl_bytes(tilted, StlEncoding::Binary), 0);
  EXPECT_NEAR(n.x * n.x + n.y * n.y + n.z * n.z, 1.0, 1e-6);
  EXPECT_NEAR(n.y, -std::sqrt(0.5), 1e-7);
  EXPECT_NEAR(n.z, std::sqrt(0.5), 1e-7);
}

TEST(StlBytesBinary, BoxNormalsPointOutward) {
  const auto box = mesh::make_box({0, 0, 0}, {1, 1, 1});
  const std::string bytes = stl_bytes(box, StlEncoding::Binary);
  for (std::size_t f = 0; f < box.triangles.size(); ++f) {
    const Vec3 n = binary_normal(bytes, f);
    const Vec3& a = box.triangles[f][0];
    // Each box facet lies in a face plane; the normal points from the centre
    // towards it.
    const double outward = n.x * (a.x - 0.5) + n.y * (a.y - 0.5) + n.z * (a.z - 0.5);
    EXPECT_DOUBLE_EQ(outward, 0.5) << "facet " << f;
  }
}

TEST(StlBytesBinary, DegenerateFacetGetsZeroNormal) {
  const auto flat = single_triangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
  EXPECT_EQ(binary_normal(stl_bytes(flat, StlEncoding::Binary), 0), (Vec3{0, 0, 0}));
}

TEST(StlBytesBinary, ValuesBeyondFloat32BecomeInfinityAndNanStaysNan) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string bytes =
      stl_bytes(single_triangle({1e39, -1e39, nan}, {0, 0, 0}, {0, 1, 0}), StlEncoding::Binary);
  EXPECT_EQ(f32_at(bytes, 84 + 12), std::numeric_limits<float>::infinity());
  EXPECT_EQ(f32_at(bytes, 84 + 16), -std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isnan(f32_at(bytes, 84 + 20)));
  EXPECT_EQ(binary_normal(bytes, 0), (Vec3{0, 0, 0}));  // no normal of an infinite facet
}

TEST(StlBytesBinary, AFacetWithAnInfiniteEdgeGetsZeroNormal) {
  // 1e39 becomes +inf: the cross product is (0, -inf, inf), of infinite length, not NaN.
  const auto infinite = single_triangle({0, 0, 0}, {1e39, 0, 0}, {0, 1, 1});
  EXPECT_EQ(binary_normal(stl_bytes(infinite, StlEncoding::Binary), 0), (Vec3{0, 0, 0}));
}

TEST(StlBytesBinary, IgnoresStoredNormals) {
  auto soup = single_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  soup.stored_normals.push_back({1, 0, 0});
  EXPECT_EQ(binary_normal(stl_bytes(soup, StlEncoding::Binary), 0), (Vec3{0, 0, 1}));
}

// --- stl_bytes, ASCII
// ------------------------------------------------------------------------

TEST(StlBytesAscii, IsOneSolidNamedStrata) {
  const std::string text = stl_bytes(mesh::make_tetrahedron(), StlEncoding::Ascii);
  EXPECT_EQ(text.rfind("solid strata\n", 0), 0U);
  EXPECT_TRUE(text.ends_with("endsolid strata\n"));
}

TEST(StlBytesAscii, WritesOneFacetBlockPerTriangle) {
  const std::string text = stl_bytes(mesh::make_box({0, 0, 0}, {1, 1, 1}), StlEncoding::Ascii);
  std::size_t facets = 0;
  std::size_t vertices = 0;
  for (std::size_t at = text.find("facet normal"); at != std::string::npos;
       at = text.find("facet normal", at + 1)) {
    ++facets;
  }
  for (std::size_t at = text.find("vertex"); at != std::string::npos;
       at = text.find("vertex", at + 1)) {
    ++vertices;
  }
  EXPECT_EQ(facets, 12U);
  EXPECT_EQ(vertices, 36U);
}

TEST(StlBytesAscii, PrintsNineSignificantDigits) {
  const std::string text =
      stl_bytes(single_triangle({0.1, 0, 0}, {1, 0, 0}, {0, 1, 1e-7}), StlEncoding::Ascii);
  EXPECT_NE(text.find("vertex 0.100000001 0 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("vertex 0 1 1.00000001e-07\n"), std::string::npos) << text;
}

TEST(StlBytesAscii, EveryNumberReadsBackToTheSameFloat) {
  const auto sphere = mesh::make_sphere(10, 2);
  std::istringstream in(stl_bytes(sphere, StlEncoding::Ascii));
  std::string word;
  std::size_t f = 0;
  int c = 0;
  while (in >> word) {
    if (word != "vertex") continue;
    std::string x, y, z;
    in >> x >> y >> z;
    const Vec3& p = sphere.triangles[f][c];
    EXPECT_EQ(std::strtof(x.c_str(), nullptr), static_cast<float>(p.x));
    EXPECT_EQ(std::strtof(y.c_str(), nullptr), static_cast<float>(p.y));
    EXPECT_EQ(std::strtof(z.c_str(), nullptr), static_cast<float>(p.z));
    if (++c == 3) {
      c = 0;
      ++f;
    }
  }
  EXPECT_EQ(f, sphere.triangles.size());
}

// --- write_stl and read_mesh
// -----------------------------------------------------------------

class WriteStlRoundTrip : public ::testing::TestWithParam<StlEncoding> {};

TEST_P(WriteStlRoundTrip, TetrahedronReadsBackBitIdentical) {
  TempDir dir;
  const auto tet = mesh::make_tetrahedron();
  ASSERT_TRUE(write_stl(dir / "tet.stl", tet, GetParam()));
  const auto back = read_mesh(dir / "tet.stl");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(bit_difference(*back, tet), "");
}

TEST_P(WriteStlRoundTrip, RingReadsBackBitIdentical) {
  TempDir dir;
  const auto ring = mesh::make_ring(20, 12, 10, 128);
  ASSERT_TRUE(write_stl(dir / "ring.stl", ring, GetParam()));
  const auto back = read_mesh(dir / "ring.stl");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(bit_difference(*back, ring), "");
}

TEST_P(WriteStlRoundTrip, SphereReadsBackBitIdentical) {
  TempDir dir;
  const auto sphere = mesh::make_sphere(10, 3);
  ASSERT_TRUE(write_stl(dir / "sphere.stl", sphere, GetParam()));
  const auto back = read_mesh(dir / "sphere.stl");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(bit_difference(*back, sphere), "");
}

TEST_P(WriteStlRoundTrip, NegativeZeroKeepsItsSign) {
  TempDir dir;
  const auto soup = single_triangle({-0.0, 0, 0}, {1, -0.0, 0}, {0, 1, -0.0});
  ASSERT_TRUE(write_stl(dir / "zero.stl", soup, GetParam()));
  const auto back = read_mesh(dir / "zero.stl");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(bit_difference(*back, soup), "");
}

TEST_P(WriteStlRoundTrip, DoubleCoordinatesComeBackRoundedToFloat32) {
  TempDir dir;
  const auto soup = single_triangle({0.1, 0.2, 0.3}, {1.1, 0.2, 0.3}, {0.1, 1.2, 0.3});
  ASSERT_TRUE(write_stl(dir / "tenths.stl", soup, GetParam()));
  const auto back = read_mesh(dir / "tenths.stl");
  ASSERT_TRUE(back) << back.error().to_string();
  ASSERT_EQ(back->triangles.size(), 1U);
  EXPECT_TRUE(same_bits(back->triangles[0][0].x, static_cast<double>(0.1F)));
  EXPECT_TRUE(same_bits(back->triangles[0][2].y, static_cast<double>(1.2F)));
}

TEST_P(WriteStlRoundTrip, KeepsTheFacetOrder) {
  TempDir dir;
  const auto shuffled = mesh::shuffle_facets(mesh::make_ring(20, 12, 10, 32), 11);
  ASSERT_TRUE(write_stl(dir / "shuffled.stl", shuffled, GetParam()));
  const auto back = read_mesh(dir / "shuffled.stl");
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(bit_difference(*back, shuffled), "");
}

INSTANTIATE_TEST_SUITE_P(Encodings, WriteStlRoundTrip,
                         ::testing::Values(StlEncoding::Binary, StlEncoding::Ascii),
                         [](const ::testing::TestParamInfo<StlEncoding>& info) {
                           return info.param == StlEncoding::Binary ? "Binary" : "Ascii";
                         });

TEST(WriteStl, ReadBackIdentifiesTheEncoding) {
  TempDir dir;
  const auto tet = mesh::make_tetrahedron();
  ASSERT_TRUE(write_stl(dir / "b.stl", tet, StlEncoding::Binary));
  ASSERT_TRUE(write_stl(dir / "a.stl", tet, StlEncoding::Ascii));
  const auto binary = read_mesh(dir / "b.stl");
  const auto ascii = read_mesh(dir / "a.stl");
  ASSERT_TRUE(binary && ascii);
  EXPECT_EQ(binary->format, "stl-binary");
  EXPECT_EQ(ascii->format, "stl-ascii");
}

TEST(WriteStl, ReadBackRaisesNoWarnings) {
  TempDir dir;
  for (const auto encoding : {StlEncoding::Binary, StlEncoding::Ascii}) {
    ASSERT_TRUE(write_stl(dir / "ring.stl", mesh::make_ring(20, 12, 10, 32), encoding));
    const auto back = read_mesh(dir / "ring.stl");
    ASSERT_TRUE(back) << back.error().to_string();
    EXPECT_TRUE(back->diagnostics.empty()) << back->diagnostics.front().message;
  }
}

TEST(WriteStl, FileHoldsExactlyTheStlBytes) {
  TempDir dir;
  const auto ring = mesh::make_ring(20, 12, 10, 16);
  ASSERT_TRUE(write_stl(dir / "ring.stl", ring, StlEncoding::Ascii));
  EXPECT_EQ(test::read_file(dir / "ring.stl"), stl_bytes(ring, StlEncoding::Ascii));
}

TEST(WriteStl, WritesModelsLargerThanOneChunkWhole) {
  TempDir dir;
  const auto ring = mesh::make_ring(20, 12, 10, 8200);  // 65600 facets: two write chunks
  for (const auto encoding : {StlEncoding::Binary, StlEncoding::Ascii}) {
    ASSERT_TRUE(write_stl(dir / "ring.stl", ring, encoding));
    EXPECT_TRUE(test::read_file(dir / "ring.stl") == stl_bytes(ring, encoding));
  }
}

TEST(WriteStl, DefaultsToBinary) {
  TempDir dir;
  const auto tet = mesh::make_tetrahedron();
  ASSERT_TRUE(write_stl(dir / "tet.stl", tet));
  EXPECT_EQ(test::read_file(dir / "tet.stl"), stl_bytes(tet, StlEncoding::Binary));
}

TEST(WriteStl, LeavesOnlyTheFinalFileInTheFolder) {
  TempDir dir;
  ASSERT_TRUE(write_stl(dir / "tet.stl", mesh::make_tetrahedron()));
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    names.push_back(entry.path().filename().string());
  }
  EXPECT_EQ(names, std::vector<std::string>{"tet.stl"});
}

TEST(WriteStl, RejectsNonFiniteCoordinateNamingTheFacet) {
  TempDir dir;
  auto soup = mesh::make_tetrahedron();
  soup.triangles[2][1].y = std::numeric_limits<double>::quiet_NaN();
  const auto written = write_stl(dir / "nan.stl", soup);
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error().code, ErrorCode::BadInput);
  EXPECT_NE(written.error().location.find("facet 2"), std::string::npos)
      << written.error().to_string();
  EXPECT_FALSE(std::filesystem::exists(dir / "nan.stl"));
}

TEST(WriteStl, RejectsCoordinateBeyondFloat32Range) {
  TempDir dir;
  auto soup = mesh::make_tetrahedron();
  soup.triangles[0][0].x = 1e39;
  const auto written = write_stl(dir / "huge.stl", soup, StlEncoding::Ascii);
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error().code, ErrorCode::BadInput);
  EXPECT_FALSE(std::filesystem::exists(dir / "huge.stl"));
}

TEST(WriteStl, FailsCleanlyInAMissingFolder) {
  TempDir dir;
  const auto written = write_stl(dir / "no" / "such" / "tet.stl", mesh::make_tetrahedron());
  ASSERT_FALSE(written);
  EXPECT_FALSE(written.error().to_string().empty());
}

TEST(WriteStl, ReplacesAnExistingFile) {
  TempDir dir;
  ASSERT_TRUE(write_stl(dir / "model.stl", mesh::make_ring(20, 12, 10, 64)));
  ASSERT_TRUE(write_stl(dir / "model.stl", mesh::make_tetrahedron()));
  EXPECT_EQ(test::read_file(dir / "model.stl"),
            stl_bytes(mesh::make_tetrahedron(), StlEncoding::Binary));
}

// --- the committed sample models (data/, made by strata-make-models)
// ----------------------------

/// Largest coordinate difference between two soups of the same size (infinity
/// otherwise).
double max_coordinate_difference(const TriangleSoup& a, const TriangleSoup& b) {
  if (a.triangles.size() != b.triangles.size()) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (std::size_t f = 0; f < a.triangles.size(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const Vec3& p = a.triangles[f][c];
      const Vec3& q = b.triangles[f][c];
      worst = std::max({worst, std::abs(p.x - q.x), std::abs(p.y - q.y), std::abs(p.z - q.z)});
    }
  }
  return worst;
}

TEST(SampleData, TetrahedronFilesHoldTheGeneratedTetrahedron) {
  const std::filesystem::path data = STRATA_DATA_DIR;
  for (const char* name : {"tetrahedron.stl", "tetrahedron_ascii.stl"}) {
    const auto read = read_mesh(data / name);
    ASSERT_TRUE(read) << read.error().to_string();
    EXPECT_EQ(bit_difference(*read, mesh::make_tetrahedron()), "") << name;
  }
}

TEST(SampleData, RingAndSphereFilesHoldTheGeneratedModels) {
  const std::filesystem::path data = STRATA_DATA_DIR;
  const auto ring = read_mesh(data / "ring.stl");
  const auto sphere = read_mesh(data / "sphere.stl");
  ASSERT_TRUE(ring) << ring.error().to_string();
  ASSERT_TRUE(sphere) << sphere.error().to_string();
  // Corners come from sin/cos; allow one float32 step (at 20 mm: 1.9e-6) for
  // another libm.
  EXPECT_LE(max_coordinate_difference(*ring, mesh::make_ring(20, 12, 10, 128)), 2e-6);
  EXPECT_LE(max_coordinate_difference(*sphere, mesh::make_sphere(10, 4)), 1e-6);
}

}  // namespace
}  // namespace strata::io
