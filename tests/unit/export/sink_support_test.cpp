// The contract every file sink keeps (src/export/sink_support.cpp): the order of begin, layers
// and finish, refused with Error{Internal} when broken; the output folder; and the clean-up of
// the layer files an earlier, longer run left.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "strata/export/cells_writer.hpp"
#include "strata/export/svg_writer.hpp"
#include "support/file_size_limit.hpp"
#include "support/sink_runs.hpp"
#include "support/text_meshes.hpp"

namespace strata::io {
namespace {

using test::read_file;
using testing::ScratchDir;
using testing::small_layers;
using testing::small_run;

void expect_internal(const Result<void>& r, const std::string& message) {
  ASSERT_FALSE(r.has_value()) << "expected: " << message;
  EXPECT_EQ(r.error().code, ErrorCode::Internal);
  EXPECT_EQ(r.error().message, message);
}

TEST(SinkContract, BeginTwiceIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  ASSERT_TRUE(sink->begin(small_run()));
  expect_internal(sink->begin(small_run()), "cells writer: begin() called twice");
  sink->abort();
  EXPECT_FALSE(std::filesystem::exists(dir / "part.cells"));
}

TEST(SinkContract, LayerBeforeBeginIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_svg_writer(dir.path(), "part");
  expect_internal(sink->add_layer(small_layers()[0].result()),
                  "SVG writer: add_layer() outside begin() .. finish()");
}

TEST(SinkContract, LayerOutOfOrderIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  ASSERT_TRUE(sink->begin(small_run()));
  expect_internal(sink->add_layer(small_layers()[1].result()),
                  "cells writer: layer 1 arrived, expected layer 0");
}

TEST(SinkContract, LayerBeyondTheGridIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  ASSERT_TRUE(sink->begin(small_run()));
  auto layers = small_layers();
  for (const auto& layer : layers) ASSERT_TRUE(sink->add_layer(layer.result()));
  layers[0].layer = 2;
  expect_internal(sink->add_layer(layers[0].result()),
                  "cells writer: layer 2 is beyond the grid's 2 layers");
}

TEST(SinkContract, LayerWithTheWrongCellCountIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  ASSERT_TRUE(sink->begin(small_run()));
  auto layer = small_layers()[0];
  layer.cells.resize(3);
  expect_internal(sink->add_layer(layer.result()),
                  "cells writer: layer 0 has 3 cells, the grid 5 x 3 needs 15");
}

TEST(SinkContract, FinishBeforeEveryLayerOrWithoutBeginIsAnInternalError) {
  ScratchDir dir;
  auto early = make_cells_writer(dir / "part.cells");
  ASSERT_TRUE(early->begin(small_run()));
  ASSERT_TRUE(early->add_layer(small_layers()[0].result()));
  expect_internal(early->finish(), "cells writer: finish() after 1 of 2 layers");
  early->abort();
  EXPECT_FALSE(std::filesystem::exists(dir / "part.cells"));

  auto unstarted = make_svg_writer(dir.path(), "part");
  expect_internal(unstarted->finish(), "SVG writer: finish() without begin()");
}

TEST(SinkContract, CreatesMissingOutputFoldersAndRemovesThemOnAbort) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "a" / "b" / "part.cells");
  ASSERT_TRUE(sink->begin(small_run()));
  EXPECT_TRUE(std::filesystem::is_directory(dir / "a" / "b"));
  sink->abort();
  EXPECT_FALSE(std::filesystem::exists(dir / "a"));
  EXPECT_TRUE(std::filesystem::is_directory(dir.path()));
}

TEST(SinkContract, FileWhereAnOutputFolderShouldBeIsBadInput) {
  ScratchDir dir;
  test::write_text_file(dir / "a", "not a folder");
  auto sink = make_cells_writer(dir / "a" / "b" / "part.cells");
  const Result<void> r = sink->begin(small_run());
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::BadInput);
  EXPECT_EQ(r.error().location, (dir / "a").string());
  EXPECT_EQ(r.error().message, "cannot create the output folder: a file of that name exists");
  EXPECT_EQ(read_file(dir / "a"), "not a folder");
}

