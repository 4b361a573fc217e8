#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "strata/core/diagnostic.hpp"
#include "strata/core/error.hpp"
#include "strata/exact/slice_exact.hpp"
#include "strata/mesh/vec3.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"
#include "strata/voxel/cell_class.hpp"

namespace strata::validate {

/// Why a cell's class differs between the fast and the exact path (SPEC §5). Reasons are tried
/// in this order and the first that applies is given.
enum class DifferenceReason : std::uint8_t {
  /// The cell is one that the scan offset changes (fast path with the offset vs without it).
  ScanOffset,
  /// Both paths make the cell solid and differ only in interior vs boundary, and a cell within
  /// the shell's reach differs in solidity: the shell step, shared by both paths, inherited it.
  Shell,
  /// A decision behind the cell lies within rounding of a tie: a vertex of a facet near the
  /// cell's row is within the tolerance of the layer plane, a segment end point is within it of
  /// the scanline, or a crossing is within it of the cell centre (ValidateOptions::
  /// near_tie_relative).
  NearDegenerate,
  /// The cell's class depends on the fill rule: nonzero and evenodd classify it differently (its
  /// winding number is neither 0 nor ±1), so overlapping, nested or repeated shells decide it.
  FillRule,
  /// None of the above.
  Unexplained,
};
inline constexpr std::size_t kDifferenceReasonCount = 5;

/// "scan-offset", "shell", "near-degenerate", "fill-rule" or "unexplained".
const char* to_string(DifferenceReason reason);

/// A cell on which the paths disagree.
struct CellDifference {
  std::uint32_t i = 0, j = 0, k = 0;
  CellClass fast = CellClass::Empty;
  CellClass exact = CellClass::Empty;
  DifferenceReason reason = DifferenceReason::Unexplained;
};

/// A cell whose class the scan offset changes (fast path, with the offset vs with offset 0).
struct OffsetChange {
  std::uint32_t i = 0, j = 0, k = 0;
  CellClass with_offset = CellClass::Empty;
  CellClass without_offset = CellClass::Empty;
};

/// Loop counts and area of one path's contours in one layer.
struct ContourCounts {
  std::uint32_t outer_loops = 0;
  std::uint32_t holes = 0;
  std::uint32_t open_chains = 0;
  std::uint32_t points = 0;
  double area_mm2 = 0.0;  ///< net signed area of the closed loops, as the path reports it
};

/// How the symmetric difference of a layer's two contour sets was measured.
enum class AreaMethod : std::uint8_t {
  /// The closed loops of both paths have the same directed edges (as multisets of double
  /// coordinates), so they bound the same region under any fill rule: the difference is 0.
  Identical,
  /// Exact overlay: the closed loops of both paths in one CGAL arrangement of Epeck segments,
  /// every face given the winding number of each path, the region of each path taken under the
  /// fill rule, the area of the faces in exactly one of them summed exactly and rounded once.
  Arrangement,
  /// The overlay failed (CGAL raised an error); only |area(fast) - area(exact)|, a lower bound of
  /// the symmetric difference, is given.
  AreaOnly,
  /// The overlay was not computed: contours were not compared (ValidateOptions::
  /// compare_contours is false), or they differ only at rounding level and the layer was beyond
  /// ValidateOptions::max_overlay_layers.
  NotCompared,
};

/// "identical", "arrangement", "area-only" or "not-compared".
const char* to_string(AreaMethod method);

/// Fast vs exact in one layer.
struct LayerComparison {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  ContourCounts fast;
  ContourCounts exact;
  /// Area of the symmetric difference of the two regions the closed loops bound under the fill
  /// rule, mm².
  double symmetric_difference_mm2 = 0.0;
  AreaMethod area_method = AreaMethod::Identical;
  /// Symmetric Hausdorff distance between the two contour sets (closed loops and open chains):
  /// the largest distance from a vertex of one set to the nearest segment (or lone point) of the
  /// other, both ways, mm. +infinity when one set is empty and the other is not.
  double hausdorff_mm = 0.0;
  std::uint64_t cells_differing = 0;

