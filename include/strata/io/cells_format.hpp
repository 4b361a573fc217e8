#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "strata/slice/grid_spec.hpp"
#include "strata/voxel/cell_class.hpp"

namespace strata::io {

/// The two encodings of the cells file (SPEC §3.1).
enum class CellsEncoding {
  Binary,  ///< `.cells`: 80-byte little-endian header, then 2 bits a cell
  Ascii,   ///< `.cells.txt`: `key value` header lines, then two characters a cell
};

/// What the header of a cells file says: the grid and the shell thickness.
struct CellsHeader {
  GridSpec grid;
  double shell_mm = 0.0;
  CellsEncoding encoding = CellsEncoding::Binary;
};

/// Magic of the binary encoding (8 bytes, no terminator).
inline constexpr std::string_view kCellsMagic = "STRCELL1";
/// Size of the binary header in this version; layers start at this offset.
inline constexpr std::uint32_t kCellsHeaderBytes = 80;
/// First line of the ASCII encoding.
inline constexpr std::string_view kCellsAsciiFirstLine = "strata-cells 1";

/// Bytes of one packed layer: ceil(nx * ny / 4) (a layer, not a row, is padded to a byte).
inline std::uint64_t packed_layer_bytes(const GridSpec& grid) {
  return (grid.cells_per_layer() + 3) / 4;
}

/// Exact size of a binary cells file for `grid`: header + nz * packed_layer_bytes.
inline std::uint64_t binary_cells_file_bytes(const GridSpec& grid) {
  return kCellsHeaderBytes + std::uint64_t{grid.nz} * packed_layer_bytes(grid);
}

/// Appends `cells` to `out` packed as the binary encoding stores a layer: 4 cells a byte, the
/// first in the two most significant bits, the last byte padded with zero bits. Each code's two
/// low bits are packed as they are: checking the codes (first_unstorable_cell) is the caller's.
void append_packed_cells(std::span<const CellClass> cells, std::string& out);

/// append_packed_cells with the codes checked on the way: returns the index of the first cell
/// the binary encoding cannot store (first_unstorable_cell), and then appends nothing, or
/// cells.size() when every cell was packed.
std::size_t append_checked_packed_cells(std::span<const CellClass> cells, std::string& out);

/// The index of the first cell whose code the binary encoding cannot store (the reserved 10, or
/// a value above 11), or cells.size() when every code is 00, 01 or 11.
std::size_t first_unstorable_cell(std::span<const CellClass> cells);

}  // namespace strata::io
