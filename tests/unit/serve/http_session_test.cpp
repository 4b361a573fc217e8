// One connection of `strata serve` (src/serve/http_session.cpp): uploads streamed to disk and
// their limits, the Host check, keep-alive, HEAD, and what closes a connection.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "support/http_client.hpp"
#include "support/read_file.hpp"
#include "support/test_server.hpp"
#include "support/text_meshes.hpp"

namespace strata::serve::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::HttpClient;
using test::HttpReply;

/// Whether the jobs folder becomes empty within 10 s (a refused or broken upload is removed by
/// the server's thread, after the answer).
bool becomes_empty(const fs::path& folder) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!fs::is_empty(folder)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

std::string upload_header(std::string_view name, std::size_t length) {
  return "POST /api/jobs?name=" + std::string(name) +
         " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: " + std::to_string(length) + "\r\n\r\n";
}

TEST(HttpSession, AnUploadIsStoredByteForByte) {
  TestServer s;
  const test::TextMesh mesh = test::triangle_with_x(test::TextMeshFormat::StlAscii, "1");
  HttpClient client(s.port());
  const HttpReply r = client.request("POST", "/api/jobs?name=" + mesh.file_name, mesh.text);
  EXPECT_EQ(r.status, 201u);
  EXPECT_EQ(json::parse(r.body), json({{"id", "000001"}}));
  EXPECT_TRUE(r.keep_alive);
  EXPECT_EQ(test::read_file(s.jobs / "000001" / "model" / mesh.file_name), mesh.text);
  EXPECT_EQ(s.wait_for("000001", "check")["check"]["state"], "done");
}

TEST(HttpSession, AnUploadWithoutContentLengthIs411AndNothingIsKept) {
  TestServer s;
  HttpClient client(s.port());
  const HttpReply r = client.request("POST", "/api/jobs?name=part.stl", kGoodModel,
                                     {{"Transfer-Encoding", "chunked"}, {"Content-Length", ""}});
  EXPECT_EQ(r.status, 411u);
  EXPECT_EQ(json::parse(r.body), error_body("an upload needs a Content-Length"));
  EXPECT_FALSE(r.keep_alive);
  EXPECT_EQ(client.read_until_closed(), "");
  EXPECT_TRUE(fs::is_empty(s.jobs.path()));
}

TEST(HttpSession, AnUploadOverTheLimitIs413AndNothingIsKept) {
  ServerOptions options;
  options.max_upload_bytes = 100;
  TestServer s(options);
  HttpClient client(s.port());
  // The whole body is sent: the server reads and drops it, so the client sees the answer.
  client.send(upload_header("part.stl", 101) + std::string(101, 's'));
  const HttpReply r = client.read_reply();
  EXPECT_EQ(r.status, 413u);
  EXPECT_EQ(json::parse(r.body),
            error_body("the file is larger than the upload limit of 0.0001 MB (strata serve "
                       "--max-upload MB): nothing was kept"));
  EXPECT_FALSE(r.keep_alive);
  EXPECT_EQ(client.read_until_closed(), "");
  EXPECT_TRUE(fs::is_empty(s.jobs.path()));
  // At the limit it is kept.
  HttpClient again(s.port());
  const std::string at_limit = std::string(kGoodModel) + std::string(100 - kGoodModel.size(), ' ');
  EXPECT_EQ(again.request("POST", "/api/jobs?name=part.stl", at_limit).status, 201u);
  EXPECT_EQ(test::read_file(s.jobs / "000001" / "model" / "part.stl"), at_limit);
}

TEST(HttpSession, AClientThatLeavesDuringAnUploadLeavesNothing) {
  TestServer s;
  HttpClient client(s.port());
  client.send(upload_header("part.stl", 1000) + "solid part\n");
  // The upload's folder is made once its header is read; it goes when the connection drops.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!fs::exists(s.jobs / "000001" / "model" / "part.stl") &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_TRUE(fs::exists(s.jobs / "000001" / "model" / "part.stl"));
  EXPECT_EQ(json::parse(HttpClient(s.port()).request("GET", "/api/jobs").body)["jobs"].size(), 0u);
  client.close();
  EXPECT_TRUE(becomes_empty(s.jobs.path()));
  EXPECT_EQ(json::parse(HttpClient(s.port()).request("GET", "/api/jobs").body)["jobs"].size(), 0u);
}

TEST(HttpSession, AServerStoppedDuringAnUploadLeavesNothing) {
  TestServer s;
  HttpClient client(s.port());
  client.send(upload_header("part.stl", 1000) + "solid part\n");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!fs::exists(s.jobs / "000001") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_TRUE(fs::exists(s.jobs / "000001"));
  s.server.reset();  // the connections still open go with the server
  EXPECT_TRUE(fs::is_empty(s.jobs.path()));
}

TEST(HttpSession, AnUploadThatCannotBeStoredIs500AndNothingIsKept) {
  // A jobs folder so deep that the model's path passes PATH_MAX (4096) while the job's folder
  // does not: the folder is made, the file cannot be opened.
  test::TempDir deep_root("serve-deep");
  fs::path deep = deep_root.path();
  while (deep.string().size() < 3900) deep /= std::string(200, 'd');
  fs::create_directories(deep);
  ServerParts parts;
  ServerOptions options;
  options.port = 0;
  options.jobs_dir = deep;
  auto server = parts.start(options);
  ASSERT_TRUE(server);
  HttpClient client((*server)->port());
  const std::string name = std::string(190, 'p') + ".stl";
  const HttpReply r = client.request("POST", "/api/jobs?name=" + name, kGoodModel);
  EXPECT_EQ(r.status, 500u);
  EXPECT_EQ(json::parse(r.body), error_body("cannot store the upload: File name too long"));
  EXPECT_FALSE(r.keep_alive);
  EXPECT_EQ(client.read_until_closed(), "");
  EXPECT_TRUE(fs::is_empty(deep));
}

