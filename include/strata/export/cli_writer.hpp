#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>

#include "strata/pipeline/layer_sink.hpp"

namespace strata::io {

/// The two encodings of a Common Layer Interface file.
enum class CliEncoding { Ascii, Binary };

/// Command codes of the binary CLI geometry section (uint16, little-endian).
inline constexpr std::uint16_t kCliLayerLong = 127;     ///< float32 z
inline constexpr std::uint16_t kCliPolylineLong = 130;  ///< int32 id, dir, n; n float32 (x, y)
inline constexpr std::uint16_t kCliHatchesLong = 132;   ///< int32 id, n; n float32 (xs, ys, xe, ye)

/// A sink that writes the layers' contours and hatches as a Common Layer Interface 2.0 file
/// (SPEC §3.2, PRIOR-ART §5). Coordinates are millimetres (`$$UNITS/00000001.000000`).
///
/// Header (ASCII in both encodings): `$$HEADERSTART`, `$$ASCII` or `$$BINARY`, `$$UNITS`,
/// `$$VERSION/200`, `$$LABEL/1,<model name>`, `$$DIMENSION/x0,y0,z0,x1,y1,z1` (the grid extent),
/// `$$LAYERS/nz`, `$$HEADEREND`.
/// - Ascii: then `$$GEOMETRYSTART`, per layer `$$LAYER/z`, per loop
///   `$$POLYLINE/1,dir,n,x1,y1,...` (dir 1 outer counter-clockwise, 0 hole clockwise, 2 open; a
///   closed loop repeats its first point at the end, so n = points + 1), per layer one
///   `$$HATCHES/1,n,xs,ys,xe,ye,...` with the layer's scanline segments (y = grid.yc(row) +
///   options.scan_offset_mm) when it has any, and `$$GEOMETRYEND`. Numbers are printed in the
///   shortest form that reads back to the same double.
/// - Binary: the binary stream follows `$$HEADEREND` directly (no line break): per layer command
///   127 (float32 z), per loop 130, per layer with hatches 132; all little-endian, float32
///   coordinates, no `$$ALIGN`.
/// The layer z is the CLI's layer height: the layer's upper surface z0 + (k + 1) * dz, so that
/// layer thicknesses follow from z differences; the contours are the section at the layer's middle
/// plane zk. Loops with fewer than two points are skipped.
///
/// File handling as make_cells_writer: temporary beside `path`, renamed by finish(), missing
/// folders created by begin(), everything removed by abort().
std::unique_ptr<LayerSink> make_cli_writer(const std::filesystem::path& path,
                                           CliEncoding encoding = CliEncoding::Ascii);

}  // namespace strata::io
