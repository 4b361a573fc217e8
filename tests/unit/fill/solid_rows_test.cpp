#include "strata/fill/solid_rows.hpp"

#include <gtest/gtest.h>

#include <random>

#include "strata/core/error.hpp"

namespace strata {
namespace {

TEST(SolidRows, RunsThatTouchJoinAndEmptyOnesAreDropped) {
  SolidRows rows(10, 3);
  rows.add(0, 1, 3);
  rows.add(0, 3, 5);  // touches the run before: one run [1, 5)
  rows.add(0, 6, 6);  // empty
  rows.add(0, 7, 10);
  rows.add(2, 0, 1);
  ASSERT_EQ(rows.row(0).size(), 2u);
  EXPECT_EQ(rows.row(0)[0], (SolidRun{1, 5}));
  EXPECT_EQ(rows.row(0)[1], (SolidRun{7, 10}));
  EXPECT_TRUE(rows.row(1).empty());
  ASSERT_EQ(rows.row(2).size(), 1u);
  EXPECT_EQ(rows.row(2)[0], (SolidRun{0, 1}));
  EXPECT_EQ(rows.count(), 4u + 3u + 1u);
  EXPECT_EQ(rows.cells()[4], 1);       // the end of the joined run
  EXPECT_EQ(rows.cells()[5], 0);       // the gap after it
  EXPECT_EQ(rows.cells()[10 + 0], 0);  // the row without runs
  EXPECT_EQ(rows.cells(), (std::vector<std::uint8_t>{0, 1, 1, 1, 1, 0, 0, 1, 1, 1,  //
                                                     0, 0, 0, 0, 0, 0, 0, 0, 0, 0,  //
                                                     1, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
}

TEST(SolidRows, AreTheBitmapTheyAreMadeFrom) {
  // Random bitmaps, sparse and dense: the runs give back every cell, and two bitmaps give equal
  // runs exactly when they are equal.
  std::mt19937 rng(7);
  for (const double density : {0.05, 0.5, 0.95}) {
    std::bernoulli_distribution solid(density);
    const std::uint32_t nx = 37, ny = 11;
    std::vector<std::uint8_t> cells(nx * ny);
    for (auto& c : cells) c = solid(rng) ? 1 : 0;
    const SolidRows rows = SolidRows::from_cells(cells, nx, ny);
    EXPECT_EQ(rows.cells(), cells);
    EXPECT_EQ(rows.count(), static_cast<std::uint64_t>(std::count(cells.begin(), cells.end(), 1)));
    for (std::uint32_t j = 0; j < ny; ++j) {
      const auto runs = rows.row(j);
      for (std::size_t r = 1; r < runs.size(); ++r) EXPECT_LT(runs[r - 1].end, runs[r].begin);
    }
    EXPECT_EQ(SolidRows::from_cells(cells, nx, ny), rows);
    cells[5 * nx + 36] ^= 1;
    EXPECT_FALSE(SolidRows::from_cells(cells, nx, ny) == rows);
  }
  EXPECT_FALSE(SolidRows(3, 2) == SolidRows(2, 3));
  EXPECT_FALSE(SolidRows().has_rows());
  EXPECT_TRUE(SolidRows().cells().empty());
}

TEST(SolidRows, RefusesRunsOutOfOrderOrOutsideTheGrid) {
  SolidRows rows(8, 4);
  rows.add(2, 3, 5);
  EXPECT_THROW(rows.add(1, 0, 1), InternalError);  // an earlier row
  EXPECT_THROW(rows.add(2, 1, 2), InternalError);  // before the row's last run
  EXPECT_THROW(rows.add(3, 0, 9), InternalError);  // past the row's end
  EXPECT_THROW(rows.add(4, 0, 1), InternalError);  // past the last row
}

}  // namespace
}  // namespace strata
