#pragma once

#include <cstdint>
#include <span>

#include "exact/exact_numbers_internal.hpp"
#include "strata/mesh/indexed_mesh.hpp"

namespace strata::exact::detail {

/// Sign of the x component of every facet's normal n = (b - a) x (c - a), exact.
std::vector<std::int8_t> facet_normal_x_signs(const IndexedMesh& mesh);

/// Cuts the candidate facets with the plane z (SPEC §2): a facet whose vertices lie on both sides
/// (a vertex with z == plane counts as above) gives one segment between the exact crossing points
/// of its two crossing edges, directed by the facet's own vertex order.
/// @param candidates facets to try, in increasing order; the others are not looked at
/// @param normal_x_signs facet_normal_x_signs(mesh), or empty when the caller needs no cells
///        (every segment's normal_x_sign is then 0)
ExactLayer cut_layer(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                     std::span<const std::int8_t> normal_x_signs, std::uint32_t layer, double z);

}  // namespace strata::exact::detail
