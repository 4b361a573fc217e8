#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/stl_format_internal.hpp"
#include "strata/io/read_mesh.hpp"
#include "support/mesh_reading.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"

namespace strata::io {
namespace {

using test::contains;
using test::corpus_file;
using test::expect_read_with_diagnostic;
using test::expect_refused;
using test::find_diagnostic;

// ---------------------------------------------------------------------------------------------
// Helpers: STL files built in memory.

using Float3 = std::array<float, 3>;

struct Facet {
  Float3 normal;
  std::array<Float3, 3> corners;
};

std::string binary_stl(const std::vector<Facet>& facets, std::string_view header = "test",
                       std::optional<std::uint32_t> declared = std::nullopt,
                       std::string_view trailing = {}, std::uint16_t attribute = 0) {
  std::string out(header.substr(0, 80));
  out.resize(80, '\0');
  const std::uint32_t count = declared.value_or(static_cast<std::uint32_t>(facets.size()));
  out.append(reinterpret_cast<const char*>(&count), 4);  // tests run on little-endian hosts
  for (const Facet& f : facets) {
    out.append(reinterpret_cast<const char*>(f.normal.data()), 12);
    for (const Float3& c : f.corners) out.append(reinterpret_cast<const char*>(c.data()), 12);
    out.append(reinterpret_cast<const char*>(&attribute), 2);
  }
  out.append(trailing);
  return out;
}

/// ASCII STL of the facets, each number printed with `format` (a printf format for one double).
std::string ascii_stl(const std::vector<Facet>& facets, const char* format = "%.9g",
                      std::string_view eol = "\n") {
  auto number = [&](float v) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, format, static_cast<double>(v));
    return std::string(buffer);
  };
  std::string out = "solid test";
  out += eol;
  for (const Facet& f : facets) {
    out += "  facet normal " + number(f.normal[0]) + " " + number(f.normal[1]) + " " +
           number(f.normal[2]);
    out += eol;
    out += "    outer loop";
    out += eol;
    for (const Float3& c : f.corners) {
      out += "      vertex " + number(c[0]) + " " + number(c[1]) + " " + number(c[2]);
      out += eol;
    }
    out += "    endloop";
    out += eol;
    out += "  endfacet";
    out += eol;
  }
  out += "endsolid test";
  out += eol;
  return out;
}

std::vector<Facet> two_facets() {
  return {
      Facet{{0.0f, 0.0f, 1.0f}, {{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}}},
      Facet{{0.0f, 0.0f, -1.0f},
            {{{0.1f, -3.25f, 1e-7f}, {2.5f, 0.75f, -0.0f}, {123.456f, 7.0f, 8.0f}}}},
  };
}

/// Bitwise equality of two soups' triangles and stored normals (so -0 differs from +0).
::testing::AssertionResult bit_identical(const TriangleSoup& a, const TriangleSoup& b) {
  if (a.triangles.size() != b.triangles.size()) {
    return ::testing::AssertionFailure()
           << a.triangles.size() << " vs " << b.triangles.size() << " triangles";
  }
  if (a.stored_normals.size() != b.stored_normals.size()) {
    return ::testing::AssertionFailure() << "stored normal counts differ";
  }
  auto same = [](const Vec3& p, const Vec3& q) {
    return std::bit_cast<std::uint64_t>(p.x) == std::bit_cast<std::uint64_t>(q.x) &&
           std::bit_cast<std::uint64_t>(p.y) == std::bit_cast<std::uint64_t>(q.y) &&
           std::bit_cast<std::uint64_t>(p.z) == std::bit_cast<std::uint64_t>(q.z);
  };
  for (std::size_t f = 0; f < a.triangles.size(); ++f) {
    for (int c = 0; c < 3; ++c) {
      if (!same(a.triangles[f][c], b.triangles[f][c])) {
        return ::testing::AssertionFailure()
               << "facet " << f << " corner " << c << ": (" << a.triangles[f][c].x << ", "
               << a.triangles[f][c].y << ", " << a.triangles[f][c].z << ") vs ("
               << b.triangles[f][c].x << ", " << b.triangles[f][c].y << ", " << b.triangles[f][c].z
               << ")";
      }
    }
    if (!same(a.stored_normals[f], b.stored_normals[f])) {
      return ::testing::AssertionFailure() << "facet " << f << ": stored normals differ";
    }
  }
  return ::testing::AssertionSuccess();
}

Vec3 as_vec3(const Float3& p) { return Vec3{p[0], p[1], p[2]}; }

const std::string kTriangle =
    "solid t\n"
    " facet normal 0 0 1\n"
    "  outer loop\n"
    "   vertex 0 0 0\n"
    "   vertex 1 0 0\n"
    "   vertex 0 1 0\n"
    "  endloop\n"
    " endfacet\n"
    "endsolid t\n";

/// kTriangle with its vertex line `line` (1-based, 4..6) replaced.
std::string triangle_with_vertex_line(int line, std::string_view replacement) {
  std::string text = kTriangle;
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = text.find('\n', start) + 1;
  const std::size_t end = text.find('\n', start);
  text.replace(start, end - start, replacement);
  return text;
}

// ---------------------------------------------------------------------------------------------
// Binary STL

TEST(ReadStlBinary, ReadsCornersAndStoredNormalsExactly) {
  const auto facets = two_facets();
  const auto soup = read_stl_bytes(binary_stl(facets), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary");
  ASSERT_EQ(soup->triangles.size(), 2u);
  ASSERT_EQ(soup->stored_normals.size(), 2u);
  for (std::size_t f = 0; f < facets.size(); ++f) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(soup->triangles[f][c], as_vec3(facets[f].corners[c]));
    EXPECT_EQ(soup->stored_normals[f], as_vec3(facets[f].normal));
  }
  EXPECT_TRUE(soup->diagnostics.empty());
}

