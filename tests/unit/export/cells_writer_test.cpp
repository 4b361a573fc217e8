#include "strata/export/cells_writer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "strata/io/cells_format.hpp"
#include "strata/io/read_cells.hpp"
#include "support/sink_runs.hpp"
#include "support/text_meshes.hpp"

namespace strata::io {
namespace {

using test::read_file;
using testing::code;
using testing::codes;
using testing::LayerData;
using testing::list_tree;
using testing::run_sink;
using testing::run_sink_prepared;
using testing::ScratchDir;
using testing::small_layers;
using testing::small_run;

std::string bytes(std::initializer_list<int> values) {
  std::string out;
  for (int v : values) out.push_back(static_cast<char>(v));
  return out;
}

/// A one-layer run of nx x ny cells.
SliceRunInfo flat_run(std::uint32_t nx, std::uint32_t ny) {
  SliceRunInfo run;
  run.grid.nx = nx;
  run.grid.ny = ny;
  run.grid.nz = 1;
  return run;
}

std::string packed_single_layer(const ScratchDir& dir, std::uint32_t nx, std::uint32_t ny,
                                const std::vector<CellClass>& cells) {
  auto sink = make_cells_writer(dir / "one.cells");
  LayerData layer;
  layer.cells = cells;
  return testing::run_and_read(*sink, flat_run(nx, ny), {layer}, dir / "one.cells")
      .substr(kCellsHeaderBytes);
}

TEST(CellsWriter, BinaryHeaderIsTheSpecLayoutLittleEndian) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells", CellsEncoding::Binary);
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  const std::string file = read_file(dir / "part.cells");
  ASSERT_GE(file.size(), 80u);
  const std::string expected = bytes({
      'S', 'T', 'R', 'C', 'E', 'L', 'L',  '1',               // magic
      80,  0,   0,   0,                                      // header size
      5,   0,   0,   0,   3,   0,   0,    0,    2, 0, 0, 0,  // nx ny nz
      0,   0,   0,   0,   0,   0,   0xF8, 0xBF,              // x0 = -1.5
      0,   0,   0,   0,   0,   0,   0x02, 0x40,              // y0 = 2.25
      0,   0,   0,   0,   0,   0,   0xC0, 0x3F,              // z0 = 0.125
      0,   0,   0,   0,   0,   0,   0xE0, 0x3F,              // dx = 0.5
      0,   0,   0,   0,   0,   0,   0xD0, 0x3F,              // dy = 0.25
      0,   0,   0,   0,   0,   0,   0xF0, 0x3F,              // dz = 1
      0,   0,   0,   0,   0,   0,   0xE8, 0x3F,              // shell t = 0.75
  });
  EXPECT_EQ(file.substr(0, 80), expected);
}

TEST(CellsWriter, BinaryLayersArePackedAndPaddedPerLayer) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  const std::string file = read_file(dir / "part.cells");
  // 15 cells a layer: ceil(15 / 4) = 4 bytes, the last holding 3 cells and 2 zero padding bits
  // (padding the rows instead would take 3 x 2 = 6 bytes).
  ASSERT_EQ(file.size(), 80u + 2 * 4);
  EXPECT_EQ(file.substr(80), bytes({0x1F, 0x71, 0x05, 0x70,     // layer 0
                                    0xFF, 0xF5, 0x7F, 0xFC}));  // layer 1
}

TEST(CellsWriter, FirstCellGoesToTheMostSignificantBits) {
  ScratchDir dir;
  EXPECT_EQ(packed_single_layer(dir, 1, 1, codes({1})), bytes({0x40}));
  EXPECT_EQ(packed_single_layer(dir, 4, 1, codes({3, 0, 0, 0})), bytes({0xC0}));
  EXPECT_EQ(packed_single_layer(dir, 4, 1, codes({0, 0, 0, 3})), bytes({0x03}));
  EXPECT_EQ(packed_single_layer(dir, 2, 2, codes({0, 1, 3, 0})), bytes({0x1C}));
}

TEST(CellsWriter, RowsRunFromJZeroAndCellsFromIZero) {
  ScratchDir dir;
  // 2 x 3: row 0 = (1, 0), row 1 = (0, 3), row 2 = (3, 1).
  EXPECT_EQ(packed_single_layer(dir, 2, 3, codes({1, 0, 0, 3, 3, 1})), bytes({0x43, 0xD0}));
}

