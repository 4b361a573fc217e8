// What the view page holds of each layer: packed as the cells file, blocks for 3D, the budget.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "strata/view/view_stack.hpp"
#include "support/page_encodings.hpp"
#include "support/sink_runs.hpp"

namespace strata::view {
namespace {

using test::inflate;

SliceRunInfo run_on(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz) {
  SliceRunInfo run;
  run.grid = GridSpec{0, 0, 0, 0.5, 0.25, 0.1, nx, ny, nz};
  run.options.shell_mm = 0.3;
  return run;
}

/// Cell (i, j) of layer k: boundary on the rim of the layer, interior inside, empty at i == 0.
CellClass pattern(std::uint32_t i, std::uint32_t j, std::uint32_t nx, std::uint32_t ny) {
  if (i == 0) return CellClass::Empty;
  if (i == 1 || j == 0 || i == nx - 1 || j == ny - 1) return CellClass::Boundary;
  return CellClass::Interior;
}

void feed(ViewStackCollector& sink, const SliceRunInfo& run, std::size_t hatches_a_layer = 0) {
  ASSERT_TRUE(sink.begin(run).has_value());
  const GridSpec& g = run.grid;
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    std::vector<CellClass> cells(g.cells_per_layer());
    for (std::uint32_t j = 0; j < g.ny; ++j) {
      for (std::uint32_t i = 0; i < g.nx; ++i) cells[j * g.nx + i] = pattern(i, j, g.nx, g.ny);
    }
    LayerContours contours;
    Contour square;
    square.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    square.is_closed = true;
    square.kind = LoopKind::Outer;
    contours.loops.push_back(square);
    std::vector<HatchSegment> hatches;
    for (std::size_t h = 0; h < hatches_a_layer; ++h) {
      hatches.push_back(HatchSegment{static_cast<std::uint32_t>(h % g.ny), 0.5, 2.0});
    }
    ASSERT_TRUE(sink.add_layer(LayerResult{k, g.zk(k), cells, contours, hatches}).has_value());
  }
  ASSERT_TRUE(sink.finish().has_value());
}

TEST(ViewStackCollector, PacksLayersAsTheCellsFileWithTheFirstCellInTheHighBits) {
  ViewStackCollector sink;
  const SliceRunInfo run = run_on(5, 3, 2);
  feed(sink, run);
  const ViewStack stack = sink.take();
  ASSERT_EQ(stack.stored, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(stack.stride, 1u);
  EXPECT_DOUBLE_EQ(stack.shell_mm, 0.3);
  const std::string layer = inflate(stack.cells_zlib[1], 4);  // ceil(15 / 4) bytes
  // Row 0: 00 11 11 11 11 | row 1: 00 11 01 01 11 | row 2: 00 11 11 11 11, then 2 padding bits.
  EXPECT_EQ(static_cast<unsigned char>(layer[0]), 0b00111111);
  EXPECT_EQ(static_cast<unsigned char>(layer[1]), 0b11001101);
  EXPECT_EQ(static_cast<unsigned char>(layer[2]), 0b01110011);
  EXPECT_EQ(static_cast<unsigned char>(layer[3]), 0b11111100);
  ASSERT_EQ(stack.contours[0].size(), 1u);
  EXPECT_EQ(stack.contours[0][0].kind, LoopKind::Outer);
  EXPECT_EQ(stack.contours[0][0].xy, (std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1}));
}

TEST(ViewStackCollector, VolumeBlocksHoldTheHighestClassOfTheirCells) {
  ViewStackCollector sink(ViewStackOptions{.max_blocks = 2});
  feed(sink, run_on(5, 3, 3));
  const ViewVolume v = sink.take().volume;
  EXPECT_EQ(v.bx, 3u);  // ceil(5 / 2)
  EXPECT_EQ(v.by, 2u);
  EXPECT_EQ(v.bz, 2u);
  EXPECT_EQ(v.nx, 2u);
  EXPECT_EQ(v.ny, 2u);
  EXPECT_EQ(v.nz, 2u);
  ASSERT_EQ(v.blocks.size(), 8u);
  for (std::uint8_t b : v.blocks) EXPECT_EQ(b, 3) << "every block touches the boundary rim";
}

TEST(ViewStackCollector, EachVolumeBlockIsTheHighestClassOfItsCellsWhateverTheirMix) {
  // Random classes on a grid whose blocks do not divide it evenly: every block against the
  // highest class of the cells it covers, found cell by cell.
  const SliceRunInfo run = run_on(23, 17, 9);
  const GridSpec& g = run.grid;
  std::mt19937 rng(7);
  const CellClass classes[] = {CellClass::Empty, CellClass::Interior, CellClass::Boundary};
  std::vector<std::vector<CellClass>> layers(g.nz, std::vector<CellClass>(g.cells_per_layer()));
  for (auto& layer : layers) {
    // Mostly empty or interior, so that many blocks stop below the boundary class.
    for (CellClass& c : layer) c = classes[rng() % 16 == 0 ? 2 : rng() % 2];
  }
  ViewStackCollector sink(ViewStackOptions{.max_blocks = 6});
  ASSERT_TRUE(sink.begin(run).has_value());
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    ASSERT_TRUE(sink.add_layer(LayerResult{k, g.zk(k), layers[k], {}, {}}).has_value());
  }
  ASSERT_TRUE(sink.finish().has_value());
  const ViewVolume v = sink.take().volume;
  ASSERT_GT(v.bx, 1u);
  ASSERT_GT(v.by, 1u);
  std::size_t below_boundary = 0;
  for (std::uint32_t bk = 0; bk < v.nz; ++bk) {
    for (std::uint32_t bj = 0; bj < v.ny; ++bj) {
      for (std::uint32_t bi = 0; bi < v.nx; ++bi) {
        std::uint8_t highest = 0;
        for (std::uint32_t k = bk * v.bz; k < std::min(g.nz, (bk + 1) * v.bz); ++k) {
          for (std::uint32_t j = bj * v.by; j < std::min(g.ny, (bj + 1) * v.by); ++j) {
            for (std::uint32_t i = bi * v.bx; i < std::min(g.nx, (bi + 1) * v.bx); ++i) {
              highest = std::max(highest, static_cast<std::uint8_t>(layers[k][j * g.nx + i]));
            }
          }
        }
        below_boundary += highest < 3 ? 1 : 0;
        EXPECT_EQ(v.blocks[(std::size_t{bk} * v.ny + bj) * v.nx + bi], highest)
            << "block (" << bi << ", " << bj << ", " << bk << ")";
      }
    }
  }
  EXPECT_GT(below_boundary, 0u);
}

