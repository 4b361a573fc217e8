#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "strata/core/result.hpp"
#include "strata/serve/task_runner.hpp"

namespace strata::serve {

/// The default of ServerOptions::max_upload_bytes (`strata serve --max-upload`, 1000 MB).
inline constexpr std::uint64_t kDefaultMaxUploadBytes = 1'000'000'000;

/// Where and how Server::start listens, and its limits.
struct ServerOptions {
  std::string bind_address = "127.0.0.1";  ///< loopback unless the user asks otherwise
  std::uint16_t port = 8080;               ///< 0: any free port (see Server::port())
  std::filesystem::path jobs_dir;          ///< one folder a job; must exist
  std::uint64_t max_upload_bytes = kDefaultMaxUploadBytes;  ///< larger uploads are refused (413)
  unsigned http_threads = 2;  ///< threads answering requests, apart from the slicing pool
};

/// The local web application of `strata serve`: the app page, the viewer and the JSON API the
/// page uses (src/serve/route.cpp lists it), over HTTP/1.1 on its own threads; tasks run on the
/// TBB pool. Jobs are folders under ServerOptions::jobs_dir.
class Server {
 public:
  /// Binds, listens and starts answering. Error{Usage} when the address cannot be bound.
  static Result<std::unique_ptr<Server>> start(const ServerOptions& options, TaskRunner runner);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// The port listened on (the one chosen when ServerOptions::port was 0).
  std::uint16_t port() const;

  /// Makes a job of a model file (copied into the jobs folder) and checks it; returns its id.
  Result<std::string> add_model(const std::filesystem::path& model);

  /// Stops accepting, cancels running tasks, waits for them and for the request threads.
  /// Idempotent; the destructor calls it. The jobs folder is left as it is.
  void stop();

  struct Impl;

 private:
  explicit Server(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace strata::serve
