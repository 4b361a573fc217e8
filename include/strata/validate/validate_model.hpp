#pragma once

#include "strata/core/result.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"
#include "strata/validate/validate_options.hpp"
#include "strata/validate/validation_report.hpp"

namespace strata::validate {

/// Cross-validates the fast path (slice_model) against the exact path (slice_model_exact) on one
/// grid and measures the accuracy of the result (SPEC §5).
///
/// The two paths run in two threads that take turns: one computes while the other waits in its
/// sink, each running at most window_layers ahead of the other, so each path's time is its own
/// and only a few layers of each are held, however large the grid. Layer pairs are compared as
/// they meet (SliceComparison). When options.scan_offset_mm is not 0, the fast path is first run
/// with the offset and with offset 0 in the same way, to list the cells the offset changes.
///
/// When validate_options.reference_slicer is on and the mesh is a closed, consistently oriented
/// 2-manifold (at most reference_max_facets facets), CGAL's Polygon_mesh_slicer with the exact
/// kernel also cuts every layer's plane, and its contours are compared with both paths' as the
/// layer pairs meet (ValidationReport::reference; its time is its own, counted in neither path).
///
/// @param mesh  the welded mesh both paths slice
/// @param grid  the grid of both paths (make_grid)
/// @return the report; when the exact path refuses the model or fails, the report says why in
///         exact_error and covers the layers it delivered. Error{Usage} for --fill-rule winding
///         (no path implements it); the fast path's errors as they are.
/// Thread safety: starts two threads; the paths use options.threads workers each.
Result<ValidationReport> validate_model(const IndexedMesh& mesh, const GridSpec& grid,
                                        const SliceOptions& options,
                                        const ValidateOptions& validate_options = {});

}  // namespace strata::validate