  /// Either path has open chains: the fast path leaves them open, the exact path closes them
  /// towards -x, so the contours are not comparable there.
  bool has_open_chains() const { return fast.open_chains > 0 || exact.open_chains > 0; }
};

/// One path's run over the whole model.
struct PathFigures {
  bool ran = false;  ///< false when the path refused the model or failed
  /// Wall time of the path's own work: both paths run in alternation (only one computes at a
  /// time), and the time spent waiting for the other and comparing is not counted.
  double seconds = 0.0;
  /// Cells by class: [0] empty, [1] interior, [2] boundary.
  std::array<std::uint64_t, 3> class_counts{};
  double cell_volume_mm3 = 0.0;     ///< solid cells * dx * dy * dz
  double contour_volume_mm3 = 0.0;  ///< sum over layers of the net contour area * dz
  std::uint64_t open_chains = 0;
  /// Extent of the solid cells (cell boxes, not centres), mm; empty() when no cell is solid.
  Bbox3 solid_bounds;
};

/// Distances from the centres of the interior cells that touch the shell to the mesh surface.
struct ShellThickness {
  /// Interior cells with a boundary 6-neighbour (all of them, counted).
  std::uint64_t cells = 0;
  /// Of which this many were measured (all, or a uniform sample; see ValidateOptions).
  std::uint64_t measured = 0;
  double min_mm = 0.0;
  double mean_mm = 0.0;
  double max_mm = 0.0;
};

/// Whole-model figures (SPEC §5), measured on the fast path's cells.
struct ModelFigures {
  /// Signed volume of the facets, accumulated exactly and rounded once (diagnose_mesh); the
  /// enclosed volume when the mesh is closed and consistently oriented.
  double mesh_volume_mm3 = 0.0;
  double surface_area_mm2 = 0.0;
  Bbox3 mesh_bounds;
  /// One-sided Hausdorff distance from the mesh surface to the centres of the boundary cells: the
  /// largest, over the surface samples, distance to the nearest boundary cell centre, mm.
  /// nullopt when it was not measured (no boundary cell, or too many of them).
  std::optional<double> surface_to_boundary_mm;
  std::uint64_t surface_samples = 0;
  /// The shell the fast path marked, measured from inside: for every interior cell that has a
  /// boundary 6-neighbour (all of them, or a uniform sample), the Euclidean distance from its
  /// centre to the nearest facet, in double. These are the innermost cells the shell does not
  /// cover, so the figures say how deep the shell reaches. In `distance` mode each value is at
  /// least t (a smaller one would be a cell the shell missed); and since the boundary neighbour,
  /// one step s away, is either closer than t to the surface or next to an empty cell (with the
  /// surface between their centres), each value is below max(t + s, 2 s), s being at most the
  /// largest cell size. In `layers` mode they show the thickness the rings actually give, in mm.
  ShellThickness shell;
  double asked_shell_mm = 0.0;
};

/// What the scan offset changes (SPEC §2: "Cross-validation reports every cell that the offset
/// changes").
struct ScanOffsetFigures {
  bool measured = false;  ///< the run had a non-zero --scan-offset
  double offset_mm = 0.0;
  std::uint64_t cells_changed = 0;
  std::vector<OffsetChange> cells;  ///< the first ValidateOptions::max_listed_cells
};

/// Why the reference slicer (ReferenceSlicerFigures) did not run.
enum class ReferenceSkip : std::uint8_t {
  None,           ///< it ran
  Off,            ///< turned off (ValidateOptions::reference_slicer)
  TooManyFacets,  ///< more facets than ValidateOptions::reference_max_facets
  Empty,          ///< no facet left
  NonManifold,    ///< edges or vertices shared in a way a 2-manifold cannot share them
  Inconsistent,   ///< a 2-manifold, but neighbouring facets are oriented against each other
  NotClosed,      ///< a 2-manifold with border edges
  Failed,         ///< CGAL raised an error while building or slicing
};

/// "none", "off", "too-many-facets", "empty", "non-manifold", "inconsistent-orientation",
/// "not-closed" or "failed".
const char* to_string(ReferenceSkip skip);

/// The reference slicer against both paths in one layer.
struct ReferenceLayerComparison {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  /// Polylines CGAL returned: closed ones (first point == last point), open ones, and single
  /// points (the plane touches the mesh at a vertex only).
  std::uint32_t closed_polylines = 0;
  std::uint32_t open_polylines = 0;
  std::uint32_t isolated_points = 0;
  /// Open polylines that are still open after joining them end to start at shared points (CGAL
  /// splits its polylines at vertices on the plane where more than two of them meet).
  std::uint32_t open_after_joining = 0;
  /// Mesh vertices exactly on the plane z = z_mm, and whether a facet lies in it.
  std::uint32_t vertices_on_plane = 0;
  bool facet_on_plane = false;
  /// Hausdorff distance (mm) and area of the symmetric difference of the regions under the fill
  /// rule (mm²), reference vs exact path and reference vs fast path. NaN when that path did not
  /// deliver the layer.
  double hausdorff_exact_mm = 0.0;
  double hausdorff_fast_mm = 0.0;
  double symmetric_difference_exact_mm2 = 0.0;
  double symmetric_difference_fast_mm2 = 0.0;
  AreaMethod area_method_exact = AreaMethod::Identical;
  AreaMethod area_method_fast = AreaMethod::Identical;
  /// The contours differ beyond the near-tie tolerance: Hausdorff distance above
  /// ValidateOptions::near_tie_relative times the model's scale, or a symmetric difference above
  /// that tolerance times the scale.
  bool differs_from_exact = false;
  bool differs_from_fast = false;

