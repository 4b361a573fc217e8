#include "strata/fill/solid_rows.hpp"

#include <algorithm>

#include "strata/core/error.hpp"

namespace strata {

SolidRows::SolidRows(std::uint32_t nx, std::uint32_t ny)
    : nx_(nx), ny_(ny), row_start_(std::size_t{ny} + 1, 0) {}

SolidRows SolidRows::from_cells(std::span<const std::uint8_t> cells, std::uint32_t nx,
                                std::uint32_t ny) {
  STRATA_ASSERT(cells.size() == std::size_t{nx} * ny, "a bitmap of nx * ny cells");
  SolidRows out(nx, ny);
  for (std::uint32_t j = 0; j < ny; ++j) {
    const std::uint8_t* row = cells.data() + std::size_t{j} * nx;
    std::uint32_t i = 0;
    while (i < nx) {
      while (i < nx && row[i] == 0) ++i;
      const std::uint32_t begin = i;
      while (i < nx && row[i] != 0) ++i;
      out.add(j, begin, i);
    }
  }
  return out;
}

void SolidRows::add(std::uint32_t row, std::uint32_t begin, std::uint32_t end) {
  if (begin >= end) return;
  STRATA_ASSERT(row < ny_ && end <= nx_, "a run within the grid");
  STRATA_ASSERT(row + 1 >= rows_started_, "rows in increasing order");
  while (rows_started_ <= row) row_start_[rows_started_++] = runs_.size();
  if (runs_.size() > row_start_[row]) {
    SolidRun& last = runs_.back();
    STRATA_ASSERT(begin >= last.end, "runs of a row in increasing order");
    if (begin == last.end) {
      last.end = end;
      return;
    }
  }
  runs_.push_back({begin, end});
}

std::span<const SolidRun> SolidRows::row(std::uint32_t j) const {
  if (j >= rows_started_) return {};
  const std::size_t begin = row_start_[j];
  const std::size_t end = j + 1 < rows_started_ ? row_start_[j + 1] : runs_.size();
  return std::span(runs_).subspan(begin, end - begin);
}

std::uint64_t SolidRows::count() const {
  std::uint64_t n = 0;
  for (const SolidRun& r : runs_) n += r.end - r.begin;
  return n;
}

std::vector<std::uint8_t> SolidRows::cells() const {
  std::vector<std::uint8_t> out(std::size_t{nx_} * ny_, 0);
  for (std::uint32_t j = 0; j < ny_; ++j) {
    std::uint8_t* at = out.data() + std::size_t{j} * nx_;
    for (const SolidRun& r : row(j)) std::fill(at + r.begin, at + r.end, std::uint8_t{1});
  }
  return out;
}

bool operator==(const SolidRows& a, const SolidRows& b) {
  if (a.nx_ != b.nx_ || a.ny_ != b.ny_) return false;
  for (std::uint32_t j = 0; j < a.ny_; ++j) {
    const auto ra = a.row(j);
    const auto rb = b.row(j);
    if (!std::equal(ra.begin(), ra.end(), rb.begin(), rb.end())) return false;
  }
  return true;
}

}  // namespace strata
