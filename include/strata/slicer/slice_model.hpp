#pragma once

#include <span>

#include "strata/core/result.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/pipeline/run_slice.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata {

/// Slices a mesh on a grid with the fast path and streams every layer, classified, to the sinks
/// in order. Only the window of layers the shell reaches is held in memory.
/// Under FillRule::Winding the cells come from the generalized winding number (src/winding)
/// instead of the crossing rule; contours and open chains are the same as under the others.
/// Layers whose chained loops are not simple take the exact path's outline
/// (exact::outline_contours) under nonzero and evenodd.
/// @return the summary; or the first sink error; or Error{Internal} when a worker fails (every
///         sink is aborted then).
Result<SliceSummary> slice_model(const IndexedMesh& mesh, const GridSpec& grid,
                                 const SliceOptions& options, std::span<LayerSink* const> sinks,
                                 const ProgressCallback& progress = {});

}  // namespace strata
