// Every file writer writes the same bytes whether a layer is added as it comes (add_layer) or
// prepared ahead on another thread, in any order, and added later (the engine's way).

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "strata/export/cells_writer.hpp"
#include "strata/export/cli_writer.hpp"
#include "strata/export/png_stack_writer.hpp"
#include "strata/export/svg_writer.hpp"
#include "support/sink_runs.hpp"

namespace strata::io {
namespace {

using test::read_file;
using testing::LayerData;
using testing::list_tree;
using testing::loop;
using testing::ScratchDir;
using testing::small_layers;
using testing::small_run;

/// small_layers() with loops of every kind and hatch segments on both layers.
std::vector<LayerData> layers_with_everything() {
  auto layers = small_layers();
  layers[0].contours.loops.push_back(
      loop({{-1.25, 2.375}, {0.75, 2.375}, {0.75, 2.875}, {-1.25, 2.875}}, LoopKind::Outer));
  layers[0].hatches = {{1, -1.1, 0.6}};
  LayerContours& c = layers[1].contours;
  c.loops.push_back(loop({{-1.0, 2.5}, {-1.0, 2.75}, {0.5, 2.75}, {0.5, 2.5}}, LoopKind::Hole, 1));
  c.loops.push_back(
      loop({{-1.25, 2.375}, {0.75, 2.375}, {0.75, 2.875}, {-1.25, 2.875}}, LoopKind::Outer));
  c.loops.push_back(loop({{0.875, 2.3}, {0.9, 2.6}, {0.95, 2.9}}, LoopKind::Open));
  layers[1].hatches = {{0, -1.25, 0.75}, {2, -1.25, -1.0}};
  return layers;
}

using MakeSink = std::function<std::unique_ptr<LayerSink>(const std::filesystem::path& dir)>;

/// Every file a run of the sink made under a fresh folder, by relative path.
std::map<std::string, std::string> files_written(const MakeSink& make, bool prepared) {
  const ScratchDir dir;
  auto sink = make(dir.path());
  const auto layers = layers_with_everything();
  auto ok = prepared ? testing::run_sink_prepared(*sink, small_run(), layers)
                     : testing::run_sink(*sink, small_run(), layers);
  EXPECT_TRUE(ok) << ok.error().to_string();
  std::map<std::string, std::string> files;
  for (const std::string& name : list_tree(dir.path())) {
    if (std::filesystem::is_regular_file(dir / name)) files[name] = read_file(dir / name);
  }
  return files;
}

void expect_same_files_either_way(const MakeSink& make, std::size_t expected_files) {
  const auto as_they_come = files_written(make, false);
  const auto prepared_ahead = files_written(make, true);
  EXPECT_EQ(as_they_come.size(), expected_files);
  EXPECT_EQ(prepared_ahead, as_they_come);
}

TEST(PreparedLayers, BinaryCellsAreTheSame) {
  expect_same_files_either_way(
      [](const auto& dir) { return make_cells_writer(dir / "part.cells", CellsEncoding::Binary); },
      1);
}

TEST(PreparedLayers, AsciiCellsAreStreamedAndTheSame) {
  // The text writer prepares nothing: a text layer is twice its cells.
  const ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells.txt", CellsEncoding::Ascii);
  ASSERT_TRUE(sink->begin(small_run()));
  EXPECT_EQ(sink->prepare_layer(small_layers()[0].result()), nullptr);
  sink->abort();
  expect_same_files_either_way(
      [](const auto& dir) {
        return make_cells_writer(dir / "part.cells.txt", CellsEncoding::Ascii);
      },
      1);
}

TEST(PreparedLayers, CliTextAndBinaryAreTheSame) {
  expect_same_files_either_way(
      [](const auto& dir) { return make_cli_writer(dir / "part.cli", CliEncoding::Ascii); }, 1);
  expect_same_files_either_way(
      [](const auto& dir) { return make_cli_writer(dir / "part.bin.cli", CliEncoding::Binary); },
      1);
}

TEST(PreparedLayers, SvgAndPngLayerFilesAreTheSame) {
  expect_same_files_either_way([](const auto& dir) { return make_svg_writer(dir, "part"); }, 2);
  expect_same_files_either_way([](const auto& dir) { return make_png_stack_writer(dir, "part"); },
                               2);
}

TEST(PreparedLayers, WhatWasPreparedForAnotherLayerIsNotWritten) {
  // Layer 1's bytes handed with layer 0: the writer encodes layer 0 itself.
  const ScratchDir dir;
  const auto layers = layers_with_everything();
  auto sink = make_cli_writer(dir / "part.cli", CliEncoding::Ascii);
  ASSERT_TRUE(sink->begin(small_run()));
  auto for_layer_1 = sink->prepare_layer(layers[1].result());
  ASSERT_NE(for_layer_1, nullptr);
  ASSERT_TRUE(sink->add_prepared_layer(layers[0].result(), std::move(for_layer_1)));
  ASSERT_TRUE(sink->add_prepared_layer(layers[1].result(), nullptr));
  ASSERT_TRUE(sink->finish());
  const auto expected = files_written(
      [](const auto& d) { return make_cli_writer(d / "part.cli", CliEncoding::Ascii); }, false);
  EXPECT_EQ(read_file(dir / "part.cli"), expected.at("part.cli"));
}

TEST(PreparedLayers, APreparedLayerStillHasToComeInOrder) {
  const ScratchDir dir;
  const auto layers = layers_with_everything();
  auto sink = make_cells_writer(dir / "part.cells", CellsEncoding::Binary);
  ASSERT_TRUE(sink->begin(small_run()));
  auto ok = sink->add_prepared_layer(layers[1].result(), sink->prepare_layer(layers[1].result()));
  ASSERT_FALSE(ok);
  EXPECT_EQ(ok.error().code, ErrorCode::Internal);
  EXPECT_NE(ok.error().message.find("layer 1 arrived, expected layer 0"), std::string::npos)
      << ok.error().message;
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(PreparedLayers, AReservedCodeFoundWhilePreparingIsReportedInItsTurn) {
  // The error made ahead is the layer's, reported when the layer is added, not before.
  const ScratchDir dir;
  auto layers = layers_with_everything();
  layers[1].cells[7] = static_cast<CellClass>(2);
  auto sink = make_cells_writer(dir / "part.cells", CellsEncoding::Binary);
  ASSERT_TRUE(sink->begin(small_run()));
  auto bad = sink->prepare_layer(layers[1].result());
  ASSERT_TRUE(
      sink->add_prepared_layer(layers[0].result(), sink->prepare_layer(layers[0].result())));
  auto ok = sink->add_prepared_layer(layers[1].result(), std::move(bad));
  ASSERT_FALSE(ok);
  EXPECT_NE(ok.error().message.find("layer 1 row 1 cell 2 has the code 2"), std::string::npos)
      << ok.error().message;
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

}  // namespace
}  // namespace strata::io
