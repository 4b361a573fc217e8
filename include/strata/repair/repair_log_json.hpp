#pragma once

#include <string>

#include "strata/repair/repair_log.hpp"

namespace strata::repair {

/// The log as a JSON object (one line, UTF-8), one snake_case key a count as named in RepairLog,
/// grouped by step ("input", "weld", "degenerate", "duplicates", "t_junctions", "orientation",
/// "stitching", "holes", "volume_orientation", "output"), plus "changed" (changed_anything())
/// and "changes": the number of changes and the first kMaxChangesListed of them as
/// {"facet": index, "change": facet_change_name()}.
std::string repair_log_json(const RepairLog& log);

}  // namespace strata::repair
