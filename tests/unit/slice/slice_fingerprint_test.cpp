#include "strata/slice/slice_fingerprint.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "core/sha256.hpp"
#include "support/temp_dir.hpp"
#include "support/text_meshes.hpp"

namespace strata {
namespace {

TEST(Sha256, MatchesTheStandardsVectors) {
  detail::Sha256 empty;
  EXPECT_EQ(empty.hex_digest(), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  detail::Sha256 abc;
  abc.update("abc");
  EXPECT_EQ(abc.hex_digest(), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // Two blocks, fed in pieces that straddle the block boundary.
  detail::Sha256 two;
  two.update("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq");
  EXPECT_EQ(two.hex_digest(), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  detail::Sha256 pieces;
  pieces.update("abcdbcdecdefdefgefghfghighijhijki");
  pieces.update("jkljklmklmnlmnomnopnopq");
  EXPECT_EQ(pieces.hex_digest(), two.hex_digest());
  // Digesting does not end the message.
  detail::Sha256 growing;
  growing.update("ab");
  EXPECT_EQ(growing.hex_digest(), growing.hex_digest());
  growing.update("c");
  EXPECT_EQ(growing.hex_digest(), abc.hex_digest());
}

TEST(Sha256, ThePlainRoundsMatchTheStandardsVectorsToo) {
  // Whichever rounds hash_digest() uses on this processor, the plain ones are checked here.
  EXPECT_EQ(detail::Sha256::portable_hex_digest(""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(detail::Sha256::portable_hex_digest(
                "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // One million 'a' (FIPS 180-4's long example): many whole blocks.
  EXPECT_EQ(detail::Sha256::portable_hex_digest(std::string(1'000'000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, AgreesWithThePlainRoundsOnEveryLengthAndSplit) {
  // Random messages of every length across a few blocks, fed whole and in random pieces: the
  // digest is the plain rounds' (on a processor with SHA instructions, theirs against it).
  std::mt19937 rng(2026);
  std::string message;
  for (std::size_t length = 0; length <= 1100; length += length < 200 ? 1 : 37) {
    message.resize(length);
    for (char& c : message) c = static_cast<char>(rng());
    const std::string expected = detail::Sha256::portable_hex_digest(message);
    detail::Sha256 whole;
    whole.update(message);
    ASSERT_EQ(whole.hex_digest(), expected) << "length " << length;
    detail::Sha256 pieces;
    for (std::size_t at = 0; at < length;) {
      const std::size_t piece = std::min<std::size_t>(length - at, rng() % 150);
      pieces.update(std::string_view(message).substr(at, piece));
      at += piece;
    }
    ASSERT_EQ(pieces.hex_digest(), expected) << "length " << length;
  }
  RecordProperty("processor_extensions", detail::Sha256::uses_processor_extensions() ? 1 : 0);
}

TEST(Sha256, TakesTheProcessorRoundsOnlyWithSsse3Sse41AndSha) {
  constexpr std::uint32_t kSsse3 = 1U << 9, kSse41 = 1U << 19, kSha = 1U << 29;
  EXPECT_TRUE(detail::Sha256::extensions_usable(kSsse3 | kSse41, kSha));
  EXPECT_TRUE(detail::Sha256::extensions_usable(~0U, ~0U));
  EXPECT_FALSE(detail::Sha256::extensions_usable(kSse41, kSha)) << "no SSSE3";
  EXPECT_FALSE(detail::Sha256::extensions_usable(kSsse3, kSha)) << "no SSE4.1";
  EXPECT_FALSE(detail::Sha256::extensions_usable(kSsse3 | kSse41, ~kSha)) << "no SHA";
  EXPECT_FALSE(detail::Sha256::extensions_usable(0, 0));
}

TEST(SliceFingerprint, ChangesWithTheModelBytesAndTheCellOptions) {
  test::TempDir dir;
  const auto a = test::write_text_file(dir / "a.stl", "solid a\nendsolid a\n");
  const auto b = test::write_text_file(dir / "b.stl", "solid b\nendsolid b\n");
  const auto a_copy = test::write_text_file(dir / "copy.stl", "solid a\nendsolid a\n");
  const SliceOptions options;
  const std::string text = cell_options_text(options);
  const std::string fa = slice_fingerprint(a, text).value();
  EXPECT_EQ(fa.size(), 64u);
  EXPECT_EQ(slice_fingerprint(a_copy, text).value(), fa);  // bytes, not names
  EXPECT_NE(slice_fingerprint(b, text).value(), fa);
  EXPECT_NE(slice_fingerprint(a, text + ";kernel=exact").value(), fa);

  const auto changed = [&](auto change) {
    SliceOptions o;
    change(o);
    return cell_options_text(o) != text;
  };
  EXPECT_TRUE(changed([](SliceOptions& o) { o.grid.dx_mm = 0.2; }));
  EXPECT_TRUE(changed([](SliceOptions& o) { o.grid.dy_mm = 0.2; }));
  EXPECT_TRUE(changed([](SliceOptions& o) { o.grid.dz_mm = 0.1000000001; }));
  EXPECT_TRUE(changed([](SliceOptions& o) { o.grid.origin = Vec3{0, 0, 0}; }));
  EXPECT_TRUE(changed([](SliceOptions& o) { o.shell_mm = 0.6; }));
  EXPECT_TRUE(changed([](SliceOptions& o) { o.shell_mode = ShellMode::Layers; }));
  EXPECT_TRUE(changed([](SliceOptions& o) { o.fill_rule = FillRule::EvenOdd; }));
  EXPECT_TRUE(changed([](SliceOptions& o) { o.scan_offset_mm = 0.0001; }));
  // What does not change a cell does not change the fingerprint.
  EXPECT_FALSE(changed([](SliceOptions& o) { o.layers = {3, 9}; }));
  EXPECT_FALSE(changed([](SliceOptions& o) { o.threads = 7; }));
  EXPECT_FALSE(changed([](SliceOptions& o) { o.batch_layers = 5; }));
}

TEST(SliceFingerprint, NamesAModelItCannotRead) {
  test::TempDir dir;
  const auto missing = dir / "missing.stl";
  const auto fingerprint = slice_fingerprint(missing, "");
  ASSERT_FALSE(fingerprint);
  EXPECT_EQ(fingerprint.error().code, ErrorCode::BadInput);
  EXPECT_EQ(fingerprint.error().location, missing.string());
}

}  // namespace
}  // namespace strata
