#include "support/validated_model.hpp"

#include "strata/slice/grid_spec.hpp"
#include "support/result_checks.hpp"

namespace strata::test {

validate::ValidationReport validated_model(const IndexedMesh& mesh, const SliceOptions& options,
                                           const validate::ValidateOptions& validate_options) {
  const GridSpec grid = make_grid(mesh.bounds(), options.grid).value();
  return value_of(validate::validate_model(mesh, grid, options, validate_options),
                  "validate_model");
}

}  // namespace strata::test
