#pragma once

#include <string>

#include "cli/slice_command.hpp"
#include "strata/core/result.hpp"
#include "strata/io/length_unit.hpp"
#include "strata/serve/task_runner.hpp"

namespace strata::cli {

/// The options a page sends for a slice or a validation (keys named after the CLI's options:
/// layer, cell, dx, dy, shell, shell_mode, fill_rule, scan_offset, kernel, origin, repair,
/// fill_holes; every key optional, none other allowed), as `strata slice` would take them.
/// @return Error{Usage} naming the key that is wrong
Result<SliceCommandOptions> slice_options_of_json(const std::string& json_text);

/// The tasks of `strata serve`, done with the same functions as `strata check`, `strata slice`
/// and `strata validate`.
/// Every model is read with `scale` (the session's --units and --scale).
serve::TaskRunner make_serve_task_runner(const io::CoordinateScale& scale = {});

}  // namespace strata::cli
