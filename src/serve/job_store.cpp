#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "serve/job_store_internal.hpp"
#include "serve/route_internal.hpp"
#include "strata/io/output_file.hpp"
#include "strata/serve/write_zip.hpp"

namespace strata::serve::detail {

namespace fs = std::filesystem;
using nlohmann::json;

/// The tasks, run one at a time in the order they were queued, on a thread of their own that
/// joins the task arena: a queued task starts as soon as the one before ends, whether or not a
/// TBB worker is free to take it (the process has one on two cores, which other work may hold),
/// and the thread's slices use the arena's other slot too.
struct JobStore::Pool {
  tbb::task_arena arena;
  std::mutex mutex;
  std::condition_variable ready;
  std::deque<std::function<void()>> tasks;
  bool stopping = false;
  std::thread runner{[this] { run(); }};  // last: it starts with every other member built

  ~Pool() {
    {
      std::lock_guard lock(mutex);
      stopping = true;
    }
    ready.notify_all();
    runner.join();
  }

  /// Queues a task; does not wait.
  void post(std::function<void()> task) {
    {
      std::lock_guard lock(mutex);
      tasks.push_back(std::move(task));
    }
    ready.notify_one();
  }

  void run() {
    for (;;) {
      std::function<void()> task;
      {
        std::unique_lock lock(mutex);
        ready.wait(lock, [this] { return stopping || !tasks.empty(); });
        if (tasks.empty()) return;  // stopping, every task run
        task = std::move(tasks.front());
        tasks.pop_front();
      }
      arena.execute(task);
    }
  }
};

namespace {

std::uint64_t now_ms() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count());
}

json parse_or_null(const std::string& text) {
  if (text.empty()) return nullptr;
  json j = json::parse(text, nullptr, false);
  return j.is_discarded() ? json(nullptr) : j;
}

json task_json(const TaskState& t, bool with_result) {
  json j = {{"state", t.state}, {"done", t.done},       {"total", t.total},
            {"error", t.error}, {"seconds", t.seconds}, {"result", nullptr}};
  if (with_result) j["result"] = parse_or_null(t.result_json);
  return j;
}

TaskState task_of_json(const json& j) {
  TaskState t;
  if (!j.is_object()) return t;
  t.state = j.value("state", std::string("none"));
  t.done = j.value("done", 0u);
  t.total = j.value("total", 0u);
  t.error = j.value("error", std::string());
  t.seconds = j.value("seconds", 0.0);
  if (j.contains("result") && !j["result"].is_null()) t.result_json = j["result"].dump();
  if (t.state == "queued" || t.state == "running") {
    t.state = "failed";
    t.error = "interrupted: the server stopped before it finished";
  }
  return t;
}

bool regular_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

}  // namespace

JobStore::JobStore(fs::path root, TaskRunner runner)
    : root_(std::move(root)), runner_(std::move(runner)), pool_(std::make_unique<Pool>()) {
  load_existing();
}

JobStore::~JobStore() { shutdown(); }

void JobStore::load_existing() {
  std::error_code ec;
  std::vector<std::shared_ptr<Job>> found;
  for (const auto& entry : fs::directory_iterator(root_, ec)) {
    const std::string id = entry.path().filename().string();
    if (!is_job_id(id) || !regular_file(entry.path() / "job.json")) continue;
    std::FILE* f = std::fopen((entry.path() / "job.json").string().c_str(), "rb");
    if (f == nullptr) continue;
    std::string text;
    char buffer[1 << 14];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    std::fclose(f);
    const json j = json::parse(text, nullptr, false);
    if (!j.is_object() || !j.contains("name") || !j["name"].is_string()) continue;
    auto name = check_upload_name(j["name"].get<std::string>());
    if (!name || *name != j["name"].get<std::string>()) continue;
    auto job = std::make_shared<Job>();
    job->id = id;
    job->name = *name;
    job->stem = stem_of(job->name);
    job->dir = entry.path();
    job->created_ms = j.value("created", std::uint64_t{0});
    job->visible = true;
    if (j.contains("options") && j["options"].is_object()) job->options_json = j["options"].dump();
    job->check = task_of_json(j.value("check", json()));
    job->slice = task_of_json(j.value("slice", json()));
    job->validate = task_of_json(j.value("validate", json()));
    if (!regular_file(job->model())) continue;
    found.push_back(job);
  }
  for (auto& job : found) {
    next_id_ = std::max<std::uint64_t>(next_id_, std::stoull(job->id, nullptr, 16) + 1);
    persist(*job);
    jobs_[job->id] = std::move(job);
  }
}

