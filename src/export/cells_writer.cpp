#include "strata/export/cells_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <string>
#include <utility>

#include "export/sink_support_internal.hpp"

namespace strata::io {

namespace {

constexpr const char* kKind = "cells writer";
// Packed bytes handed to the file at a time: keeps the buffer small on layers of 10^8 cells.
constexpr std::size_t kChunkBytes = std::size_t{1} << 16;
constexpr std::uint64_t kAheadBytes = std::uint64_t{1} << 24;

Error reserved_code_error(std::uint32_t k, std::uint64_t index, std::uint32_t nx, CellClass code) {
  return Error{ErrorCode::Internal,
               fmt::format("{}: layer {} row {} cell {} has the code {}, which is not 00, 01 or 11",
                           kKind, k, index / nx, index % nx, static_cast<unsigned>(code)),
               {}};
}

/// The grid a cells file of the run's layers describes (SPEC §3.1b): the whole grid's, with z0 the
/// bottom of the first layer sent and nz the number of layers sent.
GridSpec range_grid(const SliceRunInfo& run) {
  const LayerSpan span = run.span();
  GridSpec g = run.grid;
  g.z0 = run.grid.layer_bottom(span.first);
  g.nz = span.count();
  return g;
}

class BinaryCellsWriter final : public detail::SingleFileSink {
 public:
  explicit BinaryCellsWriter(std::filesystem::path path) : SingleFileSink(std::move(path), kKind) {}

  bool needs_cells() const override { return true; }
  bool needs_hatches() const override { return false; }

 protected:
  Result<void> write_header(OutputFile& out) override {
    const GridSpec g = range_grid(run());
    std::string header;
    header.reserve(kCellsHeaderBytes);
    // The layout: magic, four 32-bit counts (header size, nx, ny, nz), seven doubles.
    static_assert(kCellsMagic.size() + 4 * 4 + 7 * 8 == kCellsHeaderBytes, "cells header layout");
    header.append(kCellsMagic);
    detail::put_u32_le(header, kCellsHeaderBytes);
    detail::put_u32_le(header, g.nx);
    detail::put_u32_le(header, g.ny);
    detail::put_u32_le(header, g.nz);
    for (double v : {g.x0, g.y0, g.z0, g.dx, g.dy, g.dz, run().options.shell_mm}) {
      detail::put_f64_le(header, v);
    }
    out.write(header);
    return {};
  }

  // A layer of up to 16 MB packed is held to be packed ahead; a larger one is streamed.
  bool encodes_ahead() const override { return run().grid.cells_per_layer() / 4 <= kAheadBytes; }

  Result<void> write_layer(detail::LayerBytes& out, const LayerResult& layer) const override {
    const std::span<const CellClass> cells = layer.cells;
    const std::size_t n = cells.size();
    if (std::string* memory = out.memory()) {
      // Held in memory: packed straight into it (a refused layer adds nothing).
      const std::size_t bad = append_checked_packed_cells(cells, *memory);
      if (bad < n) return reserved_code_error(layer.layer, bad, run().grid.nx, cells[bad]);
      return {};
    }
    std::string chunk;
    chunk.reserve(kChunkBytes);
    for (std::size_t base = 0; base < n; base += 4 * kChunkBytes) {
      const std::span<const CellClass> part =
          cells.subspan(base, std::min(4 * kChunkBytes, n - base));
      chunk.clear();
      const std::size_t bad = append_checked_packed_cells(part, chunk);
      if (bad < part.size()) {
        return reserved_code_error(layer.layer, base + bad, run().grid.nx, part[bad]);
      }
      out.write(chunk);
    }
    return {};
  }
};

class AsciiCellsWriter final : public detail::SingleFileSink {
 public:
  explicit AsciiCellsWriter(std::filesystem::path path) : SingleFileSink(std::move(path), kKind) {}

  bool needs_cells() const override { return true; }
  bool needs_hatches() const override { return false; }

 protected:
  Result<void> write_header(OutputFile& out) override {
    const GridSpec g = range_grid(run());
    out.write(fmt::format("{}\ngrid {} {} {}\norigin {} {} {}\nspacing {} {} {}\nshell {}\n",
                          kCellsAsciiFirstLine, g.nx, g.ny, g.nz, g.x0, g.y0, g.z0, g.dx, g.dy,
                          g.dz, run().options.shell_mm));
    return {};
  }

  // Two characters a cell: a layer is streamed, not held.
  bool encodes_ahead() const override { return false; }

  Result<void> write_layer(detail::LayerBytes& out, const LayerResult& layer) const override {
    const GridSpec& g = run().grid;
    // Indices count from the file's first layer; z is the plane of the whole grid, so that a
    // range's layer lines are those of a whole run but for the index.
    out.write(fmt::format("layer {} z={}\n", layer.layer - run().span().first, layer.z_mm));
    std::string line(std::size_t{g.nx} * 2 + 1, '\n');
    for (std::uint32_t j = 0; j < g.ny; ++j) {
      const CellClass* row = layer.cells.data() + std::uint64_t{j} * g.nx;
      for (std::uint32_t i = 0; i < g.nx; ++i) {
        const auto code = static_cast<unsigned>(row[i]);
        if (code == 0b10 || code > 0b11) {
          return reserved_code_error(layer.layer, std::uint64_t{j} * g.nx + i, g.nx, row[i]);
        }
        line[2 * std::size_t{i}] = (code & 0b10) != 0 ? '1' : '0';
        line[2 * std::size_t{i} + 1] = (code & 0b01) != 0 ? '1' : '0';
      }
      out.write(line);
    }
    return {};
  }
};

}  // namespace

std::unique_ptr<LayerSink> make_cells_writer(const std::filesystem::path& path,
                                             CellsEncoding encoding) {
  if (encoding == CellsEncoding::Ascii) return std::make_unique<AsciiCellsWriter>(path);
  return std::make_unique<BinaryCellsWriter>(path);
}

}  // namespace strata::io
