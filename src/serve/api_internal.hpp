#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "serve/job_store_internal.hpp"
#include "serve/route_internal.hpp"
#include "strata/serve/server.hpp"

namespace strata::serve::detail {

/// An answer, before it is put on the wire.
struct Response {
  unsigned status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::filesystem::path file;  ///< when set, the body is this file
  std::string download_name;   ///< when set, Content-Disposition: attachment
};

/// {"error": message} with an HTTP status.
Response error_response(unsigned status, std::string_view message);

/// The app page built from web/ (web/src/app/), embedded at build time.
std::string_view app_page();

/// Answers every route but Upload (which streams its body to disk in the session).
/// Does no geometry: it checks the request and hands it to the job store.
Response handle_request(const Route& route, std::string_view body, JobStore& store,
                        const ServerOptions& options);

/// Whether a Host header names the loopback interface (localhost, 127.0.0.1, [::1], any port):
/// a server bound to loopback refuses others, so that a web site cannot reach it through a DNS
/// name pointing to 127.0.0.1.
bool is_loopback_host(std::string_view host);

}  // namespace strata::serve::detail
