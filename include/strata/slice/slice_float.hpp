#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/layer_segments.hpp"

namespace strata {

/// The layers each facet crosses: facet f crosses layer k iff zmin(f) < zk <= zmax(f), decided
/// by exact comparisons with the double zk. `first[f] > last[f]` when it crosses none
/// (horizontal facets, facets between two planes).
struct FacetLayerRanges {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> last;
};

/// Computes every facet's layer range in O(n).
FacetLayerRanges facet_layer_ranges(const IndexedMesh& mesh, const GridSpec& grid);

/// Facets grouped by the layer they start in (CSR), so a sweep over layers touches each facet
/// only while it can reach the plane: O(n + k + m) in all (Minetto et al. 2017).
struct FacetBuckets {
  std::vector<std::uint32_t> offsets;  ///< nz + 1 entries
  std::vector<FacetIndex> facets;      ///< facets starting in layer k: [offsets[k], offsets[k+1])
};

/// Groups the facets by ranges.first (each bucket in increasing facet order), leaving out those
/// that cross no layer.
FacetBuckets bucket_facets_by_first_layer(const FacetLayerRanges& ranges, std::uint32_t nz);

/// Moves a sweep's `active` facets on to the batch [k0, k1): drops those that end below k0 and
/// adds those that start in the layers [scanned, k1) not yet read and reach k0; `scanned` becomes
/// k1. The first batch may start past layer 0 (a layer range), later ones past the last.
/// @param offsets, facets  the buckets of facets by first layer (CSR, nz + 1 offsets)
/// @param last             every facet's last layer
void advance_active_facets(std::span<const std::uint32_t> offsets,
                           std::span<const FacetIndex> facets, std::span<const std::uint32_t> last,
                           std::uint32_t k0, std::uint32_t k1, std::uint32_t& scanned,
                           std::vector<FacetIndex>& active);

/// A sweep through the layers, a batch at a time: the facets grouped by first layer once, then
/// those whose range meets the current batch kept active, and listed once for each layer of the
/// batch they cross. Each layer kernel takes its candidate facets from one.
class FacetSweep {
 public:
  /// Groups the facets of `mesh` (facet_layer_ranges, bucket_facets_by_first_layer).
  void group(const IndexedMesh& mesh, const GridSpec& grid);
  /// True once group() has run (a grid has at least one layer, so the buckets are not empty).
  bool grouped() const { return !buckets_.offsets.empty(); }
  /// Moves on to the batch [k0, k1) (advance_active_facets) and lists the candidates of its
  /// layers: a pass over the active facets, rather than one for each layer.
  /// @pre grouped(), k0 < k1, and k0 no less than the last batch's k0
  void advance(std::uint32_t k0, std::uint32_t k1);
  /// The active facets that cross layer k, in increasing facet order: every later step is then
  /// independent of the order of the sweep. @pre k is in the current batch
  std::vector<FacetIndex> candidates(std::uint32_t k) const;

 private:
  FacetLayerRanges ranges_;
  FacetBuckets buckets_;
  std::vector<FacetIndex> active_;  ///< facets whose layer range meets the current batch
  std::uint32_t scanned_ = 0;       ///< layers whose buckets the sweep has read
  /// The candidates of the batch's layers (CSR): layer k's are
  /// batch_facets_[batch_offsets_[k - batch_first_] .. batch_offsets_[k - batch_first_ + 1]).
  std::uint32_t batch_first_ = 0;
  std::vector<std::size_t> batch_offsets_;
  std::vector<FacetIndex> batch_facets_;
};

/// Cuts the candidate facets with plane z = grid.zk(layer). A facet yields one segment when its
/// vertices lie on both sides (a vertex with z == zk counts as above); horizontal facets and
/// facets touching the plane from above yield none.
/// @param candidates facets whose range contains the layer (others are skipped cheaply)
LayerSegments slice_layer(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                          const GridSpec& grid, std::uint32_t layer);

}  // namespace strata
