#pragma once

#include <string>
#include <string_view>

#include "strata/core/result.hpp"

namespace strata::serve::detail {

/// Every request the page makes; anything else is NotFound, BadRequest or WrongMethod.
enum class RouteKind {
  AppPage,     ///< GET /
  ViewerPage,  ///< GET /viewer?job=ID: the view page, loading the job's data
  Info,        ///< GET /api/info: limits and defaults
  ListJobs,    ///< GET /api/jobs
  Upload,      ///< POST /api/jobs?name=FILE, the model's bytes as the body
  JobStatus,   ///< GET /api/jobs/ID
  Slice,       ///< POST /api/jobs/ID/slice, the options as a JSON body
  Cancel,      ///< POST /api/jobs/ID/cancel
  Validate,    ///< POST /api/jobs/ID/validate
  Remove,      ///< DELETE /api/jobs/ID
  ViewData,    ///< GET /api/jobs/ID/view.json: the page's data (web/DATA.md)
  File,        ///< GET /api/jobs/ID/files/KIND: a download
  NotFound,
  BadRequest,
  WrongMethod,
};

struct Route {
  RouteKind kind = RouteKind::NotFound;
  std::string job;     ///< a job id (checked by is_job_id)
  std::string file;    ///< File: one of kFileKinds
  std::string name;    ///< Upload: the checked file name
  std::string reason;  ///< BadRequest: why
};

/// The downloads of a job, by kind.
inline constexpr std::string_view kFileKinds[] = {"model", "cells", "png",        "svg",  "cli",
                                                  "json",  "html",  "validation", "check"};

/// Matches a request line. A target holding "..", a backslash, a NUL, an encoded '/', '.' or
/// '\\' in its path, or a job id that is not 1 to 16 lowercase hexadecimal digits is refused.
Route match_route(std::string_view method, std::string_view target);

/// A job id: 1 to 16 characters of [0-9a-f].
bool is_job_id(std::string_view id);

/// Decodes %XX escapes and '+' (a query value); Error when an escape is malformed.
Result<std::string> percent_decode(std::string_view text);

/// The name an upload is stored under: the last path component of `raw`, at most 200 bytes of
/// letters, digits, '-', '_', '.', ' ', '(' and ')', not starting with '.', ending in a model
/// extension (.stl, .obj, .off, .ply, optionally followed by .gz; any case).
/// @return Error{BadInput} saying what is wrong
Result<std::string> check_upload_name(std::string_view raw);

/// The model's stem, as the CLI names outputs: "part.stl.gz" -> "part".
std::string stem_of(std::string_view name);

}  // namespace strata::serve::detail
