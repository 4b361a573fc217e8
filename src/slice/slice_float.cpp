#include "strata/slice/slice_float.hpp"

#include <algorithm>
#include <limits>

#include "predicates/crossing_predicates.hpp"
#include "predicates/grid_search.hpp"

namespace strata {

namespace {

/// The number of layers whose plane zk satisfies zk <= z.
std::uint32_t layers_at_or_below(const GridSpec& grid, double z) {
  const double estimate = (z - grid.z0) / grid.dz + 0.5;
  return detail::count_prefix(estimate, grid.nz, [&](std::uint32_t k) { return grid.zk(k) <= z; });
}

}  // namespace

FacetLayerRanges facet_layer_ranges(const IndexedMesh& mesh, const GridSpec& grid) {
  FacetLayerRanges ranges;
  const std::size_t n = mesh.triangles.size();
  ranges.first.resize(n);
  ranges.last.resize(n);
  for (std::size_t f = 0; f < n; ++f) {
    const auto& t = mesh.triangles[f];
    const double z_a = mesh.vertices[t[0]].z;
    const double z_b = mesh.vertices[t[1]].z;
    const double z_c = mesh.vertices[t[2]].z;
    const double z_min = std::min({z_a, z_b, z_c});
    const double z_max = std::max({z_a, z_b, z_c});
    // Layer k is crossed iff z_min < zk <= z_max (a vertex on the plane counts as above).
    const std::uint32_t first = layers_at_or_below(grid, z_min);
    const std::uint32_t end = layers_at_or_below(grid, z_max);
    if (first < end) {
      ranges.first[f] = first;
      ranges.last[f] = end - 1;
    } else {
      ranges.first[f] = std::numeric_limits<std::uint32_t>::max();
      ranges.last[f] = 0;
    }
  }
  return ranges;
}

FacetBuckets bucket_facets_by_first_layer(const FacetLayerRanges& ranges, std::uint32_t nz) {
  FacetBuckets buckets;
  buckets.offsets.assign(std::size_t{nz} + 1, 0);
  for (std::size_t f = 0; f < ranges.first.size(); ++f) {
    if (ranges.first[f] <= ranges.last[f]) ++buckets.offsets[ranges.first[f] + 1];
  }
  for (std::uint32_t k = 0; k < nz; ++k) buckets.offsets[k + 1] += buckets.offsets[k];
  buckets.facets.resize(buckets.offsets[nz]);
  std::vector<std::uint32_t> cursor(buckets.offsets.begin(), buckets.offsets.end() - 1);
  for (std::size_t f = 0; f < ranges.first.size(); ++f) {
    if (ranges.first[f] <= ranges.last[f]) {
      buckets.facets[cursor[ranges.first[f]]++] = static_cast<FacetIndex>(f);
    }
  }
  return buckets;
}

LayerSegments slice_layer(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                          const GridSpec& grid, std::uint32_t layer) {
  LayerSegments out;
  out.layer = layer;
  out.z_mm = grid.zk(layer);
  const double z = out.z_mm;
  for (const FacetIndex f : candidates) {
    const auto& t = mesh.triangles[f];
    const bool above[3] = {mesh.vertices[t[0]].z >= z, mesh.vertices[t[1]].z >= z,
                           mesh.vertices[t[2]].z >= z};
    const int count = int{above[0]} + int{above[1]} + int{above[2]};
    if (count == 0 || count == 3) continue;
    LayerSegment segment;
    segment.facet = f;
    // Walk the facet's edges in its vertex order: the edge going down through the plane starts
    // the segment, the edge going up ends it, so the material lies on the segment's left.
    for (int e = 0; e < 3; ++e) {
      const int u = e;
      const int v = (e + 1) % 3;
      if (above[u] && !above[v]) {
        segment.start_edge = CrossedEdge{t[v], t[u]};
      } else if (!above[u] && above[v]) {
        segment.end_edge = CrossedEdge{t[u], t[v]};
      }
    }
    segment.start = detail::crossing_point(mesh.vertices[segment.start_edge.below],
                                           mesh.vertices[segment.start_edge.above], z);
    segment.end = detail::crossing_point(mesh.vertices[segment.end_edge.below],
                                         mesh.vertices[segment.end_edge.above], z);
    out.segments.push_back(segment);
  }
  return out;
}

}  // namespace strata
