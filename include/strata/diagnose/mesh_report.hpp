#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata::diagnose {

/// How many locations of each kind of defect a report keeps by default (the first ones, see
/// Occurrences and DiagnoseOptions::max_locations).
inline constexpr std::size_t kMaxLocations = 20;

/// An edge given by its end points, in millimetres. For an edge that belongs to one facet (open
/// edge) or to two facets that run it the same way (inconsistent orientation) `from` -> `to` is
/// the direction of the first facet using it; otherwise the lower-indexed vertex comes first.
struct EdgeLocation {
  Vec3 from;
  Vec3 to;
};

/// Two facets of the mesh, `first` < `second`.
struct FacetPair {
  FacetIndex first = 0;
  FacetIndex second = 0;
};

/// Two vertices of the welded mesh, in millimetres.
struct PointPair {
  Vec3 first;
  Vec3 second;
};

/// How often a defect occurs, and where its first occurrences are.
/// `locations` holds the first min(count, DiagnoseOptions::max_locations) occurrences in increasing
/// order of the lowest facet (or, for vertex defects, vertex) index involved.
template <class Location>
struct Occurrences {
  std::size_t count = 0;
  std::vector<Location> locations;

  /// True when nothing was found.
  bool empty() const { return count == 0; }
};

/// A connected shell: facets with area joined through shared edges (an edge shared by any number
/// of facets, non-manifold ones included, joins them all). Zero-area facets belong to no shell.
struct ShellReport {
  std::size_t num_facets = 0;
  FacetIndex first_facet = 0;  ///< lowest facet index of the shell; shells are listed in this order
  /// Every edge of the shell is used an even number of times by the shell's facets (no open edge).
  bool is_closed = false;
  /// Every edge of the shell is run as often in one direction as in the other, so the winding
  /// number around the shell is well defined (closed and consistently oriented).
  bool is_balanced = false;
  /// Sum of the signed tetrahedra (origin, a, b, c) over the shell's facets, accumulated exactly
  /// and rounded once; a true enclosed volume only when `is_balanced`.
  double signed_volume_mm3 = 0.0;
  /// Balanced shell with negative volume whose bounding box lies strictly inside that of a
  /// balanced shell with positive volume: taken as a cavity (the inner wall of a hollow part).
  bool is_cavity = false;
  /// Balanced shell with negative volume that is not a cavity: its facets face inwards.
  bool is_inverted = false;
};

/// The overall judgement of a mesh for slicing under SPEC §2.
enum class Verdict {
  /// Closed, consistently oriented, no non-manifold edge or vertex, no self-intersection, no
  /// duplicate, degenerate facet or inverted shell.
  Printable,
  /// Every edge is balanced (MeshReport::unbalanced_edges is empty), so the winding number is
  /// defined everywhere and the `nonzero` fill rule slices the mesh as intended, around
  /// duplicate or degenerate facets, non-manifold edges or vertices, inverted shells, shells
  /// that overlap or intersect, and cracks sealed by zero-area facets.
  PrintableUnderRule,
  /// Some edge is not balanced (open edges, inconsistently oriented neighbours, a facet repeated
  /// without its reverse): the inside of the solid is not defined there. A single duplicated
  /// facet is such a case: its edges are run twice one way and once the other.
  NeedsRepair,
};

/// "printable", "printable-under-rule" or "needs-repair".
const char* verdict_name(Verdict verdict);

/// Diagnostics of one mesh, as `strata check` prints them; see diagnose_mesh().
/// All counts refer to the exactly welded mesh (vertices merged only when all three coordinates
/// are equal); facet indices are those of the input file, starting at 0. Edges, shells and
/// duplicates are those of the facets with area, as repair tools see the mesh once zero-area
/// facets are dropped; only `unbalanced_edges` (and so the verdict) takes every facet, since a
/// zero-area facet can seal a crack (a T-junction) for the slicer's topology.
struct MeshReport {
  // ---- size and measures
  std::size_t num_input_facets = 0;  ///< facets in the soup as read
  std::size_t num_facets = 0;        ///< facets of the indexed mesh (all input facets are kept)
  std::size_t num_vertices = 0;      ///< distinct vertices after the exact weld
  Bbox3 bounds;                      ///< of the welded vertices; empty() for an empty mesh
  double surface_area_mm2 = 0.0;     ///< sum of the facet areas, in double
  /// Sum of the signed tetrahedra over all facets, accumulated exactly, rounded once to nearest.
  double volume_mm3 = 0.0;

  // ---- vertices
  double near_vertex_tolerance_mm = 0.0;  ///< the distance used for near_vertices
  /// Pairs of distinct vertices closer than near_vertex_tolerance_mm (cracks that an exact weld
  /// does not close).
  Occurrences<PointPair> near_vertices;
  bool near_vertices_truncated = false;  ///< the search stopped at its work limit
  /// Vertices whose facets with area do not form one edge-connected fan (two cones touching at
  /// their tips). A vertex on a non-manifold edge is reported through the edge, not here.
  Occurrences<Vec3> non_manifold_vertices;

  // ---- facets
  /// Zero-area facets: two equal vertices, or three collinear ones (exact test).
  Occurrences<FacetIndex> degenerate_facets;
  /// Extra copies of a facet with area with the same three vertices, in either orientation (the
  /// first copy is not counted; the locations are the extra copies).
  Occurrences<FacetIndex> duplicate_facets;

  // ---- edges (undirected edges between two distinct vertices) of the facets with area
  Occurrences<EdgeLocation> boundary_edges;      ///< edges used by exactly one facet (open)
  std::size_t num_boundary_loops = 0;            ///< connected components formed by boundary edges
  Occurrences<EdgeLocation> non_manifold_edges;  ///< edges used by more than two facets
  /// Edges used by exactly two facets that run it in the same direction.
  Occurrences<EdgeLocation> inconsistent_edges;
  /// Edges used a different number of times in each direction, counting every facet, zero-area
  /// ones included. None exactly when the facets form a closed cycle, so that the winding
  /// number is defined everywhere off the surface.
  Occurrences<EdgeLocation> unbalanced_edges;

  // ---- shells
  std::vector<ShellReport> shells;  ///< every shell, by first facet
  std::size_t num_closed_shells = 0;
  Occurrences<std::size_t> inverted_shells;  ///< indices into `shells`

  // ---- stored normals (STL); not checked when the soup has none
  bool normals_checked = false;
  /// Finite, non-zero stored normals pointing against the vertex order: dot(stored, (b-a)x(c-a))
  /// < 0, evaluated exactly.
  Occurrences<FacetIndex> flipped_normals;
  Occurrences<FacetIndex> zero_normals;        ///< stored normal (0, 0, 0)
  Occurrences<FacetIndex> non_finite_normals;  ///< stored normal with NaN or infinity

  // ---- self-intersections
  bool self_intersections_checked = false;
  /// Pairs of facets with area that intersect other than along a shared edge or at a shared
  /// vertex (exact predicates; shared means the same welded vertex). Two facets sharing an edge
  /// intersect when they are coplanar and on the same side of it. Duplicate facets are counted
  /// as duplicates, not here.
  Occurrences<FacetPair> self_intersections;
  /// The search stopped at a limit of DiagnoseOptions; `self_intersections.count` is then a
  /// lower bound.
  bool self_intersections_truncated = false;

  // ---- judgement
  Verdict verdict = Verdict::Printable;
  std::string verdict_reason;  ///< one line, e.g. "52 open edges in 2 loops"
};

}  // namespace strata::diagnose
