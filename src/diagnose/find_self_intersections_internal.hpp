#pragma once

#include <cstddef>
#include <vector>

#include "strata/diagnose/mesh_report.hpp"
#include "strata/mesh/indexed_mesh.hpp"

namespace strata::diagnose::detail {

struct SelfIntersections {
  std::vector<FacetPair> pairs;  ///< sorted; first < second in each pair
  bool truncated = false;        ///< a limit was reached: `pairs` is incomplete
};

/// Pairs of facets that intersect other than along their shared edge or at their shared vertex
/// (shared meaning the same welded vertex index), decided with exact predicates. Facets flagged
/// in `skip` (degenerate ones) take no part; facets with the same three vertices (duplicates)
/// are not reported. Two facets sharing an edge intersect when they are coplanar and lie on the
/// same side of it; two facets sharing one vertex intersect when an edge opposite the shared
/// vertex meets the other facet.
/// The candidate pairs (facets whose boxes overlap) are tested on the threads, a batch at a time,
/// and taken in the order of the sweep that finds them: the limits stop the search where testing
/// them one by one would, whatever the number of threads.
/// @param max_pairs       stop after this many intersecting pairs
/// @param max_candidates  stop after testing this many pairs of overlapping bounding boxes
SelfIntersections find_self_intersections(const IndexedMesh& mesh, const std::vector<bool>& skip,
                                          std::size_t max_pairs, std::size_t max_candidates);

}  // namespace strata::diagnose::detail
