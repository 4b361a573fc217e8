#pragma once

#include <cstddef>
#include <optional>

#include "strata/diagnose/mesh_report.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::diagnose {

/// Tuning of diagnose_mesh(); the defaults suit `strata check`.
struct DiagnoseOptions {
  /// Vertices closer than this (mm) are reported as near-coincident; unset: 1e-6 of the bounding
  /// box diagonal. Zero or negative switches the search off.
  std::optional<double> near_vertex_mm = std::nullopt;
  /// Work limit of the near-vertex search (distance evaluations); the report says when it is hit.
  std::size_t max_near_vertex_checks = 50'000'000;
  /// How many locations of each kind of defect the report keeps (the first ones); `strata view`
  /// asks for more, to draw them.
  std::size_t max_locations = kMaxLocations;
  bool check_self_intersections = true;
  /// The self-intersection search stops after finding this many pairs ...
  std::size_t max_self_intersection_pairs = 100'000;
  /// ... or after testing this many pairs of facets whose bounding boxes overlap.
  std::size_t max_self_intersection_candidates = 50'000'000;
};

/// Counts and locates the defects of a mesh (SPEC §2b) and judges whether it can be sliced.
/// @param mesh     the exact weld of `soup` (weld_vertices()): same facets in the same order
/// @param soup     the mesh as read: its stored normals are checked against the vertex order
///                 (when it has one per facet) and its facet count is reported
/// @param options  near-vertex tolerance and self-intersection limits
/// @return the report; every count refers to `mesh`, every facet index to the input order
/// @pre every vertex index of `mesh` is valid; coordinates are finite.
/// Robustness: degenerate facets, orientation, stored normals and self-intersections are decided
/// with exact predicates; the volume is accumulated exactly and rounded once; the area and the
/// near-vertex distances are computed in double. Complexity: O(n log n) plus the
/// self-intersection search, O(n log^3 n + k) for k overlapping facet boxes, bounded by options.
MeshReport diagnose_mesh(const IndexedMesh& mesh, const TriangleSoup& soup,
                         const DiagnoseOptions& options = {});

}  // namespace strata::diagnose
