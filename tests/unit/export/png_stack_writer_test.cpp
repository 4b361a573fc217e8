#include "strata/export/png_stack_writer.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "support/sink_runs.hpp"
#include "support/text_meshes.hpp"

namespace strata::io {
namespace {

using test::read_file;
using testing::list_tree;
using testing::run_sink;
using testing::ScratchDir;
using testing::small_layers;
using testing::small_run;

struct GreyImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> pixels;  ///< top row first

  std::uint8_t at(std::uint32_t column, std::uint32_t row) const {
    return pixels[std::size_t{row} * width + column];
  }
};

/// Decodes a PNG with libpng's simplified API; fails the test if it is not 8-bit grey.
GreyImage decode_png(const std::filesystem::path& path) {
  GreyImage result;
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&image, path.c_str()) == 0) {
    ADD_FAILURE() << "libpng cannot read " << path << ": " << image.message;
    return result;
  }
  EXPECT_EQ(image.format, PNG_FORMAT_GRAY) << path;
  image.format = PNG_FORMAT_GRAY;
  result.width = image.width;
  result.height = image.height;
  result.pixels.resize(PNG_IMAGE_SIZE(image));
  if (png_image_finish_read(&image, nullptr, result.pixels.data(), 0, nullptr) == 0) {
    ADD_FAILURE() << "libpng cannot decode " << path << ": " << image.message;
  }
  return result;
}

TEST(PngStackWriter, WritesOneFileALayerWithFiveDigitIndex) {
  ScratchDir dir;
  auto sink = make_png_stack_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  EXPECT_EQ(list_tree(dir.path()),
            (std::vector<std::string>{"png", "png/part_00000.png", "png/part_00001.png"}));
}

TEST(PngStackWriter, ImageIsEightBitGreyOfTheGridSize) {
  ScratchDir dir;
  auto sink = make_png_stack_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  const std::string file = read_file(dir / "png/part_00000.png");
  ASSERT_GT(file.size(), 26u);
  // IHDR: width and height big-endian at 16 and 20, bit depth at 24, colour type at 25.
  EXPECT_EQ(file.substr(12, 4), "IHDR");
  EXPECT_EQ(static_cast<unsigned char>(file[19]), 5);
  EXPECT_EQ(static_cast<unsigned char>(file[23]), 3);
  EXPECT_EQ(file[24], 8);
  EXPECT_EQ(file[25], 0);  // grey
}

TEST(PngStackWriter, PixelsShowCellsWithRowZeroAtTheBottom) {
  ScratchDir dir;
  auto sink = make_png_stack_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  const GreyImage image = decode_png(dir / "png/part_00000.png");
  ASSERT_EQ(image.width, 5u);
  ASSERT_EQ(image.height, 3u);
  // Layer 0, row j = 0 (0 1 3 3 1) is the last image row; row j = 2 (1 1 1 3 0) the first.
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{128, 128, 128, 255, 0,  //
                                                     255, 0, 128, 0, 0,      //
                                                     0, 128, 255, 255, 128}));
}

TEST(PngStackWriter, EveryLayerGetsItsOwnImage) {
  ScratchDir dir;
  auto sink = make_png_stack_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  const GreyImage image = decode_png(dir / "png/part_00001.png");
  ASSERT_EQ(image.pixels.size(), 15u);
  EXPECT_EQ(image.at(1, 1), 128);  // cell (1, 1) interior
  EXPECT_EQ(image.at(0, 1), 255);  // cell (0, 1) boundary
  EXPECT_EQ(image.at(4, 2), 255);  // cell (4, 0) boundary
}

TEST(PngStackWriter, GreyLevelsAreConfigurable) {
  ScratchDir dir;
  auto sink = make_png_stack_writer(dir.path(), "part",
                                    PngOptions{.empty = 10, .interior = 20, .boundary = 30});
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  const GreyImage image = decode_png(dir / "png/part_00000.png");
  ASSERT_EQ(image.pixels.size(), 15u);
  EXPECT_EQ(image.at(0, 2), 10);  // cell (0, 0) empty
  EXPECT_EQ(image.at(1, 2), 20);  // cell (1, 0) interior
  EXPECT_EQ(image.at(2, 2), 30);  // cell (2, 0) boundary
}

TEST(PngStackWriter, StoresThePixelPitch) {
  ScratchDir dir;
  auto sink = make_png_stack_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  const std::string file = read_file(dir / "png/part_00000.png");
  const auto at = file.find("pHYs");
  ASSERT_NE(at, std::string::npos);
  auto be32 = [&](std::size_t offset) {
    std::uint32_t v = 0;
    for (int b = 0; b < 4; ++b) v = (v << 8) | static_cast<unsigned char>(file[offset + b]);
    return v;
  };
  EXPECT_EQ(be32(at + 4), 2000u);  // dx = 0.5 mm
  EXPECT_EQ(be32(at + 8), 4000u);  // dy = 0.25 mm
}

