#pragma once

#include "strata/validate/validate_model.hpp"

namespace strata::test {

/// validate_model on the grid `options` makes from the mesh's bounds; fails the current test
/// (and returns an empty report) when the validation itself fails.
validate::ValidationReport validated_model(const IndexedMesh& mesh, const SliceOptions& options,
                                           const validate::ValidateOptions& validate_options = {});

}  // namespace strata::test
