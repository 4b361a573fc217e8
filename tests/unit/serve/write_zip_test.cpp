#include "strata/serve/write_zip.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>

#include "support/read_file.hpp"
#include "support/temp_dir.hpp"
#include "support/text_meshes.hpp"

namespace strata::serve {
namespace {

namespace fs = std::filesystem;

std::uint32_t u32(const std::string& b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}
std::uint16_t u16(const std::string& b, std::size_t at) {
  return static_cast<std::uint16_t>(static_cast<unsigned char>(b[at]) |
                                    static_cast<unsigned char>(b[at + 1]) << 8);
}

/// Reads an archive through its central directory, inflating each entry and checking its CRC.
std::map<std::string, std::string> read_zip(const std::string& zip) {
  std::map<std::string, std::string> out;
  const std::size_t end = zip.size() - 22;
  EXPECT_EQ(u32(zip, end), 0x06054b50u);
  const std::uint16_t count = u16(zip, end + 10);
  std::size_t at = u32(zip, end + 16);
  for (std::uint16_t n = 0; n < count; ++n) {
    EXPECT_EQ(u32(zip, at), 0x02014b50u);
    const std::uint16_t method = u16(zip, at + 10);
    const std::uint32_t crc = u32(zip, at + 16);
    const std::uint32_t packed = u32(zip, at + 20);
    const std::uint32_t size = u32(zip, at + 24);
    const std::uint16_t name_length = u16(zip, at + 28);
    const std::string name = zip.substr(at + 46, name_length);
    const std::size_t local = u32(zip, at + 42);
    EXPECT_EQ(u32(zip, local), 0x04034b50u);
    const std::size_t data = local + 30 + u16(zip, local + 26) + u16(zip, local + 28);
    std::string bytes(size, '\0');
    if (method == 0) {
      bytes = zip.substr(data, size);
    } else {
      EXPECT_EQ(method, 8);
      z_stream z{};
      inflateInit2(&z, -15);
      z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(zip.data() + data));
      z.avail_in = packed;
      z.next_out = reinterpret_cast<Bytef*>(bytes.data());
      z.avail_out = size;
      EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
      inflateEnd(&z);
    }
    EXPECT_EQ(crc32(0, reinterpret_cast<const Bytef*>(bytes.data()), size), crc) << name;
    out[name] = bytes;
    at += 46 + name_length + u16(zip, at + 30) + u16(zip, at + 32);
  }
  return out;
}

class WriteZip : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(dir_ / "in" / "sub"); }
  void write(const fs::path& p, const std::string& text) { test::write_text_file(p, text); }
  test::TempDir dir_{"zip"};
};

TEST_F(WriteZip, RoundTripsStoredAndDeflatedEntries) {
  const std::string repetitive(100000, 'x');
  const std::string tiny = "a";
  std::string empty;
  write(dir_ / "in" / "big.svg", repetitive);
  write(dir_ / "in" / "sub" / "t.png", tiny);
  write(dir_ / "in" / "empty", empty);
  auto entries = zip_entries_of_folder(dir_ / "in", "stack/");
  ASSERT_TRUE(entries);
  ASSERT_EQ(entries->size(), 3u);
  EXPECT_EQ((*entries)[0].name, "stack/big.svg");
  EXPECT_EQ((*entries)[2].name, "stack/sub/t.png");
  ASSERT_TRUE(write_zip(dir_ / "out.zip", *entries));
  const std::string zip = test::read_file(dir_ / "out.zip");
  EXPECT_LT(zip.size(), 5000u);  // the repetitive file was deflated
  const auto files = read_zip(zip);
  EXPECT_EQ(files.at("stack/big.svg"), repetitive);
  EXPECT_EQ(files.at("stack/sub/t.png"), tiny);
  EXPECT_EQ(files.at("stack/empty"), empty);
}

TEST_F(WriteZip, SameFilesGiveTheSameBytes) {
  write(dir_ / "in" / "a.txt", "hello hello hello");
  auto entries = zip_entries_of_folder(dir_ / "in", "");
  ASSERT_TRUE(entries);
  ASSERT_TRUE(write_zip(dir_ / "1.zip", *entries));
  ASSERT_TRUE(write_zip(dir_ / "2.zip", *entries));
  EXPECT_EQ(test::read_file(dir_ / "1.zip"), test::read_file(dir_ / "2.zip"));
}

TEST_F(WriteZip, AMissingFileIsAnErrorAndLeavesNoArchive) {
  const std::vector<ZipEntry> entries = {{"x", dir_ / "in" / "missing"}};
  const auto result = write_zip(dir_ / "out.zip", entries);
  ASSERT_FALSE(result);
  EXPECT_NE(result.error().location.find("missing"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "out.zip"));
}

TEST_F(WriteZip, AnEmptyListIsAnEmptyArchive) {
  ASSERT_TRUE(write_zip(dir_ / "out.zip", {}));
  const std::string zip = test::read_file(dir_ / "out.zip");
  EXPECT_EQ(zip.size(), 22u);
  EXPECT_TRUE(read_zip(zip).empty());
}

}  // namespace
}  // namespace strata::serve
