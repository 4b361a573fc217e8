#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "strata/core/result.hpp"
#include "strata/io/cells_format.hpp"
#include "strata/voxel/cell_class.hpp"

namespace strata::io {

/// A whole cells file in memory (for tests and small files).
struct CellsFile {
  CellsHeader header;
  /// nx * ny * nz classes, index (k * ny + j) * nx + i.
  std::vector<CellClass> cells;

  /// The class of cell (i, j, k). @pre i < nx, j < ny, k < nz.
  CellClass at(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    const GridSpec& g = header.grid;
    return cells[(std::uint64_t{k} * g.ny + j) * g.nx + i];
  }
};

/// Inclusive index ranges of the solid (interior or boundary) cells.
struct CellIndexBox {
  std::uint32_t i_min = 0, i_max = 0;
  std::uint32_t j_min = 0, j_max = 0;
  std::uint32_t k_min = 0, k_max = 0;
};

/// Counts of a cells file, gathered layer by layer without holding the grid.
struct CellsSummary {
  CellsHeader header;
  /// Cells by class: [0] empty, [1] interior, [2] boundary (as SliceSummary::class_counts).
  std::array<std::uint64_t, 3> class_counts{};
  /// The same per layer, k = 0 .. nz-1.
  std::vector<std::array<std::uint64_t, 3>> layer_counts;
  /// Where the solid cells are; nullopt when every cell is empty.
  std::optional<CellIndexBox> solid_bounds;
};

/// Called once per layer, in increasing k, with the header and the layer's nx * ny classes
/// (row-major, j * nx + i); the span lives until the call returns. An error stops the reading and
/// is returned as is.
using CellsLayerVisitor = std::function<Result<void>(const CellsHeader& header, std::uint32_t k,
                                                     std::span<const CellClass> cells)>;

/// Streams a cells file of either encoding (told apart by the binary magic or the first line),
/// checking it as it goes: binary magic, header size 80, positive sizes, finite origin and
/// spacing, file length exactly 80 + nz * ceil(nx * ny / 4), zero padding bits; ASCII header
/// keys, the shape of every line; in both, no reserved code `10`.
/// @return the header; or Error{BadInput} whose location names the file and the line (ASCII) or
///         the layer, row and cell (binary), and whose message says what was expected.
Result<CellsHeader> read_cells_layers(const std::filesystem::path& path,
                                      const CellsLayerVisitor& visit);

/// Reads a whole cells file into memory. Files of more than 2^31 cells are refused with
/// Error{BadInput} (use summarize_cells or read_cells_layers for them).
Result<CellsFile> read_cells(const std::filesystem::path& path);

/// Counts the cells of a file by class, in total and per layer, holding one layer at a time.
Result<CellsSummary> summarize_cells(const std::filesystem::path& path);

}  // namespace strata::io
