#include "strata/slice/slice_float.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <boost/sort/spreadsort/integer_sort.hpp>
#include <limits>
#include <optional>
#include <utility>

#include "core/group_by_key.hpp"
#include "predicates/crossing_predicates.hpp"
#include "predicates/grid_search.hpp"
#include "strata/core/error.hpp"

namespace strata {

namespace {

/// The number of layers whose plane zk satisfies zk <= z.
std::uint32_t layers_at_or_below(const GridSpec& grid, double z) {
  const double estimate = (z - grid.z0) / grid.dz + 0.5;
  return detail::count_prefix(estimate, grid.nz, [&](std::uint32_t k) { return grid.zk(k) <= z; });
}

}  // namespace

FacetLayerRanges facet_layer_ranges(const IndexedMesh& mesh, const GridSpec& grid) {
  // layers_at_or_below is monotone in z, so a facet's count at its lowest (highest) z is the
  // least (greatest) of its vertices' counts: each vertex is searched once, not once per facet
  // around it (six on a closed mesh). Both passes share their items out among the threads.
  constexpr std::size_t kGrain = 16384;
  std::vector<std::uint32_t> at_or_below(mesh.vertices.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.vertices.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t v = range.begin(); v < range.end(); ++v) {
                        at_or_below[v] = layers_at_or_below(grid, mesh.vertices[v].z);
                      }
                    });
  FacetLayerRanges ranges;
  const std::size_t n = mesh.triangles.size();
  ranges.first.resize(n);
  ranges.last.resize(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t f = range.begin(); f < range.end(); ++f) {
                        const auto& t = mesh.triangles[f];
                        const std::uint32_t a = at_or_below[t[0]];
                        const std::uint32_t b = at_or_below[t[1]];
                        const std::uint32_t c = at_or_below[t[2]];
                        // Layer k is crossed iff z_min < zk <= z_max (a vertex on the plane
                        // counts as above).
                        const std::uint32_t first = std::min({a, b, c});
                        const std::uint32_t end = std::max({a, b, c});
                        if (first < end) {
                          ranges.first[f] = first;
                          ranges.last[f] = end - 1;
                        } else {
                          ranges.first[f] = std::numeric_limits<std::uint32_t>::max();
                          ranges.last[f] = 0;
                        }
                      }
                    });
  return ranges;
}

FacetBuckets bucket_facets_by_first_layer(const FacetLayerRanges& ranges, std::uint32_t nz) {
  FacetBuckets buckets;
  buckets.offsets = group_by_key<std::uint32_t>(
      nz, ranges.first.size(),
      [&](std::size_t f, auto&& visit) {
        if (ranges.first[f] <= ranges.last[f]) visit(ranges.first[f], static_cast<FacetIndex>(f));
      },
      [&](std::size_t total) {
        buckets.facets.resize(total);
        return buckets.facets.data();
      });
  return buckets;
}

void advance_active_facets(std::span<const std::uint32_t> offsets,
                           std::span<const FacetIndex> facets, std::span<const std::uint32_t> last,
                           std::uint32_t k0, std::uint32_t k1, std::uint32_t& scanned,
                           std::vector<FacetIndex>& active) {
  std::erase_if(active, [&](FacetIndex f) { return last[f] < k0; });
  const std::uint32_t end =
      std::min<std::uint32_t>(k1, static_cast<std::uint32_t>(offsets.size() - 1));
  for (std::uint32_t k = scanned; k < end; ++k) {
    for (std::uint32_t r = offsets[k]; r < offsets[k + 1]; ++r) {
      // Facets that began in skipped layers count only if they reach this batch.
      if (last[facets[r]] >= k0) active.push_back(facets[r]);
    }
  }
  scanned = std::max(scanned, end);
}

void FacetSweep::group(const IndexedMesh& mesh, const GridSpec& grid) {
  ranges_ = facet_layer_ranges(mesh, grid);
  buckets_ = bucket_facets_by_first_layer(ranges_, grid.nz);
  active_.clear();
  scanned_ = 0;
}

void FacetSweep::advance(std::uint32_t k0, std::uint32_t k1) {
  STRATA_ASSERT(k0 < k1, "a batch holds a layer or more");
  advance_active_facets(buckets_.offsets, buckets_.facets, ranges_.last, k0, k1, scanned_, active_);
  // A counting sort by layer: each active facet is placed in the lists of the batch's layers it
  // crosses (one or two on a fine mesh), not looked at again for every layer of the batch.
  batch_first_ = k0;
  const std::uint32_t layers = k1 - k0;
  const auto crossed = [&](FacetIndex f) {
    return std::pair{std::max(ranges_.first[f], k0), std::min(ranges_.last[f], k1 - 1)};
  };
  batch_offsets_.assign(std::size_t{layers} + 1, 0);
  for (const FacetIndex f : active_) {
    const auto [from, to] = crossed(f);
    for (std::uint32_t k = from; k <= to; ++k) ++batch_offsets_[k - k0 + 1];
  }
  for (std::uint32_t k = 0; k < layers; ++k) batch_offsets_[k + 1] += batch_offsets_[k];
  batch_facets_.resize(batch_offsets_[layers]);
  std::vector<std::size_t> cursor(batch_offsets_.begin(), batch_offsets_.end() - 1);
  for (const FacetIndex f : active_) {
    const auto [from, to] = crossed(f);
    for (std::uint32_t k = from; k <= to; ++k) batch_facets_[cursor[k - k0]++] = f;
  }
}

std::vector<FacetIndex> FacetSweep::candidates(std::uint32_t k) const {
  STRATA_ASSERT(k >= batch_first_ && k - batch_first_ + 1 < batch_offsets_.size(),
                "the layer is in the sweep's current batch");
  const std::size_t at = k - batch_first_;
  std::vector<FacetIndex> out(batch_facets_.begin() + batch_offsets_[at],
                              batch_facets_.begin() + batch_offsets_[at + 1]);
  // Facet indices are integers: a radix-based sort (spreadsort) takes them in a few passes.
  boost::sort::spreadsort::integer_sort(out.begin(), out.end());
  return out;
}

LayerSegments slice_layer(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                          const GridSpec& grid, std::uint32_t layer) {
  LayerSegments out;
  out.layer = layer;
  out.z_mm = grid.zk(layer);
  const double z = out.z_mm;
  const auto point_on = [&](const CrossedEdge& edge) {
    return detail::crossing_point(mesh.vertices[edge.below], mesh.vertices[edge.above], z);
  };
  // The candidates are the facets whose span of layers holds this one: nearly each gives a piece.
  out.segments.reserve(candidates.size());
  for (const FacetIndex f : candidates) {
    if (const std::optional<FacetCrossing> c = facet_crossing(mesh, f, z)) {
      out.segments.push_back(LayerSegment{f, c->start_edge, c->end_edge, point_on(c->start_edge),
                                          point_on(c->end_edge)});
    }
  }
  return out;
}

}  // namespace strata
