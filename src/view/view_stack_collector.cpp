#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "strata/io/cells_format.hpp"
#include "strata/view/view_stack.hpp"
#include "view/encode_internal.hpp"

namespace strata::view {

namespace {

/// Packs a layer as the .cells file does: 4 cells a byte, the first in the high bits.
std::uint32_t blocks_along(std::uint32_t n, std::uint32_t max_blocks) {
  return std::max<std::uint32_t>(1, (n + max_blocks - 1) / max_blocks);
}

/// Bytes a base64 string of `raw` bytes takes, with its quotes and comma.
std::uint64_t base64_bytes(std::uint64_t raw) { return (raw + 2) / 3 * 4 + 3; }

std::string ordinal(std::uint32_t n) {
  const std::uint32_t tens = n % 100;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : n % 10 == 1              ? "st"
                       : n % 10 == 2              ? "nd"
                       : n % 10 == 3              ? "rd"
                                                  : "th";
  return fmt::format("{}{}", n, suffix);
}

std::string megabytes(std::uint64_t bytes) {
  return fmt::format("{:.1f} MB", static_cast<double>(bytes) / 1e6);
}

}  // namespace

ViewStackCollector::ViewStackCollector(ViewStackOptions options) : options_(options) {}

Result<void> ViewStackCollector::begin(const SliceRunInfo& run) {
  stack_ = ViewStack{};
  stack_.grid = run.grid;
  stack_.shell_mm = run.options.shell_mm;
  stack_.has_hatches = options_.hatches;
  const std::uint32_t max_blocks = std::max<std::uint32_t>(options_.max_blocks, 1);
  ViewVolume& v = stack_.volume;
  v.bx = blocks_along(run.grid.nx, max_blocks);
  v.by = blocks_along(run.grid.ny, max_blocks);
  v.bz = blocks_along(run.grid.nz, max_blocks);
  v.nx = (run.grid.nx + v.bx - 1) / v.bx;
  v.ny = (run.grid.ny + v.by - 1) / v.by;
  v.nz = (run.grid.nz + v.bz - 1) / v.bz;
  v.blocks.assign(std::size_t{v.nx} * v.ny * v.nz, 0);
  return {};
}

namespace {

/// What the page keeps of one layer, made ahead on a worker thread.
struct ViewLayer final : PreparedLayer {
  std::uint32_t layer = 0;
  std::string cells_zlib;
  std::vector<std::uint8_t> blocks;  ///< the layer's largest code in each block, v.ny * v.nx
  std::vector<ViewLoop> loops;
  std::vector<float> hatches;
};

}  // namespace

std::unique_ptr<PreparedLayer> ViewStackCollector::prepare_layer(const LayerResult& layer) const {
  const GridSpec& g = stack_.grid;
  const ViewVolume& v = stack_.volume;
  auto out = std::make_unique<ViewLayer>();
  out->layer = layer.layer;
  std::string packed;
  io::append_packed_cells(layer.cells, packed);
  out->cells_zlib = detail::zlib_compress(packed);

  out->blocks.assign(std::size_t{v.ny} * v.nx, 0);
  if (layer.cells.size() == g.cells_per_layer()) {
    // A block holds the largest code of its cells. The codes are 0, 1 and 3, so the largest is
    // their bitwise or: the rows of a block row are or-ed cell by cell (a loop the compiler
    // takes many cells a step), then each block's cells of that one row.
    std::vector<std::uint8_t> merged(g.nx);
    const auto* codes = reinterpret_cast<const std::uint8_t*>(layer.cells.data());
    for (std::uint32_t bj = 0; bj < v.ny; ++bj) {
      const std::uint32_t j0 = bj * v.by;
      const std::uint32_t j1 = std::min(g.ny, j0 + v.by);
      std::fill(merged.begin(), merged.end(), std::uint8_t{0});
      for (std::uint32_t j = j0; j < j1; ++j) {
        const std::uint8_t* row = codes + std::size_t{j} * g.nx;
        for (std::uint32_t i = 0; i < g.nx; ++i) merged[i] |= row[i];
      }
      std::uint8_t* blocks = out->blocks.data() + std::size_t{bj} * v.nx;
      for (std::uint32_t i0 = 0, b = 0; i0 < g.nx; i0 += v.bx, ++b) {
        const std::uint32_t i1 = std::min(g.nx, i0 + v.bx);
        std::uint8_t block = 0;
        for (std::uint32_t i = i0; i < i1; ++i) block |= merged[i];
        blocks[b] = block;
      }
    }
  }

  if (options_.contours) {
    for (const Contour& c : layer.contours.loops) {
      ViewLoop loop;
      loop.kind = c.kind;
      loop.xy.reserve(2 * c.points.size());
      for (const Point2& p : c.points) {
        loop.xy.push_back(static_cast<float>(p.x));
        loop.xy.push_back(static_cast<float>(p.y));
      }
      out->loops.push_back(std::move(loop));
    }
  }

  if (options_.hatches) {
    out->hatches.reserve(4 * layer.hatches.size());
    for (const HatchSegment& h : layer.hatches) {
      const auto y = static_cast<float>(g.yc(h.row));
      out->hatches.insert(out->hatches.end(),
                          {static_cast<float>(h.x_start), y, static_cast<float>(h.x_end), y});
    }
  }
  return out;
}

Result<void> ViewStackCollector::add_layer(const LayerResult& layer) {
  return add_prepared_layer(layer, prepare_layer(layer));
}

Result<void> ViewStackCollector::add_prepared_layer(const LayerResult& layer,
                                                    std::unique_ptr<PreparedLayer> prepared) {
  auto* made = dynamic_cast<ViewLayer*>(prepared.get());
  if (made == nullptr || made->layer != layer.layer) return add_layer(layer);
  ViewVolume& v = stack_.volume;
  if (layer.layer >= stack_.grid.nz) {
    return Error{ErrorCode::Internal,
                 fmt::format("view stack: layer {} is beyond the grid's {} layers", layer.layer,
                             stack_.grid.nz),
                 {}};
  }
  stack_.stored.push_back(layer.layer);
  stack_.cells_zlib.push_back(std::move(made->cells_zlib));
  std::uint8_t* plane = v.blocks.data() + std::size_t{layer.layer / v.bz} * v.ny * v.nx;
  for (std::size_t b = 0; b < made->blocks.size(); ++b) {
    plane[b] = std::max(plane[b], made->blocks[b]);
  }
  stack_.contours.push_back(std::move(made->loops));
  stack_.hatches.push_back(std::move(made->hatches));
  return {};
}

Result<void> ViewStackCollector::finish() { return {}; }

void ViewStackCollector::abort() noexcept { stack_ = ViewStack{}; }

ViewStack ViewStackCollector::take() { return std::move(stack_); }

void fit_to_budget(ViewStack& stack, std::uint64_t budget) {
  // The scanline segments go first, then every n-th layer is kept.
  std::uint64_t cells = 0, contours = 0, hatches = 0;
  for (std::size_t s = 0; s < stack.stored.size(); ++s) {
    cells += base64_bytes(stack.cells_zlib[s].size());
    for (const ViewLoop& loop : stack.contours[s]) {
      contours += base64_bytes(4 * loop.xy.size()) + 32;
    }
    hatches += base64_bytes(4 * stack.hatches[s].size());
  }
  if (stack.has_hatches && cells + contours + hatches > budget) {
    stack.has_hatches = false;
    for (auto& h : stack.hatches) std::vector<float>().swap(h);
    stack.notes.push_back(fmt::format(
        "scanline segments left out: with them the layers would take {} of the page's {} budget",
        megabytes(cells + contours + hatches), megabytes(budget)));
  }
  if (cells + contours > budget && stack.stored.size() > 1) {
    const auto stride = static_cast<std::uint32_t>(
        std::min<std::uint64_t>((cells + contours + budget - 1) / budget, stack.stored.size()));
    std::size_t kept = 0;
    for (std::size_t s = 0; s < stack.stored.size(); ++s) {
      if (stack.stored[s] % stride != 0) continue;
      stack.stored[kept] = stack.stored[s];
      stack.cells_zlib[kept] = std::move(stack.cells_zlib[s]);
      stack.contours[kept] = std::move(stack.contours[s]);
      stack.hatches[kept] = std::move(stack.hatches[s]);
      ++kept;
    }
    stack.stored.resize(kept);
    stack.cells_zlib.resize(kept);
    stack.contours.resize(kept);
    stack.hatches.resize(kept);
    stack.stride = stride;
    stack.notes.push_back(fmt::format(
        "subsampled stack: the page holds every {} layer ({} of {}) to stay within its {} "
        "budget (all layers would take {}); the cells file has every layer",
        ordinal(stride), kept, stack.grid.nz, megabytes(budget), megabytes(cells + contours)));
  }
}

}  // namespace strata::view
