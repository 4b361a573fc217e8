#include <nlohmann/json.hpp>

#include "serve/api_internal.hpp"
#include "strata/view/view_page.hpp"

namespace strata::serve::detail {

namespace {

using nlohmann::json;

Response json_response(unsigned status, std::string body) {
  Response r;
  r.status = status;
  r.body = std::move(body);
  return r;
}

/// The options of a slice or validate request: a JSON object of at most 64 KiB. Their meaning
/// is checked by the task runner, which reports a bad value as the task's error.
Result<std::string> options_of(std::string_view body) {
  if (body.size() > 65536) return Error{ErrorCode::BadInput, "the options are too long", {}};
  const json j = json::parse(body.empty() ? std::string_view("{}") : body, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    return Error{ErrorCode::BadInput, "the options must be a JSON object", {}};
  }
  return j.dump();
}

}  // namespace

Response error_response(unsigned status, std::string_view message) {
  return json_response(status, json{{"error", message}}.dump());
}

bool is_loopback_host(std::string_view host) {
  std::string_view name = host;
  if (!name.empty() && name.front() == '[') {
    const std::size_t close = name.find(']');
    if (close == std::string_view::npos) return false;
    const std::string_view rest = name.substr(close + 1);
    if (!rest.empty() && rest.front() != ':') return false;
    return name.substr(0, close + 1) == "[::1]";
  }
  if (const std::size_t colon = name.find(':'); colon != std::string_view::npos) {
    name = name.substr(0, colon);
  }
  return name == "localhost" || name == "127.0.0.1";
}

Response handle_request(const Route& route, std::string_view body, JobStore& store,
                        const ServerOptions& options) {
  switch (route.kind) {
    case RouteKind::AppPage: {
      Response r;
      r.content_type = "text/html; charset=utf-8";
      r.body = std::string(app_page());
      return r;
    }
    case RouteKind::ViewerPage: {
      if (!store.exists(route.job)) return error_response(404, "no such job");
      Response r;
      r.content_type = "text/html; charset=utf-8";
      // The view page, told to load its data from the server (web/src/data.js).
      const json remote = {{"format", "strata-view-remote"},
                           {"url", "/api/jobs/" + route.job + "/view.json"}};
      r.body = view::view_page_with_data(remote.dump());
      return r;
    }
    case RouteKind::Info:
      return json_response(200, json{{"generator", "strata 0.1.0"},
                                     {"max_upload_bytes", options.max_upload_bytes},
                                     {"formats", {".stl", ".obj", ".off", ".ply", ".3mf", ".gz"}}}
                                    .dump());
    case RouteKind::ListJobs:
      return json_response(200, store.list_json());
    case RouteKind::JobStatus: {
      auto status = store.status_json(route.job);
      return status ? json_response(200, std::move(*status)) : error_response(404, "no such job");
    }
    case RouteKind::Slice:
    case RouteKind::Validate: {
      if (!store.exists(route.job)) return error_response(404, "no such job");
      auto parsed = options_of(body);
      if (!parsed) return error_response(400, parsed.error().message);
      if (route.kind == RouteKind::Validate) {
        auto ok = store.validate(route.job, *parsed);
        if (!ok) return error_response(409, ok.error().message);
        return json_response(202, json{{"id", route.job}}.dump());
      }
      auto id = store.slice(route.job, *parsed);
      if (!id) return error_response(409, id.error().message);
      return json_response(202, json{{"id", *id}}.dump());
    }
    case RouteKind::Cancel:
      if (!store.exists(route.job)) return error_response(404, "no such job");
      store.cancel(route.job);
      return json_response(202, json{{"id", route.job}}.dump());
    case RouteKind::Remove: {
      if (!store.exists(route.job)) return error_response(404, "no such job");
      auto ok = store.remove(route.job);
      if (!ok) return error_response(409, ok.error().message);
      return json_response(200, json{{"id", route.job}}.dump());
    }
    case RouteKind::ViewData:
    case RouteKind::File: {
      const std::string kind = route.kind == RouteKind::ViewData ? "view" : route.file;
      if (!store.exists(route.job)) return error_response(404, "no such job");
      auto file = store.file(route.job, kind);
      if (!file) return error_response(404, "this job has no such file (yet)");
      Response r;
      r.content_type = file->content_type;
      r.file = file->path;
      if (route.kind == RouteKind::File) r.download_name = file->download_name;
      return r;
    }
    case RouteKind::Upload:
      return error_response(500, "an upload is answered by the session");
    case RouteKind::BadRequest:
      return error_response(400, route.reason);
    case RouteKind::WrongMethod:
      return error_response(405, "this method is not allowed here");
    case RouteKind::NotFound:
      break;
  }
  return error_response(404, "not found");
}

}  // namespace strata::serve::detail
