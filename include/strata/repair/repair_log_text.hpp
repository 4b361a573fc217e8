#pragma once

#include <string>
#include <string_view>

#include "strata/repair/repair_log.hpp"

namespace strata::repair {

/// The log for people, in the layout of diagnose::mesh_report_text(): a line "repair", then one
/// indented line a step ("  degenerate facets removed    3"), the steps that did nothing
/// included so that the reader sees they ran, and the first few changed facets. Ends with a
/// newline.
/// @param not_filled_reason why holes were left unfilled when filling was not requested, in the
///        caller's terms (the command line passes "--fill-holes not given")
std::string repair_log_text(const RepairLog& log,
                            std::string_view not_filled_reason = "filling not requested");

/// One line without newline for a progress or status message, e.g.
/// "repair: 12 facets in, 13 out; 1 duplicate removed, 2 flipped, 1 hole filled (1 facet)".
std::string repair_log_summary(const RepairLog& log);

}  // namespace strata::repair
