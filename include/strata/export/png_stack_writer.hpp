#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "strata/pipeline/layer_sink.hpp"

namespace strata::io {

/// Grey levels and compression of the PNG stack.
struct PngOptions {
  std::uint8_t empty = 0;
  std::uint8_t interior = 128;
  std::uint8_t boundary = 255;
  /// zlib level 0 (none) .. 9 (smallest). 3: a layer of three grey levels is long runs, which a
  /// fast level packs nearly as well (rear_case: 3.4 MB at 3 against 2.2 MB at 6, the stack
  /// written in well under half the time).
  int compression_level = 3;
};

/// A sink that writes one 8-bit grey PNG a layer (SPEC §3.2): `dir/png/<stem>_00000.png`, ... (the
/// layer index with at least 5 digits). The image is nx × ny pixels, pixel (i, j) shows cell
/// (i, j) with row j = 0 at the BOTTOM of the image; the pixel pitch is stored in a pHYs chunk
/// (pixels per metre, rounded) when it fits.
///
/// Each layer is written under a temporary name and renamed into place when it is complete;
/// finish() then removes files `<stem>_<index>.png` left in the folder by an earlier run with
/// more layers (index >= nz), so the folder holds exactly this run's stack. abort() (also run by
/// the destructor of a sink begun but not finished) removes every file this sink wrote, and the
/// folders it created (`dir`, `dir/png`) when they are empty again.
/// @return errors: Error{BadInput} naming the file when it cannot be written; Error{Internal} for
///         layers out of order or with the wrong cell count, or finish() before all nz layers.
std::unique_ptr<LayerSink> make_png_stack_writer(const std::filesystem::path& dir,
                                                 const std::string& stem,
                                                 const PngOptions& options = {});

}  // namespace strata::io