TEST(SinkContract, FinishRemovesOnlyTheStemsNumberedLayerFilesBeyondTheGrid) {
  ScratchDir dir;
  std::filesystem::create_directories(dir / "svg");
  const std::vector<std::string> kept = {"part_notes.svg", "part_00001.png", "other_00009.svg",
                                         "part_1.svg",     "part_0000x.svg", "part_000-1.svg"};
  const std::vector<std::string> stale = {"part_00002.svg", "part_00009.svg",
                                          "part_99999999999999999999999.svg"};
  for (const auto& name : kept) test::write_text_file(dir / "svg" / name, "x");
  for (const auto& name : stale) test::write_text_file(dir / "svg" / name, "x");
  auto sink = make_svg_writer(dir.path(), "part");
  ASSERT_TRUE(testing::run_sink(*sink, small_run(), small_layers()));
  for (const auto& name : kept) EXPECT_TRUE(std::filesystem::exists(dir / "svg" / name)) << name;
  for (const auto& name : stale) EXPECT_FALSE(std::filesystem::exists(dir / "svg" / name)) << name;
  EXPECT_TRUE(std::filesystem::exists(dir / "svg" / "part_00000.svg"));
  EXPECT_TRUE(std::filesystem::exists(dir / "svg" / "part_00001.svg"));
}

TEST(SinkContract, BeginTwiceIsAnInternalErrorForLayerFiles) {
  ScratchDir dir;
  auto sink = make_svg_writer(dir.path(), "part");
  ASSERT_TRUE(sink->begin(small_run()));
  expect_internal(sink->begin(small_run()), "SVG writer: begin() called twice");
}

TEST(SinkContract, AnOutputFolderTheSystemRefusesIsBadInputNamingIt) {
  // A name of 300 bytes is longer than a file system allows for one folder (255).
  ScratchDir dir;
  const std::filesystem::path folder = dir / std::string(300, 'f');
  auto sink = make_cells_writer(folder / "part.cells");
  const Result<void> r = sink->begin(small_run());
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::BadInput);
  EXPECT_EQ(r.error().location, folder.string());
  EXPECT_EQ(r.error().message, "cannot create the output folder: File name too long");
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(SinkContract, AnOutputFileTheSystemRefusesIsBadInputNamingIt) {
  ScratchDir dir;
  // A name longer than the system allows; built by appending (GCC 12 warns falsely about
  // a repeated character plus a literal).
  std::string name(300, 'c');
  name += ".cells";
  const std::filesystem::path file = dir / name;
  auto sink = make_cells_writer(file);
  const Result<void> r = sink->begin(small_run());
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::BadInput);
  EXPECT_EQ(r.error().location, file.string());
  EXPECT_EQ(r.error().message, "cannot create the file: File name too long");
}

TEST(SinkContract, AFolderAppearingAtTheTargetBeforeFinishFailsTheRename) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  ASSERT_TRUE(sink->begin(small_run()));
  for (const auto& layer : small_layers()) ASSERT_TRUE(sink->add_layer(layer.result()));
  std::filesystem::create_directory(dir / "part.cells");
  const Result<void> r = sink->finish();
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::BadInput);
  EXPECT_EQ(r.error().location, (dir / "part.cells").string());
  EXPECT_EQ(r.error().message, "cannot rename the finished temporary onto it: Is a directory");
  EXPECT_EQ(testing::list_tree(dir.path()), std::vector<std::string>{"part.cells"});
}

TEST(SinkContract, AFolderInPlaceOfALayerFileIsBadInput) {
  ScratchDir dir;
  std::filesystem::create_directories(dir / "svg" / "part_00001.svg");
  auto sink = make_svg_writer(dir.path(), "part");
  ASSERT_TRUE(sink->begin(small_run()));
  const auto layers = small_layers();
  ASSERT_TRUE(sink->add_layer(layers[0].result()));
  const Result<void> r = sink->add_layer(layers[1].result());
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::BadInput);
  EXPECT_EQ(r.error().location, (dir / "svg" / "part_00001.svg").string());
  EXPECT_EQ(r.error().message, "cannot write the file: a folder of that name exists");
  sink->abort();
  EXPECT_EQ(testing::list_tree(dir.path()),
            (std::vector<std::string>{"svg", "svg/part_00001.svg"}));
}

TEST(SinkContract, ALayerFileTheDiskRefusesIsBadInputAndLeavesNoTemporary) {
  ScratchDir dir;
  auto sink = make_svg_writer(dir.path(), "part");
  ASSERT_TRUE(sink->begin(small_run()));
  Result<void> added;
  {
    const test::FileSizeLimit limit(100);  // an SVG layer takes about 1.4 kB
    added = sink->add_layer(small_layers()[0].result());
  }
  ASSERT_FALSE(added.has_value());
  EXPECT_EQ(added.error().code, ErrorCode::BadInput);
  EXPECT_EQ(added.error().location, (dir / "svg" / "part_00000.svg").string());
  EXPECT_EQ(added.error().message, "cannot write the file: File too large");
  EXPECT_EQ(testing::list_tree(dir.path()), std::vector<std::string>{"svg"});
}

}  // namespace
}  // namespace strata::io
