#include "strata/export/cli_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <utility>

#include "export/sink_support_internal.hpp"

namespace strata::io {

namespace {

constexpr const char* kKind = "CLI writer";
constexpr std::int32_t kPartId = 1;
// Output is handed to the file in pieces of about this size.
constexpr std::size_t kFlushBytes = std::size_t{1} << 16;

/// CLI direction codes (PRIOR-ART §5): 0 clockwise (hole), 1 counter-clockwise (outer), 2 open.
std::int32_t cli_direction(const Contour& loop) {
  if (!loop.is_closed || loop.kind == LoopKind::Open) return 2;
  return loop.kind == LoopKind::Hole ? 0 : 1;
}

/// Where a layer's bytes are put together: straight in the layer's memory when it is encoded
/// ahead (the text is then not copied once more), else in a buffer handed to the file a piece at
/// a time.
class LayerText {
 public:
  LayerText(detail::LayerBytes& out, std::size_t most)
      : out_(out), text_(out.memory() != nullptr ? *out.memory() : buffer_) {
    if (&text_ == &buffer_) buffer_.reserve(std::min(most, kFlushBytes + 256));
  }
  LayerText(const LayerText&) = delete;
  LayerText& operator=(const LayerText&) = delete;

  std::string& text() { return text_; }
  /// Hands the buffer to the file once it holds a piece.
  void flush_if_large() {
    if (&text_ == &buffer_ && buffer_.size() >= kFlushBytes) flush();
  }
  /// Hands the rest to the file.
  void finish() {
    if (&text_ == &buffer_) flush();
  }

 private:
  void flush() {
    out_.write(buffer_);
    buffer_.clear();
  }

  detail::LayerBytes& out_;
  std::string buffer_;
  std::string& text_;
};

std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

class CliWriter final : public detail::SingleFileSink {
 public:
  CliWriter(std::filesystem::path path, CliEncoding encoding)
      : SingleFileSink(std::move(path), kKind), encoding_(encoding) {}

  bool needs_cells() const override { return false; }

 protected:
  Result<void> write_header(OutputFile& out) override {
    const GridSpec& g = run().grid;
    const bool binary = encoding_ == CliEncoding::Binary;
    std::string s = "$$HEADERSTART\n";
    s += binary ? "$$BINARY\n" : "$$ASCII\n";
    s += "$$UNITS/00000001.000000\n";  // coordinates are millimetres
    s += "$$VERSION/200\n";
    if (!run().model_name.empty())
      s += fmt::format("$$LABEL/{},{}\n", kPartId, one_line(run().model_name));
    // A layer range's file spans its layers alone (SPEC §3.1b).
    const LayerSpan span = run().span();
    s += fmt::format("$$DIMENSION/{},{},{},{},{},{}\n", g.x0, g.y0, g.layer_bottom(span.first),
                     g.x0 + g.nx * g.dx, g.y0 + g.ny * g.dy, g.z0 + span.end * g.dz);
    s += fmt::format("$$LAYERS/{}\n", span.count());
    // In the binary encoding the command stream starts right after the keyword.
    s += binary ? "$$HEADEREND" : "$$HEADEREND\n$$GEOMETRYSTART\n";
    out.write(s);
    return {};
  }

  Result<void> write_layer(detail::LayerBytes& out, const LayerResult& layer) const override {
    const GridSpec& g = run().grid;
    // The CLI's layer height is the top of the layer; the contours are its middle-plane section.
    const double z_top = g.z0 + (static_cast<double>(layer.layer) + 1.0) * g.dz;
    if (encoding_ == CliEncoding::Binary) {
      write_binary_layer(out, layer, z_top);
    } else {
      write_ascii_layer(out, layer, z_top);
    }
    return {};
  }

  Result<void> write_trailer(OutputFile& out) override {
    if (encoding_ == CliEncoding::Ascii) out.write("$$GEOMETRYEND\n");
    return {};
  }

