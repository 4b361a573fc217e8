#pragma once

#include <stdexcept>
#include <string>

namespace strata {

/// What kind of failure an Error is. A program maps these to its own status (the command line's
/// exit codes of SPEC §4: src/cli/exit_code.cpp).
enum class ErrorCode { BadInput, Usage, Internal };

/// An expected failure: bad input, bad usage, or an internal error caught at a module boundary.
/// `location` names the file and, where it applies, the line or facet ("cube.stl:12",
/// "cube.stl: facet 7"); `message` says what was wrong and what was expected.
struct Error {
  ErrorCode code = ErrorCode::BadInput;
  std::string message;
  std::string location;

  /// "location: message", or the message alone when there is no location.
  std::string to_string() const { return location.empty() ? message : location + ": " + message; }
};

/// Thrown by STRATA_ASSERT when an invariant of the library does not hold.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace strata

/// Checks an invariant; throws strata::InternalError so that tests can catch it and a caller can
/// report an internal error instead of aborting.
#define STRATA_ASSERT(cond, msg)                                                             \
  do {                                                                                       \
    if (!(cond)) {                                                                           \
      throw ::strata::InternalError(std::string(__FILE__) + ":" + std::to_string(__LINE__) + \
                                    ": assertion '" #cond "' failed: " + (msg));             \
    }                                                                                        \
  } while (false)
