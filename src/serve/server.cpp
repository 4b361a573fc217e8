#include "strata/serve/server.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/strand.hpp>
#include <mutex>
#include <thread>
#include <vector>

#include "serve/http_session_internal.hpp"
#include "serve/job_store_internal.hpp"

namespace strata::serve {

namespace net = boost::asio;
using tcp = net::ip::tcp;

struct Server::Impl {
  Impl(const ServerOptions& o, TaskRunner runner)
      : options(o),
        store(o.jobs_dir, std::move(runner)),
        ioc(static_cast<int>(std::max(1u, o.http_threads))),
        acceptor(ioc) {}

  // Declared before the io_context, so that the sessions it still holds go first.
  ServerOptions options;
  detail::JobStore store;
  detail::SessionContext context{store, options};
  net::io_context ioc;
  tcp::acceptor acceptor;
  std::vector<std::thread> threads;
  std::once_flag stopped;
  std::uint16_t port = 0;

  void accept() {
    acceptor.async_accept(net::make_strand(ioc),
                          [this](boost::system::error_code ec, tcp::socket socket) {
                            if (ec == net::error::operation_aborted || !acceptor.is_open()) return;
                            if (!ec) detail::serve_connection(std::move(socket), context);
                            accept();
                          });
  }
};

Server::Server(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Server::~Server() { stop(); }

Result<std::unique_ptr<Server>> Server::start(const ServerOptions& options, TaskRunner runner) {
  boost::system::error_code ec;
  const auto address = net::ip::make_address(options.bind_address, ec);
  if (ec) {
    return Error{ErrorCode::Usage, "not an IP address: " + options.bind_address, "--bind"};
  }
  auto impl = std::make_unique<Impl>(options, std::move(runner));
  impl->context.loopback = address.is_loopback();
  const tcp::endpoint endpoint(address, options.port);
  auto& acceptor = impl->acceptor;
  acceptor.open(endpoint.protocol(), ec);
  if (!ec) acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) acceptor.bind(endpoint, ec);
  if (!ec) acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) {
    return Error{ErrorCode::Usage,
                 "cannot listen on " + options.bind_address + " port " +
                     std::to_string(options.port) + ": " + ec.message(),
                 {}};
  }
  impl->port = acceptor.local_endpoint(ec).port();
  impl->accept();
  for (unsigned n = 0; n < std::max(1u, options.http_threads); ++n) {
    impl->threads.emplace_back([ioc = &impl->ioc] { ioc->run(); });
  }
  return std::unique_ptr<Server>(new Server(std::move(impl)));
}

std::uint16_t Server::port() const { return impl_->port; }

Result<std::string> Server::add_model(const std::filesystem::path& model) {
  return impl_->store.add_file(model);
}

void Server::stop() {
  if (!impl_) return;
  std::call_once(impl_->stopped, [impl = impl_.get()] {
    net::post(impl->acceptor.get_executor(), [impl] {
      boost::system::error_code ec;
      impl->acceptor.close(ec);
    });
    impl->store.shutdown();
    impl->ioc.stop();
    for (auto& t : impl->threads) t.join();
  });
}

}  // namespace strata::serve
