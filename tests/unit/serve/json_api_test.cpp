// The JSON API of `strata serve` over HTTP, route by route (src/serve/route.cpp lists them):
// status codes and bodies, on a server running FakeTasks.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/http_client.hpp"
#include "support/read_file.hpp"
#include "support/test_server.hpp"

namespace strata::serve::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::HttpClient;
using test::HttpReply;

TEST(JsonApi, InfoGivesTheUploadLimitAndTheFormats) {
  ServerOptions options;
  options.max_upload_bytes = 12345;
  TestServer s(options);
  HttpClient client(s.port());
  const HttpReply r = client.request("GET", "/api/info");
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(r.field("Content-Type"), "application/json");
  EXPECT_EQ(json::parse(r.body),
            json({{"generator", "strata 0.1.0"},
                  {"max_upload_bytes", 12345},
                  {"formats", {".stl", ".obj", ".off", ".ply", ".3mf", ".gz"}}}));
  // Every answer: not cached, not sniffed, no referrer.
  EXPECT_EQ(r.field("Server"), "strata");
  EXPECT_EQ(r.field("Cache-Control"), "no-store");
  EXPECT_EQ(r.field("X-Content-Type-Options"), "nosniff");
  EXPECT_EQ(r.field("Referrer-Policy"), "no-referrer");
  EXPECT_EQ(r.field("Content-Disposition"), "");
}

TEST(JsonApi, TheAppPageIsServedAtTheRoot) {
  TestServer s;
  HttpClient client(s.port());
  const HttpReply r = client.request("GET", "/");
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(r.field("Content-Type"), "text/html; charset=utf-8");
  EXPECT_EQ(r.body.rfind("<!doctype html>", 0), 0u) << r.body.substr(0, 40);
  EXPECT_NE(r.body.find("<title>strata serve</title>"), std::string::npos);
}

TEST(JsonApi, AnUploadIsCheckedSlicedAndDownloaded) {
  TestServer s;
  HttpClient client(s.port());
  HttpReply r = client.request("POST", "/api/jobs?name=my%20part.stl", kGoodModel);
  ASSERT_EQ(r.status, 201u) << r.body;
  EXPECT_EQ(json::parse(r.body), json({{"id", "000001"}}));
  EXPECT_EQ(test::read_file(s.jobs / "000001" / "model" / "my part.stl"), kGoodModel);

  json status = s.wait_for("000001", "check");
  EXPECT_EQ(status["name"], "my part.stl");
  EXPECT_EQ(status["stem"], "my part");
  EXPECT_EQ(status["check"]["state"], "done");
  EXPECT_EQ(status["check"]["result"], json({{"verdict", "printable"}}));
  EXPECT_EQ(status["slice"]["state"], "none");
  EXPECT_EQ(status["files"], json({"model", "check"}));

  r = client.request("GET", "/api/jobs");
  ASSERT_EQ(r.status, 200u);
  const json list = json::parse(r.body)["jobs"];
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0]["id"], "000001");
  EXPECT_EQ(list[0]["verdict"], "printable");
  EXPECT_EQ(list[0]["check"]["result"], nullptr);  // the list leaves results out

  // Before the slice: the model, its check, and the page's data of the model alone.
  r = client.request("GET", "/api/jobs/000001/view.json");
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(json::parse(r.body), json({{"model", "my part.stl"}}));
  EXPECT_EQ(r.field("Content-Disposition"), "");
  r = client.request("GET", "/api/jobs/000001/files/model");
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(r.body, kGoodModel);
  EXPECT_EQ(r.field("Content-Type"), "application/octet-stream");
  EXPECT_EQ(r.field("Content-Disposition"), "attachment; filename=\"my part.stl\"");
  r = client.request("GET", "/api/jobs/000001/files/check");
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(r.body, "{\"verdict\":\"printable\"}\n");
  EXPECT_EQ(r.field("Content-Disposition"), "attachment; filename=\"my part-check.json\"");
  r = client.request("GET", "/api/jobs/000001/files/cells");
  EXPECT_EQ(r.status, 404u);
  EXPECT_EQ(json::parse(r.body), error_body("this job has no such file (yet)"));

  r = client.request("POST", "/api/jobs/000001/slice", R"({"layers": 3})");
  EXPECT_EQ(r.status, 202u);
  EXPECT_EQ(json::parse(r.body), json({{"id", "000001"}}));
  status = s.wait_for("000001", "slice");
  EXPECT_EQ(status["slice"]["state"], "done");
  EXPECT_EQ(status["slice"]["done"], 3);
  EXPECT_EQ(status["slice"]["total"], 3);
  EXPECT_EQ(status["slice"]["result"], json({{"layers", 3}}));
  EXPECT_EQ(status["options"], json({{"layers", 3}}));
  EXPECT_EQ(status["files"],
            json({"model", "cells", "png", "svg", "cli", "json", "html", "check"}));
  EXPECT_EQ(test::read_file(s.jobs / "000001" / "options.json"), "{\"layers\":3}\n");

  const struct {
    const char* kind;
    const char* content_type;
    const char* download;
    std::string body;
  } downloads[] = {
      {"cells", "application/octet-stream", "my part.cells", "cells of my part"},
      {"cli", "text/plain; charset=utf-8", "my part.cli", ".cli of my part"},
      {"json", "application/json", "my part.json", ".json of my part"},
      {"html", "text/html; charset=utf-8", "my part.html", ".html of my part"},
      {"png", "application/zip", "my part-png.zip", ""},
      {"svg", "application/zip", "my part-svg.zip", ""},
  };
  for (const auto& d : downloads) {
    r = client.request("GET", std::string("/api/jobs/000001/files/") + d.kind);
    EXPECT_EQ(r.status, 200u) << d.kind;
    EXPECT_EQ(r.field("Content-Type"), d.content_type) << d.kind;
    EXPECT_EQ(r.field("Content-Disposition"),
              "attachment; filename=\"" + std::string(d.download) + "\"")
        << d.kind;
    if (!d.body.empty()) {
      EXPECT_EQ(r.body, d.body) << d.kind;
    } else {
      // A ZIP archive holding the layer under the stem's folder.
      EXPECT_EQ(r.body.rfind("PK\x03\x04", 0), 0u) << d.kind;
      EXPECT_NE(r.body.find(std::string("my part-") + d.kind + "/my part_0001." + d.kind),
                std::string::npos)
          << d.kind;
    }
  }
  // Once sliced, the page's data is the slice's.
  r = client.request("GET", "/api/jobs/000001/view.json");
  EXPECT_EQ(json::parse(r.body), json({{"layers", 3}}));
}

