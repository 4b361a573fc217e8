#pragma once

#include <string>

#include "strata/validate/validation_report.hpp"

namespace strata::validate {

/// The report for people: grid and rule, the verdict on the cells, the differing cells with
/// their reasons (the first 20), the contour figures with the worst layers, the model figures
/// (volumes, bounding boxes, surface-to-shell distance, shell thickness vs t), the cells the
/// scan offset changes, the reference slicer's figures (or why it did not run) and the times of
/// both paths. Ends with a newline.
std::string validation_text(const ValidationReport& report);

}  // namespace strata::validate
