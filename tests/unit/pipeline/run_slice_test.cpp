#include "strata/pipeline/run_slice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "strata/slicer/slice_model.hpp"
#include "support/collecting_sink.hpp"
#include "support/mesh_builders.hpp"

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
    g.fill.solid = SolidRows(grid_.nx, grid_.ny);
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

/// Empty layers, each with the contours `contours_of(k)` gives; counts its layers.
class ScriptedKernel final : public LayerKernel {
 public:
  ScriptedKernel(const GridSpec& grid, std::function<LayerContours(std::uint32_t)> contours_of)
      : grid_(grid), contours_of_(std::move(contours_of)) {}

  void prepare_batch(std::uint32_t, std::uint32_t) override {}
  LayerGeometry compute_layer(std::uint32_t k) const override {
    ++computed;
    LayerGeometry g;
    g.fill.layer = k;
    g.fill.solid = SolidRows(grid_.nx, grid_.ny);
    g.contours = contours_of_(k);
    return g;
  }
  std::string_view name() const override { return "scripted kernel"; }

  mutable std::atomic<int> computed{0};

 private:
  GridSpec grid_;
  std::function<LayerContours(std::uint32_t)> contours_of_;
};

/// A kernel that keeps the default name and fails on every layer.
class UnnamedKernel final : public LayerKernel {
 public:
  void prepare_batch(std::uint32_t, std::uint32_t) override {}
  LayerGeometry compute_layer(std::uint32_t) const override {
    throw std::runtime_error("no geometry");
  }
};

/// Accepts everything, except that begin or finish return `error`.
class RefusingSink final : public LayerSink {
 public:
  enum class Step { Begin, Finish };
  RefusingSink(Step step, Error error) : step_(step), error_(std::move(error)) {}
  Result<void> begin(const SliceRunInfo&) override {
    if (step_ == Step::Begin) return error_;
    return {};
  }
  Result<void> add_layer(const LayerResult&) override {
    ++layers;
    return {};
  }
  Result<void> finish() override {
    if (step_ == Step::Finish) return error_;
    return {};
  }
  void abort() noexcept override { aborted = true; }

  int layers = 0;
  bool aborted = false;

 private:
  Step step_;
  Error error_;
};

/// Accepts layers until `failing_layer`, whose write it refuses with `error`.
class LayerRefusingSink final : public LayerSink {
 public:
  LayerRefusingSink(std::uint32_t failing_layer, Error error)
      : failing_layer_(failing_layer), error_(std::move(error)) {}
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult& layer) override {
    if (layer.layer == failing_layer_) return error_;
    written.push_back(layer.layer);
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override { aborted = true; }

  std::vector<std::uint32_t> written;
  bool aborted = false;

 private:
  std::uint32_t failing_layer_;
  Error error_;
};

SliceOptions unit_cells() {
  SliceOptions o;
  o.grid = GridOptions{1.0, 1.0, 1.0, std::nullopt};
  o.batch_layers = 4;
  return o;
}

struct BoxRun {
  IndexedMesh mesh = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 4, 12});
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

TEST(RunSlice, AWriterThatFailsWhileTheNextBatchFailsTooReturnsTheWritersError) {
  // Batches of 4 layers: layer 1 is written while the third batch is computed, and computing
  // layer 9 of that batch throws. The run stops at the writer's error, waits for the batch in
  // flight, and reports the writer's error, not the batch's.
  const BoxRun s;
  ASSERT_GE(s.grid.nz, 12u);
  FailingKernel kernel(s.grid, 9, Failure::Throw);
  LayerRefusingSink refusing(1, Error{ErrorCode::BadInput, "no space left", "out.cells"});
  testing::CollectingSink collecting;
  LayerSink* sinks[] = {&collecting, &refusing};
  const auto r = run_slice(s.mesh, s.grid, s.options, kernel, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().to_string(), "out.cells: no space left");
  EXPECT_EQ(refusing.written, std::vector<std::uint32_t>{0});
  EXPECT_TRUE(refusing.aborted);
  EXPECT_TRUE(collecting.aborted);
  EXPECT_FALSE(collecting.finished);
}

TEST(RunSlice, LayersAreWrittenInOrderWhileLaterBatchesAreComputed) {
  const BoxRun s;
  for (const int batch : {1, 3, 4, 100}) {
    SliceOptions options = s.options;
    options.batch_layers = batch;
    options.shell_mm = 2.0;  // a shell window of two layers each side
    testing::CollectingSink sink;
    LayerSink* sinks[] = {&sink};
    ASSERT_TRUE(slice_model(s.mesh, s.grid, options, sinks).has_value());
    std::vector<std::uint32_t> all(s.grid.nz);
    for (std::uint32_t k = 0; k < s.grid.nz; ++k) all[k] = k;
    EXPECT_EQ(sink.order, all) << "batch " << batch;
    EXPECT_TRUE(sink.finished);
  }
}