TEST(JsonApi, TheViewerPageLoadsTheJobsData) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  HttpClient client(s.port());
  const HttpReply r = client.request("GET", "/viewer?job=" + id);
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(r.field("Content-Type"), "text/html; charset=utf-8");
  EXPECT_NE(r.body.find(R"({"format":"strata-view-remote","url":"/api/jobs/000001/view.json"})"),
            std::string::npos);
  const HttpReply unknown = client.request("GET", "/viewer?job=00ff");
  EXPECT_EQ(unknown.status, 404u);
  EXPECT_EQ(json::parse(unknown.body), error_body("no such job"));
  const HttpReply no_job = client.request("GET", "/viewer");
  EXPECT_EQ(no_job.status, 400u);
  EXPECT_EQ(json::parse(no_job.body), error_body("/viewer needs ?job=ID"));
}

TEST(JsonApi, ASecondSliceOfAJobIsANewJobOfTheSameModel) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  s.wait_for(id, "check");
  HttpClient client(s.port());
  ASSERT_EQ(client.request("POST", "/api/jobs/" + id + "/slice", "").status, 202u);
  EXPECT_EQ(s.wait_for(id, "slice")["options"], json::object());  // no body: default options
  const HttpReply r = client.request("POST", "/api/jobs/" + id + "/slice", R"({"layers":1})");
  EXPECT_EQ(r.status, 202u);
  EXPECT_EQ(json::parse(r.body), json({{"id", "000002"}}));
  const json second = s.wait_for("000002", "slice");
  EXPECT_EQ(second["name"], "part.stl");
  EXPECT_EQ(second["check"]["state"], "done");  // the model's check is not run again
  EXPECT_EQ(second["slice"]["result"], json({{"layers", 1}}));
  EXPECT_EQ(test::read_file(s.jobs / "000002" / "model" / "part.stl"), kGoodModel);
  EXPECT_EQ(json::parse(client.request("GET", "/api/jobs").body)["jobs"].size(), 2u);
}

