#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "strata/serve/server.hpp"
#include "support/fake_tasks.hpp"
#include "support/http_client.hpp"
#include "support/temp_dir.hpp"

namespace strata::serve::testing {

/// The text of a model the fake check passes (its first line starts with "solid").
inline constexpr std::string_view kGoodModel = "solid part\nendsolid part\n";

/// The body of the server's error answers: {"error": message}.
inline nlohmann::json error_body(std::string_view message) {
  return nlohmann::json{{"error", message}};
}

/// A fresh jobs folder (removed when destroyed) and FakeTasks, for starting servers with options
/// exactly as a test gives them: a refused address or port, a second run over the same jobs.
/// A server started from it must be destroyed first (declare it after this object).
struct ServerParts {
  /// Server::start(options, tasks.runner()), with options.jobs_dir set to `jobs` when it is empty;
  /// every other option as given.
  Result<std::unique_ptr<Server>> start(ServerOptions options) {
    if (options.jobs_dir.empty()) options.jobs_dir = jobs.path();
    return Server::start(options, tasks.runner());
  }

  test::TempDir jobs{"serve"};
  FakeTasks tasks;
};

/// A server on 127.0.0.1 and a free port, running FakeTasks, its jobs in a fresh folder; stopped
/// (and its folder removed) when destroyed.
class TestServer : public ServerParts {
 public:
  explicit TestServer(ServerOptions options = {}) {
    options.port = 0;
    options.jobs_dir = jobs.path();
    auto started = start(options);
    if (!started) throw std::runtime_error(started.error().to_string());
    server = std::move(started).value();
  }

  std::uint16_t port() const { return server->port(); }

  /// Uploads `text` as `name` on a connection of its own; the new job's id ("" on failure).
  std::string upload(std::string_view name, std::string_view text) {
    test::HttpClient client(port());
    const test::HttpReply r = client.request("POST", "/api/jobs?name=" + std::string(name), text);
    EXPECT_EQ(r.status, 201u) << r.body;
    return r.status == 201 ? nlohmann::json::parse(r.body)["id"].get<std::string>() : "";
  }

  /// The job's status once its task `which` ("check", "slice", "validate") has left queued and
  /// running; a test failure when it has not after 10 s.
  nlohmann::json wait_for(const std::string& id, const std::string& which) {
    test::HttpClient client(port());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    for (;;) {
      const test::HttpReply r = client.request("GET", "/api/jobs/" + id);
      if (r.status != 200) {
        ADD_FAILURE() << "GET /api/jobs/" << id << ": " << r.status << " " << r.body;
        return nullptr;
      }
      nlohmann::json j = nlohmann::json::parse(r.body);
      const std::string state = j[which]["state"];
      if (state != "queued" && state != "running") return j;
      if (std::chrono::steady_clock::now() > deadline) {
        ADD_FAILURE() << which << " of job " << id << " still " << state;
        return j;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

  /// Waits until the job's slice is running and has reported progress.
  void wait_for_progress(const std::string& id) {
    test::HttpClient client(port());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < deadline) {
      const auto j = nlohmann::json::parse(client.request("GET", "/api/jobs/" + id).body);
      if (j["slice"]["state"] == "running" && j["slice"]["done"].get<int>() > 0) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ADD_FAILURE() << "the slice of job " << id << " reported no progress";
  }

  // Stops before the tasks' runner and the folder (of the base) go.
  std::unique_ptr<Server> server;
};

}  // namespace strata::serve::testing
