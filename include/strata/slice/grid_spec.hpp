#pragma once

#include <cstdint>

#include "strata/core/result.hpp"
#include "strata/mesh/vec3.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata {

/// The regular grid of SPEC §2. Every quantity is computed in IEEE double exactly as written
/// (the build disables contraction), so any two implementations get the same bits.
struct GridSpec {
  double x0 = 0, y0 = 0, z0 = 0;         ///< origin: the grid's minimum corner, mm
  double dx = 1, dy = 1, dz = 1;         ///< cell size and layer thickness, mm
  std::uint32_t nx = 1, ny = 1, nz = 1;  ///< cells along x and y, layers along z

  /// Cell centre x of column i: x0 + (i + 0.5) * dx.
  double xc(std::uint32_t i) const { return x0 + (static_cast<double>(i) + 0.5) * dx; }
  /// Cell centre y of row j: y0 + (j + 0.5) * dy.
  double yc(std::uint32_t j) const { return y0 + (static_cast<double>(j) + 0.5) * dy; }
  /// Cutting plane of layer k: z0 + (k + 0.5) * dz.
  double zk(std::uint32_t k) const { return z0 + (static_cast<double>(k) + 0.5) * dz; }

  /// Bottom of layer k: z0 + k * dz (z0 itself, bit for bit, for k = 0).
  double layer_bottom(std::uint32_t k) const {
    return k == 0 ? z0 : z0 + static_cast<double>(k) * dz;
  }

  /// nx * ny.
  std::uint64_t cells_per_layer() const { return std::uint64_t{nx} * ny; }
  /// nx * ny * nz.
  std::uint64_t cell_count() const { return cells_per_layer() * nz; }
};

/// Builds the grid for a model's bounding box: origin = options.origin or the box's minimum
/// corner, n = max(1, ceil((max - origin) / d)) per axis.
/// @return Error{Usage} for non-positive or non-finite sizes, or a grid too large to index
///         (more than 2^31 cells per axis or 2^34 cells per layer).
Result<GridSpec> make_grid(const Bbox3& bounds, const GridOptions& options);

}  // namespace strata
