#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "strata/core/result.hpp"
#include "strata/serve/task_runner.hpp"

namespace strata::serve::detail {

/// A task's state as the page sees it.
struct TaskState {
  std::string state = "none";  ///< none, queued, running, done, failed, cancelled
  std::uint32_t done = 0;      ///< layers done (slice), of total
  std::uint32_t total = 0;
  std::string error;        ///< failed: the message to show
  std::string result_json;  ///< done: the runner's JSON object
  double seconds = 0.0;
};

/// A job: a folder holding the model (model/NAME), the slice options (options.json), the check
/// and validation results (check.json, validation.json), the outputs (out/) and its state
/// (job.json).
struct Job {
  std::string id;
  std::string name;  ///< the model's file name
  std::string stem;
  std::filesystem::path dir;
  std::uint64_t created_ms = 0;
  bool visible = false;      ///< false while its upload is under way
  std::string options_json;  ///< the slice's options; empty before a slice
  TaskState check, slice, validate;
  std::atomic<bool> cancel_check{false}, cancel_slice{false}, cancel_validate{false};

  std::filesystem::path model() const { return dir / "model" / name; }
  std::filesystem::path out() const { return dir / "out"; }
};

/// A download of a job.
struct JobFile {
  std::filesystem::path path;
  std::string download_name;
  std::string content_type;
};

/// The jobs of a session, their folders, and their tasks queued on the TBB pool. Thread-safe.
class JobStore {
 public:
  /// `root` must exist; jobs already there (job.json) are listed again.
  JobStore(std::filesystem::path root, TaskRunner runner);
  ~JobStore();
  JobStore(const JobStore&) = delete;
  JobStore& operator=(const JobStore&) = delete;

  /// A new, hidden job with an empty model/ folder; returns its id. The upload goes to
  /// model_path(id); then commit() or discard().
  Result<std::string> reserve(const std::string& name);
  std::filesystem::path model_path(const std::string& id) const;
  /// Shows the job and queues its check.
  void commit(const std::string& id);
  /// Removes a reserved job and its folder.
  void discard(const std::string& id);
  /// A job of a file on disk (copied), checked; returns its id.
  Result<std::string> add_file(const std::filesystem::path& model);

  bool exists(const std::string& id) const;
  /// Queues a slice with `options_json` (a JSON object): on this job if it was never sliced,
  /// else on a new job of the same model. Returns the id of the job that slices.
  Result<std::string> slice(const std::string& id, const std::string& options_json);
  /// Raises the cancel flags of the job's running or queued tasks.
  void cancel(const std::string& id);
  /// Queues `strata validate` of the job's model with `options_json`.
  Result<void> validate(const std::string& id, const std::string& options_json);
  /// Cancels the job's tasks and removes it once they stopped; Error while they run.
  Result<void> remove(const std::string& id);

  /// {"jobs": [...]} in creation order, each without its results.
  std::string list_json() const;
  /// One job with its results; nullopt when unknown.
  std::optional<std::string> status_json(const std::string& id) const;
  /// The download of `kind` (route_internal.hpp's kFileKinds) when the job has it.
  std::optional<JobFile> file(const std::string& id, const std::string& kind) const;

  /// Refuses new tasks, cancels the running ones and waits for them.
  void shutdown();

 private:
  std::shared_ptr<Job> find(const std::string& id) const;
  std::shared_ptr<Job> make_job(const std::string& name);
  void queue(const std::shared_ptr<Job>& job, TaskKind kind);
  void execute(const std::shared_ptr<Job>& job, TaskKind kind);
  void finish_slice(const std::shared_ptr<Job>& job);
  void persist(const Job& job) const;  ///< writes job.json; called with mutex_ held
  void load_existing();

  std::filesystem::path root_;
  TaskRunner runner_;
  mutable std::mutex mutex_;
  std::condition_variable idle_;
  std::map<std::string, std::shared_ptr<Job>> jobs_;
  std::uint64_t next_id_ = 1;
  std::size_t tasks_in_flight_ = 0;
  bool stopping_ = false;
  struct Pool;
  std::unique_ptr<Pool> pool_;
};

}  // namespace strata::serve::detail