TEST(CellsWriter, AsciiFileHasTheSpecLines) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells.txt", CellsEncoding::Ascii);
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  EXPECT_EQ(read_file(dir / "part.cells.txt"),
            "strata-cells 1\n"
            "grid 5 3 2\n"
            "origin -1.5 2.25 0.125\n"
            "spacing 0.5 0.25 1\n"
            "shell 0.75\n"
            "layer 0 z=0.625\n"
            "0001111101\n"
            "1100010000\n"
            "0101011100\n"
            "layer 1 z=1.625\n"
            "1111111111\n"
            "1101010111\n"
            "1111111111\n");
}

TEST(CellsWriter, AsciiNumbersReadBackToTheSameBits) {
  ScratchDir dir;
  SliceRunInfo run = flat_run(1, 1);
  run.grid.x0 = 0.1;
  run.grid.y0 = 1.0 / 3.0;
  run.grid.z0 = -1e-7;
  run.grid.dx = 0.1 + 0.2;
  auto sink = make_cells_writer(dir / "n.cells.txt", CellsEncoding::Ascii);
  LayerData layer;
  layer.cells = codes({0});
  ASSERT_TRUE(run_sink(*sink, run, {layer}));
  const auto lines = testing::lines_of(read_file(dir / "n.cells.txt"));
  ASSERT_GE(lines.size(), 4u);
  double x0 = 0, y0 = 0, z0 = 0, dx = 0;
  ASSERT_EQ(std::sscanf(lines[2].c_str(), "origin %lf %lf %lf", &x0, &y0, &z0), 3);
  ASSERT_EQ(std::sscanf(lines[3].c_str(), "spacing %lf", &dx), 1);
  EXPECT_EQ(x0, run.grid.x0);
  EXPECT_EQ(y0, run.grid.y0);
  EXPECT_EQ(z0, run.grid.z0);
  EXPECT_EQ(dx, run.grid.dx);
}

