#pragma once

#include "strata/core/diagnostic.hpp"

namespace strata::cli {

/// The library's messages speak of options by what they mean ("shell mode layers"); the command
/// line names its flags ("--shell-mode layers"). Rewrites the diagnostics that mention an option
/// in the command line's terms, before they are printed or written to a report.
void name_flags(Diagnostics& diagnostics);

}  // namespace strata::cli
