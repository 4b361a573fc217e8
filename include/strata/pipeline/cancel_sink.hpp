#pragma once

#include <atomic>

#include "strata/pipeline/layer_sink.hpp"

namespace strata {

/// The message of the Error a cancelled run returns.
inline constexpr const char* kCancelledMessage = "cancelled";

/// A sink that stops a run when a flag is raised: its add_layer returns
/// Error{Internal, kCancelledMessage}, so the pipeline aborts every sink (each removes its partial
/// output) and returns that error. Checked once a layer, between the batches' layers.
/// @param cancel  raised by another thread; must outlive the sink
class CancelSink final : public LayerSink {
 public:
  /// Watches `cancel`.
  explicit CancelSink(const std::atomic<bool>& cancel) : cancel_(cancel) {}
  Result<void> begin(const SliceRunInfo& run) override;
  Result<void> add_layer(const LayerResult& layer) override;
  Result<void> finish() override;
  void abort() noexcept override {}
  bool needs_cells() const override { return false; }
  bool needs_hatches() const override { return false; }

 private:
  Result<void> check() const;
  const std::atomic<bool>& cancel_;
};

/// True when `error` is the one a CancelSink returns.
bool is_cancelled(const Error& error);

}  // namespace strata
