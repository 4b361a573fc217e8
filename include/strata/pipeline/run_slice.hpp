#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "strata/core/diagnostic.hpp"
#include "strata/core/result.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/pipeline/layer_kernel.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata {

/// Per-layer figures for the report and the diagnostics of SPEC §5 / issue 4.
struct LayerStats {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  std::uint32_t segments = 0;
  std::uint32_t outer_loops = 0;
  std::uint32_t holes = 0;
  std::uint32_t open_chains = 0;
  /// The chained loops cross or touch each other (issue 3 / issue 4 item 4).
  bool loops_cross = false;
  /// The chained loops nest without alternating in orientation.
  bool misnested = false;
  /// The closed contours are the outline of the filled region, not the chained loops.
  bool outline = false;
  double contour_area_mm2 = 0.0;
  std::uint64_t interior = 0;
  std::uint64_t boundary = 0;
};

/// An open chain left in a layer: where it starts and ends.
struct OpenChainReport {
  std::uint32_t layer = 0;
  Point2 start;
  Point2 end;
  std::uint32_t segments = 0;
};

/// What a slice run made: counts by class, volumes, contour figures, per-layer statistics.
struct SliceSummary {
  GridSpec grid;  ///< the grid sliced
  /// The layers sliced (SliceOptions::layers resolved); the counts below cover these alone.
  LayerSpan range;
  /// False when no sink needed cells and SliceOptions::always_classify was off: the class counts
  /// and the solid volume are then 0, the contours and segments as always.
  bool cells_classified = true;
  /// Cells by class: [0] empty, [1] interior, [2] boundary.
  std::array<std::uint64_t, 3> class_counts{};
  double solid_volume_mm3 = 0.0;    ///< (interior + boundary) * dx * dy * dz
  double contour_volume_mm3 = 0.0;  ///< sum of layer contour areas * dz
  std::uint64_t segments = 0;
  std::uint64_t open_chains = 0;
  std::uint32_t crossing_loop_layers = 0;  ///< layers whose chained loops cross or touch
  std::uint32_t misnested_layers = 0;      ///< layers whose loops nest without alternating
  std::uint32_t outline_layers = 0;        ///< layers whose contours are the outline
  std::uint64_t exact_fallbacks = 0;  ///< decisions the double filter handed to exact arithmetic
  std::vector<LayerStats> layers;     ///< one per layer of `range`, in order
  std::vector<OpenChainReport> open_chain_reports;  ///< the first 1000
  Diagnostics diagnostics;
  double seconds = 0.0;
};

/// Reports progress: layers done out of the total.
using ProgressCallback = std::function<void(std::uint32_t done, std::uint32_t total)>;

/// The engine: runs any kernel over the layers of options.layers (all by default) in batches,
/// marks the shell (on `mesh`, which the kernel slices) and streams every classified layer to the
/// sinks in order, holding only the shell window. For a range the kernel also computes the layers
/// within the shell's reach around it, whose cells are read but not sent.
/// @return the summary; Error{Usage} when options.layers does not fit the grid (before any sink
///         begins); the first sink error; or Error{Internal} when the kernel, the shell step
///         or a sink throws, on any thread (the kernel's name() begins the message). Every sink is
///         aborted on any failure.
Result<SliceSummary> run_slice(const IndexedMesh& mesh, const GridSpec& grid,
                               const SliceOptions& options, LayerKernel& kernel,
                               std::span<LayerSink* const> sinks,
                               const ProgressCallback& progress = {});

}  // namespace strata
