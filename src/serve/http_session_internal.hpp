#pragma once

#include <boost/asio/ip/tcp.hpp>

#include "serve/job_store_internal.hpp"
#include "strata/serve/server.hpp"

namespace strata::serve::detail {

/// What every connection shares.
struct SessionContext {
  JobStore& store;
  const ServerOptions& options;
  bool loopback = true;  ///< bound to loopback: refuse other Host headers
};

/// Serves one connection (HTTP/1.1 keep-alive) until the client closes it or a timeout; owns
/// itself through shared_ptr while its handlers are pending.
void serve_connection(boost::asio::ip::tcp::socket socket, const SessionContext& context);

}  // namespace strata::serve::detail
