#include "strata/slice/plan_layer_ranges.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "strata/slice/slice_float.hpp"

namespace strata {

Result<LayerPlan> plan_layer_ranges(const IndexedMesh& mesh, const GridSpec& grid,
                                    std::uint32_t parts) {
  if (parts == 0 || parts > grid.nz) {
    return Error{ErrorCode::Usage,
                 fmt::format("cannot split {} layers into {} parts: take 1 to {} parts", grid.nz,
                             parts, grid.nz),
                 {}};
  }
  // Crossings per layer from every facet's layer range, by a difference array.
  const FacetLayerRanges ranges = facet_layer_ranges(mesh, grid);
  std::vector<std::int64_t> delta(std::size_t{grid.nz} + 1, 0);
  for (std::size_t f = 0; f < ranges.first.size(); ++f) {
    if (ranges.first[f] > ranges.last[f]) continue;
    ++delta[ranges.first[f]];
    --delta[std::size_t{ranges.last[f]} + 1];
  }
  std::vector<std::uint64_t> crossings(grid.nz);
  std::vector<std::uint64_t> work(grid.nz);
  const std::uint64_t cell_units = grid.cells_per_layer() / kCellsPerCrossingUnit;
  std::int64_t running = 0;
  std::uint64_t total = 0;
  for (std::uint32_t k = 0; k < grid.nz; ++k) {
    running += delta[k];
    crossings[k] = static_cast<std::uint64_t>(running);
    work[k] = crossings[k] + cell_units;
    total += work[k];
  }

  LayerPlan plan;
  plan.nz_total = grid.nz;
  std::uint32_t first = 0;
  long double done = 0;
  for (std::uint32_t p = 0; p < parts; ++p) {
    PlannedPart part;
    part.layers.first = first;
    const std::uint32_t left_after = parts - p - 1;  // parts still to come, one layer each
    const std::uint32_t last_end = grid.nz - left_after;
    const long double target =
        static_cast<long double>(total) * static_cast<long double>(p + 1) / parts;
    std::uint32_t end = first;
    // At least one layer; then each next layer whose middle of work falls within the running
    // share, while layers are left for the parts to come (the last part takes the rest).
    do {
      part.crossings += crossings[end];
      part.work += work[end];
      done += static_cast<long double>(work[end]);
      ++end;
    } while (end < last_end &&
             (p + 1 == parts || done + static_cast<long double>(work[end]) / 2 <= target));
    part.layers.end = end;
    plan.parts.push_back(part);
    first = end;
  }
  return plan;
}

}  // namespace strata
