#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "strata/core/result.hpp"

namespace strata::serve {

/// What the server asks of a job's model.
enum class TaskKind {
  Check,     ///< read the model and diagnose it, as `strata check`
  Slice,     ///< slice it with the job's options into output_dir
  Validate,  ///< compare the fast and exact paths, as `strata validate`
};

/// One task of a job, run on a worker of the TBB pool.
struct TaskRequest {
  TaskKind kind = TaskKind::Check;
  std::filesystem::path model;  ///< the job's model file
  /// Slice: the folder the outputs go to (absent before): `<stem>.cells`, `<stem>.cli`,
  /// `<stem>.json` (the report), `<stem>.html` (the page), `view.json` (the page's data,
  /// web/DATA.md), `png/`, `svg/`.
  std::filesystem::path output_dir;
  std::string stem;          ///< the outputs' stem (the model's file name without extensions)
  std::string options_json;  ///< Slice, Validate: the page's parameters, a JSON object
};

/// The task's link back to the server.
struct TaskControl {
  const std::atomic<bool>* cancel = nullptr;  ///< raised when the user cancels; never null
  std::function<void(std::uint32_t done, std::uint32_t total)> progress;
};

/// Runs a task; returns the result the page shows, as a JSON object (Check: the mesh report of
/// `strata check --json`; Slice: a summary; Validate: `strata validate --json`), or the Error
/// to show (the reader's message for a malformed model). Must not print. A cancelled task
/// returns any Error and leaves nothing in output_dir.
/// Where a check task leaves the view page's data of the model alone (no layer yet): the job's
/// folder, beside `output_dir`. The page shows it until the job is sliced.
inline std::filesystem::path model_view_path(const TaskRequest& request) {
  return request.output_dir.parent_path() / "model-view.json";
}

/// Runs one task (the command line's implementation, so the server holds no slicing code).
using TaskRunner = std::function<Result<std::string>(const TaskRequest&, const TaskControl&)>;

}  // namespace strata::serve
