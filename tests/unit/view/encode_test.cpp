// The page's encodings: base64 as atob() reads it, zlib as DecompressionStream("deflate") does.
#include <gtest/gtest.h>
#include <zlib.h>

#include <string>

#include "support/page_encodings.hpp"
#include "view/encode_internal.hpp"

namespace strata::view {
namespace {

TEST(Base64, MatchesTheRfc4648TestVectors) {
  EXPECT_EQ(detail::base64(""), "");
  EXPECT_EQ(detail::base64("f"), "Zg==");
  EXPECT_EQ(detail::base64("fo"), "Zm8=");
  EXPECT_EQ(detail::base64("foo"), "Zm9v");
  EXPECT_EQ(detail::base64("foob"), "Zm9vYg==");
  EXPECT_EQ(detail::base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(detail::base64("foobar"), "Zm9vYmFy");
}

TEST(Base64, EncodesEveryByteValue) {
  std::string all;
  for (int b = 0; b < 256; ++b) all.push_back(static_cast<char>(b));
  const std::string text = detail::base64(all);
  ASSERT_EQ(text.size(), 344u);
  EXPECT_EQ(text.substr(0, 8), "AAECAwQF");
  EXPECT_EQ(text.substr(text.size() - 8), "/P3+/w==");
}

TEST(WriteBase64, WritesExactlyTheCharactersItsSizeCounts) {
  for (const std::string bytes : {"", "f", "fo", "foo", "foob"}) {
    std::string room(detail::base64_size(bytes.size()) + 1, '#');
    const char* end = detail::write_base64(bytes, room.data());
    EXPECT_EQ(end, room.data() + room.size() - 1) << bytes;
    EXPECT_EQ(room.back(), '#') << "nothing past the end: " << bytes;
    room.pop_back();
    EXPECT_EQ(room, detail::base64(bytes));
  }
}

TEST(ZlibCompress, RoundTripsBytesWithoutRuns) {
  // The run-length strategy writes what it cannot match as literals.
  std::string noise(100'000, '\0');
  std::uint32_t x = 12345;
  for (char& c : noise) {
    x = x * 1664525u + 1013904223u;
    c = static_cast<char>(x >> 24);
  }
  EXPECT_EQ(test::inflate(detail::zlib_compress(noise), noise.size()), noise);
  EXPECT_EQ(test::inflate(detail::zlib_compress(""), 0), "");
}

TEST(ZlibCompress, RoundTripsThroughZlib) {
  std::string layer(100'000, '\0');
  for (std::size_t i = 40'000; i < 60'000; ++i) layer[i] = static_cast<char>(0x55);
  const std::string packed = detail::zlib_compress(layer);
  EXPECT_LT(packed.size(), layer.size() / 50);
  ASSERT_GE(packed.size(), 2u);
  EXPECT_EQ(static_cast<unsigned char>(packed[0]) & 0x0f, 8) << "deflate method in the header";
  std::string back(layer.size(), '\1');
  uLongf size = static_cast<uLongf>(back.size());
  ASSERT_EQ(
      uncompress(reinterpret_cast<Bytef*>(back.data()), &size,
                 reinterpret_cast<const Bytef*>(packed.data()), static_cast<uLong>(packed.size())),
      Z_OK);
  EXPECT_EQ(size, layer.size());
  EXPECT_EQ(back, layer);
}

TEST(AsBytes, ViewsScalarsInMemoryOrder) {
  const std::vector<std::uint32_t> v = {1, 0x01020304};
  const std::string_view bytes = detail::as_bytes(v);
  ASSERT_EQ(bytes.size(), 8u);
  EXPECT_EQ(bytes[0], 1);
  EXPECT_EQ(bytes[4], 4);
  EXPECT_EQ(bytes[7], 1);
}

}  // namespace
}  // namespace strata::view
