#pragma once

// Exact geometry on a mesh, shared with repair (shell volumes) and the diagnostics.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata::diagnose::detail {

/// True when a, b, c lie on one line (two or three of them equal included). Exact.
bool is_collinear(const Vec3& a, const Vec3& b, const Vec3& c);

/// Sign (-1, 0, +1) of dot(n, (b - a) x (c - a)), evaluated exactly: whether a stored normal
/// agrees with the right-hand rule of the vertex order. @pre all coordinates finite.
int normal_agreement_sign(const Vec3& n, const Vec3& a, const Vec3& b, const Vec3& c);

/// Signed volumes sum((a · (b x c)) / 6) over facets, accumulated exactly and rounded once to
/// the nearest double.
struct ExactVolumes {
  double total_mm3 = 0.0;
  std::vector<double> by_group_mm3;
};

/// @param group_of_facet  the group (shell) of every facet of `mesh`, each < num_groups
ExactVolumes exact_signed_volumes(const IndexedMesh& mesh,
                                  const std::vector<std::uint32_t>& group_of_facet,
                                  std::size_t num_groups);

}  // namespace strata::diagnose::detail