std::shared_ptr<Job> JobStore::find(const std::string& id) const {
  const auto it = jobs_.find(id);
  return it == jobs_.end() ? nullptr : it->second;
}

std::shared_ptr<Job> JobStore::make_job(const std::string& name) {
  auto job = std::make_shared<Job>();
  job->id = fmt::format("{:06x}", next_id_++);
  job->name = name;
  job->stem = stem_of(name);
  job->dir = root_ / job->id;
  job->created_ms = now_ms();
  return job;
}

Result<std::string> JobStore::reserve(const std::string& name) {
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return Error{ErrorCode::Internal, "the server is stopping", {}};
    job = make_job(name);
    jobs_[job->id] = job;
  }
  std::error_code ec;
  fs::create_directories(job->dir / "model", ec);
  if (ec) {
    std::lock_guard lock(mutex_);
    jobs_.erase(job->id);
    return Error{ErrorCode::Internal, "cannot make the job's folder: " + ec.message(),
                 job->dir.string()};
  }
  return job->id;
}

fs::path JobStore::model_path(const std::string& id) const {
  std::lock_guard lock(mutex_);
  const auto job = find(id);
  return job ? job->model() : fs::path();
}

void JobStore::commit(const std::string& id) {
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(mutex_);
    job = find(id);
    if (!job) return;
    job->visible = true;
    persist(*job);
  }
  queue(job, TaskKind::Check);
}

void JobStore::discard(const std::string& id) {
  fs::path dir;
  {
    std::lock_guard lock(mutex_);
    const auto job = find(id);
    if (!job || job->visible) return;
    dir = job->dir;
    jobs_.erase(id);
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
}

Result<std::string> JobStore::add_file(const fs::path& model) {
  auto name = check_upload_name(model.filename().string());
  if (!name) return Error{ErrorCode::BadInput, name.error().message, model.string()};
  auto id = reserve(*name);
  if (!id) return id;
  std::error_code ec;
  fs::copy_file(model, model_path(*id), ec);
  if (ec) {
    discard(*id);
    return Error{ErrorCode::BadInput, "cannot read the model: " + ec.message(), model.string()};
  }
  commit(*id);
  return id;
}

bool JobStore::exists(const std::string& id) const {
  std::lock_guard lock(mutex_);
  const auto job = find(id);
  return job && job->visible;
}

Result<std::string> JobStore::slice(const std::string& id, const std::string& options_json) {
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return Error{ErrorCode::Internal, "the server is stopping", {}};
    auto source = find(id);
    if (!source || !source->visible) return Error{ErrorCode::BadInput, "no such job", id};
    if (source->check.state == "failed") {
      return Error{ErrorCode::BadInput, "the model could not be read: " + source->check.error, {}};
    }
    if (source->slice.state == "none") {
      job = source;
    } else {
      // Another parameter set on the same model: a job of its own, so both can be compared.
      job = make_job(source->name);
      std::error_code ec;
      fs::create_directories(job->dir / "model", ec);
      fs::create_hard_link(source->model(), job->model(), ec);
      if (ec) {
        ec.clear();
        fs::copy_file(source->model(), job->model(), ec);
      }
      if (ec) {
        fs::remove_all(job->dir, ec);
        return Error{ErrorCode::Internal, "cannot copy the model into a new job", {}};
      }
      if (regular_file(source->dir / "check.json")) {
        fs::copy_file(source->dir / "check.json", job->dir / "check.json", ec);
      }
      job->check = source->check;
      if (job->check.state == "queued" || job->check.state == "running") {
        job->check = TaskState{};
      }
      job->visible = true;
      jobs_[job->id] = job;
    }
    job->options_json = options_json;
    job->slice = TaskState{};
    job->slice.state = "queued";
    job->cancel_slice = false;
    persist(*job);
  }
  auto written = io::write_text_file(job->dir / "options.json", options_json + "\n");
  (void)written;
  if (job->check.state == "none") queue(job, TaskKind::Check);
  queue(job, TaskKind::Slice);
  return job->id;
}

void JobStore::cancel(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto job = find(id);
  if (!job) return;
  for (auto* flag : {&job->cancel_check, &job->cancel_slice, &job->cancel_validate}) {
    flag->store(true);
  }
}

Result<void> JobStore::validate(const std::string& id, const std::string& options_json) {
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return Error{ErrorCode::Internal, "the server is stopping", {}};
    job = find(id);
    if (!job || !job->visible) return Error{ErrorCode::BadInput, "no such job", id};
    if (job->validate.state == "queued" || job->validate.state == "running") {
      return Error{ErrorCode::BadInput, "this job is being validated already", {}};
    }
    job->validate = TaskState{};
    job->validate.state = "queued";
    job->validate.result_json = options_json;  // the options, until the task starts
    job->cancel_validate = false;
    persist(*job);
  }
  queue(job, TaskKind::Validate);
  return {};
}