  /// True when some mesh vertex lies exactly on the layer's plane.
  bool vertex_on_plane() const { return vertices_on_plane > 0; }
};

/// An independent opinion on the contours: for a mesh that is a closed, consistently oriented
/// 2-manifold, the sections of CGAL's Polygon_mesh_slicer over a CGAL::Surface_mesh with the
/// exact kernel (Epeck), at every layer's plane z = zk, compared with both paths.
///
/// CGAL's slicer keeps a vertex on the plane on the plane (the polyline passes through it, a
/// vertex that only touches the plane gives a single point) and returns the boundary of facets
/// lying in the plane, where strata counts a vertex on the plane as above it (SPEC §2): in layers
/// whose plane contains a vertex the two may legitimately differ by such zero-area pieces or,
/// where a facet lies in the plane with the material above it, by that facet. The figures
/// therefore come twice: over the layers whose plane contains no mesh vertex (there, the
/// sections are the same exact points and must agree) and over every layer.
struct ReferenceSlicerFigures {
  bool ran = false;
  ReferenceSkip skipped = ReferenceSkip::Off;
  std::string reason;  ///< why it did not run (or stopped), for people; empty when it ran
  std::uint64_t facets = 0;
  std::uint64_t max_facets = 0;  ///< the cap it was given
  /// Facets with a repeated corner (a welded needle or point) left out of the Surface_mesh: they
  /// bound nothing.
  std::uint64_t degenerate_facets_dropped = 0;

  std::uint32_t layers_compared = 0;  ///< layers sliced and compared with at least one path
  std::uint32_t layers_vertex_on_plane = 0;
  std::uint32_t layers_facet_on_plane = 0;  ///< of those, layers where a facet lies in the plane
  /// Layers whose plane contains no vertex and whose contours differ from the path's (the goal
  /// is 0), and layers whose plane contains a vertex and whose contours differ (legitimate, see
  /// above).
  std::uint32_t layers_differing_exact = 0;
  std::uint32_t layers_differing_fast = 0;
  std::uint32_t layers_differing_exact_at_vertex = 0;
  std::uint32_t layers_differing_fast_at_vertex = 0;
  /// Of the layers whose plane contains no vertex, those whose regions differ (symmetric
  /// difference above the tolerance): contours may differ while bounding the same region, where
  /// a path gives the outline of crossing or touching loops.
  std::uint32_t layers_region_differing_exact = 0;
  std::uint32_t layers_region_differing_fast = 0;
  /// Of the layers whose plane contains no vertex, those the path outlined (its loops are open,
  /// cross, touch or are misnested, so its contours are the outline of the filled region, not
  /// the loops the slicer gives): compared by region only; a layer among them counts as
  /// differing when its region does, and its Hausdorff distance only in the "every layer" figures.
  std::uint32_t layers_outlined_exact = 0;
  std::uint32_t layers_outlined_fast = 0;
  /// Layers whose overlay was skipped (they differ at rounding level only; see
  /// ValidateOptions::max_overlay_layers).
  std::uint32_t layers_overlay_skipped = 0;

