#include <fmt/format.h>
#include <signal.h>
#include <stdlib.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/option_checks.hpp"
#include "cli/serve_tasks.hpp"
#include "cli/units_options.hpp"
#include "strata/serve/server.hpp"

namespace strata::cli {

namespace {

namespace fs = std::filesystem;

struct ServeCommandOptions {
  std::vector<std::string> models;
  int port = 8080;
  std::string bind = "127.0.0.1";
  std::string jobs_dir;
  double max_upload_mb = serve::kDefaultMaxUploadBytes / 1e6;
  UnitsCliOptions units;  ///< how every model of the session is read
};

constexpr const char* kServeHelp =
    "A local web application: open a model (file picker or drag and drop), see `strata check`'s\n"
    "verdict, set the slicing parameters, slice with a progress bar and a cancel button, look\n"
    "at the result in the viewer of `strata view` (two jobs side by side to compare), download\n"
    "every output, and run `strata validate`. Served by this process on 127.0.0.1 only, unless\n"
    "--bind names another address. A job is a folder under --jobs: the model, options.json,\n"
    "the outputs; without --jobs a temporary folder, removed at exit. Ctrl-C stops.\n\n"
    "Example: strata serve part.stl --port 8080   then open http://127.0.0.1:8080/";

/// A fresh folder under the system's temporary folder.
Result<fs::path> make_temporary_folder() {
  std::error_code ec;
  const fs::path base = fs::temp_directory_path(ec);
  if (ec) return Error{ErrorCode::Internal, "no temporary folder: " + ec.message(), {}};
  std::string pattern = (base / "strata-serve-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    return Error{ErrorCode::Internal, "cannot make a temporary folder", base.string()};
  }
  return fs::path(pattern);
}

int run_serve(const ServeCommandOptions& o) {
  // Block the stop signals in every thread (threads inherit the mask); this one waits for them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  serve::ServerOptions options;
  options.bind_address = o.bind;
  options.port = static_cast<std::uint16_t>(o.port);
  options.max_upload_bytes = static_cast<std::uint64_t>(o.max_upload_mb * 1e6);
  bool temporary = false;
  if (o.jobs_dir.empty()) {
    auto dir = make_temporary_folder();
    if (!dir) return report_error(dir.error());
    options.jobs_dir = *dir;
    temporary = true;
  } else {
    std::error_code ec;
    fs::create_directories(o.jobs_dir, ec);
    if (!fs::is_directory(o.jobs_dir, ec)) {
      return report_error(Error{ErrorCode::Usage, "cannot make the jobs folder", o.jobs_dir});
    }
    options.jobs_dir = o.jobs_dir;
  }
  const auto remove_temporary = [&] {
    std::error_code ec;
    if (temporary) fs::remove_all(options.jobs_dir, ec);
  };

  auto server = serve::Server::start(options, make_serve_task_runner(to_coordinate_scale(o.units)));
  if (!server) {
    remove_temporary();
    return report_error(server.error());
  }
  for (const std::string& model : o.models) {
    if (auto id = (*server)->add_model(model); !id) {
      std::fprintf(stderr, "strata: warning: %s\n", id.error().to_string().c_str());
    }
  }
  const bool ipv6 = o.bind.find(':') != std::string::npos;
  const std::string host = ipv6 ? "[" + o.bind + "]" : o.bind;
  if (o.bind != "127.0.0.1" && o.bind != "::1") {
    std::fprintf(stderr,
                 "strata: warning: serving on %s: other machines may reach this server, which "
                 "has no authentication; use it on a network you trust\n",
                 o.bind.c_str());
  }
  std::printf("strata serve: open http://%s:%u/ in a browser (jobs in %s%s; Ctrl-C stops)\n",
              host.c_str(), static_cast<unsigned>((*server)->port()),
              options.jobs_dir.string().c_str(), temporary ? ", removed at exit" : "");
  std::fflush(stdout);

  int signal_number = 0;
  sigwait(&stop_signals, &signal_number);
  std::fprintf(stderr, "strata: stopping (%s): cancelling running jobs\n",
               signal_number == SIGINT ? "Ctrl-C" : "SIGTERM");
  (*server)->stop();
  server->reset();
  remove_temporary();
  return kExitOk;
}

}  // namespace

void register_serve_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<ServeCommandOptions>();
  CLI::App* cmd = app.add_subcommand("serve", "Run the local web application (browser UI)");
  cmd->footer(kServeHelp);
  cmd->add_option("MODEL", options->models, "Models to open as jobs at start");
  cmd->add_option("--port", options->port, "TCP port; 0 picks a free one (printed)")
      ->default_val(8080)
      ->check(whole_number(0, 65535, "port number"));
  cmd->add_option("--bind", options->bind,
                  "Address to listen on (default loopback only; another address is reachable "
                  "from other machines)")
      ->default_val("127.0.0.1");
  cmd->add_option(
      "--jobs", options->jobs_dir,
      "Folder of the jobs, kept at exit (default: a temporary folder, removed at exit)");
  cmd->add_option("--max-upload", options->max_upload_mb,
                  "Largest model upload in MB (1 MB = 10^6 bytes); larger ones are refused")
      ->default_val(serve::kDefaultMaxUploadBytes / 1e6)
      ->check(positive_real("size in MB"));
  add_units_options(*cmd, options->units);
  cmd->callback([options, &runner] { runner = [options] { return run_serve(*options); }; });
}

}  // namespace strata::cli
