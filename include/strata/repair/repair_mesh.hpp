#pragma once

#include <cstddef>

#include "strata/core/result.hpp"
#include "strata/mesh/triangle_soup.hpp"
#include "strata/repair/repair_log.hpp"

namespace strata::repair {

/// What repair_mesh() may do beyond the steps it always takes.
struct RepairOptions {
  /// Close cracks at T-junctions by splitting the facet on the long side (step 4).
  bool close_t_junctions = true;
  /// Fill holes (loops of border edges) with triangles between their own vertices (step 7).
  bool fill_holes = false;
  /// Holes with more border edges than this are left open and counted as not filled.
  std::size_t max_hole_edges = 5000;
};

/// The repaired mesh and what was done to it.
struct RepairResult {
  /// The repaired facets: the kept input facets first, in input order (a split facet's pieces
  /// in its place), then the facets that fill holes. Every coordinate is one of the input's
  /// (no point is moved or created). `stored_normals` is empty; `format` is "repaired";
  /// `diagnostics` are the input's.
  TriangleSoup soup;
  RepairLog log;
};

/// Repairs a triangle soup for slicing, in this order:
/// 1. weld corners with exactly equal coordinates (never near ones, SPEC §2b);
/// 2. remove zero-area facets (exact collinearity test);
/// 3. remove duplicate facets (same three vertices in either orientation): one copy is kept, in
///    the orientation most copies have (the first copy's on a tie). When the copies cancel (as
///    many one way as the other, e.g. the shared wall of two boxes that touch), the last copy
///    goes too unless that leaves an edge used by a single facet; this merges two solids that
///    touch along a wall and never opens a hole;
/// 4. close cracks at T-junctions (RepairOptions::close_t_junctions): an open edge a-b facing a
///    chain of open edges a-c-...-b whose inner vertices lie exactly on the segment (exact
///    predicates) is closed by splitting the facet on the a-b side at c, ...; the pieces cover
///    the same triangle with the same orientation, so the enclosed volume does not change;
/// 5. orient (CGAL orient_polygon_soup): vertices where shells touch and ends of non-manifold
///    edges are split in the topology, and in each connected shell the smaller set of facets is
///    turned over so that neighbours agree;
/// 6. stitch border edges that coincide (CGAL stitch_borders);
/// 7. when asked, fill each hole with CGAL triangulate_hole: triangles between the hole's own
///    border vertices (no vertex added, no degenerate triangle; a 2D constrained Delaunay
///    triangulation for near-planar holes, else the minimum-area/dihedral search in a 3D
///    Delaunay space, falling back to the cubic search for holes of up to 300 edges). Only loops
///    whose every edge is used by one facet are holes; a loop along an edge other facets use (a
///    seam where step 5 cut a non-manifold edge) is counted apart and never filled. A hole is
///    left open and counted when it has more than max_hole_edges edges or no triangulation, or
///    when its patch would repeat an existing facet or run a new edge where the mesh already has
///    one (a hole passing twice through one point), which would make that edge non-manifold.
///    The patch is not checked against the rest of the surface: around an island, or on a
///    strongly curved border, it may cross other facets (the slicer's nonzero rule copes; the
///    diagnostics of the result count such crossings);
/// 8. orient closed shells to bound a volume (CGAL volume_connected_components with
///    self-intersection tests, as orient_to_bound_a_volume does): a shell nested in an odd number
///    of others faces in (a cavity), any other shell faces out; shells that intersect themselves
///    are judged by the sign of their exact volume instead. Open shells bound nothing and are
///    left as they are (the log says how many).
///
/// Exact predicates decide every test (CGAL Epick on the input's double coordinates; only the
/// choice among the triangulations of a hole weighs areas and angles in double); no coordinate is
/// computed, so the output holds only input points and reads back bit-identically
/// from a binary STL (float32 input). The input is not modified.
/// Repairing the output again changes no facet (RepairLog::changed_anything() is false); only
/// counts that describe the mesh rather than a change come back (merged points, split
/// non-manifold vertices, holes and seams left open).
///
/// @return the repaired soup and its log; Error{BadInput} for a non-finite coordinate (location
///         "facet N"); Error{Internal} when CGAL fails (message says where).
/// Complexity: O(n log n) for steps 1 to 6; step 7 is cubic in the size of a hole in the worst
/// case (holes are first tried with a Delaunay search space); step 8 runs a self-intersection
/// search over the closed shells (O(n log n + k) for k pairs of overlapping facet boxes).
Result<RepairResult> repair_mesh(const TriangleSoup& soup, const RepairOptions& options = {});

}  // namespace strata::repair