TEST(HttpSession, AnUploadWithoutAJobFolderIs503) {
  TestServer s;
  // A file where the first job's folder would go.
  test::write_text_file(s.jobs / "000001", "in the way");
  HttpClient client(s.port());
  const HttpReply r = client.request("POST", "/api/jobs?name=part.stl", kGoodModel);
  EXPECT_EQ(r.status, 503u);
  EXPECT_EQ(json::parse(r.body), error_body("cannot make the job's folder: Not a directory"));
  EXPECT_EQ(client.read_until_closed(), "");
  // The next upload takes the next id.
  EXPECT_EQ(s.upload("part.stl", kGoodModel), "000002");
}

TEST(HttpSession, AForeignHostIs403) {
  TestServer s;
  HttpClient client(s.port());
  const HttpReply r = client.request("GET", "/api/info", {}, {{"Host", "evil.example:8080"}});
  EXPECT_EQ(r.status, 403u);
  EXPECT_EQ(json::parse(r.body),
            error_body("this server answers requests to 127.0.0.1 or localhost"));
  EXPECT_FALSE(r.keep_alive);
  EXPECT_EQ(client.read_until_closed(), "");
  // A request without a Host is foreign too; localhost and [::1] are not.
  EXPECT_EQ(HttpClient(s.port()).request("GET", "/api/info", {}, {{"Host", ""}}).status, 403u);
  for (const char* host : {"localhost:1234", "[::1]:80", "127.0.0.1"}) {
    EXPECT_EQ(HttpClient(s.port()).request("GET", "/api/info", {}, {{"Host", host}}).status, 200u)
        << host;
  }
}

TEST(HttpSession, KeepAliveServesRequestsOnOneConnectionUntilClose) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  HttpClient client(s.port());
  for (int n = 0; n < 3; ++n) {
    const HttpReply r = client.request("GET", "/api/jobs");
    EXPECT_EQ(r.status, 200u);
    EXPECT_TRUE(r.keep_alive);
  }
  // An error answer keeps the connection too, once its body was read.
  EXPECT_EQ(client.request("GET", "/nothing").status, 404u);
  // A download asked to close the connection after it.
  const HttpReply last =
      client.request("GET", "/api/jobs/" + id + "/files/model", {}, {{"Connection", "close"}});
  EXPECT_EQ(last.status, 200u);
  EXPECT_EQ(last.body, kGoodModel);
  EXPECT_FALSE(last.keep_alive);
  EXPECT_EQ(client.read_until_closed(), "");
}

TEST(HttpSession, AnHttp10RequestIsAnsweredAndClosed) {
  TestServer s;
  HttpClient client(s.port());
  client.send("GET /api/jobs HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n");
  const HttpReply r = client.read_reply();
  EXPECT_EQ(r.status, 200u);
  EXPECT_EQ(json::parse(r.body), json({{"jobs", json::array()}}));
  EXPECT_FALSE(r.keep_alive);
  EXPECT_EQ(client.read_until_closed(), "");
}

TEST(HttpSession, HeadAnswersTheHeaderAlone) {
  TestServer s;
  const std::string id = s.upload("part.stl", kGoodModel);
  HttpClient client(s.port());
  const HttpReply get = client.request("GET", "/api/info");
  const HttpReply head = client.request("HEAD", "/api/info");
  EXPECT_EQ(head.status, 200u);
  EXPECT_EQ(head.field("Content-Length"), std::to_string(get.body.size()));
  EXPECT_EQ(head.body, "");
  // A file too: its length, no bytes; the next answer on the connection starts where it should.
  const HttpReply file = client.request("HEAD", "/api/jobs/" + id + "/files/model");
  EXPECT_EQ(file.status, 200u);
  EXPECT_EQ(file.field("Content-Length"), std::to_string(kGoodModel.size()));
  EXPECT_EQ(file.field("Content-Disposition"), "attachment; filename=\"part.stl\"");
  const HttpReply next = client.request("GET", "/api/jobs/" + id + "/files/model");
  EXPECT_EQ(next.status, 200u);
  EXPECT_EQ(next.body, kGoodModel);
}

TEST(HttpSession, ARequestBodyOverOneMebibyteIs413) {
  TestServer s;
  HttpClient client(s.port());
  client.send(
      "POST /api/jobs/000001/slice HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 1048577\r\n\r\n");
  const HttpReply r = client.read_reply();
  EXPECT_EQ(r.status, 413u);
  EXPECT_EQ(json::parse(r.body), error_body("the request body is too large"));
  EXPECT_FALSE(r.keep_alive);
  EXPECT_EQ(client.read_until_closed(), "");
}

TEST(HttpSession, AChunkedBodyOverOneMebibyteClosesTheConnection) {
  TestServer s;
  HttpClient client(s.port());
  // A chunk of 0x100001 bytes announced: refused as soon as its size is read.
  client.send(
      "POST /api/jobs/000001/slice HTTP/1.1\r\nHost: 127.0.0.1\r\nTransfer-Encoding: "
      "chunked\r\n\r\n100001\r\n{}");
  EXPECT_EQ(client.read_until_closed(), "");
}

TEST(HttpSession, WhatIsNotHttpClosesTheConnectionUnanswered) {
  TestServer s;
  HttpClient client(s.port());
  client.send("HELLO\r\n\r\n");
  EXPECT_EQ(client.read_until_closed(), "");
  // The server still answers others.
  EXPECT_EQ(HttpClient(s.port()).request("GET", "/api/info").status, 200u);
}

}  // namespace
}  // namespace strata::serve::testing
