#include "strata/pipeline/run_slice.hpp"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <string>

#include "../slice/box_mesh_for_tests.hpp"
#include "collecting_sink_for_tests.hpp"
#include "strata/slicer/slice_model.hpp"

namespace strata {
namespace {

enum class Failure { Throw, OutOfMemory };

/// Empty layers, except that computing layer `failing_layer` fails on whichever worker takes it.
class FailingKernel final : public LayerKernel {
 public:
  FailingKernel(const GridSpec& grid, std::uint32_t failing_layer, Failure failure)
      : grid_(grid), failing_layer_(failing_layer), failure_(failure) {}

  void prepare_batch(std::uint32_t, std::uint32_t) override {}
  LayerGeometry compute_layer(std::uint32_t k) const override {
    if (k == failing_layer_) {
      if (failure_ == Failure::OutOfMemory) throw std::bad_alloc();
      throw std::runtime_error("layer " + std::to_string(k) + " broke");
    }
    LayerGeometry g;
    g.fill.layer = k;
    g.fill.solid.assign(grid_.cells_per_layer(), 0);
    return g;
  }
  std::string_view name() const override { return "test kernel"; }

 private:
  GridSpec grid_;
  std::uint32_t failing_layer_;
  Failure failure_;
};

/// Collects layers like CollectingSink but throws on layer `failing_layer`.
class ThrowingSink final : public LayerSink {
 public:
  explicit ThrowingSink(std::uint32_t failing_layer) : failing_layer_(failing_layer) {}
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult& layer) override {
    if (layer.layer == failing_layer_) throw std::runtime_error("sink broke");
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override { aborted = true; }

  bool aborted = false;

 private:
  std::uint32_t failing_layer_;
};

SliceOptions unit_cells() {
  SliceOptions o;
  o.grid = GridOptions{1.0, 1.0, 1.0, std::nullopt};
  o.batch_layers = 4;
  return o;
}

struct BoxRun {
  IndexedMesh mesh = testing::indexed_box({0, 0, 0}, {4, 4, 12});
  SliceOptions options = unit_cells();
  GridSpec grid = make_grid(mesh.bounds(), options.grid).value();
};

TEST(RunSlice, AWorkerThatThrowsAbortsTheSinksAndReturnsAnInternalError) {
  const BoxRun s;
  ASSERT_GE(s.grid.nz, 8u);
  FailingKernel kernel(s.grid, 6, Failure::Throw);
  testing::CollectingSink sink;
  LayerSink* sinks[] = {&sink};
  const auto r = run_slice(s.mesh, s.grid, s.options, kernel, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::Internal);
  EXPECT_EQ(r.error().message, "test kernel failed: layer 6 broke");
  EXPECT_TRUE(sink.aborted);
  EXPECT_FALSE(sink.finished);
}

TEST(RunSlice, OutOfMemoryOnAWorkerIsAnInternalError) {
  const BoxRun s;
  FailingKernel kernel(s.grid, 0, Failure::OutOfMemory);
  testing::CollectingSink sink;
  LayerSink* sinks[] = {&sink};
  const auto r = run_slice(s.mesh, s.grid, s.options, kernel, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::Internal);
  EXPECT_EQ(r.error().message, "test kernel: out of memory");
  EXPECT_TRUE(sink.aborted);
}

TEST(SliceModel, ASinkThatThrowsIsAnInternalErrorAndEverySinkIsAborted) {
  const BoxRun s;
  testing::CollectingSink collecting;
  ThrowingSink throwing(3);
  LayerSink* sinks[] = {&collecting, &throwing};
  const auto r = slice_model(s.mesh, s.grid, s.options, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::Internal);
  EXPECT_EQ(r.error().message, "fast path failed: sink broke");
  EXPECT_TRUE(collecting.aborted);
  EXPECT_TRUE(throwing.aborted);
  EXPECT_FALSE(collecting.finished);
}

}  // namespace
}  // namespace strata
