#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"

namespace strata::repair {

/// Why an input facet was removed or changed by repair_mesh().
enum class FacetChangeKind {
  /// Zero area (two equal corners, or three collinear ones; exact test): removed.
  RemovedDegenerate,
  /// A further copy of a facet with the same three corners: removed (one copy is kept).
  RemovedDuplicate,
  /// The last copy of a set of copies whose orientations cancel (as many one way as the other),
  /// removed with them because no edge is left used by a single facet without it: the wall
  /// between two solids that touch along it.
  RemovedCancellingDuplicate,
  /// An edge of the facet was a crack closed at a T-junction: the facet was replaced by pieces
  /// (same plane, same area, same orientation) that end at the vertices lying on that edge.
  SplitAtTJunction,
  /// Turned over (vertex order reversed) so that its shell is consistently oriented or bounds a
  /// volume. A facet may also have been split; both changes are then listed.
  Flipped,
};

/// How many facet changes repair_log_json() and repair_log_text() list (the first ones).
inline constexpr std::size_t kMaxChangesListed = 20;

/// One removed or changed input facet.
struct FacetChange {
  FacetIndex facet = 0;  ///< index in the input soup, from 0
  FacetChangeKind kind = FacetChangeKind::RemovedDegenerate;
};

/// "removed-degenerate", "removed-duplicate", "removed-cancelling-duplicate",
/// "split-at-t-junction" or "flipped".
const char* facet_change_name(FacetChangeKind kind);

/// What repair_mesh() did, step by step, in the order the steps run. Facet indices are those of
/// the input soup. Every input facet is either kept (possibly flipped or split) or removed:
/// `input_facets == kept_input_facets + degenerate_facets_removed + duplicate_facets_removed +
/// cancelling_duplicates_removed`, and `output_facets == kept_input_facets +
/// t_junction_facets_added + hole_facets_added`.
struct RepairLog {
  // ---- input
  std::size_t input_facets = 0;
  /// Distinct vertices of the input (corners merged by exact equality of their coordinates, as
  /// `strata check` counts them).
  std::size_t input_vertices = 0;

  // ---- 1. exact weld
  /// Facet corners merged into a vertex they coincide with exactly: 3 * input_facets -
  /// input_vertices. An STL file stores every vertex once per facet, so this is large for any
  /// STL and says nothing about defects.
  std::size_t points_merged = 0;

  // ---- 2. degenerate facets
  std::size_t degenerate_facets_removed = 0;

  // ---- 3. duplicate facets (same three vertices, either orientation)
  /// Further copies removed; for each set of copies one is kept, in the orientation that most of
  /// the copies have (the first copy's on a tie).
  std::size_t duplicate_facets_removed = 0;
  /// Sets of copies with as many copies in each orientation (the winding number does not see
  /// them) whose last copy was removed too, because that leaves no edge used by a single facet.
  std::size_t cancelling_duplicates_removed = 0;

  // ---- 4. T-junctions
  /// Open edges a-b whose other side is a chain of open edges a-c-...-b through vertices lying
  /// exactly on the segment (a crack at a T-junction, often sealed by a zero-area facet that
  /// step 2 removed): the facet on the a-b side is split at c, ... and the crack is closed.
  std::size_t t_junctions_closed = 0;
  std::size_t t_junction_facets_added = 0;  ///< pieces minus the facets they replace

  // ---- 5. orientation (CGAL orient_polygon_soup)
  /// Vertices whose facets form several fans (shells touching at a vertex, ends of non-manifold
  /// edges): given one copy per fan so that the facets form a polygon mesh. The copies have the
  /// same coordinates, so a written STL file (which shares nothing) holds the same points.
  std::size_t non_manifold_vertices_split = 0;
  std::size_t vertex_copies_added = 0;  ///< the copies made for those splits
  /// Edges used by more than two facets: the facets around such an edge are not joined through
  /// it (each shell keeps its own copy of the edge).
  std::size_t non_manifold_edges = 0;
  /// Facets turned over so that each shell is consistently oriented; in each shell the smaller
  /// set of facets is turned over.
  std::size_t facets_flipped_for_consistency = 0;
  /// The oriented facets form a polygon mesh (needed by steps 6 to 8); when false those steps
  /// were skipped.
  bool polygon_mesh = false;

  // ---- 6. stitching (CGAL stitch_borders)
  /// Pairs of border edges with the same end points merged into one edge.
  std::size_t borders_stitched = 0;

  // ---- 7. holes
  /// Closed loops of border edges after stitching whose every edge is used by one facet only
  /// (holes in the surface), found whether or not filling was asked.
  std::size_t holes_found = 0;
  /// Loops of border edges that run along an edge other facets use too: the seams where step 5
  /// kept the facets of a non-manifold edge apart. The surface is not open there; never filled.
  std::size_t seams_at_shared_edges = 0;
  bool fill_holes_requested = false;
  std::size_t holes_filled = 0;
  std::size_t hole_facets_added = 0;
  /// Holes that filling was asked for but that were left open: too many edges
  /// (RepairOptions::max_hole_edges), no triangulation found, or a patch that would repeat an
  /// existing facet or make an edge non-manifold.
  std::size_t holes_not_filled = 0;

  // ---- 8. volume orientation (CGAL volume_connected_components, as in orient_to_bound_a_volume)
  std::size_t closed_shells = 0;  ///< shells without border edges after hole filling
  std::size_t open_shells = 0;    ///< shells with border edges: they bound no volume
  /// Closed shells turned over as a whole so that outer walls face out and the walls of cavities
  /// face in.
  std::size_t shells_reoriented = 0;
  std::size_t facets_flipped_with_shells = 0;  ///< facets of those shells, pieces included
  /// True when every closed shell was checked. False when there was no closed shell or no
  /// polygon mesh; `volume_orientation_note` then says why.
  bool volume_orientation_done = false;
  /// Why the step was skipped, or what it did not cover (open shells left as they were); empty
  /// when it covered the whole mesh.
  std::string volume_orientation_note;

  // ---- output
  std::size_t output_facets = 0;
  std::size_t output_vertices = 0;  ///< distinct vertices of the output (exact weld)
  /// Input facets that are in the output (turned over, split or as they were).
  std::size_t kept_input_facets = 0;
  /// Input facets whose output orientation is the reverse of theirs (counted once, whatever
  /// the step).
  std::size_t facets_flipped = 0;

  /// Every removed or changed input facet, by increasing facet index (a facet both split and
  /// flipped appears twice).
  std::vector<FacetChange> changes;

  /// True when the repair changed the facets: something removed, split, flipped or added.
  bool changed_anything() const {
    return degenerate_facets_removed + t_junctions_closed + duplicate_facets_removed +
               cancelling_duplicates_removed + facets_flipped + hole_facets_added >
           0;
  }
};

}  // namespace strata::repair
