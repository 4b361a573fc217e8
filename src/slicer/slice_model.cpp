#include "strata/slicer/slice_model.hpp"

#include <fmt/format.h>

#include "slicer/fast_kernel_internal.hpp"
#include "strata/core/internal_failure.hpp"
#include "winding/winding_kernel.hpp"

namespace strata {

namespace {

void add_winding_diagnostics(const detail::WindingKernel& kernel, SliceSummary& summary) {
  const winding::BoundaryCaps& caps = kernel.caps();
  if (caps.boundary_edges == 0) {
    summary.diagnostics.push_back(
        {Severity::Info, "winding.closed",
         "fill rule winding: the mesh has no boundary, so its winding number is the integer the "
         "crossing rule gives and every cell was decided exactly"});
    return;
  }
  summary.diagnostics.push_back(
      {Severity::Info, "winding.caps",
       fmt::format("fill rule winding: {} boundary edges in {} components were capped; the caps' "
                   "winding number was approximated hierarchically and evaluated again for {} "
                   "cells within {} of 1/2",
                   caps.boundary_edges, caps.components, kernel.guard_evaluations(),
                   detail::WindingKernel::kGuardBand)});
}

}  // namespace

Result<SliceSummary> slice_model(const IndexedMesh& mesh, const GridSpec& grid,
                                 const SliceOptions& options, std::span<LayerSink* const> sinks,
                                 const ProgressCallback& progress) {
  // run_slice turns a failure while slicing into an Error; building a kernel may fail too, before
  // any sink has begun.
  return catch_internal_failure(
      "fast path",
      [&]() -> Result<SliceSummary> {
        if (options.fill_rule == FillRule::Winding) {
          detail::WindingKernel kernel(mesh, grid, options);
          auto summary = run_slice(mesh, grid, options, kernel, sinks, progress);
          if (summary) add_winding_diagnostics(kernel, *summary);
          return summary;
        }
        detail::FastKernel kernel(mesh, grid, options);
        return run_slice(mesh, grid, options, kernel, sinks, progress);
      },
      [] {});
}

}  // namespace strata
