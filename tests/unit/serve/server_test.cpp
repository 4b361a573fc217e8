#include "strata/serve/server.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "support/http_client.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"
#include "support/test_server.hpp"
#include "support/text_meshes.hpp"

namespace strata::serve::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::HttpClient;
using test::HttpReply;

TEST(Server, ListensOnAFreePortWhenAskedForPortZero) {
  TestServer s;
  EXPECT_NE(s.port(), 0);
  EXPECT_EQ(HttpClient(s.port()).request("GET", "/api/info").status, 200u);
}

TEST(Server, RefusesABindAddressThatIsNotAnIpAddress) {
  ServerParts parts;
  ServerOptions options;
  options.bind_address = "localhost";
  const auto server = parts.start(options);
  ASSERT_FALSE(server);
  EXPECT_EQ(server.error().code, ErrorCode::Usage);
  EXPECT_EQ(server.error().message, "not an IP address: localhost");
  EXPECT_EQ(server.error().location, "--bind");
}

TEST(Server, RefusesAPortInUse) {
  TestServer first;
  ServerParts parts;
  ServerOptions options;
  options.port = first.port();
  const auto second = parts.start(options);
  ASSERT_FALSE(second);
  EXPECT_EQ(second.error().code, ErrorCode::Usage);
  EXPECT_EQ(second.error().message, "cannot listen on 127.0.0.1 port " +
                                        std::to_string(first.port()) + ": Address already in use");
}

TEST(Server, AddModelMakesACheckedJobOfACopy) {
  TestServer s;
  test::TempDir models("models");
  const fs::path model = test::write_text_file(models / "part.stl", kGoodModel);
  const auto id = s.server->add_model(model);
  ASSERT_TRUE(id) << id.error().to_string();
  EXPECT_EQ(*id, "000001");
  EXPECT_EQ(s.wait_for(*id, "check")["check"]["result"], json({{"verdict", "printable"}}));
  EXPECT_EQ(test::read_file(s.jobs / "000001" / "model" / "part.stl"), kGoodModel);
  EXPECT_TRUE(fs::exists(model));

  const auto missing = s.server->add_model(models / "missing.stl");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().code, ErrorCode::BadInput);
  EXPECT_EQ(missing.error().message, "cannot read the model: No such file or directory");
  EXPECT_EQ(missing.error().location, (models / "missing.stl").string());

  const auto not_a_model = s.server->add_model(test::write_text_file(models / "notes.txt", "x"));
  ASSERT_FALSE(not_a_model);
  EXPECT_EQ(not_a_model.error().code, ErrorCode::BadInput);
  EXPECT_EQ(not_a_model.error().message,
            "not a model file name: strata reads .stl, .obj, .off, .ply and .3mf files, and .gz of "
            "the first four");
  EXPECT_EQ(not_a_model.error().location, (models / "notes.txt").string());
  // Neither left a job behind.
  EXPECT_EQ(json::parse(HttpClient(s.port()).request("GET", "/api/jobs").body)["jobs"].size(), 1u);
}

TEST(Server, StopCancelsRunningTasksAndIsIdempotent) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  ASSERT_EQ(
      HttpClient(s.port()).request("POST", "/api/jobs/" + id + "/slice", R"({"wait":true})").status,
      202u);
  s.wait_for_progress(id);
  s.server->stop();
  s.server->stop();
  const json job = json::parse(test::read_file(s.jobs / id / "job.json"));
  EXPECT_EQ(job["slice"]["state"], "cancelled");
  EXPECT_EQ(job["slice"]["error"], "the server stopped");
  EXPECT_FALSE(fs::exists(s.jobs / id / "out"));
}

TEST(Server, AStoppingServerTakesNoNewWork) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  s.wait_for(id, "check");
  HttpClient client(s.port());  // connected before the server stops accepting
  ASSERT_EQ(client.request("POST", "/api/jobs/" + id + "/slice", R"({"hold":true})").status, 202u);
  s.wait_for_progress(id);
  // stop() waits for the held task, which holds until the test releases it.
  std::thread stopping([&s] { s.server->stop(); });
  ASSERT_TRUE(s.tasks.wait_until_held_task_cancelled());
  HttpReply r = client.request("POST", "/api/jobs/" + id + "/validate", "{}");
  EXPECT_EQ(r.status, 409u);
  EXPECT_EQ(json::parse(r.body), error_body("the server is stopping"));
  r = client.request("POST", "/api/jobs/" + id + "/slice", "{}");
  EXPECT_EQ(r.status, 409u);
  EXPECT_EQ(json::parse(r.body), error_body("the server is stopping"));
  r = client.request("POST", "/api/jobs?name=other.stl", kGoodModel);
  EXPECT_EQ(r.status, 503u);
  EXPECT_EQ(json::parse(r.body), error_body("the server is stopping"));
  s.tasks.release();
  stopping.join();
  EXPECT_FALSE(fs::exists(s.jobs / "000002"));
}

TEST(Server, BoundBeyondLoopbackItAnswersAnyHost) {
  ServerParts parts;
  ServerOptions options;
  options.bind_address = "0.0.0.0";
  options.port = 0;
  auto server = parts.start(options);
  ASSERT_TRUE(server) << server.error().to_string();
  const HttpReply r = HttpClient((*server)->port())
                          .request("GET", "/api/info", {}, {{"Host", "printer.example:8080"}});
  EXPECT_EQ(r.status, 200u);
}

TEST(Server, JobsOfAnEarlierRunAreServedAgain) {
  ServerParts parts;
  ServerOptions options;
  options.port = 0;
  {
    auto first = parts.start(options);
    ASSERT_TRUE(first);
    HttpClient client((*first)->port());
    ASSERT_EQ(client.request("POST", "/api/jobs?name=part.stl", kGoodModel).status, 201u);
  }
  auto again = parts.start(options);
  ASSERT_TRUE(again);
  const HttpReply r = HttpClient((*again)->port()).request("GET", "/api/jobs/000001/files/model");
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(r.body, kGoodModel);
}

}  // namespace
}  // namespace strata::serve::testing
