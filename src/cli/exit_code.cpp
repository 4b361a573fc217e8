#include "cli/exit_code.hpp"

#include <cstdio>

namespace strata::cli {

int exit_code(ErrorCode code) {
  switch (code) {
    case ErrorCode::BadInput:
      return kExitBadInput;
    case ErrorCode::Usage:
      return kExitUsage;
    case ErrorCode::Internal:
      return kExitInternal;
  }
  return kExitInternal;
}

int report_error(const Error& error) {
  std::fprintf(stderr, "strata: %s\n", error.to_string().c_str());
  return exit_code(error.code);
}

}  // namespace strata::cli
