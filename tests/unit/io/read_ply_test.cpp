// The PLY reader: header and body errors with the location and message each must give, the
// byte orders, triangle strips, and the warnings for odd but readable files.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/read_mesh_internal.hpp"
#include "support/mesh_reading.hpp"
#include "support/result_checks.hpp"

namespace strata::io {
namespace {

using test::find_diagnostic;
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

Error read_ply_error(std::string_view bytes, const ReadLimits& limits = {}) {
  return test::error_of(detail::read_ply_bytes(bytes, "part.ply", limits), "part.ply");
}

void expect_ply_error(std::string_view bytes, std::string_view location, std::string_view message,
                      const ReadLimits& limits = {}) {
  test::expect_bad_input(detail::read_ply_bytes(bytes, "part.ply", limits), location, message,
                         "part.ply");
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
  expect_ply_error("ply\nformat ascii 1.0\nelement vertex 3\n", "part.ply:3",
                   "PLY header has no end_header line");
}

TEST(ReadPly, FirstLineMustBePly) {
  expect_ply_error("plyx\nformat ascii 1.0\nend_header\n", "part.ply:1",
                   "not a PLY file: the first line is not 'ply'");
}

TEST(ReadPly, HeaderLineOverTheLimitIsAnError) {
  ReadLimits limits;
  limits.max_line_bytes = 16;
  // Built with append: GCC 12 warns (-Wrestrict, a false positive) on a chain of operator+.
  std::string header = "ply\nformat ascii 1.0\ncomment ";
  header.append(20, 'c');
  header.append("\nend_header\n");
  expect_ply_error(header, "part.ply:3", "line longer than the limit of 16 bytes", limits);
}

TEST(ReadPly, UnknownFormatIsNamed) {
  expect_ply_error("ply\nformat utf8 1.0\nend_header\n", "part.ply:2", "unknown PLY format 'utf8'");
}

TEST(ReadPly, HeaderWithoutFormatLineIsAnError) {
  expect_ply_error("ply\nelement vertex 0\nend_header\n", "part.ply:3",
                   "PLY header has no format line");
}

TEST(ReadPly, ElementNeedsANameAndACount) {
  expect_ply_error(ascii_header("element vertex\n"), "part.ply:3",
                   "PLY element line needs a name and a count");
}

TEST(ReadPly, ElementCountMustBeAWholeNumber) {
  const Error e = read_ply_error(ascii_header("element vertex 3.0\n"));
  EXPECT_EQ(e.location, "part.ply:3");
  EXPECT_EQ(e.message.rfind("bad number '3.0'", 0), 0u) << e.message;
}

TEST(ReadPly, AnElementLineWithoutANameIsAnError) {
  expect_ply_error(ascii_header("element\n"), "part.ply:3",
                   "PLY element line needs a name and a count");
}

TEST(ReadPly, AListCountTypeThatIsNoTypeIsAnError) {
  expect_ply_error(ascii_header("element face 1\nproperty list quad int vertex_indices\n"),
                   "part.ply:4", "PLY list property needs an integer count type");
}

TEST(ReadPly, BlankHeaderLinesAreSkippedAndTheLastLineNeedsNoLineEnd) {
  // Elements of no items: the header alone, ending without a line break, is the whole file.
  const auto soup = detail::read_ply_bytes(
      "ply\n\nformat ascii 1.0\n \nelement vertex 0\nproperty float x\nproperty float y\n"
      "property float z\nend_header",
      "part.ply", {});
  ASSERT_FALSE(soup.has_value());
  EXPECT_EQ(soup.error().location, "part.ply");
  EXPECT_EQ(soup.error().message, "no facets: the PLY file defines no faces");
}

TEST(ReadPly, PropertyBeforeAnyElementIsAnError) {
  expect_ply_error(ascii_header("property float x\n"), "part.ply:3",
                   "PLY property before any element");
}

TEST(ReadPly, ListCountTypeMustBeAnInteger) {
  expect_ply_error(ascii_header("element face 1\nproperty list float int vertex_indices\n"),
                   "part.ply:4", "PLY list property needs an integer count type");
}

TEST(ReadPly, UnknownPropertyTypeIsNamed) {
  expect_ply_error(ascii_header("element vertex 1\nproperty quad x\n"), "part.ply:4",
                   "unknown PLY property type 'quad'");
}

TEST(ReadPly, VertexElementNeedsXYAndZ) {
  expect_ply_error(ascii_header("element vertex 1\nproperty float x\nproperty float y\n") + "0 0\n",
                   "part.ply", "PLY vertex element lacks an x, y or z property");
}

TEST(ReadPly, FaceElementNeedsAVertexIndexList) {
  expect_ply_error(ascii_header("element vertex 0\nproperty float x\nproperty float y\nproperty "
                                "float z\nelement face 1\nproperty int material\n") +
                       "0\n",
                   "part.ply", "PLY face element has no vertex_indices list");
}

TEST(ReadPly, TruncatedAsciiBodyNamesTheItemAndLine) {
  expect_ply_error(triangle_header() + "0 0 0\n1 0 0\n", "part.ply:12",
                   "PLY vertex 2 of 3: file ends early (truncated?)");
}

TEST(ReadPly, TruncatedBinaryBodyNamesTheItemAndByte) {
  std::string bytes = binary_triangle(false);
  const std::size_t header = bytes.size() - 9 * 4 - 1 - 3 * 4;
  bytes.resize(header + 4 * 4);  // vertex 0 and x of vertex 1
  expect_ply_error(bytes, "part.ply: byte " + std::to_string(header + 16),
                   "PLY vertex 1 of 3: file ends early (truncated?)");
}

TEST(ReadPly, ListLongerThanTheFileIsAnError) {
  expect_ply_error(triangle_header() + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n", "part.ply:13",
                   "PLY face 0: list of 200 entries, more than the file holds");
}

TEST(ReadPly, NegativeFaceIndexIsAnError) {
  expect_ply_error(triangle_header() + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "part.ply:13",
                   "PLY face 0 uses the negative vertex index -1");
}

TEST(ReadPly, BadNumberInTheBodyGivesTheNumberMessage) {
  const Error e = read_ply_error(triangle_header() + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
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
  expect_ply_error(bytes, "part.ply:14", "more than the limit of 1 facets", limits);
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
  expect_ply_error(strip_file("4 0 1 -2 3"), "part.ply:14",
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

// ------------------------------------------------------------------------- every encoding

/// A value of a PLY body and the type its property declares ("uchar", "float64", ...).
struct PlyValue {
  std::string_view type;
  double value;
};

constexpr std::string_view kEncodings[] = {"ascii", "binary_little_endian", "binary_big_endian"};

/// A PLY file in `encoding` with the header lines `elements` and one body row an item (ASCII: a
/// line, values separated by blanks; binary: the values in their declared types).
struct PlyFile {
  std::string bytes;
  std::size_t header_bytes = 0;  ///< where the body starts
  std::size_t body_line = 0;     ///< the line of the first row (ASCII)
  bool ascii = false;

  /// Where the reader reports a problem found after `consumed` bytes of the body (binary) or on
  /// body row `row` (ASCII, from 0).
  std::string where(std::size_t row, std::size_t consumed) const {
    return ascii ? fmt::format("part.ply:{}", body_line + row)
                 : fmt::format("part.ply: byte {}", header_bytes + consumed);
  }
};

void append_value(std::string& out, const PlyValue& v, bool big_endian) {
  const std::string_view t = v.type;
  if (t == "char" || t == "int8")
    return append_raw(out, static_cast<std::int8_t>(v.value), big_endian);
  if (t == "uchar" || t == "uint8")
    return append_raw(out, static_cast<std::uint8_t>(v.value), big_endian);
  if (t == "short" || t == "int16")
    return append_raw(out, static_cast<std::int16_t>(v.value), big_endian);
  if (t == "ushort" || t == "uint16")
    return append_raw(out, static_cast<std::uint16_t>(v.value), big_endian);
  if (t == "int" || t == "int32")
    return append_raw(out, static_cast<std::int32_t>(v.value), big_endian);
  if (t == "uint" || t == "uint32")
    return append_raw(out, static_cast<std::uint32_t>(v.value), big_endian);
  if (t == "float" || t == "float32")
    return append_raw(out, static_cast<float>(v.value), big_endian);
  ASSERT_TRUE(t == "double" || t == "float64") << t;
  append_raw(out, v.value, big_endian);
}

PlyFile make_ply(std::string_view encoding, std::string_view elements,
                 const std::vector<std::vector<PlyValue>>& rows) {
  PlyFile file;
  file.bytes = fmt::format("ply\nformat {} 1.0\n{}end_header\n", encoding, elements);
  file.header_bytes = file.bytes.size();
  file.body_line =
      static_cast<std::size_t>(std::count(file.bytes.begin(), file.bytes.end(), '\n')) + 1;
  file.ascii = encoding == "ascii";
  for (const auto& row : rows) {
    for (std::size_t k = 0; k < row.size(); ++k) {
      if (file.ascii) {
        if (k > 0) file.bytes += ' ';
        file.bytes += fmt::format("{}", row[k].value);
      } else {
        append_value(file.bytes, row[k], encoding == "binary_big_endian");
      }
    }
    if (file.ascii) file.bytes += '\n';
  }
  return file;
}

constexpr std::string_view kXyzFloat = "property float x\nproperty float y\nproperty float z\n";

/// The three vertices (0,0,0) (1,0,0) (0,1,0) as float rows.
std::vector<std::vector<PlyValue>> triangle_vertices() {
  return {{{"float", 0}, {"float", 0}, {"float", 0}},
          {{"float", 1}, {"float", 0}, {"float", 0}},
          {{"float", 0}, {"float", 1}, {"float", 0}}};
}

/// triangle_vertices() followed by `rows`.
std::vector<std::vector<PlyValue>> with_triangle(std::vector<std::vector<PlyValue>> rows) {
  auto all = triangle_vertices();
  all.insert(all.end(), rows.begin(), rows.end());
  return all;
}

TEST(ReadPly, EveryScalarTypeUnderBothItsNamesReadsInEveryEncoding) {
  // x, y and z are int8, ushort and double; between them a property of every other type name,
  // so that a wrong size for any type would shift the coordinates after it.
  const std::string elements =
      "element vertex 3\nproperty char a\nproperty int8 x\nproperty uchar b\nproperty uint8 c\n"
      "property short d\nproperty int16 e\nproperty ushort y\nproperty uint16 f\n"
      "property int g\nproperty int32 h\nproperty uint i\nproperty uint32 j\nproperty float k\n"
      "property float32 l\nproperty double z\nproperty float64 m\n"
      "element face 1\nproperty list uint16 uint32 vertex_indices\n"
      "property list int8 float64 extra\n";
  auto vertex = [](double x, double y) {
    return std::vector<PlyValue>{
        {"char", -5},         {"int8", x},        {"uchar", 200},       {"uint8", 7},
        {"short", -30000},    {"int16", 1234},    {"ushort", y},        {"uint16", 65535},
        {"int", -2000000000}, {"int32", 5},       {"uint", 4000000000}, {"uint32", 6},
        {"float", 1.5},       {"float32", -2.25}, {"double", 0.5},      {"float64", 1e300}};
  };
  const std::vector<std::vector<PlyValue>> rows = {vertex(-1, 0),
                                                   vertex(2, 0),
                                                   vertex(0, 300),
                                                   {{"uint16", 3},
                                                    {"uint32", 0},
                                                    {"uint32", 1},
                                                    {"uint32", 2},
                                                    {"int8", 2},
                                                    {"float64", 1.5},
                                                    {"float64", -7}}};
  for (const std::string_view encoding : kEncodings) {
    const PlyFile file = make_ply(encoding, elements, rows);
    const auto soup = detail::read_ply_bytes(file.bytes, "part.ply", {});
    ASSERT_TRUE(soup.has_value()) << encoding << ": " << soup.error().to_string();
    ASSERT_EQ(soup->triangles.size(), 1u) << encoding;
    EXPECT_EQ(soup->triangles[0][0], (Vec3{-1, 0, 0.5})) << encoding;
    EXPECT_EQ(soup->triangles[0][1], (Vec3{2, 0, 0.5})) << encoding;
    EXPECT_EQ(soup->triangles[0][2], (Vec3{0, 300, 0.5})) << encoding;
    EXPECT_TRUE(soup->diagnostics.empty()) << encoding;
  }
}

TEST(ReadPly, AVertexElementWithoutXYOrZIsAnErrorInEveryEncoding) {
  for (const std::string_view encoding : kEncodings) {
    for (const std::string_view missing : {"x", "y", "z"}) {
      std::string elements = "element vertex 1\n";
      for (const std::string_view axis : {"x", "y", "z"}) {
        if (axis != missing) elements += fmt::format("property float {}\n", axis);
      }
      elements += "property list uchar float x_list\n";  // a list named x is not the coordinate
      const PlyFile file = make_ply(encoding, elements, {});
      expect_ply_error(file.bytes, "part.ply", "PLY vertex element lacks an x, y or z property");
    }
  }
}

TEST(ReadPly, StripsAndFacesWithoutAnIndexListAreErrorsInEveryEncoding) {
  for (const std::string_view encoding : kEncodings) {
    for (const std::string_view element : {"face", "tristrips"}) {
      const PlyFile file =
          make_ply(encoding,
                   fmt::format("element vertex 0\n{}element {} 1\nproperty list uchar int "
                               "corners\nproperty int vertex_indices\n",
                               kXyzFloat, element),
                   {});
      expect_ply_error(file.bytes, "part.ply",
                       fmt::format("PLY {} element has no vertex_indices list", element));
    }
  }
}

TEST(ReadPly, AListCountBelowZeroOrBeyondTheFileIsAnErrorInEveryEncoding) {
  const std::string elements = fmt::format(
      "element vertex 3\n{}element face 1\nproperty list int8 int vertex_indices\n", kXyzFloat);
  for (const std::string_view encoding : kEncodings) {
    const PlyFile negative =
        make_ply(encoding, elements, with_triangle({{{"int8", -1}, {"int", 0}, {"int", 1}}}));
    expect_ply_error(negative.bytes, negative.where(3, 37),
                     "PLY face 0: list of -1 entries, more than the file holds");
    const PlyFile long_list =
        make_ply(encoding, elements, with_triangle({{{"int8", 100}, {"int", 0}, {"int", 1}}}));
    expect_ply_error(long_list.bytes, long_list.where(3, 37),
                     "PLY face 0: list of 100 entries, more than the file holds");
  }
}

TEST(ReadPly, AFileEndingBeforeAListCountIsTruncatedInEveryEncoding) {
  const std::string elements = fmt::format(
      "element vertex 3\n{}element face 1\nproperty list uchar int vertex_indices\n", kXyzFloat);
  for (const std::string_view encoding : kEncodings) {
    const PlyFile file = make_ply(encoding, elements, triangle_vertices());
    expect_ply_error(file.bytes, file.where(3, 36),
                     "PLY face 0 of 1: file ends early (truncated?)");
  }
}

TEST(ReadPly, IndicesThatAreNoWholeNumberBelowTwoToThe63AreErrorsInEveryEncoding) {
  const std::string elements = fmt::format(
      "element vertex 3\n{}element face 1\nproperty list uchar double vertex_indices\n", kXyzFloat);
  for (const std::string_view encoding : kEncodings) {
    for (const double index : {1.5, 1e19, -1e19}) {
      const PlyFile file = make_ply(
          encoding, elements,
          with_triangle({{{"uchar", 3}, {"double", 0}, {"double", index}, {"double", 2}}}));
      expect_ply_error(file.bytes, file.where(3, 36 + 1 + 16),
                       fmt::format("PLY face 0: vertex index {} is not a whole number of magnitude "
                                   "below 2^63",
                                   index));
    }
  }
}

TEST(ReadPly, BinaryNegativeFaceIndexIsAnError) {
  const PlyFile file = make_ply(
      "binary_little_endian",
      fmt::format("element vertex 3\n{}element face 1\nproperty list uchar int vertex_indices\n",
                  kXyzFloat),
      with_triangle({{{"uchar", 3}, {"int", 0}, {"int", -4}, {"int", 2}}}));
  expect_ply_error(file.bytes, file.where(3, 36 + 1 + 12),
                   "PLY face 0 uses the negative vertex index -4");
}

TEST(ReadPly, StripsJoinsOtherElementsAndTheFacetLimitInEveryEncoding) {
  const std::string elements = fmt::format(
      "element vertex 4\n{}element material 1\nproperty uchar red\n"
      "element tristrips 1\nproperty list int int vertex_indices\n",
      kXyzFloat);
  std::vector<std::vector<PlyValue>> rows = triangle_vertices();
  rows.push_back({{"float", 1}, {"float", 1}, {"float", 0}});
  rows.push_back({{"uchar", 9}});
  rows.push_back({{"int", 8},
                  {"int", 0},
                  {"int", 1},
                  {"int", 2},
                  {"int", -1},
                  {"int", 1},
                  {"int", 1},
                  {"int", 3},
                  {"int", 2}});
  for (const std::string_view encoding : kEncodings) {
    const PlyFile file = make_ply(encoding, elements, rows);
    const auto soup = detail::read_ply_bytes(file.bytes, "part.ply", {});
    ASSERT_TRUE(soup.has_value()) << encoding << ": " << soup.error().to_string();
    ASSERT_EQ(soup->triangles.size(), 2u) << encoding;
    // The second strip (1 1 3 2): (1 1 3) joins, (1 3 2) is its second triangle, turned over.
    EXPECT_EQ(soup->triangles[1][0], (Vec3{1, 1, 0})) << encoding;
    EXPECT_EQ(soup->triangles[1][1], (Vec3{1, 0, 0})) << encoding;
    EXPECT_EQ(soup->triangles[1][2], (Vec3{0, 1, 0})) << encoding;
    ASSERT_NE(find_diagnostic(*soup, "ply.strip_joins"), nullptr) << encoding;

    ReadLimits limits;
    limits.max_triangles = 1;
    expect_ply_error(file.bytes, file.where(5, 4 * 12 + 1 + 4 * 9),
                     "more than the limit of 1 facets", limits);

    std::vector<std::vector<PlyValue>> bad = rows;
    bad.back()[6].value = -3;
    const PlyFile negative = make_ply(encoding, elements, bad);
    expect_ply_error(negative.bytes, negative.where(5, 4 * 12 + 1 + 4 * 9),
                     "PLY strip uses the negative vertex index -3");
  }
}

TEST(ReadPly, ABinaryNonFiniteCoordinateIsAnErrorNamingTheFace) {
  // A binary file has no lines: the face is named by its number.
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<std::vector<PlyValue>, std::string>> cases = {
      {{{"float", nan}, {"float", 0}, {"float", 0}}, "(nan, 0, 0)"},
      {{{"float", 1}, {"float", -inf}, {"float", 0}}, "(1, -inf, 0)"},
      {{{"float", 1}, {"float", 0}, {"float", inf}}, "(1, 0, inf)"}};
  for (const auto& [vertex, shown] : cases) {
    auto rows = triangle_vertices();
    rows[1] = vertex;
    rows.push_back({{"uchar", 3}, {"int", 0}, {"int", 1}, {"int", 2}});
    const PlyFile file = make_ply(
        "binary_little_endian",
        fmt::format("element vertex 3\n{}element face 1\nproperty list uchar int vertex_indices\n",
                    kXyzFloat),
        rows);
    expect_ply_error(file.bytes, "part.ply: face 0",
                     "PLY vertex 1 has a non-finite coordinate " + shown +
                         "; NaN and infinity cannot be sliced");
  }
}

}  // namespace
}  // namespace strata::io
