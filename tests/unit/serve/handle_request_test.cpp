#include <gtest/gtest.h>

#include "serve/api_internal.hpp"
#include "support/fake_tasks.hpp"
#include "support/temp_dir.hpp"

namespace strata::serve::detail {
namespace {

TEST(IsLoopbackHost, AcceptsLoopbackNamesWithAnyPort) {
  for (const char* host :
       {"127.0.0.1", "127.0.0.1:8080", "localhost", "localhost:1", "[::1]", "[::1]:8080"}) {
    EXPECT_TRUE(is_loopback_host(host)) << host;
  }
  for (const char* host : {"", "evil.example", "127.0.0.1.evil.example", "localhost.evil",
                           "[::2]:80", "[::1]x", "[::1", "10.0.0.1:8080"}) {
    EXPECT_FALSE(is_loopback_host(host)) << host;
  }
}

TEST(ErrorResponse, IsJsonWithTheMessage) {
  const Response r = error_response(413, "too \"big\"");
  EXPECT_EQ(r.status, 413u);
  EXPECT_EQ(r.content_type, "application/json");
  EXPECT_EQ(r.body, R"({"error":"too \"big\""})");
}

TEST(HandleRequest, LeavesUploadsToTheSession) {
  // The session streams an upload's body to disk itself; handed one, the handler says so.
  test::TempDir jobs("serve");
  testing::FakeTasks tasks;
  JobStore store(jobs.path(), tasks.runner());
  Route upload;
  upload.kind = RouteKind::Upload;
  upload.name = "part.stl";
  const Response r = handle_request(upload, "solid part\n", store, ServerOptions{});
  EXPECT_EQ(r.status, 500u);
  EXPECT_EQ(r.body, R"({"error":"an upload is answered by the session"})");
  EXPECT_EQ(store.list_json(), R"({"jobs":[]})");
}

}  // namespace
}  // namespace strata::serve::detail