Result<void> JobStore::remove(const std::string& id) {
  fs::path dir;
  {
    std::lock_guard lock(mutex_);
    const auto job = find(id);
    if (!job || !job->visible) return Error{ErrorCode::BadInput, "no such job", id};
    for (const TaskState* t : {&job->check, &job->slice, &job->validate}) {
      if (t->state == "queued" || t->state == "running") {
        return Error{ErrorCode::BadInput, "the job is running: cancel it first", {}};
      }
    }
    dir = job->dir;
    jobs_.erase(id);
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  return {};
}

void JobStore::queue(const std::shared_ptr<Job>& job, TaskKind kind) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    ++tasks_in_flight_;
    TaskState& t = kind == TaskKind::Check   ? job->check
                   : kind == TaskKind::Slice ? job->slice
                                             : job->validate;
    if (t.state == "none") t.state = "queued";
  }
  // post does not wait: the request threads never block on the pool.
  pool_->post([this, job, kind] {
    execute(job, kind);
    std::lock_guard lock(mutex_);
    --tasks_in_flight_;
    idle_.notify_all();
  });
}

void JobStore::execute(const std::shared_ptr<Job>& job, TaskKind kind) {
  TaskRequest request;
  request.kind = kind;
  request.model = job->model();
  request.output_dir = job->out();
  request.stem = job->stem;
  std::atomic<bool>* cancel = kind == TaskKind::Check   ? &job->cancel_check
                              : kind == TaskKind::Slice ? &job->cancel_slice
                                                        : &job->cancel_validate;
  const auto state_of = [&]() -> TaskState& {
    return kind == TaskKind::Check   ? job->check
           : kind == TaskKind::Slice ? job->slice
                                     : job->validate;
  };
  {
    std::lock_guard lock(mutex_);
    TaskState& t = state_of();
    if (cancel->load() || stopping_) {
      t.state = "cancelled";
      persist(*job);
      return;
    }
    t.state = "running";
    if (kind == TaskKind::Validate) {
      request.options_json = t.result_json;
      t.result_json.clear();
    } else {
      request.options_json = job->options_json;
    }
    persist(*job);
  }
  if (kind == TaskKind::Slice) {
    std::error_code ec;
    fs::remove_all(job->out(), ec);
  }
  TaskControl control;
  control.cancel = cancel;
  control.progress = [this, job, &state_of](std::uint32_t done, std::uint32_t total) {
    std::lock_guard lock(mutex_);
    state_of().done = done;
    state_of().total = total;
  };
  const auto started = std::chrono::steady_clock::now();
  Result<std::string> result = Error{ErrorCode::Internal, "not run", {}};
  try {
    result = runner_(request, control);
  } catch (const std::bad_alloc&) {
    result = Error{ErrorCode::Internal, "out of memory", {}};
  } catch (const std::exception& e) {
    result = Error{ErrorCode::Internal, std::string("internal error: ") + e.what(), {}};
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const bool cancelled = cancel->load();
  if (result && kind == TaskKind::Slice && !cancelled) {
    // The PNG and SVG stacks are offered as one archive each.
    for (const char* what : {"png", "svg"}) {
      auto entries = zip_entries_of_folder(job->out() / what, job->stem + "-" + what + "/");
      if (!entries) {
        result = entries.error();
        break;
      }
      const fs::path archive = job->out() / (job->stem + "-" + what + ".zip");
      if (auto ok = write_zip(archive, *entries); !ok) {
        result = ok.error();
        break;
      }
    }
  }
  if (!result || cancelled) {
    std::error_code ec;
    if (kind == TaskKind::Slice) fs::remove_all(job->out(), ec);
  } else {
    const char* file = kind == TaskKind::Check      ? "check.json"
                       : kind == TaskKind::Validate ? "validation.json"
                                                    : nullptr;
    if (file != nullptr) {
      auto written = io::write_text_file(job->dir / file, *result + "\n");
      (void)written;
    }
  }
  std::lock_guard lock(mutex_);
  TaskState& t = state_of();
  t.seconds = seconds;
  if (cancelled) {
    t.state = "cancelled";
    t.error = stopping_ ? "the server stopped" : "cancelled by the user: nothing was kept";
  } else if (!result) {
    t.state = "failed";
    t.error = result.error().to_string();
  } else {
    t.state = "done";
    t.result_json = std::move(result).value();
  }
  persist(*job);
}

void JobStore::persist(const Job& job) const {
  if (!job.visible) return;
  json j = {{"id", job.id},
            {"name", job.name},
            {"created", job.created_ms},
            {"options", parse_or_null(job.options_json)},
            {"check", task_json(job.check, true)},
            {"slice", task_json(job.slice, true)},
            {"validate", task_json(job.validate, job.validate.state == "done")}};
  auto written = io::write_text_file(job.dir / "job.json", j.dump(1) + "\n");
  (void)written;
}

std::string JobStore::list_json() const {
  std::lock_guard lock(mutex_);
  json list = json::array();
  for (const auto& [id, job] : jobs_) {
    if (!job->visible) continue;
    json verdict = nullptr;
    if (job->check.state == "done") {
      const json r = parse_or_null(job->check.result_json);
      if (r.is_object() && r.contains("verdict")) verdict = r["verdict"];
    }
    list.push_back({{"id", id},
                    {"name", job->name},
                    {"created", job->created_ms},
                    {"options", parse_or_null(job->options_json)},
                    {"verdict", verdict},
                    {"check", task_json(job->check, false)},
                    {"slice", task_json(job->slice, false)},
                    {"validate", task_json(job->validate, false)}});
  }
  return json{{"jobs", list}}.dump();
}

std::optional<std::string> JobStore::status_json(const std::string& id) const {
  std::lock_guard lock(mutex_);
  const auto job = find(id);
  if (!job || !job->visible) return std::nullopt;
  json files = json::array();
  for (const std::string_view kind : kFileKinds) {
    const bool available = kind == "model"        ? true
                           : kind == "check"      ? job->check.state == "done"
                           : kind == "validation" ? job->validate.state == "done"
                                                  : job->slice.state == "done";
    if (available) files.push_back(kind);
  }
  json j = {{"id", job->id},
            {"name", job->name},
            {"stem", job->stem},
            {"created", job->created_ms},
            {"options", parse_or_null(job->options_json)},
            {"check", task_json(job->check, true)},
            {"slice", task_json(job->slice, true)},
            {"validate", task_json(job->validate, job->validate.state == "done")},
            {"files", files}};
  return j.dump();
}

std::optional<JobFile> JobStore::file(const std::string& id, const std::string& kind) const {
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(mutex_);
    job = find(id);
    if (!job || !job->visible) return std::nullopt;
    const bool slice_done = job->slice.state == "done";
    if (!slice_done && kind != "model" && kind != "check" && kind != "validation" &&
        kind != "view") {
      return std::nullopt;
    }
    if (kind == "view" && !slice_done) {
      // Before the slice, the page's data of the model alone, which the check leaves.
      JobFile f{job->dir / "model-view.json", "view.json", "application/json"};
      if (!regular_file(f.path)) return std::nullopt;
      return f;
    }
  }
  const std::string& s = job->stem;
  JobFile f;
  if (kind == "model") {
    f = {job->model(), job->name, "application/octet-stream"};
  } else if (kind == "check") {
    f = {job->dir / "check.json", s + "-check.json", "application/json"};
  } else if (kind == "validation") {
    f = {job->dir / "validation.json", s + "-validation.json", "application/json"};
  } else if (kind == "cells") {
    f = {job->out() / (s + ".cells"), s + ".cells", "application/octet-stream"};
  } else if (kind == "png" || kind == "svg") {
    f = {job->out() / (s + "-" + kind + ".zip"), s + "-" + kind + ".zip", "application/zip"};
  } else if (kind == "cli") {
    f = {job->out() / (s + ".cli"), s + ".cli", "text/plain; charset=utf-8"};
  } else if (kind == "json") {
    f = {job->out() / (s + ".json"), s + ".json", "application/json"};
  } else if (kind == "html") {
    f = {job->out() / (s + ".html"), s + ".html", "text/html; charset=utf-8"};
  } else if (kind == "view") {
    f = {job->out() / "view.json", "view.json", "application/json"};
  } else {
    return std::nullopt;
  }
  if (!regular_file(f.path)) return std::nullopt;
  return f;
}

void JobStore::shutdown() {
  std::unique_lock lock(mutex_);
  stopping_ = true;
  for (auto& [id, job] : jobs_) {
    for (auto* flag : {&job->cancel_check, &job->cancel_slice, &job->cancel_validate}) {
      flag->store(true);
    }
  }
  idle_.wait(lock, [this] { return tasks_in_flight_ == 0; });
}

}  // namespace strata::serve::detail
