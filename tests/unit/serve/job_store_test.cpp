#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "serve/job_store_internal.hpp"

namespace strata::serve::detail {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class JobStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("strata-jobs-" +
             std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    model_ = root_.parent_path() / (root_.filename().string() + "-part.stl");
    std::ofstream(model_) << "solid x\nendsolid x\n";
  }
  void TearDown() override {
    fs::remove_all(root_);
    fs::remove(model_);
  }

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

  fs::path root_;
  fs::path model_;
};

/// Check answers {"verdict": "printable"}; slice writes a file and then waits for a cancel.
TaskRunner fake_runner(bool slice_waits) {
  return [slice_waits](const TaskRequest& r, const TaskControl& c) -> Result<std::string> {
    if (r.kind == TaskKind::Check) return std::string(R"({"verdict":"printable"})");
    if (r.kind == TaskKind::Validate) return std::string(R"({"verdict":"agree"})");
    fs::create_directories(r.output_dir);
    for (const char* name : {".cells", ".cli", ".json", ".html"}) {
      std::ofstream(r.output_dir / (r.stem + name)) << "x";
    }
    std::ofstream(r.output_dir / "view.json") << "{}";
    fs::create_directories(r.output_dir / "png");
    std::ofstream(r.output_dir / "png" / "a.png") << "p";
    fs::create_directories(r.output_dir / "svg");
    for (std::uint32_t k = 0; slice_waits && k < 100000; ++k) {
      c.progress(k, 100000);
      if (c.cancel->load()) return Error{ErrorCode::Internal, "cancelled", {}};
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return std::string(R"({"cells":{}})");
  };
}

TEST_F(JobStoreTest, AnUploadIsCheckedAndSlicedIntoItsFolder) {
  JobStore store(root_, fake_runner(false));
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

TEST_F(JobStoreTest, ACancelledSliceLeavesNoOutput) {
  JobStore store(root_, fake_runner(true));
  auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  ASSERT_TRUE(store.slice(*id, "{}"));
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
  JobStore store(root_, fake_runner(false));
  auto id = store.reserve("part.stl");
  ASSERT_TRUE(id);
  std::ofstream(store.model_path(*id)) << "partial";
  EXPECT_FALSE(store.exists(*id));  // hidden while uploading
  store.discard(*id);
  EXPECT_FALSE(fs::exists(root_ / *id));
  EXPECT_EQ(json::parse(store.list_json())["jobs"].size(), 0u);
}

TEST_F(JobStoreTest, JobsOfAnEarlierSessionAreListedAgain) {
  std::string id;
  {
    JobStore store(root_, fake_runner(false));
    auto added = store.add_file(model_);
    ASSERT_TRUE(added);
    id = *added;
    wait_for(store, id, "check");
  }
  JobStore again(root_, fake_runner(false));
  ASSERT_TRUE(again.exists(id));
  EXPECT_EQ(json::parse(*again.status_json(id))["check"]["state"], "done");
  auto next = again.add_file(model_);
  ASSERT_TRUE(next);
  EXPECT_NE(*next, id);
}

TEST_F(JobStoreTest, ShutdownCancelsRunningTasks) {
  JobStore store(root_, fake_runner(true));
  auto id = store.add_file(model_);
  ASSERT_TRUE(id);
  ASSERT_TRUE(store.slice(*id, "{}"));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  store.shutdown();
  const std::string state = json::parse(*store.status_json(*id))["slice"]["state"];
  EXPECT_TRUE(state == "cancelled" || state == "queued") << state;
  EXPECT_FALSE(store.slice(*id, "{}"));
}

}  // namespace
}  // namespace strata::serve::detail
