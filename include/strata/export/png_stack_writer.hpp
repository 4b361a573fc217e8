#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "strata/pipeline/layer_sink.hpp"

namespace strata::io {

/// Grey levels of the PNG stack.
struct PngOptions {
  std::uint8_t empty = 0;
  std::uint8_t interior = 128;
  std::uint8_t boundary = 255;
};

/// A sink that writes one 8-bit grey PNG a layer (SPEC §3.2): `dir/png/<stem>_00000.png`, ... (the
/// layer index with at least 5 digits). The image is nx × ny pixels, pixel (i, j) shows cell
/// (i, j) with row j = 0 at the BOTTOM of the image; the pixel pitch is stored in a pHYs chunk
/// (pixels per metre, rounded) when it fits. The image data is deflated as runs of a grey level
/// and copies of the row above, what a layer is made of.
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