TEST(ViewStackCollector, KeepsTheSameWhetherLayersArePreparedAheadOrNot) {
  // The engine prepares layers on its threads, in any order; what is kept must not change, the
  // blocks shared by both layers included (max_blocks 1: one block holds every cell).
  auto layers = io::testing::small_layers();
  layers[1].contours.loops.push_back(io::testing::loop({{0, 0}, {1, 0}, {0, 1}}, LoopKind::Hole));
  layers[1].hatches = {{0, -1.25, 0.75}, {2, -1.25, -1.0}};
  for (std::uint32_t max_blocks : {1u, 2u, 200u}) {
    ViewStackCollector as_they_come(ViewStackOptions{.max_blocks = max_blocks});
    ViewStackCollector prepared(ViewStackOptions{.max_blocks = max_blocks});
    ASSERT_TRUE(io::testing::run_sink(as_they_come, io::testing::small_run(), layers));
    ASSERT_TRUE(io::testing::run_sink_prepared(prepared, io::testing::small_run(), layers));
    const ViewStack a = as_they_come.take();
    const ViewStack b = prepared.take();
    EXPECT_EQ(b.stored, a.stored);
    EXPECT_EQ(b.cells_zlib, a.cells_zlib);
    ASSERT_EQ(b.contours.size(), a.contours.size());
    for (std::size_t s = 0; s < a.contours.size(); ++s) {
      ASSERT_EQ(b.contours[s].size(), a.contours[s].size());
      for (std::size_t l = 0; l < a.contours[s].size(); ++l) {
        EXPECT_EQ(b.contours[s][l].kind, a.contours[s][l].kind);
        EXPECT_EQ(b.contours[s][l].xy, a.contours[s][l].xy);
      }
    }
    EXPECT_EQ(b.hatches, a.hatches);
    EXPECT_EQ(b.volume.blocks, a.volume.blocks);
    EXPECT_EQ(a.volume.blocks.size(), max_blocks == 1 ? 1u : max_blocks == 2 ? 8u : 30u);
  }
}

