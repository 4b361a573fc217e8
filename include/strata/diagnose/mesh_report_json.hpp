#pragma once

#include <string>

#include "strata/diagnose/mesh_report.hpp"

namespace strata::diagnose {

/// The report as a JSON object (one line, UTF-8): counts, measures, the kept locations, the
/// shells and the verdict. Keys are snake_case; lengths in mm, areas in mm², volumes in mm³;
/// points are [x, y, z] arrays; numbers that are not finite are written as null.
std::string mesh_report_json(const MeshReport& report);

}  // namespace strata::diagnose
