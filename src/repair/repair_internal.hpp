#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"
#include "strata/repair/repair_mesh.hpp"

namespace strata::repair::detail {

/// A facet during the repair: three vertices of the welded soup and the input facet it comes from
/// (a facet split at a T-junction leaves several pieces with the same origin).
struct WorkFacet {
  std::array<VertexIndex, 3> v{};
  FacetIndex origin = 0;
  /// A piece of a facet split at a T-junction (otherwise `v` are the origin's corners in order).
  bool piece = false;
};

/// The soup after the steps that need no halfedge structure (1 to 4 of repair_mesh()).
struct CleanSoup {
  std::vector<Vec3> vertices;        ///< the exact weld of the input
  std::vector<WorkFacet> facets;     ///< kept facets in input order, pieces in place
  std::vector<FacetChange> changes;  ///< removals and splits, in the order they were made
};

/// Steps 1 to 4: weld, remove zero-area facets, remove duplicates, close T-junction cracks. Fills
/// the matching counts of `log`. @pre every coordinate finite.
CleanSoup clean_soup(const TriangleSoup& soup, const RepairOptions& options, RepairLog& log);

/// One facet of the repaired mesh.
struct OutputFacet {
  std::array<Vec3, 3> corners;
  /// Index into CleanSoup::facets, or -1 for a facet that fills a hole.
  std::int64_t clean_index = -1;
  /// The vertex order is the reverse of the clean facet's.
  bool flipped = false;
};

/// Steps 5 to 8 on CGAL's halfedge structure: orientation, stitching, holes, volume orientation.
/// Fills the matching counts of `log`. Facets come out in the order of `clean`, then the hole
/// patches. Throws what CGAL throws.
std::vector<OutputFacet> orient_and_close(const CleanSoup& clean, const RepairOptions& options,
                                          RepairLog& log);

}  // namespace strata::repair::detail