 private:
  void write_ascii_layer(detail::LayerBytes& out, const LayerResult& layer, double z_top) const {
    // Room for the layer's text reserved ahead, so that it is not moved as it grows: a number
    // and its separator take at most 25 characters (17 digits, sign, point and exponent), a
    // line's keyword and counts less than 64. The piece kept before flushing holds a point or a
    // hatch more than the flush size.
    constexpr std::size_t kNumberBytes = 25;
    std::size_t most = 64;
    for (const Contour& loop : layer.contours.loops)
      most += 64 + (loop.points.size() + 1) * 2 * kNumberBytes;
    most += 64 + layer.hatches.size() * 4 * kNumberBytes;
    out.reserve_more(most);
    LayerText text(out, most);
    std::string& s = text.text();
    s += "$$LAYER/";
    detail::append_number(s, z_top);
    s += '\n';
    for (const Contour& loop : layer.contours.loops) {
      if (loop.points.size() < 2) continue;
      const std::int32_t dir = cli_direction(loop);
      const std::size_t n = loop.points.size() + (dir == 2 ? 0 : 1);
      fmt::format_to(std::back_inserter(s), "$$POLYLINE/{},{},{}", kPartId, dir, n);
      for (std::size_t p = 0; p < n; ++p) {
        const Point2& pt = loop.points[p % loop.points.size()];
        detail::append_text(s, ',', pt.x, ',', pt.y);
        text.flush_if_large();
      }
      s += '\n';
    }
    if (!layer.hatches.empty()) {
      fmt::format_to(std::back_inserter(s), "$$HATCHES/{},{}", kPartId, layer.hatches.size());
      detail::RepeatedNumber row_y;
      for (const HatchSegment& h : layer.hatches) {
        const double y = run().grid.yc(h.row) + run().options.scan_offset_mm;
        detail::append_text(s, ',', h.x_start, ',', detail::RepeatedValue{row_y, y}, ',', h.x_end,
                            ',', detail::RepeatedValue{row_y, y});
        text.flush_if_large();
      }
      s += '\n';
    }
    text.finish();
  }

  void write_binary_layer(detail::LayerBytes& out, const LayerResult& layer, double z_top) const {
    // 6 bytes for the layer, 14 a line's or the hatches' start, 8 a point, 16 a hatch.
    std::size_t most = 6 + 14;
    for (const Contour& loop : layer.contours.loops) most += 14 + (loop.points.size() + 1) * 8;
    most += layer.hatches.size() * 16;
    out.reserve_more(most);
    LayerText text(out, most);
    std::string& s = text.text();
    detail::put_u16_le(s, kCliLayerLong);
    detail::put_f32_le(s, static_cast<float>(z_top));
    for (const Contour& loop : layer.contours.loops) {
      if (loop.points.size() < 2) continue;
      const std::int32_t dir = cli_direction(loop);
      const std::size_t n = loop.points.size() + (dir == 2 ? 0 : 1);
      detail::put_u16_le(s, kCliPolylineLong);
      detail::put_i32_le(s, kPartId);
      detail::put_i32_le(s, dir);
      detail::put_i32_le(s, static_cast<std::int32_t>(n));
      for (std::size_t p = 0; p < n; ++p) {
        const Point2& pt = loop.points[p % loop.points.size()];
        detail::put_f32_le(s, static_cast<float>(pt.x));
        detail::put_f32_le(s, static_cast<float>(pt.y));
        text.flush_if_large();
      }
    }
    if (!layer.hatches.empty()) {
      detail::put_u16_le(s, kCliHatchesLong);
      detail::put_i32_le(s, kPartId);
      detail::put_i32_le(s, static_cast<std::int32_t>(layer.hatches.size()));
      for (const HatchSegment& h : layer.hatches) {
        const double y = run().grid.yc(h.row) + run().options.scan_offset_mm;
        detail::put_f32_le(s, static_cast<float>(h.x_start));
        detail::put_f32_le(s, static_cast<float>(y));
        detail::put_f32_le(s, static_cast<float>(h.x_end));
        detail::put_f32_le(s, static_cast<float>(y));
        text.flush_if_large();
      }
    }
    text.finish();
  }

  CliEncoding encoding_;
};

}  // namespace

std::unique_ptr<LayerSink> make_cli_writer(const std::filesystem::path& path,
                                           CliEncoding encoding) {
  return std::make_unique<CliWriter>(path, encoding);
}

}  // namespace strata::io
