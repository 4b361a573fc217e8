#include <algorithm>
#include <array>
#include <cctype>
#include <vector>

#include "serve/route_internal.hpp"

namespace strata::serve::detail {

namespace {

std::vector<std::string_view> split_path(std::string_view path) {
  std::vector<std::string_view> parts;
  std::size_t at = 1;  // past the leading '/'
  while (at <= path.size()) {
    const std::size_t end = std::min(path.find('/', at), path.size());
    parts.push_back(path.substr(at, end - at));
    at = end + 1;
  }
  return parts;
}

/// The value of `key` in a query string, still encoded; empty view when absent.
std::string_view query_value(std::string_view query, std::string_view key, bool& found) {
  found = false;
  std::size_t at = 0;
  while (at <= query.size()) {
    const std::size_t end = std::min(query.find('&', at), query.size());
    const std::string_view pair = query.substr(at, end - at);
    const std::size_t eq = pair.find('=');
    if (pair.substr(0, eq) == key) {
      found = true;
      return eq == std::string_view::npos ? std::string_view() : pair.substr(eq + 1);
    }
    at = end + 1;
  }
  return {};
}

bool lower_ends_with(std::string_view text, std::string_view tail) {
  if (text.size() < tail.size()) return false;
  for (std::size_t n = 0; n < tail.size(); ++n) {
    const auto c = static_cast<unsigned char>(text[text.size() - tail.size() + n]);
    if (std::tolower(c) != tail[n]) return false;
  }
  return true;
}

Route bad(std::string reason) {
  Route r;
  r.kind = RouteKind::BadRequest;
  r.reason = std::move(reason);
  return r;
}

Route route(RouteKind kind, std::string_view job = {}) {
  Route r;
  r.kind = kind;
  r.job = std::string(job);
  return r;
}

}  // namespace

bool is_job_id(std::string_view id) {
  return !id.empty() && id.size() <= 16 && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
  });
}

Result<std::string> percent_decode(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t n = 0; n < text.size(); ++n) {
    const char c = text[n];
    if (c == '+') {
      out.push_back(' ');
    } else if (c == '%') {
      if (n + 2 >= text.size()) {
        return Error{ErrorCode::BadInput, "a malformed %-escape", {}};
      }
      const auto hex = [](char h) -> int {
        if (h >= '0' && h <= '9') return h - '0';
        if (h >= 'a' && h <= 'f') return h - 'a' + 10;
        if (h >= 'A' && h <= 'F') return h - 'A' + 10;
        return -1;
      };
      const int hi = hex(text[n + 1]);
      const int lo = hex(text[n + 2]);
      if (hi < 0 || lo < 0) return Error{ErrorCode::BadInput, "a malformed %-escape", {}};
      out.push_back(static_cast<char>(hi * 16 + lo));
      n += 2;
    } else {
      out.push_back(c);
    }
  }
  return out;
}

Result<std::string> check_upload_name(std::string_view raw) {
  std::string_view name = raw;
  if (const std::size_t slash = name.find_last_of("/\\"); slash != std::string_view::npos) {
    name = name.substr(slash + 1);
  }
  if (name.empty()) return Error{ErrorCode::BadInput, "the upload has no file name", {}};
  if (name.size() > 200) {
    return Error{ErrorCode::BadInput, "the file name is longer than 200 characters", {}};
  }
  if (name.front() == '.') {
    return Error{ErrorCode::BadInput, "the file name starts with '.'", {}};
  }
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (!(std::isalnum(u) != 0 || c == '-' || c == '_' || c == '.' || c == ' ' || c == '(' ||
          c == ')')) {
      return Error{ErrorCode::BadInput,
                   "the file name may hold letters, digits, '-', '_', '.', ' ', '(' and ')' "
                   "only: rename the file",
                   {}};
    }
  }
  std::string_view bare = name;
  const bool gzipped = lower_ends_with(bare, ".gz");
  if (gzipped) bare.remove_suffix(3);
  // Something precedes the extension: the name does not start with '.'. A 3MF file is a zip
  // archive already, never gzipped.
  const bool model = lower_ends_with(bare, ".stl") || lower_ends_with(bare, ".obj") ||
                     lower_ends_with(bare, ".off") || lower_ends_with(bare, ".ply") ||
                     (!gzipped && lower_ends_with(bare, ".3mf"));
  if (!model) {
    return Error{ErrorCode::BadInput,
                 "not a model file name: strata reads .stl, .obj, .off, .ply and .3mf files, and "
                 ".gz of the first four",
                 {}};
  }
  return std::string(name);
}

