#include <chrono>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "validate/paired_run_internal.hpp"

namespace strata::validate::detail {

namespace {

using Clock = std::chrono::steady_clock;

struct Side {
  bool begun = false;
  bool ended = false;
  bool running = false;
  std::map<std::uint32_t, HeldLayer> held;  ///< delivered, not yet paired
  Clock::time_point since;
  double busy = 0.0;
};

/// The turn-taking between the two paths; every member is guarded by `mutex`.
class Coordinator {
 public:
  Coordinator(const PairCallback& on_pair, std::uint32_t window)
      : on_pair_(on_pair), window_(std::max<std::uint32_t>(1, window)) {}

  void start(int s) {
    std::lock_guard lock(mutex_);
    resume(s);
  }

  void end(int s) {
    std::lock_guard lock(mutex_);
    Side& me = sides_[s];
    me.ended = true;
    pause(s);
    // The partner's held layers will never find their pair now.
    Side& other = sides_[1 - s];
    while (!other.held.empty()) {
      auto node = other.held.extract(other.held.begin());
      deliver_alone(1 - s, node.mapped());
    }
    token_ = 1 - s;
    changed_.notify_all();
  }

  /// Blocks until b has reached its first layer (or ended), so that its preparation runs alone.
  void wait_until_begun(int s) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return sides_[s].begun || sides_[s].ended; });
  }

  Result<void> begin(int s) {
    std::unique_lock lock(mutex_);
    sides_[s].begun = true;
    changed_.notify_all();
    wait_turn(s, lock);
    if (error_) return *error_;
    return {};
  }

  Result<void> add_layer(int s, const LayerResult& layer) {
    std::unique_lock lock(mutex_);
    if (error_) return *error_;
    Side& me = sides_[s];
    Side& other = sides_[1 - s];
    if (auto it = other.held.find(layer.layer); it != other.held.end()) {
      auto node = other.held.extract(it);
      const LayerResult theirs = node.mapped().view();
      deliver(s == 0 ? &layer : &theirs, s == 0 ? &theirs : &layer, s);
    } else if (other.ended) {
      deliver(s == 0 ? &layer : nullptr, s == 0 ? nullptr : &layer, s);
    } else {
      // Hatches are not kept: the comparison does not use them.
      me.held.emplace(layer.layer,
                      HeldLayer{layer.layer,
                                layer.z_mm,
                                std::vector<CellClass>(layer.cells.begin(), layer.cells.end()),
                                layer.contours,
                                {}});
      if (me.held.size() >= window_) {
        token_ = 1 - s;
        changed_.notify_all();
        wait_turn(s, lock);
      }
    }
    if (error_) return *error_;
    return {};
  }

  double busy(int s) const { return sides_[s].busy; }

 private:
  void pause(int s) {
    Side& side = sides_[s];
    if (!side.running) return;
    side.busy += std::chrono::duration<double>(Clock::now() - side.since).count();
    side.running = false;
  }
  void resume(int s) {
    sides_[s].since = Clock::now();
    sides_[s].running = true;
  }

  void wait_turn(int s, std::unique_lock<std::mutex>& lock) {
    const auto my_turn = [&] { return token_ == s || sides_[1 - s].ended; };
    if (my_turn()) return;
    pause(s);
    changed_.wait(lock, my_turn);
    resume(s);
  }

  /// Hands a pair, or a lone layer, to the callback. Its time goes to neither path: the running
  /// side `timed` (or -1) is paused meanwhile.
  void deliver(const LayerResult* a, const LayerResult* b, int timed) {
    const bool was_running = timed >= 0 && sides_[timed].running;
    if (was_running) pause(timed);
    try {
      if (!error_) on_pair_(a, b);
    } catch (const std::exception& e) {
      error_ = Error{ErrorCode::Internal, std::string("comparing layers: ") + e.what(), {}};
      changed_.notify_all();
    }
    if (was_running) resume(timed);
  }

  void deliver_alone(int owner, const HeldLayer& layer) {
    const LayerResult view = layer.view();
    deliver(owner == 0 ? &view : nullptr, owner == 1 ? &view : nullptr, -1);
  }

  const PairCallback& on_pair_;
  const std::uint32_t window_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int token_ = 0;
  Side sides_[2];
  std::optional<Error> error_;
};

class TurnSink final : public LayerSink {
 public:
  TurnSink(Coordinator& coordinator, int side) : coordinator_(coordinator), side_(side) {}
  Result<void> begin(const SliceRunInfo&) override { return coordinator_.begin(side_); }
  Result<void> add_layer(const LayerResult& layer) override {
    return coordinator_.add_layer(side_, layer);
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override {}

 private:
  Coordinator& coordinator_;
  int side_;
};

}  // namespace

PairedOutcome run_paired(const SliceCall& a, const SliceCall& b, const PairCallback& on_pair,
                         std::uint32_t window) {
  Coordinator coordinator(on_pair, window);
  PairedOutcome outcome;
  const auto run_side = [&](int s, const SliceCall& call, Result<SliceSummary>& result) {
    TurnSink sink(coordinator, s);
    LayerSink* sinks[] = {&sink};
    coordinator.start(s);
    try {
      result = call(sinks);
    } catch (const std::exception& e) {
      result = Error{ErrorCode::Internal, e.what(), {}};
    }
    coordinator.end(s);
  };
  std::thread thread_b([&] { run_side(1, b, outcome.b); });
  coordinator.wait_until_begun(1);
  std::thread thread_a([&] { run_side(0, a, outcome.a); });
  thread_a.join();
  thread_b.join();
  // No layer is left held: a side holds layers only while its partner runs, and the partner's
  // end hands them over.
  outcome.seconds_a = coordinator.busy(0);
  outcome.seconds_b = coordinator.busy(1);
  return outcome;
}

}  // namespace strata::validate::detail
