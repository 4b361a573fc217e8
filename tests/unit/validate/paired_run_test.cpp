// The two paths taking turns: pairs in order, lone layers when a path ends early, the window that
// hands the turn over, and failures on either side.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "validate/paired_run_internal.hpp"

namespace strata::validate::detail {
namespace {

/// A slicing call that delivers the layers `ks` (in that order) to its sinks, a 2 x 1 grid each,
/// the first cell holding k; stops with the first error a sink returns.
SliceCall path_of(std::vector<std::uint32_t> ks) {
  return [ks](std::span<LayerSink* const> sinks) -> Result<SliceSummary> {
    SliceRunInfo run;
    run.grid = GridSpec{0, 0, 0, 1, 1, 1, 2, 1, 8};
    for (LayerSink* sink : sinks) {
      if (auto ok = sink->begin(run); !ok) return ok.error();
    }
    const LayerContours contours;
    const std::vector<HatchSegment> hatches;
    for (const std::uint32_t k : ks) {
      const std::vector<CellClass> cells = {k % 2 ? CellClass::Interior : CellClass::Boundary,
                                            CellClass::Empty};
      for (LayerSink* sink : sinks) {
        if (auto ok = sink->add_layer(LayerResult{k, k + 0.5, cells, contours, hatches}); !ok) {
          return ok.error();
        }
      }
    }
    SliceSummary summary;
    summary.grid = run.grid;
    return summary;
  };
}

/// What the callback saw: k of each side's layer, -1 for none.
struct Seen {
  std::vector<std::pair<int, int>> calls;
  PairCallback callback() {
    return [this](const LayerResult* a, const LayerResult* b) {
      if (a && b) {
        EXPECT_TRUE(std::ranges::equal(a->cells, b->cells)) << "a pair holds the same layer";
      }
      calls.emplace_back(a ? static_cast<int>(a->layer) : -1, b ? static_cast<int>(b->layer) : -1);
    };
  }
};

using Calls = std::vector<std::pair<int, int>>;

TEST(RunPaired, PairsTheLayersOfBothPathsInIncreasingOrder) {
  for (const std::uint32_t window : {1u, 2u, 8u}) {
    Seen seen;
    const PairedOutcome outcome =
        run_paired(path_of({0, 1, 2, 3, 4}), path_of({0, 1, 2, 3, 4}), seen.callback(), window);
    ASSERT_TRUE(outcome.a.has_value()) << outcome.a.error().message;
    ASSERT_TRUE(outcome.b.has_value()) << outcome.b.error().message;
    EXPECT_EQ(seen.calls, (Calls{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}})) << "window " << window;
    EXPECT_GE(outcome.seconds_a, 0.0);
    EXPECT_GE(outcome.seconds_b, 0.0);
  }
}

TEST(RunPaired, HandsOverTheHeldLayersAPartnerThatEndedNeverDelivers) {
  // a runs first and holds all its layers (the window is wide); b pairs two and ends.
  Seen seen;
  const PairedOutcome outcome =
      run_paired(path_of({0, 1, 2, 3, 4}), path_of({0, 1}), seen.callback(), 8);
  EXPECT_TRUE(outcome.a.has_value());
  EXPECT_TRUE(outcome.b.has_value());
  EXPECT_EQ(seen.calls, (Calls{{0, 0}, {1, 1}, {2, -1}, {3, -1}, {4, -1}}));
}

TEST(RunPaired, RunsAPathOnAloneOnceItsPartnerHasEnded) {
  // A window of one layer: a hands the turn to b after each layer; b ends after the first.
  Seen seen;
  const PairedOutcome outcome = run_paired(path_of({0, 1, 2, 3}), path_of({0}), seen.callback(), 1);
  EXPECT_TRUE(outcome.a.has_value());
  EXPECT_TRUE(outcome.b.has_value());
  EXPECT_EQ(seen.calls, (Calls{{0, 0}, {1, -1}, {2, -1}, {3, -1}}));
}

TEST(RunPaired, GivesTheLayersOfTheSecondPathAloneWhenTheFirstDeliversNone) {
  Seen seen;
  const PairedOutcome outcome = run_paired(path_of({}), path_of({0, 1, 2}), seen.callback(), 1);
  EXPECT_TRUE(outcome.a.has_value());
  EXPECT_TRUE(outcome.b.has_value());
  EXPECT_EQ(seen.calls, (Calls{{-1, 0}, {-1, 1}, {-1, 2}}));
}

TEST(RunPaired, RunsTheFirstPathAloneWhenTheSecondFailsBeforeItsFirstLayer) {
  Seen seen;
  const SliceCall refuses = [](std::span<LayerSink* const>) -> Result<SliceSummary> {
    return Error{ErrorCode::BadInput, "no facet", "empty.stl"};
  };
  const PairedOutcome outcome = run_paired(path_of({0, 1, 2}), refuses, seen.callback(), 2);
  EXPECT_TRUE(outcome.a.has_value());
  ASSERT_FALSE(outcome.b.has_value());
  EXPECT_EQ(outcome.b.error().to_string(), "empty.stl: no facet");
  EXPECT_EQ(seen.calls, (Calls{{0, -1}, {1, -1}, {2, -1}}));
}

TEST(RunPaired, ReportsAnExceptionOfASlicingCallAsAnInternalError) {
  Seen seen;
  const SliceCall throws = [](std::span<LayerSink* const>) -> Result<SliceSummary> {
    throw std::runtime_error("out of cells");
  };
  const PairedOutcome outcome = run_paired(throws, path_of({0, 1}), seen.callback(), 2);
  ASSERT_FALSE(outcome.a.has_value());
  EXPECT_EQ(outcome.a.error().code, ErrorCode::Internal);
  EXPECT_EQ(outcome.a.error().message, "out of cells");
  EXPECT_TRUE(outcome.b.has_value());
  EXPECT_EQ(seen.calls, (Calls{{-1, 0}, {-1, 1}}));
}

TEST(RunPaired, StopsBothPathsWhenTheComparisonThrows) {
  int calls = 0;
  const PairCallback fails = [&](const LayerResult*, const LayerResult*) {
    ++calls;
    throw std::runtime_error("layer pair refused");
  };
  const PairedOutcome outcome = run_paired(path_of({0, 1, 2, 3}), path_of({0, 1, 2, 3}), fails, 1);
  EXPECT_EQ(calls, 1) << "no layer is compared after the failure";
  for (const Result<SliceSummary>* side : {&outcome.a, &outcome.b}) {
    ASSERT_FALSE(side->has_value());
    EXPECT_EQ(side->error().code, ErrorCode::Internal);
    EXPECT_EQ(side->error().message, "comparing layers: layer pair refused");
  }
}

}  // namespace
}  // namespace strata::validate::detail
