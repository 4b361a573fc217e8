#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "serve/job_store_internal.hpp"
#include "support/fake_tasks.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"
#include "support/text_meshes.hpp"

namespace strata::serve::detail {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class JobStoreTest : public ::testing::Test {
 protected:
  void SetUp() override { test::write_text_file(model_, "solid x\nendsolid x\n"); }

  /// Waits until the job's task `which` has left queued and running.
  json wait_for(JobStore& store, const std::string& id, const std::string& which) {
    for (int n = 0; n < 2000; ++n) {
      const json j = json::parse(*store.status_json(id));
      const std::string state = j[which]["state"];
      if (state != "queued" && state != "running") return j;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ADD_FAILURE() << "the task did not end";
    return json::parse(*store.status_json(id));
  }

  // The jobs folder, and the models beside it (outside it, as a user's files are).
  test::TempDir jobs_{"jobs"};
  test::TempDir models_{"models"};
  fs::path root_ = jobs_.path();
  fs::path model_ = models_ / "part.stl";
  testing::FakeTasks tasks_;
};

TEST_F(JobStoreTest, AnUploadIsCheckedAndSlicedIntoItsFolder) {
  JobStore store(root_, tasks_.runner());
  auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  EXPECT_EQ(wait_for(store, *id, "check")["check"]["result"]["verdict"], "printable");
  auto sliced = store.slice(*id, R"({"shell":1})");
  ASSERT_TRUE(sliced);
  EXPECT_EQ(*sliced, *id);  // the first slice of a job runs in it
  const json j = wait_for(store, *id, "slice");
  EXPECT_EQ(j["slice"]["state"], "done");
  EXPECT_EQ(j["options"]["shell"], 1);
  EXPECT_TRUE(fs::exists(root_ / *id / "options.json"));
  EXPECT_TRUE(fs::exists(root_ / *id / "job.json"));
  const auto png = store.file(*id, "png");
  ASSERT_TRUE(png);
  EXPECT_TRUE(fs::exists(png->path));
  EXPECT_EQ(png->download_name, fs::path(model_).stem().string() + "-png.zip");
  // A second parameter set is a job of its own, with the same model.
  auto second = store.slice(*id, R"({"shell":2})");
  ASSERT_TRUE(second);
  EXPECT_NE(*second, *id);
  EXPECT_EQ(wait_for(store, *second, "slice")["slice"]["state"], "done");
  EXPECT_EQ(json::parse(store.list_json())["jobs"].size(), 2u);
}

TEST_F(JobStoreTest, AQueuedCheckStartsWhileEveryTbbWorkerIsHeldElsewhere) {
  // The tasks have a thread of their own: a check does not wait for a TBB worker, which other
  // work in the process may hold for long (here until the check has ended).
  JobStore store(root_, tasks_.runner());
  const int slots = tbb::this_task_arena::max_concurrency();
  std::atomic<int> held{0};
  std::atomic<bool> release{false};
  std::thread holder([&] {
    tbb::parallel_for(0, slots, 1, [&](int) {
      ++held;
      while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
  });
  for (int n = 0; n < 2000 && held < slots; ++n) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  const json j = wait_for(store, *id, "check");
  release = true;
  holder.join();
  EXPECT_EQ(j["check"]["state"], "done");
}

TEST_F(JobStoreTest, ACancelledSliceLeavesNoOutput) {
  JobStore store(root_, tasks_.runner());
  auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  ASSERT_TRUE(store.slice(*id, R"({"wait":true})"));
  for (int n = 0; n < 2000; ++n) {
    if (json::parse(*store.status_json(*id))["slice"]["done"].get<int>() > 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  store.cancel(*id);
  const json j = wait_for(store, *id, "slice");
  EXPECT_EQ(j["slice"]["state"], "cancelled");
  EXPECT_FALSE(fs::exists(root_ / *id / "out"));
  EXPECT_FALSE(store.file(*id, "cells"));
}

TEST_F(JobStoreTest, ADiscardedUploadLeavesNothing) {
  JobStore store(root_, tasks_.runner());
  auto id = store.reserve("part.stl");
  ASSERT_TRUE(id);
  std::ofstream(store.model_path(*id)) << "partial";
  EXPECT_FALSE(store.exists(*id));  // hidden while uploading
  EXPECT_EQ(json::parse(store.list_json())["jobs"].size(), 0u);
  store.discard(*id);
  EXPECT_FALSE(fs::exists(root_ / *id));
  EXPECT_EQ(json::parse(store.list_json())["jobs"].size(), 0u);
}

TEST_F(JobStoreTest, JobsOfAnEarlierSessionAreListedAgain) {
  std::string id;
  {
    JobStore store(root_, tasks_.runner());
    auto added = store.add_file(model_);
    ASSERT_TRUE(added);
    id = *added;
    wait_for(store, id, "check");
  }
  JobStore again(root_, tasks_.runner());
  ASSERT_TRUE(again.exists(id));
  EXPECT_EQ(json::parse(*again.status_json(id))["check"]["state"], "done");
  auto next = again.add_file(model_);
  ASSERT_TRUE(next);
  EXPECT_NE(*next, id);
}

TEST_F(JobStoreTest, ShutdownCancelsRunningTasks) {
  JobStore store(root_, tasks_.runner());
  auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  ASSERT_TRUE(store.slice(*id, R"({"wait":true})"));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  store.shutdown();
  const std::string state = json::parse(*store.status_json(*id))["slice"]["state"];
  EXPECT_TRUE(state == "cancelled" || state == "queued") << state;
  EXPECT_FALSE(store.slice(*id, "{}"));
}

TEST_F(JobStoreTest, ATaskThatFailsKeepsItsMessageAndNoOutput) {
  JobStore store(root_, tasks_.runner());
  auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  const struct {
    const char* options;
    std::string error;
  } failures[] = {
      {R"({"fail":"no cells"})", "no cells"},
      {R"({"throw":"broken"})", "internal error: broken"},
      {R"({"out_of_memory":true})", "out of memory"},
      // A slice without its SVG stack cannot offer the stack's archive.
      {R"({"no_svg":true})", "/out/svg: No such file or directory"},
  };
  for (const auto& f : failures) {
    auto sliced = store.slice(*id, f.options);
    ASSERT_TRUE(sliced) << f.options;
    const json j = wait_for(store, *sliced, "slice");
    EXPECT_EQ(j["slice"]["state"], "failed") << f.options;
    const std::string error = j["slice"]["error"];
    if (f.error.front() == '/') {
      EXPECT_EQ(error, (root_ / *sliced).string() + f.error) << f.options;
    } else {
      EXPECT_EQ(error, f.error) << f.options;
    }
    EXPECT_FALSE(fs::exists(root_ / *sliced / "out")) << f.options;
    EXPECT_FALSE(store.file(*sliced, "cells")) << f.options;
  }
}

TEST_F(JobStoreTest, AnUnknownJobIsRefusedOrLeftAlone) {
  JobStore store(root_, tasks_.runner());
  const auto expect_no_such_job = [](const Error& e) {
    EXPECT_EQ(e.code, ErrorCode::BadInput);
    EXPECT_EQ(e.message, "no such job");
    EXPECT_EQ(e.location, "00ff");
  };
  expect_no_such_job(store.slice("00ff", "{}").error());
  expect_no_such_job(store.validate("00ff", "{}").error());
  expect_no_such_job(store.remove("00ff").error());
  store.cancel("00ff");
  store.commit("00ff");
  store.discard("00ff");
  EXPECT_FALSE(store.exists("00ff"));
  EXPECT_FALSE(store.status_json("00ff"));
  EXPECT_FALSE(store.file("00ff", "model"));
  EXPECT_EQ(store.model_path("00ff"), fs::path());
  EXPECT_TRUE(fs::is_empty(root_));
}

TEST_F(JobStoreTest, AJobFolderInTheWayIsAnInternalError) {
  JobStore store(root_, tasks_.runner());
  test::write_text_file(root_ / "000001", "a file, not a folder");
  const auto id = store.reserve("part.stl");
  ASSERT_FALSE(id);
  EXPECT_EQ(id.error().code, ErrorCode::Internal);
  EXPECT_EQ(id.error().message, "cannot make the job's folder: Not a directory");
  EXPECT_EQ(id.error().location, (root_ / "000001").string());
  EXPECT_FALSE(store.exists("000001"));
  test::write_text_file(root_ / "000002", "another file");
  const auto added = store.add_file(model_);
  ASSERT_FALSE(added);
  EXPECT_EQ(added.error().message, "cannot make the job's folder: Not a directory");
}

TEST_F(JobStoreTest, AJobBeingUploadedIsInvisible) {
  JobStore store(root_, tasks_.runner());
  const auto id = store.reserve("part.stl");
  ASSERT_TRUE(id);
  EXPECT_EQ(store.slice(*id, "{}").error().message, "no such job");
  EXPECT_EQ(store.validate(*id, "{}").error().message, "no such job");
  EXPECT_EQ(store.remove(*id).error().message, "no such job");
  EXPECT_FALSE(store.exists(*id));
  EXPECT_FALSE(store.status_json(*id));
  EXPECT_FALSE(store.file(*id, "model"));
  EXPECT_TRUE(fs::is_directory(root_ / *id / "model"));
}

TEST_F(JobStoreTest, DiscardLeavesACommittedJobAlone) {
  JobStore store(root_, tasks_.runner());
  const auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  store.discard(*id);
  EXPECT_TRUE(store.exists(*id));
  EXPECT_EQ(test::read_file(root_ / *id / "model" / model_.filename()), "solid x\nendsolid x\n");
}

TEST_F(JobStoreTest, AnUploadCommittedWhileStoppingIsKeptUnchecked) {
  JobStore store(root_, tasks_.runner());
  const auto id = store.reserve("part.stl");
  ASSERT_TRUE(id);
  test::write_text_file(store.model_path(*id), "solid x\n");
  store.shutdown();
  store.commit(*id);
  ASSERT_TRUE(store.exists(*id));
  EXPECT_EQ(json::parse(*store.status_json(*id))["check"]["state"], "none");
  EXPECT_EQ(json::parse(test::read_file(root_ / *id / "job.json"))["check"]["state"], "none");
}

TEST_F(JobStoreTest, ASliceOfAModelStillBeingCheckedChecksItsNewJobAgain) {
  JobStore store(root_, tasks_.runner());
  test::write_text_file(model_, "solid wait\n");
  const auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  for (int n = 0; n < 5000 && json::parse(*store.status_json(*id))["check"]["state"] != "running";
       ++n) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_EQ(json::parse(*store.status_json(*id))["check"]["state"], "running");
  ASSERT_TRUE(store.slice(*id, "{}"));  // the job's own first slice
  const auto second = store.slice(*id, R"({"layers":1})");
  ASSERT_TRUE(second);
  ASSERT_NE(*second, *id);
  // The running check is the first job's: the new job queues its own, with nothing copied.
  const std::string state = json::parse(*store.status_json(*second))["check"]["state"];
  EXPECT_TRUE(state == "queued" || state == "running") << state;
  EXPECT_FALSE(fs::exists(root_ / *second / "check.json"));
  store.cancel(*id);
  store.cancel(*second);
  EXPECT_EQ(wait_for(store, *second, "check")["check"]["state"], "cancelled");
}

TEST_F(JobStoreTest, OnlyTheDownloadsAJobHasAreOffered) {
  JobStore store(root_, tasks_.runner());
  const fs::path bad = test::write_text_file(models_ / "bad.stl", "not a mesh");
  auto id = store.add_file(bad);
  fs::remove(bad);
  ASSERT_TRUE(id);
  EXPECT_EQ(wait_for(store, *id, "check")["check"]["state"], "failed");
  // A model that cannot be read leaves no page data, and no check to download.
  EXPECT_FALSE(store.file(*id, "view"));
  EXPECT_FALSE(store.file(*id, "check"));
  EXPECT_TRUE(store.file(*id, "model"));

  auto good = store.add_file(model_);
  ASSERT_TRUE(good);
  ASSERT_TRUE(store.slice(*good, "{}"));
  EXPECT_EQ(wait_for(store, *good, "slice")["slice"]["state"], "done");
  EXPECT_FALSE(store.file(*good, "validation"));  // never validated
  EXPECT_FALSE(store.file(*good, "options"));     // not a download
  const auto view = store.file(*good, "view");
  ASSERT_TRUE(view);
  EXPECT_EQ(view->path, root_ / *good / "out" / "view.json");
}

TEST_F(JobStoreTest, AnEarlierSessionsJobsAreReadBackWhenSound) {
  const auto job = [&](const std::string& id, const json& j, bool with_model = true) {
    fs::create_directories(root_ / id / "model");
    if (!j.is_null()) test::write_text_file(root_ / id / "job.json", j.dump());
    if (with_model) test::write_text_file(root_ / id / "model" / "part.stl", "solid x\n");
  };
  const json sound = {{"id", "000001"},
                      {"name", "part.stl"},
                      {"created", 1234},
                      {"options", {{"shell", 1}}},
                      {"check", {{"state", "done"}, {"result", {{"verdict", "printable"}}}}},
                      {"slice", {{"state", "running"}, {"done", 3}, {"total", 9}}},
                      {"validate", 7}};
  // 00000a: a validation the last session had queued.
  job("000001", sound);
  job("000002", nullptr);  // no job.json
  job("000003", nullptr);
  test::write_text_file(root_ / "000003" / "job.json", "{not json");
  job("000004", {{"id", "000004"}});                            // no name
  job("000005", {{"name", 5}});                                 // a name that is not text
  job("000006", {{"name", "run.sh"}});                          // not a model's name
  job("000007", {{"name", "sub/part.stl"}});                    // a path, not a name
  job("000008", {{"name", "part.stl"}}, /*with_model=*/false);  // its model is gone
  job("notes", {{"name", "part.stl"}});                         // not a job id
  job("00000a", {{"name", "part.stl"}, {"options", "fast"}, {"validate", {{"state", "queued"}}}});

  JobStore store(root_, tasks_.runner());
  const json list = json::parse(store.list_json())["jobs"];
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["id"], "000001");
  EXPECT_EQ(list[1]["id"], "00000a");
  const json first = json::parse(*store.status_json("000001"));
  EXPECT_EQ(first["created"], 1234);
  EXPECT_EQ(first["options"], json({{"shell", 1}}));
  EXPECT_EQ(first["check"]["result"], json({{"verdict", "printable"}}));
  EXPECT_EQ(first["validate"]["state"], "none");
  // A task the last session left unfinished failed.
  EXPECT_EQ(first["slice"]["state"], "failed");
  EXPECT_EQ(first["slice"]["error"], "interrupted: the server stopped before it finished");
  EXPECT_EQ(first["slice"]["done"], 3);
  EXPECT_EQ(json::parse(test::read_file(root_ / "000001" / "job.json"))["slice"]["state"],
            "failed");
  const json tenth = json::parse(*store.status_json("00000a"));
  EXPECT_EQ(tenth["options"], nullptr);
  EXPECT_EQ(tenth["validate"]["state"], "failed");
  // New jobs take ids after the highest one read.
  auto next = store.add_file(model_);
  ASSERT_TRUE(next);
  EXPECT_EQ(*next, "00000b");
}

}  // namespace
}  // namespace strata::serve::detail
