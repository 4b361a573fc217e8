#pragma once

#include <cstdint>
#include <vector>

#include "strata/core/result.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/layer_range.hpp"

namespace strata {

/// One part of a plan: a layer range and the work estimated for it.
struct PlannedPart {
  LayerSpan layers;
  std::uint64_t crossings = 0;  ///< facet crossings of its layer planes
  std::uint64_t work = 0;       ///< crossings + cell units (see plan_layer_ranges)
};

struct LayerPlan {
  std::uint32_t nz_total = 0;
  std::vector<PlannedPart> parts;  ///< in layer order; they tile [0, nz_total)
};

/// Work per cell unit of a layer: a facet crossing costs about as much as this many cells
/// (segment, contour and fill work against the classification and output of one cell).
inline constexpr std::uint64_t kCellsPerCrossingUnit = 64;

/// Splits the layers of `grid` into `parts` consecutive ranges of balanced work, for a
/// scheduler that slices them apart (SPEC §3.1b) and merges the outputs. A layer's work is the
/// number of facets that cross its plane plus nx * ny / kCellsPerCrossingUnit, so a range of
/// many facet-dense layers is shorter than a range of empty ones. Part p takes the layers whose
/// middle of running work falls within (p + 1) / parts of the total, with at least one layer
/// for itself and for each part still to come. O(facets + nz).
/// @return Error{Usage} when parts is 0 or more than the grid's layers.
Result<LayerPlan> plan_layer_ranges(const IndexedMesh& mesh, const GridSpec& grid,
                                    std::uint32_t parts);

}  // namespace strata
