#pragma once

#include "strata/core/error.hpp"

namespace strata::cli {

/// Exit codes of SPEC §4.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInternal = 3;
inline constexpr int kExitCellsDiffer = 4;

/// The exit code of SPEC §4 for a library error: bad input 1, bad usage 2, internal error 3.
int exit_code(ErrorCode code);

/// Prints "strata: <location>: <message>" on stderr and returns the error's exit code.
int report_error(const Error& error);

}  // namespace strata::cli
