#include "strata/validate/validate_model.hpp"

#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "strata/exact/slice_exact.hpp"
#include "strata/slicer/slice_model.hpp"
#include "strata/validate/slice_comparison.hpp"
#include "validate/paired_run_internal.hpp"
#include "validate/reference_slicer_internal.hpp"

namespace strata::validate {

namespace {

// Memory the layers held while one path waits for the other may take (one byte a cell).
constexpr double kWindowBytes = 256.0e6;
constexpr std::uint32_t kMaxWindowLayers = 64;

std::uint32_t window_layers(const GridSpec& grid, const ValidateOptions& vopts) {
  if (vopts.window_layers > 0) return vopts.window_layers;
  const double per_layer = static_cast<double>(std::max<std::uint64_t>(1, grid.cells_per_layer()));
  return static_cast<std::uint32_t>(
      std::clamp(kWindowBytes / per_layer, 2.0, static_cast<double>(kMaxWindowLayers)));
}

void fill_path(const SliceSummary& summary, double seconds, PathFigures& path) {
  path.ran = true;
  path.seconds = seconds;
  path.class_counts = summary.class_counts;
  path.cell_volume_mm3 = summary.solid_volume_mm3;
  path.contour_volume_mm3 = summary.contour_volume_mm3;
  path.open_chains = summary.open_chains;
}

}  // namespace

Result<ValidationReport> validate_model(const IndexedMesh& mesh, const GridSpec& grid,
                                        const SliceOptions& options,
                                        const ValidateOptions& validate_options) {
  if (options.fill_rule == FillRule::Winding) {
    return Error{ErrorCode::Usage,
                 "validate compares the paths under fill rule nonzero or evenodd; the exact path "
                 "does not implement winding (solid angles are not exact)",
                 {}};
  }
  SliceComparison comparison(mesh, grid, options, validate_options);
  const std::uint32_t window = window_layers(grid, validate_options);
  const auto fast_with = [&](const SliceOptions& o) {
    return [&mesh, &grid, o](std::span<LayerSink* const> sinks) {
      return slice_model(mesh, grid, o, sinks);
    };
  };

  if (options.scan_offset_mm != 0.0) {
    SliceOptions no_offset = options;
    no_offset.scan_offset_mm = 0.0;
    const detail::PairedOutcome offset_run = detail::run_paired(
        fast_with(options), fast_with(no_offset),
        [&](const LayerResult* with, const LayerResult* without) {
          if (with && without)
            comparison.add_scan_offset_layer(with->layer, with->cells, without->cells);
        },
        window);
    if (!offset_run.a) return offset_run.a.error();
    if (!offset_run.b) return offset_run.b.error();
  }

  // Built before both paths start, so that its time is its own.
  detail::ReferenceComparison reference(mesh, grid, options, validate_options);
  ExactSliceReport exact_soup;
  const detail::PairedOutcome run = detail::run_paired(
      fast_with(options),
      [&](std::span<LayerSink* const> sinks) {
        return slice_model_exact(mesh, grid, options, sinks, {}, &exact_soup);
      },
      [&](const LayerResult* fast, const LayerResult* exact) {
        // The comparison of the paths and the reference slicer's share nothing but the layers
        // they read: they run side by side, each still taking the layers in order. Isolated,
        // so that a thread waiting here takes no slicing task, whose layer would come back to
        // the sink that is waiting.
        tbb::this_task_arena::isolate([&] {
          tbb::parallel_invoke(
              [&] {
                if (fast && exact) {
                  comparison.add_layers(*fast, *exact);
                } else if (fast) {
                  comparison.add_fast_layer(*fast);
                }
              },
              [&] { reference.add_layer(fast, exact); });
        });
      },
      window);
  if (!run.a) return run.a.error();

  ValidationReport report = comparison.finish();
  report.exact_soup = exact_soup;
  report.reference = reference.finish();
  fill_path(run.a.value(), run.seconds_a, report.fast);
  Diagnostics diagnostics = run.a->diagnostics;
  if (run.b) {
    fill_path(run.b.value(), run.seconds_b, report.exact);
    for (const Diagnostic& d : run.b->diagnostics) {
      if (std::none_of(diagnostics.begin(), diagnostics.end(),
                       [&](const Diagnostic& x) { return x.message == d.message; })) {
        diagnostics.push_back(d);
      }
    }
  } else {
    report.exact_error = run.b.error();
  }
  diagnostics.insert(diagnostics.end(), report.diagnostics.begin(), report.diagnostics.end());
  report.diagnostics = std::move(diagnostics);
  return report;
}

}  // namespace strata::validate