TEST(JsonApi, ACancelledSliceKeepsNothingAndARunningJobCannotBeRemoved) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  HttpClient client(s.port());
  ASSERT_EQ(client.request("POST", "/api/jobs/" + id + "/slice", R"({"wait":true})").status, 202u);
  s.wait_for_progress(id);
  HttpReply r = client.request("DELETE", "/api/jobs/" + id);
  EXPECT_EQ(r.status, 409u);
  EXPECT_EQ(json::parse(r.body), error_body("the job is running: cancel it first"));

  r = client.request("POST", "/api/jobs/" + id + "/cancel");
  EXPECT_EQ(r.status, 202u);
  EXPECT_EQ(json::parse(r.body), json({{"id", id}}));
  const json status = s.wait_for(id, "slice");
  EXPECT_EQ(status["slice"]["state"], "cancelled");
  EXPECT_EQ(status["slice"]["error"], "cancelled by the user: nothing was kept");
  EXPECT_EQ(status["files"], json({"model", "check"}));
  EXPECT_FALSE(fs::exists(s.jobs / id / "out"));
  EXPECT_EQ(client.request("GET", "/api/jobs/" + id + "/files/cells").status, 404u);

  r = client.request("DELETE", "/api/jobs/" + id);
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(json::parse(r.body), json({{"id", id}}));
  EXPECT_FALSE(fs::exists(s.jobs / id));
  r = client.request("GET", "/api/jobs/" + id);
  EXPECT_EQ(r.status, 404u);
  EXPECT_EQ(json::parse(r.body), error_body("no such job"));
}

TEST(JsonApi, ValidateRunsWithItsOptionsOnceAtATime) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  HttpClient client(s.port());
  HttpReply r = client.request("POST", "/api/jobs/" + id + "/validate", R"({"shell": 1})");
  EXPECT_EQ(r.status, 202u);
  EXPECT_EQ(json::parse(r.body), json({{"id", id}}));
  json status = s.wait_for(id, "validate");
  EXPECT_EQ(status["validate"]["state"], "done");
  EXPECT_EQ(status["validate"]["result"],
            json({{"verdict", "agree"}, {"options", {{"shell", 1}}}}));
  r = client.request("GET", "/api/jobs/" + id + "/files/validation");
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(json::parse(r.body)["verdict"], "agree");
  EXPECT_EQ(r.field("Content-Disposition"), "attachment; filename=\"part-validation.json\"");

  // A validation the fake holds until cancelled: a second one is refused meanwhile.
  ASSERT_EQ(client.request("POST", "/api/jobs/" + id + "/validate", R"({"wait":true})").status,
            202u);
  r = client.request("POST", "/api/jobs/" + id + "/validate", "{}");
  EXPECT_EQ(r.status, 409u);
  EXPECT_EQ(json::parse(r.body), error_body("this job is being validated already"));
  ASSERT_EQ(client.request("POST", "/api/jobs/" + id + "/cancel").status, 202u);
  status = s.wait_for(id, "validate");
  EXPECT_EQ(status["validate"]["state"], "cancelled");
  EXPECT_EQ(status["validate"]["result"], nullptr);
  EXPECT_EQ(status["files"], json({"model", "check"}));
}

TEST(JsonApi, AModelThatCannotBeReadIsNotSliced) {
  TestServer s;
  const std::string id = s.upload("broken.stl", "garbage\n");
  const json status = s.wait_for(id, "check");
  const std::string read_error = (s.jobs / id / "model" / "broken.stl").string() + ": not a mesh";
  EXPECT_EQ(status["check"]["state"], "failed");
  EXPECT_EQ(status["check"]["error"], read_error);
  HttpClient client(s.port());
  const HttpReply r = client.request("POST", "/api/jobs/" + id + "/slice", "{}");
  EXPECT_EQ(r.status, 409u);
  EXPECT_EQ(json::parse(r.body), error_body("the model could not be read: " + read_error));
  // Its page data was never written.
  EXPECT_EQ(client.request("GET", "/api/jobs/" + id + "/view.json").status, 404u);
}

TEST(JsonApi, OptionsMustBeAJsonObjectOfAtMost64KiB) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  HttpClient client(s.port());
  for (const char* body : {"{", "[1]", "\"text\"", "{\"a\":}"}) {
    for (const char* action : {"slice", "validate"}) {
      const HttpReply r = client.request("POST", "/api/jobs/" + id + "/" + action, body);
      EXPECT_EQ(r.status, 400u) << action << " " << body;
      EXPECT_EQ(json::parse(r.body), error_body("the options must be a JSON object"))
          << action << " " << body;
    }
  }
  const std::string long_options = json{{"note", std::string(65536, 'x')}}.dump();
  const HttpReply r = client.request("POST", "/api/jobs/" + id + "/slice", long_options);
  EXPECT_EQ(r.status, 400u);
  EXPECT_EQ(json::parse(r.body), error_body("the options are too long"));
  EXPECT_EQ(s.wait_for(id, "check")["slice"]["state"], "none");
}

