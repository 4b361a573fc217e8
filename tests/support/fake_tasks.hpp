#pragma once

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <new>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <thread>

#include "strata/serve/task_runner.hpp"

namespace strata::serve::testing {

/// A task runner without geometry, for the tests of the job store and the server; what a task
/// does is steered by the model's first line (check) and by the task's options (slice):
/// - check: a model whose text starts with "solid" gives {"verdict":"printable"} and leaves the
///   model's page data {"model":"<file name>"} at model_view_path(), or, starting with "solid
///   wait", is checked until cancelled; any other model fails with Error{BadInput, "not a mesh",
///   model path}.
/// - slice: writes the files a real slice writes, with known content: <stem>.cells ("cells of
///   <stem>"), <stem>.cli, <stem>.json, <stem>.html, view.json ({"layers":N}), one PNG and one
///   SVG layer in png/ and svg/; reports progress layer by layer for "layers" (default 2) and
///   answers {"layers":N}. "wait": true reports progress until cancelled; "fail": MESSAGE returns
///   Error{BadInput, MESSAGE}; "throw": WHAT throws std::runtime_error(WHAT); "out_of_memory":
///   true throws std::bad_alloc; "no_svg": true leaves svg/ out; "hold": true ignores the cancel
///   flag until release().
/// - validate: {"verdict":"agree","options":OPTIONS}; "wait": true waits until cancelled.
/// The object must outlive every task its runner runs.
class FakeTasks {
 public:
  TaskRunner runner() {
    return [this](const TaskRequest& r, const TaskControl& c) { return run(r, c); };
  }

  /// Lets the tasks held by "hold" end.
  void release() {
    std::lock_guard lock(mutex_);
    released_ = true;
    changed_.notify_all();
  }

  /// Waits until a task held by "hold" has seen its cancel flag raised; false after 10 s.
  bool wait_until_held_task_cancelled() {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, std::chrono::seconds(10), [this] { return held_cancelled_; });
  }

 private:
  Result<std::string> run(const TaskRequest& r, const TaskControl& c) {
    namespace fs = std::filesystem;
    using nlohmann::json;
    const json options = json::parse(r.options_json.empty() ? "{}" : r.options_json);
    if (r.kind == TaskKind::Check) {
      std::string first(10, '\0');
      std::ifstream(r.model, std::ios::binary).read(first.data(), 10);
      if (first.rfind("solid", 0) != 0) {
        return Error{ErrorCode::BadInput, "not a mesh", r.model.string()};
      }
      if (first == "solid wait") return wait_for_cancel(c);
      std::ofstream(model_view_path(r)) << json{{"model", r.model.filename().string()}}.dump();
      return std::string(R"({"verdict":"printable"})");
    }
    if (r.kind == TaskKind::Validate) {
      if (options.value("wait", false)) return wait_for_cancel(c);
      return json{{"verdict", "agree"}, {"options", options}}.dump();
    }
    if (options.contains("fail")) {
      return Error{ErrorCode::BadInput, options["fail"].get<std::string>(), {}};
    }
    if (options.contains("throw")) throw std::runtime_error(options["throw"].get<std::string>());
    if (options.contains("out_of_memory")) throw std::bad_alloc();
    const std::uint32_t layers = options.value("layers", 2u);
    fs::create_directories(r.output_dir / "png");
    std::ofstream(r.output_dir / (r.stem + ".cells")) << "cells of " << r.stem;
    for (const char* extension : {".cli", ".json", ".html"}) {
      std::ofstream(r.output_dir / (r.stem + extension)) << extension << " of " << r.stem;
    }
    std::ofstream(r.output_dir / "view.json") << json{{"layers", layers}}.dump();
    std::ofstream(r.output_dir / "png" / (r.stem + "_0001.png")) << "png layer";
    if (!options.value("no_svg", false)) {
      fs::create_directories(r.output_dir / "svg");
      std::ofstream(r.output_dir / "svg" / (r.stem + "_0001.svg")) << "<svg/>";
    }
    for (std::uint32_t k = 1; k <= layers; ++k) c.progress(k, layers);
    if (options.value("wait", false)) return wait_for_cancel(c);
    if (options.value("hold", false)) return hold(c);
    return json{{"layers", layers}}.dump();
  }

  static Result<std::string> wait_for_cancel(const TaskControl& c) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    for (std::uint32_t k = 0; std::chrono::steady_clock::now() < deadline; ++k) {
      c.progress(k % 1000, 1000);
      if (c.cancel->load()) return Error{ErrorCode::Internal, "cancelled", {}};
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return Error{ErrorCode::Internal, "never cancelled", {}};
  }

  Result<std::string> hold(const TaskControl& c) {
    std::unique_lock lock(mutex_);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!released_ && std::chrono::steady_clock::now() < deadline) {
      if (c.cancel->load() && !held_cancelled_) {
        held_cancelled_ = true;
        changed_.notify_all();
      }
      changed_.wait_for(lock, std::chrono::milliseconds(1));
    }
    return Error{ErrorCode::Internal, "released", {}};
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  bool released_ = false;
  bool held_cancelled_ = false;
};

}  // namespace strata::serve::testing
