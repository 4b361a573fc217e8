#include "strata/slice/grid_spec.hpp"

#include <fmt/format.h>

#include <cmath>

namespace strata {
namespace {

constexpr double kMaxCellsPerAxis = 2147483647.0;    // 2^31 - 1
constexpr double kMaxCellsPerLayer = 17179869184.0;  // 2^34

Result<std::uint32_t> cells_along(const char* axis, double lo, double hi, double d) {
  if (!(d > 0.0) || !std::isfinite(d)) {
    return Error{ErrorCode::Usage,
                 fmt::format("cell size along {} must be a positive number, got {}", axis, d),
                 {}};
  }
  const double n = std::ceil((hi - lo) / d);
  if (!std::isfinite(n) || n > kMaxCellsPerAxis) {
    return Error{ErrorCode::Usage,
                 fmt::format("the model spans {} mm along {}: {} cells of {} mm are more than the "
                             "grid can index; use larger cells",
                             hi - lo, axis, n, d),
                 {}};
  }
  return static_cast<std::uint32_t>(std::max(1.0, n));
}

}  // namespace

Result<GridSpec> make_grid(const Bbox3& bounds, const GridOptions& options) {
  if (bounds.empty()) return Error{ErrorCode::BadInput, "the model has no vertices", {}};
  GridSpec grid;
  const Vec3 origin = options.origin.value_or(bounds.min);
  if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(origin.z)) {
    return Error{ErrorCode::Usage, "the grid origin must be finite", {}};
  }
  grid.x0 = origin.x;
  grid.y0 = origin.y;
  grid.z0 = origin.z;
  grid.dx = options.dx_mm;
  grid.dy = options.dy_mm;
  grid.dz = options.dz_mm;
  auto nx = cells_along("x", grid.x0, bounds.max.x, grid.dx);
  if (!nx) return nx.error();
  auto ny = cells_along("y", grid.y0, bounds.max.y, grid.dy);
  if (!ny) return ny.error();
  auto nz = cells_along("z", grid.z0, bounds.max.z, grid.dz);
  if (!nz) return nz.error();
  grid.nx = *nx;
  grid.ny = *ny;
  grid.nz = *nz;
  if (static_cast<double>(grid.nx) * grid.ny > kMaxCellsPerLayer) {
    return Error{ErrorCode::Usage,
                 fmt::format("a layer of {} x {} cells is larger than strata holds in memory "
                             "(2^34 cells); use larger cells",
                             grid.nx, grid.ny),
                 {}};
  }
  return grid;
}

}  // namespace strata
