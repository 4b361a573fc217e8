#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace strata {

/// A stretch of solid cells along a row: columns [begin, end).
struct SolidRun {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  friend bool operator==(const SolidRun&, const SolidRun&) = default;
};

/// The solid cells of one layer as runs along its rows: a row of a sliced model holds a few runs
/// where its bitmap would hold nx bytes, so the stages that read a layer's solid cells (the first
/// ring of the shell, the rings of the layers mode) walk runs rather than every cell.
/// The runs of a row are in increasing order, none empty and no two touching, so two layers with
/// the same solid cells hold the same runs.
class SolidRows {
 public:
  /// No rows: the cells were not computed.
  SolidRows() = default;
  /// nx by ny cells, none solid yet.
  SolidRows(std::uint32_t nx, std::uint32_t ny);
  /// The runs of a row-major bitmap (nonzero bytes are solid) of nx by ny cells.
  static SolidRows from_cells(std::span<const std::uint8_t> cells, std::uint32_t nx,
                              std::uint32_t ny);

  /// Adds columns [begin, end) of `row` as solid. Rows come in increasing order, and the runs of a
  /// row in increasing order; a run that touches the one before joins it; an empty one is
  /// ignored.
  void add(std::uint32_t row, std::uint32_t begin, std::uint32_t end);

  /// False when there are no rows (the cells were not computed).
  bool has_rows() const { return ny_ != 0; }
  std::uint32_t nx() const { return nx_; }
  std::uint32_t ny() const { return ny_; }
  /// The runs of row j (j < ny).
  std::span<const SolidRun> row(std::uint32_t j) const;
  /// The solid cells counted.
  std::uint64_t count() const;
  /// The row-major bitmap, 1 for a solid cell and 0 otherwise (empty without rows).
  std::vector<std::uint8_t> cells() const;

  friend bool operator==(const SolidRows& a, const SolidRows& b);

 private:
  std::uint32_t nx_ = 0, ny_ = 0;
  std::vector<SolidRun> runs_;
  /// Row j's runs are runs_[row_start_[j] .. row_start_[j + 1]), the end of the last row added
  /// being runs_.size(); the starts are set up to that row, and the rows past it hold none.
  std::vector<std::size_t> row_start_;
  std::uint32_t rows_started_ = 0;  ///< the rows whose start is set: the last row added is the last
};

}  // namespace strata