/// Prepares every layer ahead (a copy of its cells, tagged with its index) and checks, as each
/// layer is added, that what arrives with it is what was prepared of that layer.
class PreparingSink final : public LayerSink {
 public:
  struct Copy final : PreparedLayer {
    std::uint32_t layer = 0;
    std::vector<CellClass> cells;
  };

  Result<void> begin(const SliceRunInfo& run) override {
    prepared_ = std::vector<std::atomic<int>>(run.grid.nz);
    return {};
  }
  std::unique_ptr<PreparedLayer> prepare_layer(const LayerResult& layer) const override {
    ++prepared_[layer.layer];
    auto copy = std::make_unique<Copy>();
    copy->layer = layer.layer;
    copy->cells.assign(layer.cells.begin(), layer.cells.end());
    return copy;
  }
  Result<void> add_layer(const LayerResult& layer) override {
    added_without.push_back(layer.layer);
    return {};
  }
  Result<void> add_prepared_layer(const LayerResult& layer,
                                  std::unique_ptr<PreparedLayer> prepared) override {
    const auto* copy = dynamic_cast<const Copy*>(prepared.get());
    if (copy == nullptr || copy->layer != layer.layer ||
        !std::ranges::equal(copy->cells, layer.cells)) {
      mismatched.push_back(layer.layer);
    }
    order.push_back(layer.layer);
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override {}

  /// How often each layer was prepared.
  std::vector<int> times_prepared() const {
    std::vector<int> times;
    for (const auto& n : prepared_) times.push_back(n.load());
    return times;
  }

  std::vector<std::uint32_t> order, mismatched, added_without;

 private:
  mutable std::vector<std::atomic<int>> prepared_;
};

TEST(RunSlice, EveryLayerSentIsPreparedOnceAndArrivesWithWhatWasPreparedOfIt) {
  const BoxRun s;
  for (const int batch : {1, 3, 4, 100}) {
    for (const bool ranged : {false, true}) {
      SliceOptions options = s.options;
      options.batch_layers = batch;
      options.shell_mm = 2.0;  // the layers around a range are sliced for the shell, not sent
      if (ranged) options.layers = LayerRange{3, 8};
      PreparingSink sink;
      LayerSink* sinks[] = {&sink};
      ASSERT_TRUE(slice_model(s.mesh, s.grid, options, sinks).has_value());
      const LayerSpan span = ranged ? LayerSpan{3, 8} : LayerSpan{0, s.grid.nz};
      std::vector<std::uint32_t> sent;
      std::vector<int> times(s.grid.nz, 0);
      for (std::uint32_t k = span.first; k < span.end; ++k) {
        sent.push_back(k);
        times[k] = 1;
      }
      EXPECT_EQ(sink.order, sent) << "batch " << batch;
      EXPECT_EQ(sink.times_prepared(), times) << "batch " << batch;
      EXPECT_TRUE(sink.mismatched.empty()) << "batch " << batch;
      EXPECT_TRUE(sink.added_without.empty()) << "batch " << batch;
    }
  }
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

TEST(RunSlice, ASinkThatCannotBeginStopsTheRunBeforeAnyLayer) {
  const BoxRun s;
  ScriptedKernel kernel(s.grid, [](std::uint32_t) { return LayerContours{}; });
  testing::CollectingSink collecting;
  RefusingSink refusing(RefusingSink::Step::Begin,
                        Error{ErrorCode::BadInput, "cannot write here", "out/box.cells"});
  LayerSink* sinks[] = {&collecting, &refusing};
  const auto r = run_slice(s.mesh, s.grid, s.options, kernel, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().to_string(), "out/box.cells: cannot write here");
  EXPECT_EQ(kernel.computed.load(), 0);
  EXPECT_TRUE(collecting.layers.empty());
  EXPECT_TRUE(collecting.aborted);
  EXPECT_TRUE(refusing.aborted);
}

TEST(RunSlice, ASinkThatCannotFinishAbortsEverySink) {
  const BoxRun s;
  ScriptedKernel kernel(s.grid, [](std::uint32_t) { return LayerContours{}; });
  testing::CollectingSink collecting;
  RefusingSink refusing(RefusingSink::Step::Finish,
                        Error{ErrorCode::BadInput, "disk full", "out/box.png"});
  LayerSink* sinks[] = {&collecting, &refusing};
  const auto r = run_slice(s.mesh, s.grid, s.options, kernel, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().to_string(), "out/box.png: disk full");
  EXPECT_EQ(collecting.layers.size(), s.grid.nz);  // every layer was handed on first
  EXPECT_EQ(refusing.layers, static_cast<int>(s.grid.nz));
  EXPECT_TRUE(collecting.finished);  // finished before the other failed, and aborted after
  EXPECT_TRUE(collecting.aborted);
  EXPECT_TRUE(refusing.aborted);
}

TEST(RunSlice, AKernelWithoutANameIsCalledLayerKernelInItsFailure) {
  const BoxRun s;
  UnnamedKernel kernel;
  testing::CollectingSink sink;
  LayerSink* sinks[] = {&sink};
  const auto r = run_slice(s.mesh, s.grid, s.options, kernel, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().message, "layer kernel failed: no geometry");
  EXPECT_TRUE(sink.aborted);
}

/// `count` open chains of one segment each, from (k, n) to (k, n + 1).
LayerContours open_chains(std::uint32_t k, std::uint32_t count) {
  LayerContours c;
  c.layer = k;
  for (std::uint32_t n = 0; n < count; ++n) {
    Contour open;
    open.points = {{double(k), double(n)}, {double(k), double(n + 1)}};
    c.loops.push_back(open);
  }
  c.open_chains = count;
  return c;
}

TEST(RunSlice, OpenChainsAreAllCountedAndTheFirstThousandReported) {
  const BoxRun s;
  ASSERT_EQ(s.grid.nz, 12u);
  ScriptedKernel kernel(s.grid, [](std::uint32_t k) { return open_chains(k, 100); });
  testing::CollectingSink sink;
  LayerSink* sinks[] = {&sink};
  const auto r = run_slice(s.mesh, s.grid, s.options, kernel, sinks);
  ASSERT_TRUE(r.has_value()) << r.error().to_string();
  EXPECT_EQ(r->open_chains, 1200u);
  EXPECT_EQ(r->layers[11].open_chains, 100u);
  ASSERT_EQ(r->open_chain_reports.size(), 1000u);
  const OpenChainReport& last = r->open_chain_reports.back();  // layer 9's last chain
  EXPECT_EQ(last.layer, 9u);
  EXPECT_EQ(last.start, (Point2{9.0, 99.0}));
  EXPECT_EQ(last.end, (Point2{9.0, 100.0}));
  EXPECT_EQ(last.segments, 1u);
}

TEST(RunSlice, LoopDiagnosticsNameTheFirstLayersAndWhatTheContoursAre) {
  const BoxRun s;
  // Loops cross in layers 1 to 7, outlined in 2 and 3 only; they nest wrongly in layer 9, not
  // outlined; and in layer 10 they both cross and nest wrongly, outlined.
  ScriptedKernel kernel(s.grid, [](std::uint32_t k) {
    LayerContours c;
    c.layer = k;
    c.loops_cross = (k >= 1 && k <= 7) || k == 10;
    c.misnested = k == 9 || k == 10;
    c.outline = k == 2 || k == 3 || k == 10;
    return c;
  });
  testing::CollectingSink sink;
  LayerSink* sinks[] = {&sink};
  const auto r = run_slice(s.mesh, s.grid, s.options, kernel, sinks);
  ASSERT_TRUE(r.has_value()) << r.error().to_string();
  EXPECT_EQ(r->crossing_loop_layers, 8u);
  EXPECT_EQ(r->misnested_layers, 2u);
  EXPECT_EQ(r->outline_layers, 3u);
  ASSERT_EQ(r->diagnostics.size(), 2u);
  EXPECT_EQ(r->diagnostics[0].code, "contours.loops_cross");
  EXPECT_EQ(r->diagnostics[0].message,
            "loops cross or touch each other in 8 layers (first: 1, 2, 3, 4, 5, ...): contours "
            "are the outline of the filled region in 3 of them");
  EXPECT_EQ(r->diagnostics[1].code, "contours.loops_misnested");
  EXPECT_EQ(r->diagnostics[1].message,
            "nested loops do not alternate in orientation in 2 layers (first: 9, 10): contours "
            "are the outline of the filled region in 1 of them");

  // Misnested in layer 4 alone, not outlined: the chained loops are the contours.
  ScriptedKernel chained(s.grid, [](std::uint32_t k) {
    LayerContours c;
    c.misnested = k == 4;
    return c;
  });
  const auto only = run_slice(s.mesh, s.grid, s.options, chained, sinks);
  ASSERT_TRUE(only.has_value());
  ASSERT_EQ(only->diagnostics.size(), 1u);
  EXPECT_EQ(only->diagnostics[0].message,
            "nested loops do not alternate in orientation in 1 layers (first: 4): contours are "
            "the chained loops");
}

}  // namespace
}  // namespace strata