TEST(ViewStackCollector, AddsALayerPreparedForAnotherOrNotAtAllAsItComes) {
  // A prepared layer that is missing or belongs to another layer is not used: the layer is
  // taken as it comes, and the stack is the one the plain run keeps.
  const auto layers = io::testing::small_layers();
  ASSERT_GE(layers.size(), 2u);
  ViewStackCollector as_they_come;
  ASSERT_TRUE(io::testing::run_sink(as_they_come, io::testing::small_run(), layers));
  ViewStackCollector mismatched;
  ASSERT_TRUE(mismatched.begin(io::testing::small_run()));
  for (std::size_t i = 0; i < layers.size(); ++i) {
    // Layer 0 gets no prepared layer; every other layer gets the previous layer's.
    std::unique_ptr<PreparedLayer> other =
        i == 0 ? nullptr : mismatched.prepare_layer(layers[i - 1].result());
    ASSERT_TRUE(mismatched.add_prepared_layer(layers[i].result(), std::move(other)));
  }
  ASSERT_TRUE(mismatched.finish());
  const ViewStack a = as_they_come.take();
  const ViewStack b = mismatched.take();
  EXPECT_EQ(b.stored, a.stored);
  EXPECT_EQ(b.cells_zlib, a.cells_zlib);
  EXPECT_EQ(b.volume.blocks, a.volume.blocks);
  EXPECT_EQ(b.hatches, a.hatches);
}

TEST(ViewStackCollector, KeepsTheScanlinesAsSegmentsAtTheRowCentres) {
  ViewStackCollector sink;
  feed(sink, run_on(5, 3, 1), 2);
  const ViewStack stack = sink.take();
  ASSERT_TRUE(stack.has_hatches);
  EXPECT_EQ(stack.hatches[0],
            (std::vector<float>{0.5f, 0.125f, 2.0f, 0.125f, 0.5f, 0.375f, 2.0f, 0.375f}));
}

TEST(FitToBudget, LeavesAStackWithinBudgetAlone) {
  ViewStackCollector sink;
  feed(sink, run_on(40, 30, 10), 30);
  ViewStack stack = sink.take();
  fit_to_budget(stack, std::uint64_t{1} << 30);
  EXPECT_EQ(stack.stored.size(), 10u);
  EXPECT_TRUE(stack.has_hatches);
  EXPECT_TRUE(stack.notes.empty());
}

