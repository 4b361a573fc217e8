#include "cli/exit_code.hpp"

#include <cstdio>

namespace strata::cli {

int report_error(const Error& error) {
  std::fprintf(stderr, "strata: %s\n", error.to_string().c_str());
  return static_cast<int>(error.code);
}

}  // namespace strata::cli
