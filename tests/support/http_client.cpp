#include "support/http_client.hpp"

#include <algorithm>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <cctype>
#include <stdexcept>

namespace strata::test {

namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;

std::string lowercase(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

std::string HttpReply::field(std::string_view name) const {
  const auto it = fields.find(lowercase(name));
  return it == fields.end() ? std::string() : it->second;
}

struct HttpClient::Impl {
  explicit Impl(std::chrono::milliseconds t) : timeout(t) {}

  /// Runs the operation just started to its end; every operation has the timeout.
  void finish(const beast::error_code& ec, const char* what) {
    ioc.restart();
    ioc.run();
    if (ec) throw std::runtime_error(std::string("HTTP client, ") + what + ": " + ec.message());
  }

  std::chrono::milliseconds timeout;
  net::io_context ioc;
  beast::tcp_stream stream{ioc};
  beast::flat_buffer buffer;
  std::uint16_t port = 0;
};

HttpClient::HttpClient(std::uint16_t port, std::chrono::milliseconds timeout)
    : impl_(std::make_unique<Impl>(timeout)) {
  impl_->port = port;
  beast::error_code ec;
  impl_->stream.expires_after(timeout);
  impl_->stream.async_connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port),
                              [&ec](beast::error_code e) { ec = e; });
  impl_->finish(ec, "connect");
}

HttpClient::~HttpClient() { close(); }

HttpReply HttpClient::request(std::string_view method, std::string_view target,
                              std::string_view body, const HttpFields& fields) {
  http::request<http::string_body> req;
  req.method_string(beast::string_view(method.data(), method.size()));
  req.target(beast::string_view(target.data(), target.size()));
  req.version(11);
  req.set(http::field::host, "127.0.0.1:" + std::to_string(impl_->port));
  req.body() = std::string(body);
  if (!body.empty() || method == "POST") {
    req.content_length(body.size());
  }
  for (const auto& [name, value] : fields) {
    if (value.empty()) {
      req.erase(name);
    } else {
      req.set(name, value);
    }
  }
  beast::error_code ec;
  impl_->stream.expires_after(impl_->timeout);
  http::async_write(impl_->stream, req, [&ec](beast::error_code e, std::size_t) { ec = e; });
  impl_->finish(ec, "write the request");
  return read_reply(method == "HEAD");
}

void HttpClient::send(std::string_view bytes) {
  beast::error_code ec;
  impl_->stream.expires_after(impl_->timeout);
  net::async_write(impl_->stream, net::buffer(bytes.data(), bytes.size()),
                   [&ec](beast::error_code e, std::size_t) { ec = e; });
  impl_->finish(ec, "send");
}

HttpReply HttpClient::read_reply(bool head) {
  http::response_parser<http::string_body> parser;
  parser.body_limit(std::uint64_t{1} << 30);
  parser.skip(head);
  beast::error_code ec;
  impl_->stream.expires_after(impl_->timeout);
  http::async_read(impl_->stream, impl_->buffer, parser,
                   [&ec](beast::error_code e, std::size_t) { ec = e; });
  impl_->finish(ec, "read the answer");
  const auto& message = parser.get();
  HttpReply reply;
  reply.status = message.result_int();
  reply.body = message.body();
  for (const auto& f : message) {
    reply.fields[lowercase(std::string_view(f.name_string().data(), f.name_string().size()))] =
        std::string(f.value());
  }
  reply.keep_alive = message.keep_alive();
  return reply;
}

std::string HttpClient::read_until_closed() {
  std::string data = beast::buffers_to_string(impl_->buffer.data());
  impl_->buffer.consume(impl_->buffer.size());
  char chunk[4096];
  for (;;) {
    beast::error_code ec;
    std::size_t n = 0;
    impl_->stream.expires_after(impl_->timeout);
    impl_->stream.async_read_some(net::buffer(chunk), [&](beast::error_code e, std::size_t got) {
      ec = e;
      n = got;
    });
    impl_->ioc.restart();
    impl_->ioc.run();
    data.append(chunk, n);
    if (ec == net::error::eof || ec == net::error::connection_reset) return data;
    if (ec) throw std::runtime_error("HTTP client, read until closed: " + ec.message());
  }
}

void HttpClient::close() {
  beast::error_code ec;
  impl_->stream.socket().shutdown(tcp::socket::shutdown_both, ec);
  impl_->stream.close();
}

}  // namespace strata::test
