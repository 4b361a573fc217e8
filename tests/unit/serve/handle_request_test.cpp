#include <gtest/gtest.h>

#include "serve/api_internal.hpp"

namespace strata::serve::detail {
namespace {

TEST(IsLoopbackHost, AcceptsLoopbackNamesWithAnyPort) {
  for (const char* host :
       {"127.0.0.1", "127.0.0.1:8080", "localhost", "localhost:1", "[::1]", "[::1]:8080"}) {
    EXPECT_TRUE(is_loopback_host(host)) << host;
  }
  for (const char* host : {"", "evil.example", "127.0.0.1.evil.example", "localhost.evil",
                           "[::2]:80", "[::1]x", "10.0.0.1:8080"}) {
    EXPECT_FALSE(is_loopback_host(host)) << host;
  }
}

TEST(ErrorResponse, IsJsonWithTheMessage) {
  const Response r = error_response(413, "too \"big\"");
  EXPECT_EQ(r.status, 413u);
  EXPECT_EQ(r.content_type, "application/json");
  EXPECT_EQ(r.body, R"({"error":"too \"big\""})");
}

}  // namespace
}  // namespace strata::serve::detail
