#pragma once

#include <filesystem>
#include <memory>

#include "strata/io/cells_format.hpp"
#include "strata/pipeline/layer_sink.hpp"

namespace strata::io {

/// A sink that writes the cells file of SPEC §3.1 as the layers arrive, one layer in memory at a
/// time.
/// - Binary (`.cells`): the 80-byte little-endian header ("STRCELL1", 80, nx, ny, nz, x0, y0, z0,
///   dx, dy, dz, t), then every layer packed 2 bits a cell, 4 cells a byte, first cell in the most
///   significant bits, row j = 0 first and i = 0 first within a row, the layer (not the row)
///   padded with zero bits to a whole byte.
/// - Ascii (`.cells.txt`): `strata-cells 1`, `grid nx ny nz`, `origin x0 y0 z0`,
///   `spacing dx dy dz`, `shell t`, then per layer `layer k z=zk` and ny lines of nx codes
///   `00`/`01`/`11`, row j = 0 first. Doubles are printed in the shortest form that reads back
///   to the same bits.
/// The grid comes from SliceRunInfo::grid and t from SliceRunInfo::options.shell_mm.
///
/// The file is written under a temporary name beside `path` and renamed onto it by finish();
/// missing parent folders are created by begin(). abort() (also run by the destructor of a sink
/// begun but not finished) removes the temporary, the file if finish() had already renamed it,
/// and the folders begin() created when they are empty again.
/// @return errors: Error{BadInput} naming the path when it cannot be written; Error{Internal}
///         when layers arrive out of order, with the wrong cell count, a reserved code, or when
///         finish() comes before all nz layers.
std::unique_ptr<LayerSink> make_cells_writer(const std::filesystem::path& path,
                                             CellsEncoding encoding = CellsEncoding::Binary);

}  // namespace strata::io