TEST(FitToBudget, DropsTheScanlinesFirst) {
  ViewStackCollector sink;
  feed(sink, run_on(40, 30, 10), 300);
  ViewStack stack = sink.take();
  // 300 segments of 16 bytes a layer take about 64 kB of base64 in all; the cells far less.
  fit_to_budget(stack, 20'000);
  EXPECT_FALSE(stack.has_hatches);
  EXPECT_EQ(stack.stored.size(), 10u);
  ASSERT_EQ(stack.notes.size(), 1u);
  EXPECT_NE(stack.notes[0].find("scanline segments left out"), std::string::npos);
}

TEST(FitToBudget, ThenKeepsEveryNthLayerAndSaysSo) {
  ViewStackCollector sink;
  feed(sink, run_on(40, 30, 10));
  ViewStack stack = sink.take();
  fit_to_budget(stack, 300);
  EXPECT_GT(stack.stride, 1u);
  for (std::uint32_t k : stack.stored) EXPECT_EQ(k % stack.stride, 0u);
  EXPECT_EQ(stack.cells_zlib.size(), stack.stored.size());
  EXPECT_EQ(stack.contours.size(), stack.stored.size());
  ASSERT_FALSE(stack.notes.empty());
  EXPECT_NE(stack.notes.back().find("subsampled stack"), std::string::npos);
  EXPECT_NE(stack.notes.back().find("of 10"), std::string::npos);
}

TEST(ViewStackCollector, ForgetsTheLayersWhenTheRunIsAborted) {
  ViewStackCollector sink;
  feed(sink, run_on(5, 3, 2));
  sink.abort();
  const ViewStack stack = sink.take();
  EXPECT_TRUE(stack.stored.empty());
  EXPECT_TRUE(stack.cells_zlib.empty());
  EXPECT_TRUE(stack.volume.blocks.empty());
}

TEST(ViewStackCollector, LeavesOutContoursAndScanlinesWhenAskedTo) {
  ViewStackCollector sink(ViewStackOptions{.hatches = false, .contours = false});
  feed(sink, run_on(5, 3, 2), 2);
  const ViewStack stack = sink.take();
  EXPECT_FALSE(stack.has_hatches);
  ASSERT_EQ(stack.contours.size(), 2u);
  EXPECT_TRUE(stack.contours[0].empty());
  EXPECT_TRUE(stack.hatches[0].empty());
}

/// `layers` stored layers of 3 compressed bytes each (7 bytes of page text with their quotes and
/// comma), no contours, no scanlines.
ViewStack stack_of(std::uint32_t layers) {
  ViewStack stack;
  stack.grid.nz = layers;
  for (std::uint32_t k = 0; k < layers; ++k) {
    stack.stored.push_back(k);
    stack.cells_zlib.emplace_back("abc");
    stack.contours.emplace_back();
    stack.hatches.emplace_back();
  }
  stack.has_hatches = false;
  return stack;
}

TEST(FitToBudget, NamesTheStrideAsAnOrdinal) {
  // 30 layers take 210 bytes: a budget of 210 / n keeps every n-th layer.
  const struct {
    std::uint64_t budget;
    const char* words;
  } cases[] = {
      {105, "every 2nd layer (15 of 30)"}, {70, "every 3rd layer (10 of 30)"},
      {53, "every 4th layer (8 of 30)"},   {20, "every 11th layer (3 of 30)"},
      {10, "every 21st layer (2 of 30)"},
  };
  for (const auto& c : cases) {
    ViewStack stack = stack_of(30);
    fit_to_budget(stack, c.budget);
    ASSERT_EQ(stack.notes.size(), 1u) << c.budget;
    EXPECT_NE(stack.notes[0].find(c.words), std::string::npos) << stack.notes[0];
  }
  ViewStack stack = stack_of(30);
  fit_to_budget(stack, 10);
  EXPECT_EQ(stack.notes[0],
            "subsampled stack: the page holds every 21st layer (2 of 30) to stay within its 0.0 MB "
            "budget (all layers would take 0.0 MB); the cells file has every layer");
  EXPECT_EQ(stack.stored, (std::vector<std::uint32_t>{0, 21}));
  EXPECT_EQ(stack.stride, 21u);
}

TEST(FitToBudget, KeepsTheOnlyLayerEvenOverBudget) {
  ViewStack stack = stack_of(1);
  fit_to_budget(stack, 1);
  EXPECT_EQ(stack.stored.size(), 1u);
  EXPECT_EQ(stack.stride, 1u);
  EXPECT_TRUE(stack.notes.empty());
}

}  // namespace
}  // namespace strata::view
