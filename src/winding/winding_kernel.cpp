#include "winding/winding_kernel.hpp"

#include <algorithm>
#include <cmath>

#include "strata/contour/assemble_contours.hpp"
#include "strata/fill/scanline_fill.hpp"

namespace strata::detail {

namespace {

std::vector<std::array<Vec3, 3>> cap_triangles(const winding::BoundaryCaps& caps) {
  std::vector<std::array<Vec3, 3>> out;
  out.reserve(caps.closed.triangles.size() - caps.mesh_facets);
  for (std::size_t f = caps.mesh_facets; f < caps.closed.triangles.size(); ++f) {
    const auto& t = caps.closed.triangles[f];
    out.push_back(
        {caps.closed.vertices[t[0]], caps.closed.vertices[t[1]], caps.closed.vertices[t[2]]});
  }
  return out;
}

/// The runs of solid cells along each row, as hatches from the first cell's left edge to the
/// last cell's right edge.
std::vector<HatchSegment> hatches_from_runs(const SolidRows& solid, const GridSpec& grid) {
  std::vector<HatchSegment> hatches;
  for (std::uint32_t j = 0; j < grid.ny; ++j) {
    for (const SolidRun& r : solid.row(j)) {
      hatches.push_back({j, grid.x0 + static_cast<double>(r.begin) * grid.dx,
                         grid.x0 + static_cast<double>(r.end) * grid.dx});
    }
  }
  return hatches;
}

}  // namespace

WindingKernel::WindingKernel(const IndexedMesh& mesh, const GridSpec& grid,
                             const SliceOptions& options)
    : caps_(winding::cap_boundary(mesh)),
      cap_tree_(cap_triangles(caps_)),
      grid_(grid),
      options_(options) {
  sweep_.group(caps_.closed, grid);
}

void WindingKernel::prepare_batch(std::uint32_t k0, std::uint32_t k1) { sweep_.advance(k0, k1); }

LayerGeometry WindingKernel::compute_layer(std::uint32_t k) const {
  const std::vector<FacetIndex> candidates = sweep_.candidates(k);
  const LayerSegments closed = slice_layer(caps_.closed, candidates, grid_, k);
  const std::vector<std::int32_t> integer =
      scanline_winding_numbers(caps_.closed, closed, grid_, options_.scan_offset_mm);

  LayerGeometry geometry;
  geometry.fill.layer = k;
  std::vector<std::uint8_t> solid(grid_.cells_per_layer(), 0);
  std::uint64_t guarded = 0;
  for (std::uint32_t j = 0; j < grid_.ny; ++j) {
    const std::size_t row = std::size_t{j} * grid_.nx;
    for (std::uint32_t i = 0; i < grid_.nx; ++i) {
      const std::int32_t n = integer[row + i];
      if (cap_tree_.empty()) {
        solid[row + i] = n >= 1 ? 1 : 0;
        continue;
      }
      const Vec3 q{grid_.xc(i), grid_.yc(j) + options_.scan_offset_mm, grid_.zk(k)};
      double w = n - cap_tree_.evaluate(q);
      if (std::abs(w - 0.5) < kGuardBand) {
        w = n - (cap_tree_.facet_count() <= kDirectGuardFacets ? cap_tree_.evaluate_direct(q)
                                                               : cap_tree_.evaluate(q, kGuardBeta));
        ++guarded;
      }
      solid[row + i] = w >= 0.5 ? 1 : 0;
    }
  }
  guard_evaluations_ += guarded;
  geometry.fill.solid = SolidRows::from_cells(solid, grid_.nx, grid_.ny);
  geometry.fill.hatches = hatches_from_runs(geometry.fill.solid, grid_);

  // The contours are the mesh's own: the caps only serve the inside test.
  LayerSegments own{closed.layer, closed.z_mm, {}};
  for (const LayerSegment& s : closed.segments) {
    if (s.facet < caps_.mesh_facets) own.segments.push_back(s);
  }
  geometry.segments = static_cast<std::uint32_t>(own.segments.size());
  geometry.contours = assemble_contours(own);
  return geometry;
}

}  // namespace strata::detail
