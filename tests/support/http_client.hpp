#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace strata::test {

/// One answer of an HTTP server.
struct HttpReply {
  unsigned status = 0;
  std::string body;
  /// Header fields by lowercase name ("content-type").
  std::map<std::string, std::string> fields;
  bool keep_alive = false;

  /// The value of a header field (any case); empty when absent.
  std::string field(std::string_view name) const;
};

/// Header fields to add to, or put in place of, a request's defaults.
using HttpFields = std::vector<std::pair<std::string, std::string>>;

/// An HTTP/1.1 client on one connection to 127.0.0.1:port (Boost.Beast), for the tests of
/// `strata serve`. Every operation gives up after `timeout` and throws std::runtime_error, as it
/// does when the connection fails, so that a test never hangs on a silent server.
///
///     HttpClient client(server->port());
///     const HttpReply r = client.request("GET", "/api/info");
///     EXPECT_EQ(r.status, 200u);
class HttpClient {
 public:
  explicit HttpClient(std::uint16_t port,
                      std::chrono::milliseconds timeout = std::chrono::seconds(10));
  ~HttpClient();
  HttpClient(const HttpClient&) = delete;
  HttpClient& operator=(const HttpClient&) = delete;

  /// Sends a request and reads its answer. Host is "127.0.0.1:port" and Content-Length the
  /// body's, unless `fields` sets them; a field set to "" is left out (e.g. {"Content-Length",
  /// ""} with {"Transfer-Encoding", "chunked"}). For "HEAD" the answer's body is not read.
  HttpReply request(std::string_view method, std::string_view target, std::string_view body = {},
                    const HttpFields& fields = {});

  /// Writes bytes as they are (a hand-made request, or part of a body).
  void send(std::string_view bytes);
  /// Reads one answer; `head`: the answer to a HEAD request (no body).
  HttpReply read_reply(bool head = false);
  /// Reads until the server closes the connection; returns what came before that (nothing
  /// expected after a complete answer).
  std::string read_until_closed();
  /// Closes the connection from this side.
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace strata::test
