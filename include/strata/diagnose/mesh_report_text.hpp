#pragma once

#include <string>

#include "strata/diagnose/mesh_report.hpp"

namespace strata::diagnose {

/// The report for people: one line a measure or defect, the first few locations of each defect,
/// and the verdict with its reason on the last line. Ends with a newline.
std::string mesh_report_text(const MeshReport& report);

}  // namespace strata::diagnose
