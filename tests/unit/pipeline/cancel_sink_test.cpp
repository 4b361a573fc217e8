#include "strata/pipeline/cancel_sink.hpp"

#include <gtest/gtest.h>

#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slicer/slice_model.hpp"

namespace strata {
namespace {

/// Raises the flag after `after` layers.
class RaiseAfter final : public LayerSink {
 public:
  RaiseAfter(std::atomic<bool>& flag, std::uint32_t after) : flag_(flag), after_(after) {}
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult&) override {
    if (++seen_ >= after_) flag_ = true;
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override { aborted_ = true; }
  std::uint32_t seen_ = 0;
  bool aborted_ = false;

 private:
  std::atomic<bool>& flag_;
  std::uint32_t after_;
};

TEST(CancelSink, StopsTheRunBetweenLayersAndAbortsEverySink) {
  std::atomic<bool> cancel{false};
  CancelSink stop(cancel);
  RaiseAfter raise(cancel, 3);
  LayerSink* sinks[] = {&stop, &raise};
  const IndexedMesh mesh = weld_vertices(mesh::make_box(Vec3{0, 0, 0}, Vec3{10, 10, 10}));
  SliceOptions options;
  options.grid.dx_mm = options.grid.dy_mm = options.grid.dz_mm = 0.5;
  auto grid = make_grid(mesh.bounds(), options.grid);
  ASSERT_TRUE(grid);
  const auto result = slice_model(mesh, *grid, options, sinks);
  ASSERT_FALSE(result);
  EXPECT_TRUE(is_cancelled(result.error()));
  EXPECT_EQ(raise.seen_, 3u);
  EXPECT_TRUE(raise.aborted_);
}

TEST(CancelSink, LetsARunThroughWhenNotRaised) {
  std::atomic<bool> cancel{false};
  CancelSink stop(cancel);
  LayerSink* sinks[] = {&stop};
  const IndexedMesh mesh = weld_vertices(mesh::make_box(Vec3{0, 0, 0}, Vec3{2, 2, 2}));
  SliceOptions options;
  auto grid = make_grid(mesh.bounds(), options.grid);
  ASSERT_TRUE(grid);
  EXPECT_TRUE(slice_model(mesh, *grid, options, sinks));
  EXPECT_FALSE(is_cancelled(Error{ErrorCode::Internal, "cancelled", "somewhere"}));
}

TEST(IsCancelled, KnowsTheErrorOfACancelSinkAlone) {
  EXPECT_TRUE(is_cancelled(Error{ErrorCode::Internal, kCancelledMessage, {}}));
  EXPECT_FALSE(is_cancelled(Error{ErrorCode::BadInput, kCancelledMessage, {}}));
  EXPECT_FALSE(is_cancelled(Error{ErrorCode::Internal, "canceled", {}}));
  EXPECT_FALSE(is_cancelled(Error{ErrorCode::Internal, kCancelledMessage, "out.cells"}));
}

}  // namespace
}  // namespace strata
