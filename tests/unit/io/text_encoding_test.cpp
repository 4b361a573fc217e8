// The decoding step in front of the text readers (src/io/decode_text_encoding.cpp), through
// read_mesh: UTF-8 with a byte-order mark and UTF-16 of both byte orders with a mark read as the
// original; other wide encodings are refused with a message about the encoding.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "support/corpus.hpp"
#include "support/mesh_reading.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"
#include "support/text_encodings.hpp"
#include "support/text_meshes.hpp"

namespace strata::io {
namespace {

using test::contains;
using test::find_diagnostic;
using test::to_utf16;
using test::Utf16Order;

/// A text file of the corpus, one of each text format (OBJ with comments, groups, negative
/// indices and quads; ASCII STL with tabs; OFF with comments; ASCII PLY).
struct EncodedCase {
  std::string corpus_path;
  Utf16Order order;
};

std::string encoded_case_name(const ::testing::TestParamInfo<EncodedCase>& info) {
  return test::sanitize_test_name(info.param.corpus_path) +
         (info.param.order == Utf16Order::LittleEndian ? "_LE" : "_BE");
}

std::vector<EncodedCase> encoded_cases() {
  std::vector<EncodedCase> cases;
  for (const char* path :
       {"prusaslicer/tests/data/pyramid.obj", "trimesh/models/negative_indices.obj",
        "openscad/tests/data/obj/dodecahedron.obj",
        "assimp-testmodels/models/OBJ/concave_polygon.obj", "stl-models/polytopes/cube.ascii.stl",
        "trimesh/models/comments.off", "assimp-testmodels/models/PLY/cube.ply"}) {
    for (const Utf16Order order : {Utf16Order::LittleEndian, Utf16Order::BigEndian}) {
      cases.push_back({path, order});
    }
  }
  return cases;
}

class Utf16CorpusCopy : public ::testing::TestWithParam<EncodedCase> {};

TEST_P(Utf16CorpusCopy, ReadsTheSameTrianglesAsTheOriginal) {
  const std::filesystem::path path = test::corpus_dir() / GetParam().corpus_path;
  const std::string original = test::read_file(path);
  ASSERT_FALSE(original.empty()) << path;
  const auto expected = read_mesh_bytes(original, path.string());
  ASSERT_TRUE(expected) << expected.error().to_string();
  ASSERT_FALSE(expected->triangles.empty());

  const auto decoded = read_mesh_bytes(to_utf16(original, GetParam().order), path.string());
  ASSERT_TRUE(decoded) << decoded.error().to_string();
  EXPECT_EQ(decoded->triangles, expected->triangles);
  EXPECT_EQ(decoded->format, expected->format);
  const Diagnostic* note = find_diagnostic(*decoded, "io.text_encoding");
  ASSERT_NE(note, nullptr);
  EXPECT_EQ(note->severity, Severity::Info);
  EXPECT_EQ(note->message,
            path.string() +
                (GetParam().order == Utf16Order::LittleEndian ? ": UTF-16 LE" : ": UTF-16 BE") +
                " text, decoded before reading");
}

INSTANTIATE_TEST_SUITE_P(Corpus, Utf16CorpusCopy, ::testing::ValuesIn(encoded_cases()),
                         encoded_case_name);

TEST(TextEncoding, Utf8ByteOrderMarkIsDroppedInEveryTextFormat) {
  for (const test::TextMeshFormat format : test::all_text_mesh_formats()) {
    SCOPED_TRACE(std::string(test::format_name(format)));
    const test::TextMesh mesh = test::triangle_with_x(format, "1");
    const auto expected = read_mesh_bytes(mesh.text, mesh.file_name);
    ASSERT_TRUE(expected) << expected.error().to_string();
    const auto marked = read_mesh_bytes("\xEF\xBB\xBF" + mesh.text, mesh.file_name);
    ASSERT_TRUE(marked) << marked.error().to_string();
    EXPECT_EQ(marked->triangles, expected->triangles);
    EXPECT_EQ(marked->format, expected->format);
    const Diagnostic* note = find_diagnostic(*marked, "io.text_encoding");
    ASSERT_NE(note, nullptr);
    EXPECT_EQ(note->message, mesh.file_name +
                                 ": UTF-8 with a byte-order mark text, decoded "
                                 "before reading");
  }
}

TEST(TextEncoding, Utf16FileOnDiskIsReadByPath) {
  const test::TempDir dir("encoding");
  const std::string original =
      test::read_file(test::corpus_dir() / "prusaslicer/tests/data/pyramid.obj");
  const auto path =
      test::write_text_file(dir / "pyramid.obj", to_utf16(original, Utf16Order::BigEndian));
  const auto soup = read_mesh(path);
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 6u);
  EXPECT_EQ(soup->format, "obj");
}

TEST(TextEncoding, NonAsciiCommentDecodesAndLinesKeepTheirNumbers) {
  // "é" and "€" in a comment; the bad number on line 3 is reported at line 3 of the file.
  const std::string text = "# pièce 5 €\nv 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const Utf16Order order : {Utf16Order::LittleEndian, Utf16Order::BigEndian}) {
    const auto soup = read_mesh_bytes(to_utf16(text, order), "part.obj");
    ASSERT_FALSE(soup);
    EXPECT_EQ(soup.error().location, "part.obj:3");
    EXPECT_TRUE(contains(soup.error().message, "bad number '1e999'")) << soup.error().message;
  }
}

