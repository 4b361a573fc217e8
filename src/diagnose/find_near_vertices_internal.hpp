#pragma once

#include <cstddef>

#include "strata/diagnose/mesh_report.hpp"
#include "strata/mesh/indexed_mesh.hpp"

namespace strata::diagnose::detail {

struct NearVertices {
  /// Pairs of distinct vertices closer than the tolerance, (lower vertex, higher vertex), listed
  /// in increasing order of the lower vertex, then of the cell and the index of the higher one.
  Occurrences<PointPair> pairs;
  bool truncated = false;  ///< the checks ran out: `pairs` is incomplete
};

/// Pairs of distinct vertices closer than `tolerance` (> 0), found through a grid of cells twice
/// that size, so that the ball around a vertex meets at most 2 x 2 x 2 cells. Each pair is
/// checked once, from its lower vertex; after `max_checks` checks the search stops. Keeps the
/// first `limit` pairs. The vertices are shared out among the threads; what is found, and where
/// the checks run out, does not depend on their number.
NearVertices find_near_vertices(const IndexedMesh& mesh, const Bbox3& bounds, double tolerance,
                                std::size_t max_checks, std::size_t limit);

}  // namespace strata::diagnose::detail
