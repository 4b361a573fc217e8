#pragma once

#include "strata/core/error.hpp"

namespace strata::cli {

/// Prints "strata: <location>: <message>" on stderr and returns the error's exit code.
int report_error(const Error& error);

}  // namespace strata::cli
