#pragma once

#include <cstdint>
#include <span>

#include "strata/core/result.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/pipeline/run_slice.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata {

/// What the exact path did to read the mesh as a polygon soup, and where each layer's contours
/// came from.
struct ExactSliceReport {
  std::uint64_t input_points = 0;    ///< vertices of the mesh handed in
  std::uint64_t input_polygons = 0;  ///< its facets
  /// Points repair_polygon_soup removed: copies of exactly equal coordinates merged (an unwelded
  /// mesh) and points no facet uses.
  std::uint64_t points_merged = 0;
  /// Polygons repair_polygon_soup removed: facets with a repeated corner, duplicate facets (either
  /// orientation; one of each group is kept).
  std::uint64_t polygons_removed = 0;
  /// Points orient_polygon_soup added to split non-manifold vertices and edges.
  std::uint64_t points_duplicated = 0;
  /// Polygons orient_polygon_soup turned over to make the orientation consistent. The slice
  /// itself always uses the facets' own vertex order (SPEC §2); this only says how consistent the
  /// input was.
  std::uint64_t polygons_reversed = 0;
  /// Edges orient_polygon_soup found shared by more than two polygons.
  std::uint64_t non_manifold_edges = 0;
  /// True when the repaired, oriented soup is a polygon mesh (then held as a halfedge structure).
  bool polygon_mesh = false;
  /// Layers whose contours were chained through the halfedge structure.
  std::uint32_t halfedge_layers = 0;
  /// Layers whose contours came from the exact 2D arrangement of their segments (the soup is not
  /// a polygon mesh, a chain did not close, facets there were removed by the repair, or their
  /// orientations disagree).
  std::uint32_t arrangement_layers = 0;
  /// Layers that no facet crosses.
  std::uint32_t empty_layers = 0;
};

/// Slices a mesh with the exact path, the oracle the fast path is checked against, and streams
/// every classified layer to the sinks in order (through run_slice, so the shell step, batching
/// and sinks are the fast path's).
///
/// Cells: every decision of SPEC §2's inside rule is taken on exact rational values (the crossing
/// points of the facets' edges with the plane, the scanline crossings) compared with the grid's
/// double values; hatches are the exact crossings rounded once to double.
/// Contours: the facets are read as a soup into CGAL, repaired (repair_polygon_soup) and oriented
/// (orient_polygon_soup, which may duplicate non-manifold vertices; the input is never refused).
/// When the result is a polygon mesh, each layer's exact crossing points are chained face to face
/// through the halfedge structure, every segment keeping the direction its own facet's vertex
/// order gives. Otherwise, or when a chain does not close or the directions disagree, the layer's
/// contours are the boundaries of the region the fill rule makes solid, computed on the exact
/// 2D arrangement of the segments with winding numbers from their directions: overlapping,
/// touching and T-junction segments are resolved exactly, outer loops come counter-clockwise and
/// holes clockwise. Where the segments do not close up (open or duplicated facets) every dangling
/// end point is joined by a horizontal edge leftwards to just left of the layer, which is where
/// the +x crossing rule of SPEC §2 makes the cells change class; such layers also count their
/// open chains. Contour points are exact values rounded once to double.
///
/// @param report when not null, receives what the soup repair did and the per-layer methods
/// @return the summary; Error{Usage} for FillRule::Winding; Error{BadInput} for a mesh with
///         non-finite coordinates or vertex indices out of range; Error{Internal} when CGAL or an
///         invariant fails (every sink is aborted then); or the first sink error.
/// Thread safety: layers are computed in parallel (options.threads); nothing global is installed.
Result<SliceSummary> slice_model_exact(const IndexedMesh& mesh, const GridSpec& grid,
                                       const SliceOptions& options,
                                       std::span<LayerSink* const> sinks,
                                       const ProgressCallback& progress = {},
                                       ExactSliceReport* report = nullptr);

}  // namespace strata
