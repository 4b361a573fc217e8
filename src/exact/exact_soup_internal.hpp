#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "exact/exact_numbers_internal.hpp"
#include "strata/exact/slice_exact.hpp"
#include "strata/mesh/indexed_mesh.hpp"

namespace strata::exact::detail {

/// Whether CGAL's repair_polygon_soup would do no more to the mesh's soup than remove its unused
/// points (remove_isolated_points_in_polygon_soup): no two vertices at one position (CGAL merges
/// those first; +0 and -0 are one), no facet with a repeated corner, no two facets on the same
/// three vertices (it keeps one). Facets stay triangles, so its other steps (consecutive repeats,
/// pinched or short polygons) find nothing either. SoupMesh then skips the repair's other steps
/// and knows each face's input facet by its index.
bool is_clean_soup(const IndexedMesh& mesh);

/// The mesh read as a polygon soup into CGAL, repaired (repair_polygon_soup) and oriented
/// (orient_polygon_soup), and, when that is a polygon mesh of triangles, held as a halfedge
/// structure whose faces know the input facet they come from. The repair never changes the slice:
/// segment directions always come from the input facets' own vertex order.
class SoupMesh {
 public:
  /// Builds the soup and the halfedge structure. Throws what CGAL throws (the caller turns it
  /// into an Error). @pre every vertex index in range, every coordinate finite.
  explicit SoupMesh(const IndexedMesh& mesh);
  ~SoupMesh();
  SoupMesh(const SoupMesh&) = delete;
  SoupMesh& operator=(const SoupMesh&) = delete;

  /// What repair and orientation did (the soup fields of ExactSliceReport).
  const ExactSliceReport& repair_report() const;

  /// Chains one layer's segments into closed loops by walking the halfedge structure face to face
  /// across the crossed edges. A loop's points are its segments' start points, in order, moved
  /// out of `layer.points` (the layer's points are then spent; its segments are unchanged).
  /// @return nullopt when the soup is not a polygon mesh, a chain reaches a border, a facet of
  ///         the layer is not in the mesh (removed by the repair) or two neighbouring facets'
  ///         directions disagree: the caller then uses the arrangement, and `layer` is as it was.
  /// Safe to call from several threads, each with its own layer.
  std::optional<std::vector<ExactLoop>> chain_layer(ExactLayer& layer) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace strata::exact::detail
