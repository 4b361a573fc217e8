#include "strata/export/svg_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "export/sink_support_internal.hpp"

namespace strata::io {

namespace {

// Strokes are given in screen pixels (vector-effect non-scaling-stroke), so contours stay visible
// whatever the part's size and the zoom.
constexpr const char* kStyle =
    "<style>\n"
    ".grid{fill:none;stroke:#b0b0b0;stroke-width:0.5px;vector-effect:non-scaling-stroke}\n"
    ".outer{fill:#9ecae1;fill-opacity:0.35;fill-rule:nonzero;stroke:#08519c;stroke-width:1px;"
    "vector-effect:non-scaling-stroke}\n"
    ".hole{fill:#fdd0a2;fill-opacity:0.6;fill-rule:nonzero;stroke:#d94801;stroke-width:1px;"
    "vector-effect:non-scaling-stroke}\n"
    ".open{fill:none;stroke:#e31a1c;stroke-width:1.5px;vector-effect:non-scaling-stroke}\n"
    ".open-end{fill:#e31a1c;stroke:none}\n"
    ".hatch{fill:none;stroke:#31a354;stroke-width:0.5px;vector-effect:non-scaling-stroke}\n"
    ".label{font-family:sans-serif;fill:#333333}\n"
    "</style>\n";

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out.push_back(c);
    }
  }
  return out;
}

class SvgWriter final : public detail::LayerFilesSink {
 public:
  SvgWriter(const std::filesystem::path& dir, std::string stem)
      : LayerFilesSink(dir, "svg", std::move(stem), "svg", "SVG writer") {}

  bool needs_cells() const override { return false; }

 protected:
  Result<void> write_layer(detail::LayerBytes& out, const LayerResult& layer) const override {
    const GridSpec& g = run().grid;
    const double width = g.nx * g.dx;
    const double height = g.ny * g.dy;
    const double y1 = g.y0 + height;
    const double extent = std::max(width, height);
    const double margin = 0.05 * extent;
    const double font = 0.6 * margin;
    const double end_radius = std::max(0.4 * std::min(g.dx, g.dy), 0.004 * extent);

    std::string s;
    s.reserve(4096);
    const std::string title =
        xml_escape(fmt::format("{} layer {} z={} mm", stem(), layer.layer, layer.z_mm));
    s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    s += fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}mm\" height=\"{}mm\" "
        "viewBox=\"{} {} {} {}\">\n",
        width + 2 * margin, height + 2 * margin, g.x0 - margin, -y1 - margin, width + 2 * margin,
        height + 2 * margin);
    s += fmt::format("<title>{}</title>\n", title);
    s += kStyle;
    s += fmt::format("<rect class=\"grid\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>\n", g.x0,
                     -y1, width, height);
    out.write(s);

    // Closed loops by increasing depth, so holes are drawn over the loops that contain them.
    const std::vector<Contour>& loops = layer.contours.loops;
    std::vector<std::size_t> order(loops.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return loops[a].depth < loops[b].depth; });
    for (const std::size_t index : order) {
      const Contour& loop = loops[index];
      if (loop.points.empty()) continue;
      const bool closed = loop.is_closed && loop.kind != LoopKind::Open;
      const char* cls = !closed ? "open" : loop.kind == LoopKind::Hole ? "hole" : "outer";
      s.clear();
      s += fmt::format("<path class=\"{}\" d=\"M", cls);
      for (std::size_t p = 0; p < loop.points.size(); ++p) {
        // " x y" then " L x y", y flipped so that +y is up in the picture.
        const Point2& point = loop.points[p];
        if (p == 0) {
          detail::append_text(s, ' ', point.x, ' ', -point.y);
        } else {
          detail::append_text(s, ' ', 'L', ' ', point.x, ' ', -point.y);
        }
      }
      s += closed ? " Z\"/>\n" : "\"/>\n";
      if (!closed) {
        for (const Point2& end : {loop.points.front(), loop.points.back()}) {
          s += fmt::format("<circle class=\"open-end\" cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n", end.x,
                           -end.y, end_radius);
        }
      }
      out.write(s);
    }

    if (!layer.hatches.empty()) {
      s.clear();
      s += "<path class=\"hatch\" d=\"";
      bool first = true;
      detail::RepeatedNumber row_y;
      for (const HatchSegment& h : layer.hatches) {
        const double y = g.yc(h.row) + run().options.scan_offset_mm;
        // "M x y H x", and a space before each but the first.
        if (!first) s += ' ';
        first = false;
        detail::append_text(s, 'M', ' ', h.x_start, ' ', detail::RepeatedValue{row_y, -y}, ' ', 'H',
                            ' ', h.x_end);
        if (s.size() > (std::size_t{1} << 16)) {
          out.write(s);
          s.clear();
        }
      }
      s += "\"/>\n";
      out.write(s);
    }

    s.clear();
    s += fmt::format("<text class=\"label\" x=\"{}\" y=\"{}\" font-size=\"{}\">{}</text>\n", g.x0,
                     -y1 - 0.3 * margin, font, title);
    s += "</svg>\n";
    out.write(s);
    return {};
  }
};

}  // namespace

std::unique_ptr<LayerSink> make_svg_writer(const std::filesystem::path& dir,
                                           const std::string& stem) {
  return std::make_unique<SvgWriter>(dir, stem);
}

}  // namespace strata::io
