#pragma once

#include <string>

#include "strata/validate/validation_report.hpp"

namespace strata::validate {

/// The report as a JSON object (pretty-printed, UTF-8, ending with a newline): grid, options,
/// both paths, the exact path's soup repair, cells (compared, differing, by reason, the listed
/// differences as {"i","j","k","fast","exact","reason"}), contours (totals and one entry a
/// layer), scan offset, model figures, the reference slicer ("reference_slicer": whether it ran
/// and why not, its maxima, counts and one entry a layer) and times. Keys are snake_case; lengths
/// in mm, areas in mm², volumes in mm³, times in s; cell classes as "00", "01", "11"; numbers that
/// are not finite are written as null.
std::string validation_json(const ValidationReport& report);

}  // namespace strata::validate
