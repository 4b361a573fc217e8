#include <fmt/format.h>

#include "strata/core/thousands.hpp"
#include "strata/view/display_mesh.hpp"

namespace strata::view {

NotedDisplayMesh make_noted_display_mesh(const IndexedMesh& mesh, std::size_t max_facets,
                                         SliceStage stage, CountDigits digits) {
  NotedDisplayMesh out{make_display_mesh(mesh, max_facets), std::nullopt};
  if (!out.mesh.simplified) return out;
  const auto count = [&](std::size_t n) {
    return digits == CountDigits::GroupedByThousands ? with_thousands(n) : std::to_string(n);
  };
  out.note = fmt::format(
      "display mesh simplified from {} to {} facets for the browser; slicing {} "
      "every facet",
      count(out.mesh.facets_in_model), count(out.mesh.facets()),
      stage == SliceStage::Sliced ? "used" : "uses");
  return out;
}

}  // namespace strata::view
