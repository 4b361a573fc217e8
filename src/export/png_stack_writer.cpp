#include "strata/export/png_stack_writer.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "export/grey_png_internal.hpp"
#include "export/sink_support_internal.hpp"

namespace strata::io {

namespace {

/// A row's grey levels, each picked by compares rather than a table, so that the compiler takes
/// many pixels a step.
void grey_row(const CellClass* cells, std::uint32_t width, const std::array<std::uint8_t, 4>& grey,
              std::uint8_t* row) {
  const auto* codes = reinterpret_cast<const std::uint8_t*>(cells);
  const std::uint8_t g0 = grey[0], g1 = grey[1], g2 = grey[2], g3 = grey[3];
  for (std::uint32_t i = 0; i < width; ++i) {
    const std::uint8_t c = codes[i] & 0b11u;
    row[i] = static_cast<std::uint8_t>((c == 0 ? g0 : 0) | (c == 1 ? g1 : 0) | (c == 2 ? g2 : 0) |
                                       (c == 3 ? g3 : 0));
  }
}

/// Pixels per metre for a cell size in mm, or 0 when it does not fit the chunk's 32 bits.
std::uint32_t pixels_per_metre(double cell_mm) {
  const double ppm = std::round(1000.0 / cell_mm);
  if (!(ppm >= 1.0 && ppm <= 4294967295.0)) return 0;
  return static_cast<std::uint32_t>(ppm);
}

class PngStackWriter final : public detail::LayerFilesSink {
 public:
  PngStackWriter(const std::filesystem::path& dir, std::string stem, const PngOptions& options)
      : LayerFilesSink(dir, "png", std::move(stem), "png", "PNG stack writer"), options_(options) {}

  bool needs_cells() const override { return true; }
  bool needs_hatches() const override { return false; }

 protected:
  Result<void> write_layer(detail::LayerBytes& out, const LayerResult& layer) const override {
    const GridSpec& g = run().grid;
    // IHDR takes a width and a height of 1 .. 2^31 - 1.
    constexpr std::uint32_t kMaxSide = 0x7fffffffu;
    if (g.nx == 0 || g.ny == 0 || g.nx > kMaxSide || g.ny > kMaxSide) {
      return Error{ErrorCode::Internal,
                   fmt::format("cannot encode the PNG of layer {}: a PNG is 1 to {} pixels wide "
                               "and high, the grid's layers are {} x {} cells",
                               layer.layer, kMaxSide, g.nx, g.ny),
                   layer_path(layer.layer).string()};
    }
    std::uint32_t ppm_x = pixels_per_metre(g.dx);
    std::uint32_t ppm_y = pixels_per_metre(g.dy);
    if (ppm_x == 0 || ppm_y == 0) ppm_x = ppm_y = 0;
    const std::array<std::uint8_t, 4> grey = {options_.empty, options_.interior, options_.empty,
                                              options_.boundary};
    detail::GreyPngEncoder png(g.nx, g.ny, ppm_x, ppm_y);
    for (std::uint32_t r = 0; r < g.ny; ++r) {
      // Row j = 0 at the bottom: the first image row is the last grid row.
      grey_row(layer.cells.data() + std::size_t{g.ny - 1 - r} * g.nx, g.nx, grey, png.next_row());
      png.add_row();
    }
    out.write(png.finish());
    return {};
  }

 private:
  PngOptions options_;
};

}  // namespace

std::unique_ptr<LayerSink> make_png_stack_writer(const std::filesystem::path& dir,
                                                 const std::string& stem,
                                                 const PngOptions& options) {
  return std::make_unique<PngStackWriter>(dir, stem, options);
}

}  // namespace strata::io
