#include <boost/asio/dispatch.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <chrono>
#include <limits>
#include <memory>
#include <optional>

#include "serve/api_internal.hpp"
#include "serve/http_session_internal.hpp"
#include "serve/route_internal.hpp"

namespace strata::serve::detail {

namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using namespace std::chrono_literals;

constexpr std::uint64_t kMaxRequestBody = 1 << 20;  // options JSON; uploads have their own limit
constexpr std::uint64_t kMaxDrainBytes = 256ull << 20;

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, const SessionContext& context)
      : stream_(std::move(socket)), context_(context) {}
  ~Session() {
    if (!upload_id_.empty()) context_.store.discard(upload_id_);
  }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  void start() {
    net::dispatch(stream_.get_executor(), [self = shared_from_this()] { self->read_header(); });
  }

 private:
  void read_header() {
    header_.emplace();
    header_->header_limit(16 * 1024);
    // The body's limit depends on the route: checked once the header is read. (Not boost::none:
    // Boost 1.74 compares a Content-Length with the optional and refuses every body then.)
    header_->body_limit(std::numeric_limits<std::uint64_t>::max());
    stream_.expires_after(120s);
    http::async_read_header(
        stream_, buffer_, *header_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
  }

  void on_header(beast::error_code ec) {
    if (ec) return close();
    const auto& req = header_->get();
    keep_alive_ = req.keep_alive();
    version_ = req.version();
    head_ = req.method() == http::verb::head;
    const auto host = req[http::field::host];
    if (context_.loopback && !is_loopback_host(std::string_view(host.data(), host.size()))) {
      return reply(error_response(403, "this server answers requests to 127.0.0.1 or localhost"),
                   true);
    }
    const Route route =
        match_route(std::string_view(req.method_string().data(), req.method_string().size()),
                    std::string_view(req.target().data(), req.target().size()));
    if (route.kind == RouteKind::Upload) return start_upload(route);
    if (header_->content_length() && *header_->content_length() > kMaxRequestBody) {
      return reply(error_response(413, "the request body is too large"), true);
    }
    request_.emplace(std::move(*header_));
    request_->body_limit(kMaxRequestBody);
    http::async_read(stream_, buffer_, *request_,
                     [self = shared_from_this(), route](beast::error_code ec2, std::size_t) {
                       if (ec2) return self->close();
                       self->reply(handle_request(route, self->request_->get().body(),
                                                  self->context_.store, self->context_.options),
                                   false);
                     });
  }

  void start_upload(const Route& route) {
    const std::uint64_t limit = context_.options.max_upload_bytes;
    // A length up front, so that a large file is refused before a byte of it is stored.
    const auto length = header_->content_length();
    if (!length) {
      return reply(error_response(411, "an upload needs a Content-Length"), true);
    }
    if (*length > limit) return reply(too_large(), true);
    auto id = context_.store.reserve(route.name);
    if (!id) return reply(error_response(503, id.error().message), true);
    upload_id_ = *id;
    upload_.emplace(std::move(*header_));
    upload_->body_limit(limit);
    beast::error_code ec;
    upload_->get().body().open(context_.store.model_path(upload_id_).string().c_str(),
                               beast::file_mode::write, ec);
    if (ec) {
      context_.store.discard(upload_id_);
      return reply(error_response(500, "cannot store the upload: " + ec.message()), true);
    }
    stream_.expires_after(30min);
    http::async_read(
        stream_, buffer_, *upload_,
        [self = shared_from_this()](beast::error_code ec2, std::size_t) { self->on_upload(ec2); });
  }

  void on_upload(beast::error_code ec) {
    beast::error_code closed;
    upload_->get().body().file().close(closed);
    const std::string id = upload_id_;
    upload_id_.clear();
    if (ec || closed) {
      // The client went away or the file could not be completed: nothing is kept. (The body
      // cannot pass the limit: its Content-Length was checked against it.)
      context_.store.discard(id);
      return close();
    }
    context_.store.commit(id);
    Response r;
    r.status = 201;
    r.body = std::string(R"({"id":")") + id + "\"}";
    reply(std::move(r), false);
  }

  Response too_large() const {
    const double mb = static_cast<double>(context_.options.max_upload_bytes) / 1e6;
    char text[160];
    std::snprintf(text, sizeof text,
                  "the file is larger than the upload limit of %.6g MB (strata serve "
                  "--max-upload MB): nothing was kept",
                  mb);
    return error_response(413, text);
  }

  template <class Body>
  void common_fields(http::response<Body>& res, const Response& r, bool close_after) {
    res.set(http::field::server, "strata");
    res.set(http::field::content_type, r.content_type);
    res.set(http::field::cache_control, "no-store");
    res.set("X-Content-Type-Options", "nosniff");
    res.set("Referrer-Policy", "no-referrer");
    if (!r.download_name.empty()) {
      res.set(http::field::content_disposition, "attachment; filename=\"" + r.download_name + "\"");
    }
    res.keep_alive(keep_alive_ && !close_after);
  }

  void reply(Response r, bool close_after) {
    if (!r.file.empty()) {
      http::file_body::value_type body;
      beast::error_code ec;
      body.open(r.file.string().c_str(), beast::file_mode::scan, ec);
      if (ec) return reply(error_response(404, "the file is gone"), close_after);
      http::response<http::file_body> res{std::piecewise_construct,
                                          std::make_tuple(std::move(body)),
                                          std::make_tuple(http::status::ok, version_)};
      common_fields(res, r, close_after);
      res.prepare_payload();
      return send(std::move(res), close_after);
    }
    http::response<http::string_body> res{static_cast<http::status>(r.status), version_};
    common_fields(res, r, close_after);
    res.body() = std::move(r.body);
    res.prepare_payload();
    if (head_) res.body().clear();
    send(std::move(res), close_after);
  }

  template <class Message>
  void send(Message&& message, bool close_after) {
    auto owned = std::make_shared<std::decay_t<Message>>(std::forward<Message>(message));
    const bool skip_body = head_;
    stream_.expires_after(10min);
    const auto done = [self = shared_from_this(), owned, close_after](beast::error_code ec,
                                                                      std::size_t) {
      self->on_write(ec, close_after || owned->need_eof());
    };
    if (skip_body) {
      auto serializer =
          std::make_shared<http::response_serializer<typename std::decay_t<Message>::body_type>>(
              *owned);
      http::async_write_header(
          stream_, *serializer,
          [done, serializer](beast::error_code ec, std::size_t n) { done(ec, n); });
    } else {
      http::async_write(stream_, *owned, done);
    }
  }

  void on_write(beast::error_code ec, bool close_after) {
    if (ec) return close();
    if (close_after) return drain();
    buffer_.consume(buffer_.size());
    read_header();
  }

  /// After refusing a request whose body was not read: say no more and read what the client
  /// still sends (up to a bound), so that it sees the answer rather than a reset connection.
  void drain() {
    beast::error_code ec;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
    stream_.expires_after(5s);
    drain_more();
  }

  void drain_more() {
    scratch_.resize(1 << 16);
    stream_.async_read_some(net::buffer(scratch_),
                            [self = shared_from_this()](beast::error_code ec, std::size_t n) {
                              self->drained_ += n;
                              if (ec || self->drained_ > kMaxDrainBytes) return self->close();
                              self->drain_more();
                            });
  }

  void close() {
    if (!upload_id_.empty()) {
      context_.store.discard(upload_id_);
      upload_id_.clear();
    }
    beast::error_code ec;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ec);
    stream_.close();
  }

  beast::tcp_stream stream_;
  const SessionContext& context_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::empty_body>> header_;
  std::optional<http::request_parser<http::string_body>> request_;
  std::optional<http::request_parser<http::file_body>> upload_;
  std::string upload_id_;
  std::vector<char> scratch_;
  std::uint64_t drained_ = 0;
  unsigned version_ = 11;
  bool keep_alive_ = true;
  bool head_ = false;
};

}  // namespace

void serve_connection(tcp::socket socket, const SessionContext& context) {
  std::make_shared<Session>(std::move(socket), context)->start();
}

}  // namespace strata::serve::detail
