#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "strata/contour/contour.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"
#include "strata/validate/validate_options.hpp"
#include "strata/validate/validation_report.hpp"

namespace strata::validate::detail {

/// One plane's section by CGAL's Polygon_mesh_slicer, as strata contours.
struct ReferenceSection {
  /// Closed loops (outer counter-clockwise, holes clockwise, as the facets' orientation gives),
  /// chains left open, and single points (LoopKind::Open, one point each). Points are the exact
  /// intersection points rounded once to the nearest double.
  std::vector<Contour> contours;
  std::uint32_t closed_polylines = 0;  ///< as CGAL returned them
  std::uint32_t open_polylines = 0;
  std::uint32_t isolated_points = 0;
  std::uint32_t open_after_joining = 0;
};

/// Joins open chains end to start where an end point equals a start point (CGAL cuts its
/// polylines at vertices on the plane where more than two of them meet; each piece keeps the
/// orientation of its facets, so the pieces of a loop follow each other). A chain that comes back
/// to its first point becomes a closed contour (that point not repeated, Outer when
/// counter-clockwise, Hole otherwise); the others stay open (LoopKind::Open), each counted in
/// `out.open_after_joining`. Chains are taken in order, each joined to the first unused chain that
/// starts where it ends.
void join_chains(std::vector<std::vector<Point2>> chains, ReferenceSection& out);

/// CGAL's Polygon_mesh_slicer with the exact kernel (Epeck) over a CGAL::Surface_mesh of the
/// mesh, built once when the mesh is a closed, consistently oriented 2-manifold.
///
/// The mesh qualifies when, once its facets with a repeated corner are left out, the facets form
/// a polygon mesh as they are (CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh: no
/// non-manifold edge or vertex, neighbours oriented alike; orient_polygon_soup, on a copy, tells
/// which of the two fails) and the Surface_mesh is closed (CGAL::is_closed).
class ReferenceSlicer {
 public:
  /// Checks the mesh and builds the Surface_mesh and the AABB tree of its edges. Never throws:
  /// a refused mesh, or a CGAL error, leaves ready() false with the reason in figures().
  /// @param max_facets  meshes with more facets are refused without being looked at
  /// The mesh must outlive the slicer.
  ReferenceSlicer(const IndexedMesh& mesh, std::size_t max_facets);
  ~ReferenceSlicer();
  ReferenceSlicer(const ReferenceSlicer&) = delete;
  ReferenceSlicer& operator=(const ReferenceSlicer&) = delete;

  bool ready() const;
  /// skipped, reason, facets, max_facets, degenerate_facets_dropped, build_seconds.
  const ReferenceSlicerFigures& figures() const;

  /// The section by the plane z = z_mm (an exact double): CGAL's polylines with their closing
  /// point dropped, open ones joined end to start where they meet. Throws what CGAL throws.
  /// @pre ready()
  ReferenceSection slice(double z_mm) const;

  /// Vertices of the sliced mesh with z == z_mm exactly, and whether one of its facets lies in
  /// that plane.
  std::uint32_t vertices_on_plane(double z_mm) const;
  bool facet_on_plane(double z_mm) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Runs the reference slicer on every layer both paths deliver and compares its contours with
/// theirs (validate_model's helper). Not thread-safe; calls come one at a time.
class ReferenceComparison {
 public:
  /// Builds the slicer when validate_options.reference_slicer is on (timed in build_seconds).
  ReferenceComparison(const IndexedMesh& mesh, const GridSpec& grid, const SliceOptions& options,
                      const ValidateOptions& validate_options);
  ~ReferenceComparison();
  ReferenceComparison(const ReferenceComparison&) = delete;
  ReferenceComparison& operator=(const ReferenceComparison&) = delete;

  /// Layer k of either path or both (the same k); nothing when the slicer is not ready. A CGAL
  /// error stops the reference slicer (skipped = Failed, with the layer and message).
  void add_layer(const LayerResult* fast, const LayerResult* exact);

  ReferenceSlicerFigures finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace strata::validate::detail
