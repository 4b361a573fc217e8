// append_empty_zip_entry: one more (empty, stored) entry in a plain zip archive, nothing for
// anything else.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "io/read_mesh_internal.hpp"
#include "support/three_mf_package.hpp"

namespace strata::io::detail {
namespace {

std::uint32_t le16(const std::string& b, std::size_t at) {
  return static_cast<unsigned char>(b[at]) | static_cast<unsigned char>(b[at + 1]) << 8;
}

std::uint32_t le32(const std::string& b, std::size_t at) {
  return le16(b, at) | le16(b, at + 2) << 16;
}

TEST(AppendEmptyZipEntry, AddsTheEntryAfterTheOthers) {
  const std::string zip = test::make_zip({{"a.txt", "alpha"}, {"dir/b.txt", "beta"}});
  const auto out = append_empty_zip_entry(zip, "Metadata/thumbnail.png");
  ASSERT_TRUE(out.has_value());
  // The end record: 3 entries, the directory right after the new local entry (30 + 22 bytes).
  const std::size_t end = out->size() - 22;
  ASSERT_EQ(le32(*out, end), 0x06054b50u);
  EXPECT_EQ(le16(*out, end + 8), 3u);
  EXPECT_EQ(le16(*out, end + 10), 3u);
  const std::uint32_t old_directory = le32(zip, zip.size() - 22 + 16);
  EXPECT_EQ(le32(*out, end + 16), old_directory + 30 + 22);
  EXPECT_EQ(le32(*out, end + 12), le32(zip, zip.size() - 22 + 12) + 46 + 22);
  // The entries before it are untouched, and so is the old directory.
  EXPECT_EQ(out->substr(0, old_directory), zip.substr(0, old_directory));
  EXPECT_EQ(le32(*out, old_directory), 0x04034b50u);
  EXPECT_EQ(out->substr(old_directory + 30, 22), "Metadata/thumbnail.png");
  // Appending it twice is refused: the archive holds it.
  EXPECT_FALSE(append_empty_zip_entry(*out, "Metadata/thumbnail.png").has_value());
  EXPECT_TRUE(append_empty_zip_entry(*out, "other").has_value());
}

TEST(AppendEmptyZipEntry, LeavesAnythingButAPlainZipAlone) {
  const std::string zip = test::make_zip({{"a.txt", "alpha"}});
  EXPECT_FALSE(append_empty_zip_entry("", "x").has_value());
  EXPECT_FALSE(append_empty_zip_entry("not a zip archive at all, just text", "x").has_value());
  // Cut short: the end record is gone.
  EXPECT_FALSE(append_empty_zip_entry(zip.substr(0, zip.size() - 5), "x").has_value());
  // A directory offset beyond the end record.
  std::string bad = zip;
  bad[bad.size() - 22 + 16] = '\x7f';
  EXPECT_FALSE(append_empty_zip_entry(bad, "x").has_value());
  // A directory that declares more bytes than its entries take (six bytes that begin like a
  // record): the entry goes before them, and is found again.
  std::string padded =
      zip.substr(0, zip.size() - 22) + "PK\x01\x02\x14\x03" + zip.substr(zip.size() - 22);
  const auto directory_size = static_cast<unsigned char>(padded[padded.size() - 22 + 12]);
  padded[padded.size() - 22 + 12] = static_cast<char>(directory_size + 6);
  const auto patched = append_empty_zip_entry(padded, "x");
  ASSERT_TRUE(patched.has_value());
  EXPECT_FALSE(append_empty_zip_entry(*patched, "x").has_value());
}

}  // namespace
}  // namespace strata::io::detail