TEST(JsonApi, AnUnknownJobIs404OnEveryRoute) {
  TestServer s;
  HttpClient client(s.port());
  const struct {
    const char* method;
    const char* target;
  } requests[] = {{"GET", "/api/jobs/00ff"},
                  {"DELETE", "/api/jobs/00ff"},
                  {"POST", "/api/jobs/00ff/slice"},
                  {"POST", "/api/jobs/00ff/validate"},
                  {"POST", "/api/jobs/00ff/cancel"},
                  {"GET", "/api/jobs/00ff/view.json"},
                  {"GET", "/api/jobs/00ff/files/cells"}};
  for (const auto& q : requests) {
    const HttpReply r = client.request(q.method, q.target, "{}");
    EXPECT_EQ(r.status, 404u) << q.method << " " << q.target;
    EXPECT_EQ(json::parse(r.body), error_body("no such job")) << q.method << " " << q.target;
  }
}

TEST(JsonApi, AnythingElseIsNotFound) {
  TestServer s;
  HttpClient client(s.port());
  for (const char* target : {"/index.html", "/api", "/api/jobs/XYZ", "/api/jobs/0001/job.json",
                             "/api/jobs/0001/files/options", "/favicon.ico"}) {
    const HttpReply r = client.request("GET", target);
    EXPECT_EQ(r.status, 404u) << target;
    EXPECT_EQ(json::parse(r.body), error_body("not found")) << target;
  }
}

TEST(JsonApi, TraversalAndEncodedSeparatorsAre400) {
  TestServer s;
  s.upload("part.stl", kGoodModel);
  HttpClient client(s.port());
  for (const char* target : {"/api/jobs/000001/files/../../job.json", "/api/jobs/..",
                             "/api/jobs/000001\\..\\job.json", "//etc/passwd"}) {
    const HttpReply r = client.request("GET", target);
    EXPECT_EQ(r.status, 400u) << target;
    EXPECT_EQ(json::parse(r.body), error_body("the path is refused")) << target;
  }
  for (const char* target :
       {"/api/jobs/000001/files/%2e%2e%2fjob.json", "/api%2fjobs", "/api/jobs/000001%5cjob.json"}) {
    const HttpReply r = client.request("GET", target);
    EXPECT_EQ(r.status, 400u) << target;
    EXPECT_EQ(json::parse(r.body), error_body("encoded characters are refused in the path"))
        << target;
  }
  const HttpReply r = client.request("GET", "*");
  EXPECT_EQ(r.status, 400u);
  EXPECT_EQ(json::parse(r.body), error_body("the request target is not a path"));
}

TEST(JsonApi, AMethodARouteDoesNotTakeIs405) {
  TestServer s;
  HttpClient client(s.port());
  const struct {
    const char* method;
    const char* target;
  } requests[] = {{"PUT", "/api/jobs/0001"},
                  {"GET", "/api/jobs/0001/slice"},
                  {"GET", "/api/jobs/0001/cancel"},
                  {"POST", "/"},
                  {"DELETE", "/api/info"},
                  {"POST", "/viewer?job=0001"},
                  {"PUT", "/api/jobs"},
                  {"POST", "/api/jobs/0001/view.json"},
                  {"POST", "/api/jobs/0001/files/cells"}};
  for (const auto& q : requests) {
    const HttpReply r = client.request(q.method, q.target);
    EXPECT_EQ(r.status, 405u) << q.method << " " << q.target;
    EXPECT_EQ(json::parse(r.body), error_body("this method is not allowed here"))
        << q.method << " " << q.target;
  }
}

TEST(JsonApi, AnUploadNeedsAModelFileName) {
  TestServer s;
  HttpClient client(s.port());
  const struct {
    const char* target;
    const char* error;
  } uploads[] = {
      {"/api/jobs", "an upload needs ?name=FILE"},
      {"/api/jobs?name=run.sh",
       "not a model file name: strata reads .stl, .obj, .off, .ply and .3mf files, and .gz of the "
       "first four"},
      {"/api/jobs?name=.stl", "the file name starts with '.'"},
      {"/api/jobs?name=a%3Bb.stl",
       "the file name may hold letters, digits, '-', '_', '.', ' ', '(' and ')' only: rename the "
       "file"},
      {"/api/jobs?name=part%2", "a malformed %-escape"},
  };
  for (const auto& u : uploads) {
    const HttpReply r = client.request("POST", u.target, kGoodModel);
    EXPECT_EQ(r.status, 400u) << u.target;
    EXPECT_EQ(json::parse(r.body), error_body(u.error)) << u.target;
  }
  EXPECT_EQ(json::parse(client.request("GET", "/api/jobs").body), json({{"jobs", json::array()}}));
  EXPECT_TRUE(fs::is_empty(s.jobs.path()));
}

}  // namespace
}  // namespace strata::serve::testing
