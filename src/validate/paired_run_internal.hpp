#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "strata/contour/contour.hpp"
#include "strata/core/result.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/pipeline/run_slice.hpp"

namespace strata::validate::detail {

/// A layer one path delivered, kept until the other path delivers the same k.
struct HeldLayer {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  std::vector<CellClass> cells;
  LayerContours contours;
  std::vector<HatchSegment> hatches;  ///< left empty: the comparison does not read them

  LayerResult view() const { return LayerResult{layer, z_mm, cells, contours, hatches}; }
};

/// Runs a slicing call with the given sinks (slice_model or slice_model_exact, bound to the mesh,
/// grid and options).
using SliceCall = std::function<Result<SliceSummary>(std::span<LayerSink* const> sinks)>;

/// Called with the two paths' layer k when both have delivered it, or with one of them null
/// when the other path ended without it. Calls come in increasing k. A layer that was held while
/// the other path caught up comes without its hatches.
using PairCallback = std::function<void(const LayerResult* a, const LayerResult* b)>;

struct PairedOutcome {
  Result<SliceSummary> a = Error{ErrorCode::Internal, "not run", {}};
  Result<SliceSummary> b = Error{ErrorCode::Internal, "not run", {}};
  double seconds_a = 0.0;  ///< a's own work (waiting and the callbacks not counted)
  double seconds_b = 0.0;
};

/// Runs two slicing calls in two threads that take turns, so that only one computes at any time:
/// b runs first until it is ready to deliver layers (its own preparation, timed alone), then a
/// runs until it holds `window` layers that b has not delivered yet, then b until it holds
/// `window` layers a has not delivered, and so on; a path whose partner has ended runs on alone.
/// Each layer pair is handed to `on_pair` as soon as both halves exist, then dropped.
/// An exception thrown by on_pair stops both runs with Error{Internal}.
PairedOutcome run_paired(const SliceCall& a, const SliceCall& b, const PairCallback& on_pair,
                         std::uint32_t window);

}  // namespace strata::validate::detail
