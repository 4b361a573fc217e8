#pragma once

// The Markdown report of strata-validation (validation/REPORT.md).

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "validation_records.hpp"

namespace strata::validation {

/// The report: how it was run, the totals, the refusals, every run with differing cells, a
/// line a model and the files skipped.
/// @param too_large     corpus files left out for their size: path and bytes
/// @param wall_seconds  the whole validation's time
std::string make_report(const std::vector<ModelRecord>& records,
                        const std::vector<std::pair<std::string, std::uint64_t>>& too_large,
                        const RunnerOptions& o, double wall_seconds);

}  // namespace strata::validation
