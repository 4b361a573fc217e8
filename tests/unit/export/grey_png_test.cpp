#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "export/grey_png_internal.hpp"
#include "support/page_encodings.hpp"

// The PNG encoder of the stack against zlib's and libpng's decoders: every stream inflates to
// the rows it was given, with a correct checksum, on rows of runs, of noise, repeated, one or
// two bytes wide, and wider than deflate's window.

namespace strata::io::detail {
namespace {

using Rows = std::vector<std::vector<std::uint8_t>>;

std::vector<std::uint8_t> joined(const Rows& rows) {
  std::vector<std::uint8_t> all;
  for (const auto& row : rows) all.insert(all.end(), row.begin(), row.end());
  return all;
}

/// The zlib stream of `rows`, inflated back (zlib checks the Adler-32 too, and the test fails
/// when the stream inflates to another size than the rows').
std::vector<std::uint8_t> round_trip(const Rows& rows) {
  std::string stream;
  RowDeflater deflater(rows.front().size(), stream);
  for (const auto& row : rows) deflater.add_row(row.data());
  deflater.finish();
  const std::string back = test::inflate(stream, rows.size() * rows.front().size());
  return {back.begin(), back.end()};
}

/// Rows of runs of a few levels, each row the one above with probability `repeat`.
Rows layer_like(std::size_t width, std::size_t height, double repeat, std::mt19937& random) {
  const std::uint8_t levels[] = {0, 128, 255, 143, 144};
  Rows rows;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::geometric_distribution<std::size_t> run_length(0.01);
  for (std::size_t r = 0; r < height; ++r) {
    if (!rows.empty() && unit(random) < repeat) {
      rows.push_back(rows.back());
      continue;
    }
    std::vector<std::uint8_t> row;
    while (row.size() < width) {
      const std::uint8_t level = levels[random() % 5];
      const std::size_t n = std::min(width - row.size(), 1 + run_length(random));
      row.insert(row.end(), n, level);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

TEST(RowDeflater, RunsAndRepeatedRowsInflateToTheRows) {
  std::mt19937 random(11);
  for (const std::size_t width : {1, 2, 3, 4, 257, 258, 259, 260, 261, 1000, 32768, 32769}) {
    for (const double repeat : {0.0, 0.5, 1.0}) {
      const Rows rows = layer_like(width, width > 5000 ? 6 : 40, repeat, random);
      EXPECT_EQ(round_trip(rows), joined(rows)) << width << " wide, repeat " << repeat;
    }
  }
}

TEST(RowDeflater, NoiseAndEveryByteValueInflateToTheRows) {
  std::mt19937 random(12);
  Rows rows(30, std::vector<std::uint8_t>(300));
  for (auto& row : rows) {
    for (auto& byte : row) byte = static_cast<std::uint8_t>(random());
  }
  EXPECT_EQ(round_trip(rows), joined(rows));
  Rows every(1, std::vector<std::uint8_t>(256));
  for (int v = 0; v < 256; ++v) every[0][v] = static_cast<std::uint8_t>(v);
  every.push_back(every[0]);
  EXPECT_EQ(round_trip(every), joined(every));
}

TEST(RowDeflater, LongRunsAcrossRowsAndTheChecksumOfManyBytes) {
  // One level throughout: a single run over every row, longer than the checksum's modulus.
  const Rows flat(300, std::vector<std::uint8_t>(1000, 255));
  EXPECT_EQ(round_trip(flat), joined(flat));
  // Rows alternating between two contents: no row is the one above.
  Rows alternating;
  for (int r = 0; r < 100; ++r) alternating.emplace_back(700, r % 2 == 0 ? 7 : 200);
  EXPECT_EQ(round_trip(alternating), joined(alternating));
}

TEST(RowDeflater, LayersOfRunsCompressWell) {
  std::mt19937 random(13);
  const Rows rows = layer_like(2000, 200, 0.5, random);
  std::string stream;
  RowDeflater deflater(2000, stream);
  for (const auto& row : rows) deflater.add_row(row.data());
  deflater.finish();
  // Within half again of what zlib's level 3 makes of the same bytes.
  const std::vector<std::uint8_t> all = joined(rows);
  std::vector<Bytef> packed(compressBound(static_cast<uLong>(all.size())));
  uLongf size = packed.size();
  ASSERT_EQ(compress2(packed.data(), &size, all.data(), static_cast<uLong>(all.size()), 3), Z_OK);
  EXPECT_LT(stream.size(), size * 3 / 2) << "zlib: " << size;
}

TEST(GreyPngEncoder, LibpngReadsThePixelsBack) {
  std::mt19937 random(14);
  for (const std::uint32_t width : {1u, 2u, 77u, 40000u}) {
    const std::uint32_t height = width > 1000 ? 3 : 50;
    const Rows rows = layer_like(width, height, 0.3, random);
    GreyPngEncoder encoder(width, height, 10000, 5000);
    for (const auto& row : rows) {
      std::copy(row.begin(), row.end(), encoder.next_row());
      encoder.add_row();
    }
    const std::string png = encoder.finish();
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    ASSERT_NE(png_image_begin_read_from_memory(&image, png.data(), png.size()), 0) << image.message;
    EXPECT_EQ(image.width, width);
    EXPECT_EQ(image.height, height);
    EXPECT_EQ(image.format, PNG_FORMAT_GRAY);
    std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(image));
    ASSERT_NE(png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr), 0)
        << image.message;
    EXPECT_EQ(pixels, joined(rows)) << width << " wide";
    EXPECT_NE(png.find("pHYs"), std::string::npos);
  }
}

}  // namespace
}  // namespace strata::io::detail