TEST(PngStackWriter, AbortRemovesEarlierLayersAndTheFoldersItCreated) {
  ScratchDir dir;
  auto sink = make_png_stack_writer(dir / "out", "part");
  auto layers = small_layers();
  ASSERT_TRUE(sink->begin(small_run()));
  ASSERT_TRUE(sink->add_layer(layers[0].result()));
  EXPECT_TRUE(std::filesystem::exists(dir / "out/png/part_00000.png"));
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(PngStackWriter, AbortLeavesForeignFilesAndTheirFolder) {
  ScratchDir dir;
  std::filesystem::create_directory(dir / "png");
  test::write_text_file(dir / "png/notes.txt", "mine");
  auto sink = make_png_stack_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  sink->abort();
  EXPECT_EQ(list_tree(dir.path()), (std::vector<std::string>{"png", "png/notes.txt"}));
}

TEST(PngStackWriter, DestroyingAnUnfinishedSinkLeavesNothing) {
  ScratchDir dir;
  testing::expect_destroyed_unfinished_sink_leaves_nothing(
      make_png_stack_writer(dir.path(), "part"), dir);
}

TEST(PngStackWriter, FinishRemovesStaleLayersOfALongerEarlierRun) {
  ScratchDir dir;
  std::filesystem::create_directory(dir / "png");
  test::write_text_file(dir / "png/part_00002.png", "old");
  test::write_text_file(dir / "png/part_00007.png", "old");
  test::write_text_file(dir / "png/other_00009.png", "other stem");
  test::write_text_file(dir / "png/part_final.png", "not a layer");
  auto sink = make_png_stack_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  EXPECT_EQ(list_tree(dir.path()),
            (std::vector<std::string>{"png", "png/other_00009.png", "png/part_00000.png",
                                      "png/part_00001.png", "png/part_final.png"}));
}

TEST(PngStackWriter, WrongCellCountIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_png_stack_writer(dir.path(), "part");
  auto layers = small_layers();
  layers[0].cells.resize(4);
  ASSERT_TRUE(sink->begin(small_run()));
  auto added = sink->add_layer(layers[0].result());
  ASSERT_FALSE(added);
  EXPECT_EQ(added.error().code, ErrorCode::Internal);
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(PngStackWriter, NoPixelPitchWhenACellSizeDoesNotFitThePngChunk) {
  // The pHYs chunk holds whole pixels per metre in 32 bits: a 5 m cell rounds to 0 of them, a
  // 1e-7 mm cell needs 10^10. Both axes are then left without a pitch.
  for (const auto& [dx, dy] : {std::pair{5000.0, 0.25}, std::pair{0.5, 1e-7}}) {
    ScratchDir dir;
    SliceRunInfo run = small_run();
    run.grid.dx = dx;
    run.grid.dy = dy;
    auto sink = make_png_stack_writer(dir.path(), "part");
    ASSERT_TRUE(run_sink(*sink, run, small_layers()));
    const std::string file = read_file(dir / "png/part_00000.png");
    EXPECT_EQ(file.find("pHYs"), std::string::npos) << dx << " x " << dy;
    const GreyImage image = decode_png(dir / "png/part_00000.png");
    EXPECT_EQ(image.width, 5u);
    EXPECT_EQ(image.height, 3u);
  }
}

TEST(PngStackWriter, AnImagePngCannotHoldIsAnInternalErrorNamingTheLayerFile) {
  // A grid without columns has layers of zero cells, which the sink contract allows but PNG
  // does not (IHDR needs a width of at least 1).
  ScratchDir dir;
  SliceRunInfo run = small_run();
  run.grid.nx = 0;
  auto sink = make_png_stack_writer(dir.path(), "part");
  ASSERT_TRUE(sink->begin(run));
  testing::LayerData layer;
  auto added = sink->add_layer(layer.result());
  ASSERT_FALSE(added);
  EXPECT_EQ(added.error().code, ErrorCode::Internal);
  EXPECT_EQ(added.error().message,
            "cannot encode the PNG of layer 0: a PNG is 1 to 2147483647 pixels wide and high, the "
            "grid's layers are 0 x 3 cells");
  EXPECT_EQ(added.error().location, (dir / "png/part_00000.png").string());
  EXPECT_EQ(list_tree(dir.path()), std::vector<std::string>{"png"});  // no temporary left
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

}  // namespace
}  // namespace strata::io
