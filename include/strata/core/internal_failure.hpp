#pragma once

#include <exception>
#include <new>
#include <string>
#include <string_view>

#include "strata/core/error.hpp"

namespace strata {

/// Calls attempt() (which returns a Result) and turns an exception it throws into
/// Error{Internal}, so that a library caller gets an Error, never an exception, whatever failed:
/// "<name>: out of memory" for std::bad_alloc, "<name> failed: <what>" for any other
/// std::exception (CGAL's failures, a broken invariant, a sink's I/O). `on_failure` runs before
/// the Error is returned (for example to abort the sinks that began).
template <class Attempt, class OnFailure>
auto catch_internal_failure(std::string_view name, Attempt&& attempt, OnFailure&& on_failure)
    -> decltype(attempt()) {
  try {
    return attempt();
  } catch (const std::bad_alloc&) {
    on_failure();
    return Error{ErrorCode::Internal, std::string(name) + ": out of memory", {}};
  } catch (const std::exception& e) {
    on_failure();
    return Error{ErrorCode::Internal, std::string(name) + " failed: " + e.what(), {}};
  }
}

}  // namespace strata
