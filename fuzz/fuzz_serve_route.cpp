// The bytes as the request line of `strata serve` (a method, a space, the target) and as a Host
// header. The router must answer every request line, and what it routes must be safe to act on:
// a route to a job names a valid job id; an upload names a file that passes the name check, holds
// no path separator and does not start with '.'; a download names one of the file kinds; a
// refusal says why; a path holding ".." is never routed. The same bytes also go through the
// percent decoding and the name check on their own, and a host passes for the loopback interface
// only by one of its names.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "serve/api_internal.hpp"
#include "serve/route_internal.hpp"

namespace {

using namespace strata::serve::detail;
using strata::fuzz::check;

bool safe_name(std::string_view name) {
  return !name.empty() && name.front() != '.' && name.find('/') == std::string_view::npos &&
         name.find('\\') == std::string_view::npos && name.find('\0') == std::string_view::npos &&
         name.size() <= 200;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = strata::fuzz::as_bytes(data, size);
  const std::size_t space = bytes.find(' ');
  const std::string_view method = space == std::string_view::npos ? "GET" : bytes.substr(0, space);
  const std::string_view target = space == std::string_view::npos ? bytes : bytes.substr(space + 1);

  const Route route = match_route(method, target);
  switch (route.kind) {
    case RouteKind::JobStatus:
    case RouteKind::Slice:
    case RouteKind::Cancel:
    case RouteKind::Validate:
    case RouteKind::Remove:
    case RouteKind::ViewData:
    case RouteKind::ViewerPage:
      check(is_job_id(route.job), "a route to a job names a valid job id");
      break;
    case RouteKind::File:
      check(is_job_id(route.job), "a download names a valid job id");
      check(std::find(std::begin(kFileKinds), std::end(kFileKinds), route.file) !=
                std::end(kFileKinds),
            "a download names one of the file kinds");
      break;
    case RouteKind::Upload:
      check(safe_name(route.name), "an upload's name is a plain file name");
      check(check_upload_name(route.name).has_value(), "an upload's name passes the name check");
      break;
    case RouteKind::BadRequest:
      check(!route.reason.empty(), "a bad request says why");
      break;
    default:
      break;
  }
  const std::string_view path = target.substr(0, target.find('?'));
  check(path.find("..") == std::string_view::npos || route.kind == RouteKind::BadRequest ||
            route.kind == RouteKind::NotFound || route.kind == RouteKind::WrongMethod,
        "a target whose path holds '..' is refused");

  if (const auto decoded = percent_decode(bytes)) {
    check(decoded->size() <= bytes.size(), "decoding never lengthens the text");
  } else {
    check(!decoded.error().message.empty(), "a malformed escape is named");
  }
  if (const auto name = check_upload_name(bytes)) {
    check(safe_name(*name), "a checked upload name is a plain file name");
    check(!stem_of(*name).empty(), "a checked name has a stem");
  } else {
    check(!name.error().message.empty(), "a refused upload name says why");
  }
  // The guard against DNS rebinding: no other name passes for the loopback interface.
  if (is_loopback_host(bytes)) {
    const std::string_view host = bytes.front() == '[' ? bytes.substr(0, bytes.find(']') + 1)
                                                       : bytes.substr(0, bytes.find(':'));
    check(host == "localhost" || host == "127.0.0.1" || host == "[::1]",
          "only a loopback name passes for the loopback host");
  }
  return 0;
}
