#pragma once

#include <cstddef>
#include <cstdint>

#include "strata/pipeline/run_slice.hpp"

namespace strata::validate {

/// Limits and tolerances of a cross-validation run (validate_model, SliceComparison). The
/// defaults suit `strata validate`; every limit only bounds what is listed or sampled, never
/// what is counted.
struct ValidateOptions {
  /// Differing cells, and cells changed by the scan offset, listed with their position (the
  /// first ones in (k, j, i) order); all of them are counted.
  std::size_t max_listed_cells = 1000;
  /// Cells changed by the scan offset that are remembered to explain differences between the
  /// paths (in (k, j, i) order); beyond this, a differing cell is only checked for the other
  /// reasons.
  std::size_t max_remembered_offset_cells = 10'000'000;
  /// Points sampled on the mesh surface for the one-sided Hausdorff distance to the boundary
  /// cells: every vertex, then edge midpoints and centroids of every s-th facet, s chosen so
  /// that the total stays within this budget.
  std::size_t max_surface_samples = 200'000;
  /// Interior cells next to the shell whose distance to the surface is measured: all of them,
  /// or a uniform sample of this many (reservoir sampling with a fixed seed).
  std::size_t max_shell_samples = 100'000;
  /// Boundary cells remembered for the surface Hausdorff distance; when the fast path has more,
  /// that distance is not computed (and the report says so).
  std::size_t max_boundary_cells = 20'000'000;
  /// A decision lies "within rounding of a tie" when the quantities it compares differ by at
  /// most this fraction of the model's coordinate scale (the largest absolute coordinate or the
  /// bounding box diagonal, whichever is larger).
  double near_tie_relative = 1e-9;
  /// Compare the contours of every layer (symmetric difference and Hausdorff distance). The
  /// loop counts are compared either way.
  bool compare_contours = true;
  /// The exact overlay is the costly part of the contour comparison. When this is not 0, layers
  /// whose contours differ only within the near-tie tolerance (same loop counts, Hausdorff
  /// distance at most near_tie_relative times the model's scale) are overlaid only for about
  /// this many layers spread evenly over the grid; the others are marked
  /// AreaMethod::NotCompared. Layers with larger differences are always overlaid.
  std::uint32_t max_overlay_layers = 0;
  /// Also slice with CGAL's Polygon_mesh_slicer (exact kernel) and compare its contours with
  /// both paths' (ReferenceSlicerFigures), when the mesh is a closed, consistently oriented
  /// 2-manifold with at most reference_max_facets facets.
  bool reference_slicer = true;
  std::size_t reference_max_facets = 200'000;
  /// Layers a path may run ahead of the other before it waits (0: chosen from the layer size).
  std::uint32_t window_layers = 0;
  /// Told the layers compared so far out of nz (called from the slicing threads, one at a time).
  ProgressCallback progress;
};

}  // namespace strata::validate