  std::uint64_t polylines = 0;
  std::uint64_t open_polylines = 0;
  std::uint64_t isolated_points = 0;
  std::uint64_t open_after_joining = 0;

  /// Over the layers whose plane contains no vertex (Hausdorff: and which the path did not
  /// outline).
  double max_hausdorff_exact_mm = 0.0;
  double max_hausdorff_fast_mm = 0.0;
  double max_symmetric_difference_exact_mm2 = 0.0;
  double max_symmetric_difference_fast_mm2 = 0.0;
  /// Over every layer.
  double max_hausdorff_exact_all_mm = 0.0;
  double max_hausdorff_fast_all_mm = 0.0;
  double max_symmetric_difference_exact_all_mm2 = 0.0;
  double max_symmetric_difference_fast_all_mm2 = 0.0;

  double build_seconds = 0.0;  ///< checking the mesh, building the Surface_mesh and AABB tree
  double slice_seconds = 0.0;  ///< slicing every layer and rounding the points
  double compare_seconds = 0.0;
  /// Build, slice and compare time together.
  double seconds() const { return build_seconds + slice_seconds + compare_seconds; }

  std::vector<ReferenceLayerComparison> layers;  ///< the compared layers, in order
};

/// The result of validate_model (SPEC §5): fast path vs exact path on one grid.
struct ValidationReport {
  GridSpec grid;
  SliceOptions options;
  PathFigures fast;
  PathFigures exact;
  /// Why the exact path did not run or stopped (it refused the model or failed); layers it did
  /// not deliver are not compared.
  std::optional<Error> exact_error;
  /// What the exact path did to read the mesh as a soup.
  ExactSliceReport exact_soup;

  std::vector<LayerComparison> layers;  ///< the compared layers, in order
  std::uint32_t layers_compared = 0;
  std::uint64_t cells_compared = 0;
  std::uint64_t cells_differing = 0;
  /// Differing cells by reason, indexed by DifferenceReason.
  std::array<std::uint64_t, kDifferenceReasonCount> differing_by_reason{};
  std::vector<CellDifference> differences;  ///< the first ValidateOptions::max_listed_cells

  /// Contours, over the layers without open chains (LayerComparison::has_open_chains): the
  /// largest and the total symmetric difference, the largest Hausdorff distance.
  double max_symmetric_difference_mm2 = 0.0;
  double total_symmetric_difference_mm2 = 0.0;
  double max_hausdorff_mm = 0.0;
  /// The same Hausdorff maximum over every layer, open chains included.
  double max_hausdorff_all_mm = 0.0;
  std::uint32_t layers_with_open_chains = 0;
  std::uint32_t layers_with_different_counts = 0;  ///< loop, hole or open-chain counts differ
  std::uint32_t layers_area_only = 0;              ///< AreaMethod::AreaOnly
  std::uint32_t layers_arrangement = 0;            ///< AreaMethod::Arrangement
  /// Layers whose contours differ at rounding level only and were not overlaid (AreaMethod::
  /// NotCompared with compare_contours on; see ValidateOptions::max_overlay_layers).
  std::uint32_t layers_overlay_skipped = 0;

  ScanOffsetFigures scan_offset;
  ModelFigures model;
  /// CGAL's Polygon_mesh_slicer against both paths (closed 2-manifolds only).
  ReferenceSlicerFigures reference;
  double comparison_seconds = 0.0;  ///< spent comparing layers and measuring the model
  /// Warnings of both paths and notes of the comparison (metrics that could not be measured).
  Diagnostics diagnostics;

  /// True when the exact path ran to the end and no cell differs.
  bool cells_agree() const { return !exact_error && cells_differing == 0; }
  /// exact.seconds / fast.seconds (0 when either did not run).
  double time_ratio() const {
    return fast.ran && exact.ran && fast.seconds > 0.0 ? exact.seconds / fast.seconds : 0.0;
  }
};

}  // namespace strata::validate