TEST(CellsWriter, LayerOutOfOrderIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  auto layers = small_layers();
  ASSERT_TRUE(sink->begin(small_run()));
  auto added = sink->add_layer(layers[1].result());
  ASSERT_FALSE(added);
  EXPECT_EQ(added.error().code, ErrorCode::Internal);
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(CellsWriter, WrongCellCountIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  auto layers = small_layers();
  layers[0].cells.pop_back();
  ASSERT_TRUE(sink->begin(small_run()));
  auto added = sink->add_layer(layers[0].result());
  ASSERT_FALSE(added);
  EXPECT_EQ(added.error().code, ErrorCode::Internal);
}

TEST(PackedCells, AreTheFourCellsABytePackingOfEveryLengthAndMix) {
  // Against the encoding written out: cell c of a byte in bits 7-2c and 6-2c, the last byte
  // padded with zero bits; every length from 0 to 67 cells, random codes 00, 01 and 11.
  std::mt19937 rng(7);
  for (std::size_t n = 0; n < 68; ++n) {
    for (int round = 0; round < 20; ++round) {
      std::vector<CellClass> cells(n);
      for (CellClass& c : cells) c = code(std::array<unsigned, 3>{0, 1, 3}[rng() % 3]);
      std::string expected((n + 3) / 4, '\0');
      for (std::size_t i = 0; i < n; ++i) {
        expected[i / 4] = static_cast<char>(static_cast<unsigned char>(expected[i / 4]) |
                                            static_cast<unsigned>(cells[i]) << (6 - 2 * (i % 4)));
      }
      std::string packed = "head";
      append_packed_cells(cells, packed);
      ASSERT_EQ(packed, "head" + expected) << n << " cells";
      EXPECT_EQ(first_unstorable_cell(cells), n);
      std::string checked = "head";
      EXPECT_EQ(append_checked_packed_cells(cells, checked), n);
      ASSERT_EQ(checked, "head" + expected) << n << " cells, checked";
    }
  }
}

TEST(PackedCells, FindTheFirstCodeTheEncodingCannotStoreWherever) {
  for (std::size_t n = 1; n < 40; ++n) {
    for (std::size_t at = 0; at < n; ++at) {
      for (const unsigned bad : {2U, 4U, 6U, 0x80U, 0xFFU}) {
        std::vector<CellClass> cells(n, code(3));
        cells[at] = code(bad);
        if (at + 1 < n) cells[n - 1] = code(2);  // a later one is not the first
        ASSERT_EQ(first_unstorable_cell(cells), at) << n << " cells, code " << bad << " at " << at;
        std::string packed = "head";
        ASSERT_EQ(append_checked_packed_cells(cells, packed), at) << n << " cells, at " << at;
        ASSERT_EQ(packed, "head") << "a refused layer adds nothing";
      }
    }
  }
}

TEST(PackedCells, FindTheFirstUnstorableCodeInALongLayer) {
  // Long enough for the blocks of 256 cells: a bad code at the edges of a block, in the middle,
  // in the tail after the last whole block, and with a later bad code in the same block.
  const std::size_t n = 2000;
  for (const std::size_t at :
       {0UL, 7UL, 8UL, 255UL, 256UL, 257UL, 1000UL, 1791UL, 1792UL, 1999UL}) {
    for (const unsigned bad : {2U, 0x80U}) {
      std::vector<CellClass> cells(n, code(1));
      cells[at] = code(bad);
      if (at + 3 < n) cells[at + 3] = code(4);
      ASSERT_EQ(first_unstorable_cell(cells), at) << "code " << bad << " at " << at;
      std::string packed;
      ASSERT_EQ(append_checked_packed_cells(cells, packed), at) << "code " << bad << " at " << at;
      ASSERT_TRUE(packed.empty());
    }
  }
  EXPECT_EQ(first_unstorable_cell(std::vector<CellClass>(n, code(3))), n);
}

TEST(CellsWriter, ReservedCodeIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  auto layers = small_layers();
  layers[0].cells[7] = code(2);
  ASSERT_TRUE(sink->begin(small_run()));
  auto added = sink->add_layer(layers[0].result());
  ASSERT_FALSE(added);
  EXPECT_EQ(added.error().code, ErrorCode::Internal);
  EXPECT_NE(added.error().message.find("row 1 cell 2"), std::string::npos) << added.error().message;
}

TEST(CellsWriter, CodesAboveThreeAreInternalErrorsInBothEncodings) {
  for (const CellsEncoding encoding : {CellsEncoding::Binary, CellsEncoding::Ascii}) {
    ScratchDir dir;
    auto sink = make_cells_writer(dir / "part.cells", encoding);
    auto layers = small_layers();
    layers[0].cells[11] = code(4);
    ASSERT_TRUE(sink->begin(small_run()));
    auto added = sink->add_layer(layers[0].result());
    ASSERT_FALSE(added);
    EXPECT_EQ(added.error().code, ErrorCode::Internal);
    EXPECT_EQ(added.error().message,
              "cells writer: layer 0 row 2 cell 1 has the code 4, which is not 00, 01 or 11");
  }
}

TEST(CellsWriter, AsciiReservedCodeIsAnInternalError) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells.txt", CellsEncoding::Ascii);
  auto layers = small_layers();
  layers[1].cells[9] = code(2);
  ASSERT_TRUE(sink->begin(small_run()));
  ASSERT_TRUE(sink->add_layer(layers[0].result()));
  auto added = sink->add_layer(layers[1].result());
  ASSERT_FALSE(added);
  EXPECT_EQ(added.error().code, ErrorCode::Internal);
  EXPECT_EQ(added.error().message,
            "cells writer: layer 1 row 1 cell 4 has the code 2, which is not 00, 01 or 11");
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(CellsWriter, ALayerOfManyChunksReadsBackCellForCell) {
  // 700 x 500 cells pack into 87,500 bytes, more than the 64 KiB handed to the file at once.
  ScratchDir dir;
  SliceRunInfo run = flat_run(700, 500);
  run.grid.nz = 2;
  std::vector<LayerData> layers(2);
  for (std::uint32_t k = 0; k < 2; ++k) {
    layers[k].layer = k;
    for (std::uint32_t idx = 0; idx < 700 * 500; ++idx) {
      const std::uint32_t value = (idx * 7 + k) % 3;
      layers[k].cells.push_back(code(value == 2 ? 3 : static_cast<int>(value)));
    }
  }
  auto sink = make_cells_writer(dir / "big.cells");
  ASSERT_TRUE(run_sink(*sink, run, layers));
  EXPECT_EQ(std::filesystem::file_size(dir / "big.cells"), kCellsHeaderBytes + 2 * 87500u);
  const auto read = read_cells(dir / "big.cells");
  ASSERT_TRUE(read) << read.error().to_string();
  std::vector<CellClass> expected = layers[0].cells;
  expected.insert(expected.end(), layers[1].cells.begin(), layers[1].cells.end());
  EXPECT_EQ(read->cells, expected);
  // Prepared ahead, as the engine does, a layer is packed whole into memory: the same bytes.
  auto prepared = make_cells_writer(dir / "prepared.cells");
  ASSERT_TRUE(run_sink_prepared(*prepared, run, layers));
  EXPECT_EQ(read_file(dir / "prepared.cells"), read_file(dir / "big.cells"));
}

TEST(CellsWriter, FinishBeforeAllLayersFailsAndWritesNothing) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  auto layers = small_layers();
  ASSERT_TRUE(sink->begin(small_run()));
  ASSERT_TRUE(sink->add_layer(layers[0].result()));
  auto finished = sink->finish();
  ASSERT_FALSE(finished);
  EXPECT_EQ(finished.error().code, ErrorCode::Internal);
  EXPECT_FALSE(std::filesystem::exists(dir / "part.cells"));
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(CellsWriter, NoFileUnderTheFinalNameBeforeFinish) {
  ScratchDir dir;
  testing::expect_file_only_after_finish(*make_cells_writer(dir / "part.cells"), small_layers(),
                                         dir, "part.cells");
}

TEST(CellsWriter, AbortRemovesTheTemporaryAndTheFoldersItCreated) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "out" / "deep" / "part.cells");
  auto layers = small_layers();
  ASSERT_TRUE(sink->begin(small_run()));
  ASSERT_TRUE(sink->add_layer(layers[0].result()));
  EXPECT_FALSE(list_tree(dir.path()).empty());
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(CellsWriter, AbortAfterFinishRemovesTheFinishedFile) {
  ScratchDir dir;
  auto sink = make_cells_writer(dir / "part.cells");
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  ASSERT_TRUE(std::filesystem::exists(dir / "part.cells"));
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(CellsWriter, AbortKeepsFoldersThatExistedBefore) {
  ScratchDir dir;
  std::filesystem::create_directory(dir / "out");
  auto sink = make_cells_writer(dir / "out" / "part.cells");
  ASSERT_TRUE(sink->begin(small_run()));
  sink->abort();
  EXPECT_EQ(list_tree(dir.path()), std::vector<std::string>{"out"});
}

TEST(CellsWriter, DestroyingAnUnfinishedSinkLeavesNothing) {
  ScratchDir dir;
  testing::expect_destroyed_unfinished_sink_leaves_nothing(
      make_cells_writer(dir / "new" / "part.cells"), dir);
}

TEST(CellsWriter, UnwritableTargetIsBadInput) {
  ScratchDir dir;
  test::write_text_file(dir / "file", "x");
  auto sink = make_cells_writer(dir / "file" / "part.cells");
  auto begun = sink->begin(small_run());
  ASSERT_FALSE(begun);
  EXPECT_EQ(begun.error().code, ErrorCode::BadInput);
}

TEST(CellsWriter, RewritesEveryConformanceVectorByteForByte) {
  ScratchDir dir;
  const auto vectors = std::filesystem::path(STRATA_SHARED_DIR) / "vectors";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(vectors)) {
    if (entry.path().extension() != ".cells") continue;
    SCOPED_TRACE(entry.path().filename().string());
    auto file = read_cells(entry.path());
    ASSERT_TRUE(file) << file.error().to_string();
    SliceRunInfo run;
    run.grid = file->header.grid;
    run.options.shell_mm = file->header.shell_mm;
    const std::uint64_t per_layer = run.grid.cells_per_layer();
    std::vector<LayerData> layers(run.grid.nz);
    for (std::uint32_t k = 0; k < run.grid.nz; ++k) {
      layers[k].layer = k;
      layers[k].z_mm = run.grid.zk(k);
      layers[k].cells.assign(file->cells.begin() + k * per_layer,
                             file->cells.begin() + (k + 1) * per_layer);
    }
    auto sink = make_cells_writer(dir / "again.cells");
    ASSERT_TRUE(run_sink(*sink, run, layers));
    EXPECT_EQ(read_file(dir / "again.cells"), read_file(entry.path()));
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

}  // namespace
}  // namespace strata::io
