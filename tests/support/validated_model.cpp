#include "support/validated_model.hpp"

#include <gtest/gtest.h>

#include <utility>

#include "strata/slice/grid_spec.hpp"

namespace strata::test {

validate::ValidationReport validated_model(const IndexedMesh& mesh, const SliceOptions& options,
                                           const validate::ValidateOptions& validate_options) {
  const GridSpec grid = make_grid(mesh.bounds(), options.grid).value();
  auto report = validate::validate_model(mesh, grid, options, validate_options);
  EXPECT_TRUE(report.has_value()) << (report ? "" : report.error().to_string());
  return report ? std::move(report).value() : validate::ValidationReport{};
}

}  // namespace strata::test
