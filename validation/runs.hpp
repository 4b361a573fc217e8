#pragma once

// Running one model: the grids it is validated on and a validation of each grid and fill rule.

#include "validation_records.hpp"

namespace strata::validation {

/// Reads the model and validates it under the nonzero and evenodd fill rules on an aligned and
/// a shifted grid (validate::validate_model, one run each).
ModelRecord validate_case(const ModelCase& m, const RunnerOptions& o);

}  // namespace strata::validation