TEST(TextEncoding, Utf16WithoutMarkIsRefusedNamingTheEncoding) {
  const std::string original =
      test::read_file(test::corpus_dir() / "trimesh/models/negative_indices.obj");
  for (const auto& [order, encoding] : {std::pair{Utf16Order::LittleEndian, "UTF-16 LE"},
                                        std::pair{Utf16Order::BigEndian, "UTF-16 BE"}}) {
    const auto soup = read_mesh_bytes(to_utf16(original, order, false), "part.obj");
    ASSERT_FALSE(soup);
    EXPECT_EQ(soup.error().code, ErrorCode::BadInput);
    EXPECT_EQ(soup.error().location, "part.obj");
    EXPECT_EQ(soup.error().message,
              std::string("the file looks like ") + encoding +
                  " text without a byte-order mark (NUL bytes between its characters); strata "
                  "reads ASCII or UTF-8, and UTF-16 with a byte-order mark: save it again in one "
                  "of those");
  }
}

TEST(TextEncoding, Utf16WithoutMarkIsRefusedWhateverTheExtension) {
  // The same refusal for a .stl (which would otherwise be judged by its binary size) and for a
  // name without extension, never "no facets".
  const std::string stl =
      test::read_file(test::corpus_dir() / "stl-models/polytopes/cube.ascii.stl");
  for (const char* name : {"cube.stl", "cube"}) {
    const auto soup = read_mesh_bytes(to_utf16(stl, Utf16Order::LittleEndian, false), name);
    ASSERT_FALSE(soup);
    EXPECT_EQ(soup.error().location, name);
    EXPECT_TRUE(contains(soup.error().message, "UTF-16 LE text without a byte-order mark"))
        << soup.error().message;
  }
}

/// `text` as UTF-32 of one byte order, ASCII only.
std::string to_utf32(std::string_view text, bool big_endian, bool with_mark) {
  std::string out;
  auto put = [&](std::uint32_t c) {
    for (int k = 0; k < 4; ++k) {
      const int shift = big_endian ? 8 * (3 - k) : 8 * k;
      out += static_cast<char>((c >> shift) & 0xFF);
    }
  };
  if (with_mark) put(0xFEFF);
  for (const char c : text) put(static_cast<unsigned char>(c));
  return out;
}

TEST(TextEncoding, Utf32IsRefusedWithOrWithoutMark) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const bool big_endian : {false, true}) {
    const auto marked = read_mesh_bytes(to_utf32(text, big_endian, true), "part.obj");
    ASSERT_FALSE(marked);
    EXPECT_EQ(marked.error().location, "part.obj");
    EXPECT_EQ(marked.error().message,
              "the file is UTF-32 text (byte-order mark), which strata does not read; save it as "
              "ASCII, UTF-8 or UTF-16");
    const auto unmarked = read_mesh_bytes(to_utf32(text, big_endian, false), "part.obj");
    ASSERT_FALSE(unmarked);
    EXPECT_TRUE(
        contains(unmarked.error().message, big_endian ? "UTF-32 BE text without a byte-order mark"
                                                      : "UTF-32 LE text without a byte-order mark"))
        << unmarked.error().message;
  }
}

TEST(TextEncoding, Utf16OfOddLengthIsRefused) {
  const std::string text = to_utf16("v 0 0 0\n", Utf16Order::LittleEndian) + "v";
  const auto soup = read_mesh_bytes(text, "part.obj");
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().location, "part.obj");
  EXPECT_EQ(soup.error().message,
            "UTF-16 LE text of an odd number of bytes (19): the file is cut short or not UTF-16");
}

TEST(TextEncoding, UnpairedSurrogatesAreRefusedWithTheirByte) {
  // Mark (2 bytes), 'v' (2), then a lone high surrogate at byte 4 followed by ' '.
  const auto high = read_mesh_bytes(std::string("\xFE\xFF\x00v\xD8\x00\x00 ", 8), "part.obj");
  ASSERT_FALSE(high);
  EXPECT_EQ(high.error().message,
            "invalid UTF-16 BE: a high surrogate without its low half at byte 4");
  const auto low = read_mesh_bytes(std::string("\xFF\xFEv\x00\x00\xDC", 6), "part.obj");
  ASSERT_FALSE(low);
  EXPECT_EQ(low.error().message,
            "invalid UTF-16 LE: a low surrogate without its high half at byte 4");
}

TEST(TextEncoding, BinaryStlWhoseHeaderStartsLikeAMarkIsStillBinary) {
  // An 80-byte header starting with FF FE, one facet: the size fits binary STL, so no decoding.
  std::string bytes(84 + 50, '\0');
  bytes[0] = '\xFF';
  bytes[1] = '\xFE';
  bytes[80] = 1;
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::memcpy(bytes.data() + 84 + 12, corners, sizeof corners);
  const auto soup = read_mesh_bytes(bytes, "marked.stl");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "stl-binary");
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0][1], (Vec3{1, 0, 0}));
  EXPECT_EQ(find_diagnostic(*soup, "io.text_encoding"), nullptr);
}

}  // namespace
}  // namespace strata::io