std::string stem_of(std::string_view name) {
  if (lower_ends_with(name, ".gz")) name.remove_suffix(3);
  const std::size_t dot = name.find_last_of('.');
  if (dot != std::string_view::npos && dot > 0) name = name.substr(0, dot);
  return name.empty() ? std::string("model") : std::string(name);
}

Route match_route(std::string_view method, std::string_view target) {
  if (target.empty() || target.front() != '/') return bad("the request target is not a path");
  const std::size_t q = target.find('?');
  const std::string_view path = target.substr(0, q);
  const std::string_view query =
      q == std::string_view::npos ? std::string_view() : target.substr(q + 1);
  if (path.find("..") != std::string_view::npos || path.find('\\') != std::string_view::npos ||
      path.find('\0') != std::string_view::npos || path.find("//") != std::string_view::npos) {
    return bad("the path is refused");
  }
  if (path.find('%') != std::string_view::npos) {
    return bad("encoded characters are refused in the path");
  }
  const bool get = method == "GET" || method == "HEAD";
  const bool post = method == "POST";
  const std::vector<std::string_view> parts = split_path(path);

  if (path == "/") return get ? route(RouteKind::AppPage) : route(RouteKind::WrongMethod);
  if (path == "/viewer") {
    if (!get) return route(RouteKind::WrongMethod);
    bool found = false;
    const std::string_view job = query_value(query, "job", found);
    if (!found || !is_job_id(job)) return bad("/viewer needs ?job=ID");
    return route(RouteKind::ViewerPage, job);
  }
  if (parts.size() < 2 || parts[0] != "api") return route(RouteKind::NotFound);
  if (parts.size() == 2 && parts[1] == "info") {
    return get ? route(RouteKind::Info) : route(RouteKind::WrongMethod);
  }
  if (parts[1] != "jobs") return route(RouteKind::NotFound);
  if (parts.size() == 2) {
    if (get) return route(RouteKind::ListJobs);
    if (!post) return route(RouteKind::WrongMethod);
    bool found = false;
    const std::string_view raw = query_value(query, "name", found);
    if (!found) return bad("an upload needs ?name=FILE");
    auto decoded = percent_decode(raw);
    if (!decoded) return bad(decoded.error().message);
    auto name = check_upload_name(*decoded);
    if (!name) return bad(name.error().message);
    Route r = route(RouteKind::Upload);
    r.name = std::move(name).value();
    return r;
  }
  const std::string_view job = parts[2];
  if (!is_job_id(job)) return route(RouteKind::NotFound);
  if (parts.size() == 3) {
    if (get) return route(RouteKind::JobStatus, job);
    if (method == "DELETE") return route(RouteKind::Remove, job);
    return route(RouteKind::WrongMethod);
  }
  if (parts.size() == 4) {
    const std::string_view action = parts[3];
    if (action == "view.json") {
      return get ? route(RouteKind::ViewData, job) : route(RouteKind::WrongMethod);
    }
    const std::array<std::pair<std::string_view, RouteKind>, 3> actions = {
        {{"slice", RouteKind::Slice},
         {"cancel", RouteKind::Cancel},
         {"validate", RouteKind::Validate}}};
    for (const auto& [word, kind] : actions) {
      if (action == word) return post ? route(kind, job) : route(RouteKind::WrongMethod);
    }
    return route(RouteKind::NotFound);
  }
  if (parts.size() == 5 && parts[3] == "files") {
    const std::string_view kind = parts[4];
    if (std::find(std::begin(kFileKinds), std::end(kFileKinds), kind) == std::end(kFileKinds)) {
      return route(RouteKind::NotFound);
    }
    if (!get) return route(RouteKind::WrongMethod);
    Route r = route(RouteKind::File, job);
    r.file = std::string(kind);
    return r;
  }
  return route(RouteKind::NotFound);
}

}  // namespace strata::serve::detail