TEST(ReadStlBinary, FloatToDoubleConversionIsExact) {
  const float tricky = 0.1f;  // not 0.1 in double: the float's own value must come through
  const auto soup = read_stl_bytes(
      binary_stl({Facet{{0, 0, 1}, {{{tricky, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}}), "t.stl");
  ASSERT_TRUE(soup);
  EXPECT_EQ(soup->triangles[0][0].x, static_cast<double>(tricky));
  EXPECT_NE(soup->triangles[0][0].x, 0.1);
}

TEST(ReadStlBinary, NegativeZeroKeepsItsSign) {
  const auto soup = read_stl_bytes(
      binary_stl({Facet{{0, 0, 1}, {{{-0.0f, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}}), "t.stl");
  ASSERT_TRUE(soup);
  EXPECT_TRUE(std::signbit(soup->triangles[0][0].x));
}

TEST(ReadStlBinary, HeaderStartingWithSolidIsStillBinary) {
  const auto soup = read_stl_bytes(binary_stl(two_facets(), "solid cube"), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary");
  EXPECT_EQ(soup->triangles.size(), 2u);
}

TEST(ReadStlBinary, HeaderThatLooksLikeAsciiIsStillBinary) {
  const auto soup = read_stl_bytes(
      binary_stl(two_facets(), "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"),
      "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary");
  EXPECT_EQ(soup->triangles.size(), 2u);
}

TEST(ReadStlBinary, ColorMaterialHeaderIsStillBinary) {
  using namespace std::string_literals;
  const std::string header =
      "COLOR="s + "\xff\x80\x00\xff"s + ",MATERIAL="s + "\x80\x80\x80\xff\x40\x40\x40\xff"s;
  const auto soup = read_stl_bytes(binary_stl(two_facets(), header), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary");
  EXPECT_EQ(soup->triangles.size(), 2u);
}

TEST(ReadStlBinary, AttributeBytesAreIgnored) {
  const auto plain = read_stl_bytes(binary_stl(two_facets()), "t.stl");
  const auto coloured =
      read_stl_bytes(binary_stl(two_facets(), "test", std::nullopt, {}, 0xfc1f), "t.stl");
  ASSERT_TRUE(plain);
  ASSERT_TRUE(coloured);
  EXPECT_TRUE(bit_identical(*plain, *coloured));
  EXPECT_TRUE(coloured->diagnostics.empty());
}

TEST(ReadStlBinary, StrayTrailingByteIsReadWithWarning) {
  const auto soup =
      read_stl_bytes(binary_stl(two_facets(), "solid x", std::nullopt, "\n"), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary");
  EXPECT_EQ(soup->triangles.size(), 2u);
  const Diagnostic* warning = find_diagnostic(*soup, "stl.trailing_bytes");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->severity, Severity::Warning);
  EXPECT_TRUE(contains(warning->message, "t.stl")) << warning->message;
  EXPECT_TRUE(contains(warning->message, "1 stray byte")) << warning->message;
}

TEST(ReadStlBinary, FortyNineTrailingBytesAreStillBinary) {
  const auto soup =
      read_stl_bytes(binary_stl(two_facets(), "t", std::nullopt, std::string(49, 'x')), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 2u);
  ASSERT_NE(find_diagnostic(*soup, "stl.trailing_bytes"), nullptr);
  EXPECT_TRUE(contains(find_diagnostic(*soup, "stl.trailing_bytes")->message, "49 stray bytes"));
}

TEST(ReadStlBinary, ShortFileNamesDeclaredAndPresentFacets) {
  // The example of STYLE §4, to the byte.
  std::vector<Facet> facets(1187, two_facets()[0]);
  const auto soup = read_stl_bytes(binary_stl(facets, "cube", 1200), "cube.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().code, ErrorCode::BadInput);
  EXPECT_EQ(soup.error().to_string(),
            "cube.stl: header declares 1200 facets, file ends after 1187 (59434 of 60084 bytes)");
}

TEST(ReadStlBinary, TruncationInsideAFacetIsError) {
  std::string bytes = binary_stl(two_facets());
  bytes.resize(bytes.size() - 20);
  const auto soup = read_stl_bytes(bytes, "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl");
  EXPECT_TRUE(contains(soup.error().message, "header declares 2 facets, file ends after 1"))
      << soup.error().message;
}

TEST(ReadStlBinary, FileLongerByAWholeFacetIsError) {
  const auto soup = read_stl_bytes(binary_stl(two_facets(), "x", 1), "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "header declares 1 facets")) << soup.error().message;
  EXPECT_TRUE(contains(soup.error().message, "184 bytes long")) << soup.error().message;
}

TEST(ReadStlBinary, SolidHeaderWithWrongCountReportsTheSizes) {
  const auto soup = read_stl_bytes(binary_stl(two_facets(), "solid cube", 7), "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "header declares 7 facets")) << soup.error().message;
  EXPECT_TRUE(contains(soup.error().message, "not ASCII STL either")) << soup.error().message;
}

TEST(ReadStlBinary, ZeroDeclaredFacetsIsError) {
  const auto soup = read_stl_bytes(binary_stl({}), "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl");
  EXPECT_TRUE(contains(soup.error().message, "no facets")) << soup.error().message;
}

TEST(ReadStlBinary, NanCornerIsErrorNamingTheFacet) {
  auto facets = two_facets();
  facets[1].corners[2][1] = std::numeric_limits<float>::quiet_NaN();
  const auto soup = read_stl_bytes(binary_stl(facets), "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl: facet 1");
  EXPECT_TRUE(contains(soup.error().message, "non-finite")) << soup.error().message;
}

TEST(ReadStlBinary, InfiniteCornerIsError) {
  auto facets = two_facets();
  facets[0].corners[0][2] = -std::numeric_limits<float>::infinity();
  const auto soup = read_stl_bytes(binary_stl(facets), "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl: facet 0");
}

TEST(ReadStlBinary, NanNormalIsIgnoredAndTheFacetKept) {
  auto facets = two_facets();
  facets[1].normal = {std::numeric_limits<float>::quiet_NaN(), 0, 0};
  const auto soup = read_stl_bytes(binary_stl(facets), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 2u);
  EXPECT_EQ(soup->stored_normals[1], Vec3{});
  const Diagnostic* warning = find_diagnostic(*soup, "stl.bad_normal");
  ASSERT_NE(warning, nullptr);
  EXPECT_TRUE(contains(warning->message, "t.stl: facet 1")) << warning->message;
}

/// `n` facets along x, facet f's corners offset by f: every one distinct.
std::vector<Facet> many_facets(int n) {
  std::vector<Facet> facets;
  for (int f = 0; f < n; ++f) {
    const auto x = static_cast<float>(f);
    facets.push_back(Facet{{0, 0, 1}, {{{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}}}});
  }
  return facets;
}

TEST(ReadStlBinary, ManyFacetsReadInPartsKeepTheirOrderAndReportTheFirstBadCorner) {
  // 50,000 facets are converted in parts: the soup is in file order, and of two bad corners far
  // apart the error names the first facet, whichever part is done first.
  auto facets = many_facets(50000);
  const auto soup = read_stl_bytes(binary_stl(facets), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 50000u);
  for (int f = 0; f < 50000; f += 997) {
    EXPECT_EQ(soup->triangles[f][1], (Vec3{f + 1.0, 0, 0}));
    EXPECT_EQ(soup->stored_normals[f], (Vec3{0, 0, 1}));
  }
  facets[41000].corners[2][1] = std::numeric_limits<float>::quiet_NaN();
  facets[20500].corners[1][0] = std::numeric_limits<float>::infinity();
  const auto bad = read_stl_bytes(binary_stl(facets), "t.stl");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().location, "t.stl: facet 20500");
  EXPECT_TRUE(contains(bad.error().message, "corner 1 has a non-finite coordinate (inf, 0, 0)"))
      << bad.error().message;
}

TEST(ReadStlBinary, BadNormalsOfManyFacetsAreReportedInFileOrder) {
  auto facets = many_facets(50000);
  for (const int f : {45000, 7, 30000}) {
    facets[f].normal = {0, std::numeric_limits<float>::infinity(), 0};
  }
  const auto soup = read_stl_bytes(binary_stl(facets), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->stored_normals[30000], Vec3{});
  EXPECT_EQ(soup->stored_normals[30001], (Vec3{0, 0, 1}));
  std::vector<std::string> messages;
  for (const Diagnostic& d : soup->diagnostics) {
    if (d.code == "stl.bad_normal") messages.push_back(d.message);
  }
  ASSERT_FALSE(messages.empty());
  const std::string all = fmt::format("{}", fmt::join(messages, "\n"));
  const auto at = [&](const char* facet) { return all.find(facet); };
  ASSERT_NE(at("facet 7:"), std::string::npos) << all;
  ASSERT_NE(at("facet 30000"), std::string::npos) << all;
  EXPECT_LT(at("facet 7:"), at("facet 30000")) << all;
}

TEST(ReadStlBinary, CountAboveTheLimitFails) {
  ReadLimits limits;
  limits.max_triangles = 1;
  const auto soup = read_stl_bytes(binary_stl(two_facets()), "t.stl", limits);
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "limit")) << soup.error().message;
}

TEST(ReadStlBinary, HugeDeclaredCountFailsFast) {
  // 4294967295 facets would be 200 GiB: rejected from the size alone, nothing is reserved.
  const auto soup = read_stl_bytes(binary_stl(two_facets(), "x", 0xFFFFFFFFu), "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "header declares 4294967295 facets"))
      << soup.error().message;
}

TEST(ReadStlBinary, CoordinatesAtFloatMaxAreKept) {
  const float big = std::numeric_limits<float>::max();
  const auto soup = read_stl_bytes(
      binary_stl({Facet{{0, 0, 1}, {{{big, -big, 0}, {-big, big, 1}, {0, 0, big}}}}}), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles[0][0].x, 3.4028234663852886e38);
  EXPECT_EQ(soup->triangles[0][0].y, -3.4028234663852886e38);
}

TEST(ReadStlBinary, MapCoordinatesKeepTheirFloat32Bits) {
  // UTM-like coordinates: 4.8e6 m with the half-metre steps float32 can hold there.
  const Float3 a{4812345.5f, 5432101.0f, 312.25f};
  const Float3 b{4812346.0f, 5432101.5f, 312.5f};
  const Float3 c{4812345.5f, 5432102.0f, 313.0f};
  const auto soup = read_stl_bytes(binary_stl({Facet{{0, 0, 1}, {{a, b, c}}}}), "t.stl");
  ASSERT_TRUE(soup);
  EXPECT_EQ(soup->triangles[0][0].x, 4812345.5);
  EXPECT_EQ(soup->triangles[0][1].y, 5432101.5);
}

// ---------------------------------------------------------------------------------------------
// Detection

TEST(ReadStlDetection, EmptyBytesAreAnError) {
  const auto soup = read_stl_bytes("", "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl");
  EXPECT_TRUE(contains(soup.error().message, "0 bytes")) << soup.error().message;
}

TEST(ReadStlDetection, ShortTextThatIsNotSolidIsAnError) {
  const auto soup = read_stl_bytes("hello world\n", "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_TRUE(contains(soup.error().message, "not an STL file")) << soup.error().message;
}

TEST(ReadStlDetection, BinaryLayoutComparesCountWithSize) {
  const std::string exact = binary_stl(two_facets());
  EXPECT_EQ(detail::stl_binary_layout(exact).fit, detail::StlBinaryFit::Exact);
  EXPECT_EQ(detail::stl_binary_layout(exact + "ab").fit, detail::StlBinaryFit::TrailingBytes);
  EXPECT_EQ(detail::stl_binary_layout(exact + std::string(50, 'a')).fit,
            detail::StlBinaryFit::Mismatch);
  EXPECT_EQ(detail::stl_binary_layout(exact.substr(0, 100)).fit, detail::StlBinaryFit::Mismatch);
  EXPECT_EQ(detail::stl_binary_layout(exact.substr(0, 83)).fit, detail::StlBinaryFit::TooShort);
}

TEST(ReadStlDetection, SolidIsRecognisedAfterWhitespaceInAnyCase) {
  EXPECT_TRUE(detail::starts_with_solid("solid x"));
  EXPECT_TRUE(detail::starts_with_solid(" \t\r\n SOLID"));
  EXPECT_TRUE(detail::starts_with_solid("\xEF\xBB\xBFsolid x"));
  EXPECT_FALSE(detail::starts_with_solid("solidworks"));
  EXPECT_FALSE(detail::starts_with_solid("x solid"));
}

TEST(ReadStlDetection, AsciiWithLeadingBlankLinesIsAscii) {
  const auto soup = read_stl_bytes("\n\n   " + kTriangle, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-ascii");
  EXPECT_EQ(soup->triangles.size(), 1u);
}

// ---------------------------------------------------------------------------------------------
// Binary STL files, read a block of records at a time

/// `count` facets of random coordinates; every 5,000th stored normal is NaN.
std::vector<Facet> random_facets(std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f);
  std::vector<Facet> facets(count);
  for (std::size_t f = 0; f < count; ++f) {
    for (float& v : facets[f].normal) v = coordinate(rng);
    for (Float3& corner : facets[f].corners) {
      for (float& v : corner) v = coordinate(rng);
    }
    if (f % 5000 == 17) facets[f].normal[1] = std::numeric_limits<float>::quiet_NaN();
  }
  return facets;
}

/// Reads `bytes` both from a file named `file_name` and from memory under the file's path, and
/// expects the same soup, diagnostics and format, or the same error.
void expect_file_reads_as_bytes(std::string_view file_name, const std::string& bytes,
                                const CoordinateScale& scale = {}) {
  SCOPED_TRACE(std::string(file_name));
  const test::TempDir dir("read-stl");
  const auto path = dir / std::string(file_name);
  test::write_file(path, bytes);
  const auto from_file = read_mesh(path, {}, scale);
  const auto from_bytes = read_mesh_bytes(bytes, path.string(), {}, scale);
  ASSERT_EQ(from_file.has_value(), from_bytes.has_value())
      << (from_file ? from_bytes.error().to_string() : from_file.error().to_string());
  if (!from_file) {
    EXPECT_EQ(from_file.error().to_string(), from_bytes.error().to_string());
    return;
  }
  EXPECT_TRUE(bit_identical(*from_file, *from_bytes));
  EXPECT_EQ(from_file->format, from_bytes->format);
  ASSERT_EQ(from_file->diagnostics.size(), from_bytes->diagnostics.size());
  for (std::size_t i = 0; i < from_file->diagnostics.size(); ++i) {
    EXPECT_EQ(from_file->diagnostics[i].code, from_bytes->diagnostics[i].code);
    EXPECT_EQ(from_file->diagnostics[i].message, from_bytes->diagnostics[i].message);
  }
}

TEST(ReadStlBinaryFile, AFileOfManyBlocksReadsAsItsBytesDo) {
  // 40,000 facets are several blocks of records; NaN normals are warned of from every block.
  const std::string bytes = binary_stl(random_facets(40000, 3), "blocks", std::nullopt, "xyz");
  expect_file_reads_as_bytes("blocks.stl", bytes);
  expect_file_reads_as_bytes("blocks.stl", bytes, CoordinateScale{LengthUnit::Centimetre, 1.5});
  const auto soup = read_mesh_bytes(bytes, "blocks.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 40000u);
  const Diagnostic* normals = find_diagnostic(*soup, "stl.bad_normal");
  ASSERT_NE(normals, nullptr);
  EXPECT_TRUE(contains(normals->message, "facet 17:")) << normals->message;
  ASSERT_NE(find_diagnostic(*soup, "stl.trailing_bytes"), nullptr);
}

TEST(ReadStlBinaryFile, ANonFiniteCornerInALaterBlockNamesItsFacet) {
  std::vector<Facet> facets = random_facets(40000, 4);
  facets[33333].corners[2][0] = std::numeric_limits<float>::infinity();
  facets[39999].corners[0][1] = std::numeric_limits<float>::quiet_NaN();
  const std::string bytes = binary_stl(facets);
  expect_file_reads_as_bytes("corner.stl", bytes);
  const auto soup = read_mesh_bytes(bytes, "corner.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "corner.stl: facet 33333");
  EXPECT_TRUE(contains(soup.error().message, "corner 2 has a non-finite coordinate"))
      << soup.error().message;
}

TEST(ReadStlBinaryFile, AFileIsDispatchedAsItsBytesAre) {
  // What is decided from a file's first 84 bytes and its size must be what the whole bytes
  // decide: names that refuse or choose a format, and heads of other formats that happen to
  // fit a binary STL's size.
  const std::vector<Facet> facets = two_facets();
  const std::vector<std::string> contents = {
      binary_stl(facets),
      binary_stl(facets, "solid looks like text"),
      binary_stl(facets, "ply\nformat binary_little_endian 1.0"),
      binary_stl(facets, std::string("PK\x03\x04", 4)),
      binary_stl(facets, std::string("\x1f\x8b", 2)),
      binary_stl(facets, "x", 7),
      binary_stl(facets, "x", std::nullopt, std::string(50, 'y')),
      std::string(84, '\0'),
      "solid",
  };
  for (const std::string& bytes : contents) {
    for (const char* name : {"m.stl", "m.STL", "m.obj", "m.ply", "m.off", "m.amf", "m.3mf", "m"}) {
      expect_file_reads_as_bytes(name, bytes);
    }
  }
}

TEST(ReadStlBinaryFile, RecordsThatCannotBeReadAreAnErrorNamingThem) {
  // A file that shrinks or fails while its blocks are read: the error names the first facets
  // not read, whichever block failed first.
  const std::string bytes = binary_stl(random_facets(40000, 5));
  const detail::StlBinaryLayout layout = detail::stl_binary_layout(bytes);
  const auto from_memory = [&](std::uint32_t first) {
    return bytes.data() + detail::kStlBinaryHeaderBytes +
           std::size_t{first} * detail::kStlBinaryFacetBytes;
  };
  const auto failing_at = [&](std::uint32_t facet) -> detail::StlRecordBlocks {
    return [&, facet](std::uint32_t first, std::uint32_t count, std::vector<char>&) {
      return first <= facet && facet < first + count ? nullptr : from_memory(first);
    };
  };
  const auto read =
      detail::read_stl_records(failing_at(25000), bytes.size(), "gone.stl", layout, ReadLimits{});
  ASSERT_FALSE(read);
  unsigned first = 0;
  unsigned last = 0;
  ASSERT_EQ(std::sscanf(read.error().message.c_str(), "cannot read facets %u to %u", &first, &last),
            2)
      << read.error().message;
  EXPECT_LE(first, 25000u);
  EXPECT_GE(last, 25000u);
  EXPECT_EQ(read.error().location, fmt::format("gone.stl: facet {}", first));
  EXPECT_TRUE(contains(read.error().message, "changed or failed while it was read"));
}

TEST(ReadStlBinaryFile, RecordsThatCannotBeReadAgainAreAnError) {
  // A non-finite corner or normal is read again for its message: a file that fails then is an
  // error too, not a message made of other bytes.
  std::vector<Facet> facets = random_facets(40000, 6);
  facets[20001].corners[1][2] = std::numeric_limits<float>::infinity();
  const std::string with_corner = binary_stl(facets);
  const std::string with_normals = binary_stl(random_facets(40000, 7));
  for (const std::string* bytes : {&with_corner, &with_normals}) {
    // Every record may be read once: the parallel pass reads each exactly once, and a record
    // read a second time is a reading again.
    std::vector<std::atomic<bool>> read_before(40000);
    const detail::StlRecordBlocks once = [&](std::uint32_t first, std::uint32_t count,
                                             std::vector<char>&) -> const char* {
      bool again = false;
      for (std::uint32_t f = first; f < first + count; ++f) again |= read_before[f].exchange(true);
      if (again) return nullptr;
      return bytes->data() + detail::kStlBinaryHeaderBytes +
             std::size_t{first} * detail::kStlBinaryFacetBytes;
    };
    const auto read = detail::read_stl_records(once, bytes->size(), "flaky.stl",
                                               detail::stl_binary_layout(*bytes), ReadLimits{});
    ASSERT_FALSE(read);
    EXPECT_TRUE(contains(read.error().message, "cannot read facets")) << read.error().message;
  }
}

// ---------------------------------------------------------------------------------------------
// ASCII STL

TEST(ReadStlAscii, ReadsFacetsAndStoredNormals) {
  const auto soup = read_stl_bytes(kTriangle, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-ascii");
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0][1], (Vec3{1, 0, 0}));
  ASSERT_EQ(soup->stored_normals.size(), 1u);
  EXPECT_EQ(soup->stored_normals[0], (Vec3{0, 0, 1}));
  EXPECT_TRUE(soup->diagnostics.empty());
}

TEST(ReadStlAscii, KeywordsAreCaseInsensitive) {
  const std::string text =
      "SOLID Block\n FACET NORMAL 0 0 1\n  Outer Loop\n   VERTEX 0 0 0\n   Vertex 1 0 0\n"
      "   vErTeX 0 1 0\n  ENDLOOP\n EndFacet\nENDSOLID Block\n";
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_TRUE(bit_identical(*soup, *read_stl_bytes(kTriangle, "t.stl")));
  EXPECT_TRUE(soup->diagnostics.empty());
}

TEST(ReadStlAscii, CrLfLineEndingsReadLikeLf) {
  const auto facets = two_facets();
  const auto lf = read_stl_bytes(ascii_stl(facets), "t.stl");
  const auto crlf = read_stl_bytes(ascii_stl(facets, "%.9g", "\r\n"), "t.stl");
  ASSERT_TRUE(lf);
  ASSERT_TRUE(crlf) << crlf.error().to_string();
  EXPECT_TRUE(bit_identical(*lf, *crlf));
}

TEST(ReadStlAscii, BareCrLineEndingsReadLikeLf) {
  const auto facets = two_facets();
  const auto lf = read_stl_bytes(ascii_stl(facets), "t.stl");
  const auto cr = read_stl_bytes(ascii_stl(facets, "%.9g", "\r"), "t.stl");
  ASSERT_TRUE(lf);
  ASSERT_TRUE(cr) << cr.error().to_string();
  EXPECT_TRUE(bit_identical(*lf, *cr));
}

TEST(ReadStlAscii, LineNumbersCountEveryKindOfLineEnd) {
  // LF, CRLF and bare CR mixed: the NaN is on line 5 whatever ends the lines before it.
  const std::string text =
      "solid t\n facet normal 0 0 1\r\n  outer loop\r   vertex 0 0 0\n   vertex nan 0 0\n";
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl:5");
}

TEST(ReadStlAscii, TabsSeparateTokens) {
  const std::string text =
      "solid\tt\n\tfacet\tnormal\t0\t0\t1\n\t\touter\tloop\n\t\t\tvertex\t0\t0\t0\n"
      "\t\t\tvertex\t1\t0\t0\n\t\t\tvertex\t0\t1\t0\n\t\tendloop\n\tendfacet\nendsolid\tt\n";
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_TRUE(bit_identical(*soup, *read_stl_bytes(kTriangle, "t.stl")));
}

TEST(ReadStlAscii, ScientificNotationAndSignsAreNumbers) {
  const auto soup =
      read_stl_bytes(triangle_with_vertex_line(5, "   vertex 1.5E+01 -2.5e-1 +3"), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles[0][1], (Vec3{15.0, -0.25, 3.0}));
  const auto dots = read_stl_bytes(triangle_with_vertex_line(5, "   vertex .5 5. -0.0e0"), "t.stl");
  ASSERT_TRUE(dots) << dots.error().to_string();
  EXPECT_EQ(dots->triangles[0][1], (Vec3{0.5, 5.0, 0.0}));
  EXPECT_TRUE(std::signbit(dots->triangles[0][1].z));
}

TEST(ReadStlAscii, NumbersAreRoundedToNearestFloat32) {
  const auto soup =
      read_stl_bytes(triangle_with_vertex_line(5, "   vertex 0.1 4812345.3 1e-50"), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles[0][1].x, static_cast<double>(0.1f));
  EXPECT_EQ(soup->triangles[0][1].y, 4812345.5);  // float32 spacing is 0.5 there
  EXPECT_EQ(soup->triangles[0][1].z, 0.0);        // below the smallest float32
}

TEST(ReadStlAscii, SolidNamesWithSpacesAndUtf8AreAccepted) {
  std::string text = kTriangle;
  text.replace(0, 7, "solid Moon \xe6\x9c\x88\xe7\x90\x83 by  someone");
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
  EXPECT_TRUE(soup->diagnostics.empty());
}

TEST(ReadStlAscii, SeveralSolidsAreAllRead) {
  const auto soup = read_stl_bytes(kTriangle + kTriangle + kTriangle, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 3u);
  const Diagnostic* info = find_diagnostic(*soup, "stl.multiple_solids");
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->severity, Severity::Info);
  EXPECT_TRUE(contains(info->message, "3 solids")) << info->message;
}

TEST(ReadStlAscii, MissingEndsolidIsAWarning) {
  std::string text = kTriangle;
  text.resize(text.find("endsolid"));
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
  const Diagnostic* warning = find_diagnostic(*soup, "stl.missing_endsolid");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->severity, Severity::Warning);
  EXPECT_TRUE(contains(warning->message, "t.stl:1")) << warning->message;
}

TEST(ReadStlAscii, BareEndsolidIsAccepted) {
  std::string text = kTriangle;
  text.replace(text.find("endsolid t"), 10, "endsolid");
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup);
  EXPECT_TRUE(soup->diagnostics.empty());
}

class ReadStlAsciiBadNormal : public ::testing::TestWithParam<const char*> {};

TEST_P(ReadStlAsciiBadNormal, IsIgnoredAndTheFacetKept) {
  std::string text = kTriangle;
  text.replace(text.find("facet normal 0 0 1"), 18, GetParam());
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->stored_normals[0], Vec3{});
  const Diagnostic* warning = find_diagnostic(*soup, "stl.bad_normal");
  ASSERT_NE(warning, nullptr);
  EXPECT_TRUE(contains(warning->message, "t.stl:2")) << warning->message;
}

INSTANTIATE_TEST_SUITE_P(ReadStl, ReadStlAsciiBadNormal,
                         ::testing::Values("facet normal nan nan nan", "facet normal inf 0 -inf",
                                           "facet normal 1.#INF 0 0", "facet normal a b c",
                                           "facet normal 0 0", "facet normal", "facet",
                                           "facet normal 1e39 0 0"));

TEST(ReadStlAscii, ManyBadNormalsMakeOneCountedWarning) {
  std::string one = kTriangle.substr(kTriangle.find(" facet"));
  one.resize(one.find("endsolid"));
  one.replace(one.find("normal 0 0 1"), 12, "normal nan 0 0");
  std::string text = "solid t\n";
  for (int i = 0; i < 20; ++i) text += one;
  text += "endsolid t\n";
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup);
  ASSERT_EQ(soup->diagnostics.size(), 1u);
  EXPECT_TRUE(contains(soup->diagnostics[0].message, "20 times")) << soup->diagnostics[0].message;
}

struct BadVertexCase {
  const char* line;
  const char* message_part;
};

class ReadStlAsciiBadVertex : public ::testing::TestWithParam<BadVertexCase> {};

TEST_P(ReadStlAsciiBadVertex, IsAnErrorNamingFileAndLine) {
  const auto soup = read_stl_bytes(triangle_with_vertex_line(5, GetParam().line), "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().code, ErrorCode::BadInput);
  EXPECT_EQ(soup.error().location, "t.stl:5");
  EXPECT_TRUE(contains(soup.error().message, GetParam().message_part)) << soup.error().message;
}

INSTANTIATE_TEST_SUITE_P(
    ReadStl, ReadStlAsciiBadVertex,
    ::testing::Values(
        BadVertexCase{"vertex nan 0 0", "not a number (inf and nan are not accepted)"},
        BadVertexCase{"vertex 0 NaN 0", "not a number (inf and nan are not accepted)"},
        BadVertexCase{"vertex 0 0 inf", "not a number (inf and nan are not accepted)"},
        BadVertexCase{"vertex -Infinity 0 0", "not a number (inf and nan are not accepted)"},
        BadVertexCase{"vertex 0 0 blah", "not a number"},
        BadVertexCase{"vertex 1,5 0 0", "not a number"},
        BadVertexCase{"vertex 0 0 1e", "not a number"}, BadVertexCase{"vertex 0 0 \x10", "\\x10"},
        BadVertexCase{"vertex 0 0", "2 coordinates"},
        BadVertexCase{"vertex 0 0 0 0", "more than 3"},
        BadVertexCase{"vertex 3.5e38 0 0", "too large for a float32"},
        BadVertexCase{"vertex 0 -1e39 0", "too large for a float32"},
        BadVertexCase{"vertex 0 0 1e400", "too large for a float32"},
        BadVertexCase{"vertex 3.40282357e38 0 0", "too large for a float32"}));

TEST(ReadStlAscii, LargestFloat32ValuesAreAccepted) {
  // 3.40282356e38 lies below FLT_MAX + half an ulp, so it rounds to FLT_MAX.
  const auto soup =
      read_stl_bytes(triangle_with_vertex_line(5, "vertex 3.4028235e38 -3.40282356e38 0"), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles[0][1].x, static_cast<double>(FLT_MAX));
  EXPECT_EQ(soup->triangles[0][1].y, -static_cast<double>(FLT_MAX));
}

TEST(ReadStlAscii, QuadIsTriangulatedAsAFanWithWarning) {
  const std::string text =
      "solid q\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
      "   vertex 1 1 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid q\n";
  const auto soup = read_stl_bytes(text, "q.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 2u);
  EXPECT_EQ(soup->triangles[0], (std::array<Vec3, 3>{Vec3{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}));
  EXPECT_EQ(soup->triangles[1], (std::array<Vec3, 3>{Vec3{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  ASSERT_EQ(soup->stored_normals.size(), 2u);
  EXPECT_EQ(soup->stored_normals[1], (Vec3{0, 0, 1}));
  const Diagnostic* warning = find_diagnostic(*soup, "stl.polygon_facet");
  ASSERT_NE(warning, nullptr);
  EXPECT_TRUE(contains(warning->message, "q.stl:2")) << warning->message;
}

TEST(ReadStlAscii, TwoVertexFacetIsSkippedWithWarningNamingTheLine) {
  const std::string text =
      "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
      "  endloop\n endfacet\n" +
      kTriangle.substr(kTriangle.find(" facet"));
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->stored_normals.size(), 1u);
  const Diagnostic* warning = find_diagnostic(*soup, "stl.short_facet");
  ASSERT_NE(warning, nullptr);
  EXPECT_TRUE(contains(warning->message, "t.stl:2")) << warning->message;
  EXPECT_TRUE(contains(warning->message, "no area")) << warning->message;
}

TEST(ReadStlAscii, FacetsWithoutEnoughVerticesOnlyIsError) {
  const std::string text =
      "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n  endloop\n endfacet\n"
      " facet normal 0 0 1\n  outer loop\n  endloop\n endfacet\nendsolid t\n";
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl");
  EXPECT_TRUE(contains(soup.error().message, "no facets")) << soup.error().message;
}

TEST(ReadStlAscii, EmptySolidIsError) {
  const auto soup = read_stl_bytes("solid empty\nendsolid empty\n", "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl");
  EXPECT_TRUE(contains(soup.error().message, "no facets")) << soup.error().message;
}

TEST(ReadStlAscii, FileEndingInsideAFacetIsError) {
  const std::string text = kTriangle.substr(0, kTriangle.find("  endloop"));
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl:6");
  EXPECT_TRUE(contains(soup.error().message, "starts at line 2")) << soup.error().message;
}

TEST(ReadStlAscii, LineLongerThanTheLimitFailsFast) {
  ReadLimits limits;
  limits.max_line_bytes = 64;
  std::string long_line = "vertex 0 0 0";
  long_line.append(100, ' ');
  const auto soup = read_stl_bytes(triangle_with_vertex_line(4, long_line), "t.stl", limits);
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl:4");
  EXPECT_TRUE(contains(soup.error().message, "64 bytes")) << soup.error().message;
}

TEST(ReadStlAscii, TextAfterKeywordsIsAWarning) {
  std::string text = kTriangle;
  text.replace(text.find("endloop"), 7, "endloop foo");
  text.replace(text.find("endfacet"), 8, "endfacet bar ");
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  const Diagnostic* warning = find_diagnostic(*soup, "stl.trailing_tokens");
  ASSERT_NE(warning, nullptr);
  EXPECT_TRUE(contains(warning->message, "t.stl:7")) << warning->message;
  EXPECT_TRUE(contains(warning->message, "2 times")) << warning->message;
}

TEST(ReadStlAscii, ContentAfterTheLastEndsolidIsIgnoredWithWarning) {
  const auto soup = read_stl_bytes(kTriangle + std::string("\0\0\0garbage", 10), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
  EXPECT_NE(find_diagnostic(*soup, "stl.content_after_endsolid"), nullptr);
}

TEST(ReadStlAscii, FacetsAfterEndsolidWithoutSolidAreRead) {
  const std::string facet = kTriangle.substr(8, kTriangle.find("endsolid") - 8);
  const auto soup = read_stl_bytes(kTriangle + facet, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 2u);
  EXPECT_NE(find_diagnostic(*soup, "stl.facet_outside_solid"), nullptr);
}

TEST(ReadStlAscii, MissingEndfacetIsAWarning) {
  std::string text = kTriangle;
  text.erase(text.find(" endfacet\n"), 10);
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 1u);
  EXPECT_NE(find_diagnostic(*soup, "stl.missing_endfacet"), nullptr);
}

TEST(ReadStlAscii, VertexOutsideAFacetIsError) {
  const auto soup = read_stl_bytes("solid t\n vertex 0 0 0\nendsolid t\n", "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl:2");
}

TEST(ReadStlAscii, UnknownKeywordIsError) {
  const auto soup = read_stl_bytes(triangle_with_vertex_line(5, "   vortex 0 0 0"), "t.stl");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "t.stl:5");
  EXPECT_TRUE(contains(soup.error().message, "'vortex'")) << soup.error().message;
}

TEST(ReadStlAscii, AsciiAndBinaryEncodingsGiveBitIdenticalSoups) {
  const unsigned seed = 20240611;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> exponent(-40, 40);
  auto random_float = [&] { return std::ldexp(unit(rng), exponent(rng)); };
  std::vector<Facet> facets;
  for (int i = 0; i < 500; ++i) {
    Facet f;
    for (float& v : f.normal) v = unit(rng);
    for (auto& corner : f.corners) {
      for (float& v : corner) v = random_float();
    }
    facets.push_back(f);
  }
  // Values where text and binary part ways if the reader is careless.
  facets.push_back(Facet{{-0.0f, 0.0f, 1.0f},
                         {{{FLT_MAX, -FLT_MAX, FLT_MIN},
                           {FLT_TRUE_MIN, -0.0f, 4812345.5f},
                           {0.1f, 1.0f / 3.0f, 16777217.0f}}}});
  const auto binary = read_stl_bytes(binary_stl(facets), "b.stl");
  ASSERT_TRUE(binary) << binary.error().to_string();
  for (const char* format : {"%.9g", "%.17g", "%.8e", "%.12E", "%.60f"}) {
    SCOPED_TRACE(format);
    const auto ascii = read_stl_bytes(ascii_stl(facets, format), "a.stl");
    ASSERT_TRUE(ascii) << ascii.error().to_string();
    EXPECT_TRUE(bit_identical(*ascii, *binary));
  }
}

// ---------------------------------------------------------------------------------------------
// Corpus files read in place (../shared/corpus).

TEST(ReadStlCorpus, BinaryWithOneStrayByteAfterTheLastFacet) {
  const auto soup = read_mesh(corpus_file("numpy-stl/tests/stl_binary/HalfDonut.stl"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary");
  EXPECT_EQ(soup->triangles.size(), 288u);
  EXPECT_NE(find_diagnostic(*soup, "stl.trailing_bytes"), nullptr);
}

TEST(ReadStlCorpus, BinaryWithAttributeBytes) {
  const auto soup = read_mesh(corpus_file("cgal-data/data/meshes/sphere.stl"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary");
  EXPECT_EQ(soup->triangles.size(), 320u);
  EXPECT_TRUE(soup->diagnostics.empty());
}

TEST(ReadStlCorpus, UpperCaseKeywordsAndScientificNotation) {
  const auto soup = read_mesh(corpus_file("admesh/examples/block.stl"));
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-ascii");
  EXPECT_EQ(soup->triangles.size(), 12u);
}

TEST(ReadStlCorpus, BrokenFourVerticesIsFanTriangulated) {
  expect_read_with_diagnostic(corpus_file("stl-models/broken/fourVertices.ascii.stl"), 5u,
                              "stl.polygon_facet");
}

TEST(ReadStlCorpus, BrokenIncorrectFaceCounterIsError) {
  const auto path = corpus_file("stl-models/broken/incorrectFaceCounter.bin.stl");
  const auto soup = read_mesh(path);
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, path.string());
  EXPECT_EQ(soup.error().message,
            "header declares 66 facets, file ends after 4 (284 of 3384 bytes)");
}

TEST(ReadStlCorpus, BrokenMissingNormalKeepsTheFacet) {
  expect_read_with_diagnostic(corpus_file("stl-models/broken/missingNormal.ascii.stl"), 4u,
                              "stl.bad_normal");
}

TEST(ReadStlCorpus, BrokenFolderReadableFilesGiveTheirFacets) {
  const std::pair<const char*, std::size_t> files[] = {
      {"stl-models/broken/missingFace.ascii.stl", 3},
      {"stl-models/broken/singleFace.ascii.stl", 1},
      {"stl-models/broken/solidNameMismatch.ascii.stl", 4},
      {"stl-models/broken/wrongHeader.bin.stl", 12},
      {"stl-models/broken/wrongNormal.ascii.stl", 4},
      {"stl-models/broken/wrongNormals.ascii.stl", 4},
  };
  for (const auto& [file, facets] : files) {
    const auto soup = read_mesh(corpus_file(file));
    ASSERT_TRUE(soup) << soup.error().to_string();
    EXPECT_EQ(soup->triangles.size(), facets) << file;
  }
}

TEST(ReadStlCorpus, BinaryWithFortyNineTrailingBytes) {
  expect_read_with_diagnostic(corpus_file("stl-models/misc/multiWordName.bin.stl"), 4u,
                              "stl.trailing_bytes");
}

TEST(ReadStlCorpus, OpenscadZeroByteFileIsError) {
  expect_refused(corpus_file("openscad/tests/data/stl/empty.stl"), "0 bytes");
}

TEST(ReadStlCorpus, ZeroFacetFilesAreErrors) {
  for (const char* file :
       {"openscad/tests/data/stl/empty2.stl", "stl-models/misc/faceless.ascii.stl",
        "trimesh/models/empty.stl", "trimesh/models/emptyIO/stl_empty_bin.stl"}) {
    const auto soup = read_mesh(corpus_file(file));
    ASSERT_FALSE(soup) << file;
    EXPECT_TRUE(contains(soup.error().message, "no facets")) << soup.error().to_string();
    EXPECT_FALSE(soup.error().location.empty());
  }
}

TEST(ReadStlCorpus, OpenscadInvalidVertexNamesItsLine) {
  const auto soup = read_mesh(corpus_file("openscad/tests/data/stl/invalidvertex.stl"));
  ASSERT_FALSE(soup);
  EXPECT_TRUE(soup.error().location.ends_with("invalidvertex.stl:89")) << soup.error().location;
  EXPECT_TRUE(contains(soup.error().message, "'blah'")) << soup.error().message;
}

TEST(ReadStlCorpus, OpenscadControlByteInsideAVertexLineIsError) {
  const auto soup = read_mesh(corpus_file("openscad/tests/data/stl/unparseable.stl"));
  ASSERT_FALSE(soup);
  EXPECT_TRUE(soup.error().location.ends_with("unparseable.stl:4")) << soup.error().location;
}

TEST(ReadStlCorpus, OpenscadTooManyVerticesIsFanTriangulated) {
  expect_read_with_diagnostic(corpus_file("openscad/tests/data/stl/toomanyvertices.stl"), 14u,
                              "stl.polygon_facet");
}

TEST(ReadStlCorpus, OpenscadNanNormalKeepsTheFacet) {
  expect_read_with_diagnostic(corpus_file("openscad/tests/data/scad/bugs/issue945e.stl"), 94u,
                              "stl.bad_normal");
}

// ---------------------------------------------------------------------------------------------
// The rest of the ASCII grammar's refusals and warnings, each with its place and message.

Error ascii_error(std::string_view text, const ReadLimits& limits = {}) {
  const auto soup = read_stl_bytes(text, "t.stl", limits);
  EXPECT_FALSE(soup.has_value());
  return soup ? Error{} : soup.error();
}

TEST(ReadStlAscii, AVertexWithOneCoordinateSaysSo) {
  const Error e = ascii_error(triangle_with_vertex_line(5, "   vertex 1"));
  EXPECT_EQ(e.location, "t.stl:5");
  EXPECT_EQ(e.message, "vertex has 1 coordinate, expected 3");
}

TEST(ReadStlAscii, KeywordLengthWordsThatAreNoKeywordsAreUnknown) {
  // Words of the lengths of the keywords (5, 7 and 8 letters) that are none of them.
  for (const std::string_view word : {"hello", "endlooq", "endfacex"}) {
    const Error e = ascii_error(triangle_with_vertex_line(5, fmt::format("   {} 0 0 0", word)));
    EXPECT_EQ(e.location, "t.stl:5");
    EXPECT_EQ(e.message,
              fmt::format("expected 'vertex', 'endloop' or 'endfacet', found '{}'", word));
  }
}

TEST(ReadStlAscii, LoopKeywordsOutsideAFacetAreErrors) {
  for (const std::string_view word : {"outer", "endloop", "endfacet"}) {
    const Error e = ascii_error(fmt::format("solid t\n  {}\nendsolid t\n", word));
    EXPECT_EQ(e.location, "t.stl:2");
    EXPECT_EQ(e.message, fmt::format("'{}' outside a facet", word));
  }
  const Error other = ascii_error("solid t\n  vortex\nendsolid t\n");
  EXPECT_EQ(other.location, "t.stl:2");
  EXPECT_EQ(other.message, "expected 'facet' or 'endsolid', found 'vortex'");
}

TEST(ReadStlAscii, OuterWithoutLoopIsAWarningQuotingTheRest) {
  std::string text = kTriangle;
  text.replace(text.find("outer loop"), 10, "outer lop x");
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  const Diagnostic* warning = find_diagnostic(*soup, "stl.trailing_tokens");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->message, "t.stl:3: unexpected text 'lop x' after 'outer' ignored");
}

TEST(ReadStlAscii, LongOrControlCharacterTextIsQuotedShortAndVisible) {
  std::string text = kTriangle;
  std::string long_endloop = "endloop ";
  long_endloop.append(70, 'y');
  text.replace(text.find("endloop"), 7, long_endloop);
  text.replace(text.find("endfacet"), 8, "endfacet \x7f\x01z");
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  const Diagnostic* warning = find_diagnostic(*soup, "stl.trailing_tokens");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->message, "t.stl:7: unexpected text '" + std::string(60, 'y') +
                                  "...' after 'endloop' ignored (2 times in all; also at line 8)");
}

TEST(ReadStlAscii, ABadNormalOfOtherTextIsQuoted) {
  std::string text = kTriangle;
  text.replace(text.find("facet normal 0 0 1"), 18, "facet \x7f normal");
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  const Diagnostic* warning = find_diagnostic(*soup, "stl.bad_normal");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->message,
            "t.stl:2: stored normal '\\x7f normal' is not three finite numbers; the normal is "
            "ignored, the facet kept");
}

TEST(ReadStlAscii, ASolidOrFacetInsideAFacetEndsItWithAWarning) {
  const std::string facet = kTriangle.substr(8, kTriangle.find(" endfacet") - 8);
  const std::string text = "solid a\n" + facet + facet + " endfacet\n" + facet + "solid b\n" +
                           facet + " endfacet\nendsolid b\n";
  const auto soup = read_stl_bytes(text, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 4u);
  const Diagnostic* endfacet = find_diagnostic(*soup, "stl.missing_endfacet");
  ASSERT_NE(endfacet, nullptr);
  EXPECT_EQ(endfacet->message,
            "t.stl:2: facet has no 'endfacet' line; read up to line 8 (2 times in all; also at "
            "line 15)");
  const Diagnostic* endsolid = find_diagnostic(*soup, "stl.missing_endsolid");
  ASSERT_NE(endsolid, nullptr);
  EXPECT_EQ(endsolid->message, "t.stl:1: solid has no 'endsolid' line");
  const Diagnostic* solids = find_diagnostic(*soup, "stl.multiple_solids");
  ASSERT_NE(solids, nullptr);
  EXPECT_EQ(solids->message, "t.stl: 2 solids in one file; all are read");
}

TEST(ReadStlAscii, FacetsBeyondTheLimitAreAnErrorWhereverTheFacetEnds) {
  ReadLimits limits;
  limits.max_triangles = 1;
  const std::string facet = kTriangle.substr(8, kTriangle.find("endsolid") - 8);
  const Error at_endfacet = ascii_error("solid t\n" + facet + facet + "endsolid t\n", limits);
  EXPECT_EQ(at_endfacet.location, "t.stl:9");
  EXPECT_EQ(at_endfacet.message, "more than the limit of 1 facets");
  const std::string open_facet = facet.substr(0, facet.find(" endfacet"));
  const Error at_solid = ascii_error("solid t\n" + facet + open_facet + "endsolid t\n", limits);
  EXPECT_EQ(at_solid.location, "t.stl:9");
  EXPECT_EQ(at_solid.message, "more than the limit of 1 facets");
}

TEST(ReadStlAscii, AByteOrderMarkBeforeSolidIsSkipped) {
  const auto soup = read_stl_bytes("\xEF\xBB\xBF" + kTriangle, "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-ascii");
  EXPECT_EQ(soup->triangles.size(), 1u);
}

TEST(ReadStlDetection, SolidEndsAtABlankOrALineEnd) {
  EXPECT_TRUE(detail::starts_with_solid("\tsolid\n"));
  EXPECT_TRUE(detail::starts_with_solid("\v\fsolid\r"));
  EXPECT_TRUE(detail::starts_with_solid("solid"));
  EXPECT_FALSE(detail::starts_with_solid("solidity"));
  EXPECT_FALSE(detail::starts_with_solid("soli"));
}

TEST(ReadStlBinary, ANonFiniteCoordinateOnAnyAxisNamesTheCorner) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Float3 ok{0, 0, 0};
  const std::vector<std::pair<Float3, std::string>> cases = {
      {{inf, 0, 0}, "corner 1 has a non-finite coordinate (inf, 0, 0)"},
      {{0, -inf, 0}, "corner 1 has a non-finite coordinate (0, -inf, 0)"},
      {{0, 0, nan}, "corner 1 has a non-finite coordinate (0, 0, nan)"}};
  for (const auto& [corner, message] : cases) {
    const auto soup =
        read_stl_bytes(binary_stl({{{0, 0, 1}, {ok, corner, Float3{0, 1, 0}}}}), "t.stl");
    ASSERT_FALSE(soup);
    EXPECT_EQ(soup.error().location, "t.stl: facet 0");
    EXPECT_EQ(soup.error().message, message + "; NaN and infinity cannot be sliced");
  }
}

TEST(ReadStlBinary, ANonFiniteNormalOnAnyAxisIsIgnored) {
  const float inf = std::numeric_limits<float>::infinity();
  const Facet base{{0, 0, 1}, {Float3{0, 0, 0}, Float3{1, 0, 0}, Float3{0, 1, 0}}};
  Facet y = base;
  y.normal = {0, inf, 0};
  Facet z = base;
  z.normal = {0, 0, -inf};
  const auto soup = read_stl_bytes(binary_stl({base, y, z}), "t.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->stored_normals, (std::vector<Vec3>{{0, 0, 1}, {}, {}}));
  const Diagnostic* warning = find_diagnostic(*soup, "stl.bad_normal");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->message,
            "t.stl: facet 1: stored normal (0, inf, 0) is not finite; the normal is ignored, the "
            "facet kept (2 times in all; also at facet 2)");
}

}  // namespace
}  // namespace strata::io
