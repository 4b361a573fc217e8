#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "strata/pipeline/layer_sink.hpp"

namespace strata::io {

/// A sink that draws every layer as an SVG file (SPEC §3.2): `dir/svg/<stem>_00000.svg`, ... (the
/// layer index with at least 5 digits). The viewBox is in millimetres and covers the grid extent
/// with a small margin, y flipped so that +y is up (an SVG point (x, -y) shows the layer point
/// (x, y)); the drawing is as wide and high as the part in mm.
/// - the grid extent: a thin grey rectangle;
/// - closed loops: one `<path class="outer">` (counter-clockwise) or `<path class="hole">`
///   (clockwise) each, closed with Z, in different colours with a light fill (fill-rule nonzero),
///   drawn by increasing nesting depth;
/// - open chains: one red `<path class="open">` each, its two ends marked by
///   `<circle class="open-end">`;
/// - hatches (scanline segments): one `<path class="hatch">` of thin horizontal lines, each at its
///   row's y = grid.yc(row) + options.scan_offset_mm;
/// - a title with the layer index and z.
/// Strokes do not scale with zoom. Files are written and renamed as for the PNG stack, with the
/// same clean-up of stale files by finish() and removal of everything written by abort().
std::unique_ptr<LayerSink> make_svg_writer(const std::filesystem::path& dir,
                                           const std::string& stem);

}  // namespace strata::io
