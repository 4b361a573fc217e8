#include "strata/export/png_stack_writer.hpp"

#include <fmt/format.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csetjmp>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "export/sink_support_internal.hpp"

namespace strata::io {

namespace {

/// What the libpng callbacks need; plain data, because libpng reports errors with longjmp.
struct PngTarget {
  detail::LayerBytes* out = nullptr;
  char message[256] = {};
};

void png_write_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* target = static_cast<PngTarget*>(png_get_io_ptr(png));
  target->out->write(std::string_view(reinterpret_cast<const char*>(data), length));
}

void png_flush_nothing(png_structp) {}

[[noreturn]] void png_fail(png_structp png, png_const_charp message) {
  auto* target = static_cast<PngTarget*>(png_get_error_ptr(png));
  std::snprintf(target->message, sizeof target->message, "%s", message);
  png_longjmp(png, 1);
}

void png_ignore_warning(png_structp, png_const_charp) {}

/// The image as libpng sees it: nx × ny grey pixels, the top image row being grid row ny-1.
struct PngImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  const CellClass* cells = nullptr;    ///< row-major, row j = 0 first
  std::array<std::uint8_t, 4> grey{};  ///< grey level by cell code
  std::uint8_t* row_buffer = nullptr;  ///< width bytes
  int compression_level = 6;
  std::uint32_t pixels_per_metre_x = 0;  ///< 0: no pHYs chunk
  std::uint32_t pixels_per_metre_y = 0;
};

/// A row's grey levels. Out of line: in encode_png, which libpng may longjmp out of, the
/// compiler keeps every value in memory and takes one pixel a step; here, with each grey picked
/// by compares rather than a table, it takes many.
[[gnu::noinline]] void grey_row(const CellClass* cells, std::uint32_t width,
                                const std::array<std::uint8_t, 4>& grey, std::uint8_t* row) {
  const auto* codes = reinterpret_cast<const std::uint8_t*>(cells);
  const std::uint8_t g0 = grey[0], g1 = grey[1], g2 = grey[2], g3 = grey[3];
  for (std::uint32_t i = 0; i < width; ++i) {
    const std::uint8_t c = codes[i] & 0b11u;
    row[i] = static_cast<std::uint8_t>((c == 0 ? g0 : 0) | (c == 1 ? g1 : 0) | (c == 2 ? g2 : 0) |
                                       (c == 3 ? g3 : 0));
  }
}

// Every libpng call lives in this one function, whose frame holds only trivially destructible
// objects: a longjmp out of libpng then skips no destructor.
bool encode_png(PngTarget* target, const PngImage* image) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, target, png_fail, png_ignore_warning);
  if (png == nullptr) {
    std::snprintf(target->message, sizeof target->message, "%s", "libpng could not start");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(target->message, sizeof target->message, "%s", "libpng could not start");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, target, png_write_bytes, png_flush_nothing);
  // libpng refuses images wider than 10^6 pixels by default; the PNG format allows 2^31-1.
  png_set_user_limits(png, 0x7fffffffu, 0x7fffffffu);
  png_set_compression_level(png, image->compression_level);
  // No row filter: trying the five filters on every row cost most of the encoding time, and
  // on three grey levels in long runs it made the files larger, not smaller.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_IHDR(png, info, image->width, image->height, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (image->pixels_per_metre_x != 0) {
    png_set_pHYs(png, info, image->pixels_per_metre_x, image->pixels_per_metre_y,
                 PNG_RESOLUTION_METER);
  }
  png_write_info(png, info);
  for (std::uint32_t r = 0; r < image->height; ++r) {
    // Row j = 0 at the bottom: the first image row is the last grid row.
    const CellClass* cells = image->cells + std::uint64_t{image->height - 1 - r} * image->width;
    grey_row(cells, image->width, image->grey, image->row_buffer);
    png_write_row(png, image->row_buffer);
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
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

 protected:
  Result<void> write_layer(detail::LayerBytes& out, const LayerResult& layer) const override {
    const GridSpec& g = run().grid;
    std::vector<std::uint8_t> row_buffer(g.nx);
    PngImage image;
    image.width = g.nx;
    image.height = g.ny;
    image.cells = layer.cells.data();
    image.grey = {options_.empty, options_.interior, options_.empty, options_.boundary};
    image.row_buffer = row_buffer.data();
    image.compression_level = std::clamp(options_.compression_level, 0, 9);
    image.pixels_per_metre_x = pixels_per_metre(g.dx);
    image.pixels_per_metre_y = pixels_per_metre(g.dy);
    if (image.pixels_per_metre_x == 0 || image.pixels_per_metre_y == 0) {
      image.pixels_per_metre_x = image.pixels_per_metre_y = 0;
    }
    PngTarget target;
    target.out = &out;
    if (!encode_png(&target, &image)) {
      return Error{
          ErrorCode::Internal,
          fmt::format("cannot encode the PNG of layer {}: {}", layer.layer, target.message),
          layer_path(layer.layer).string()};
    }
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
