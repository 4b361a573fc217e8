#pragma once

#include <cstdint>
#include <vector>

#include "exact/exact_numbers_internal.hpp"
#include "strata/contour/contour.hpp"

namespace strata::exact::detail {

/// Turns exact loops into a layer's contours: points rounded once to double; closed loops get
/// their shoelace area (of the rounded points), their kind (Outer when counter-clockwise, decided
/// exactly at the lexicographically smallest vertex) and their depth (the number of other closed
/// loops that strictly contain a point of their first edge, by exact predicates).
/// @param open_chains the layer's open chain count (Open loops among `loops` included)
LayerContours finish_contours(std::uint32_t layer, double z_mm, std::vector<ExactLoop> loops,
                              std::uint32_t open_chains);

}  // namespace strata::exact::detail
