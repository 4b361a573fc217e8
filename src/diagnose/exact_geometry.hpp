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

/// Signed volumes sum((a · (b x c)) / 6) over facets, each the exact sum rounded once to the
/// nearest double.
struct ExactVolumes {
  double total_mm3 = 0.0;
  std::vector<double> by_group_mm3;
  /// Whether a floating-point evaluation with a proven error bound decided every rounding
  /// (false: the sums were taken on integers). The values are the same either way.
  bool decided_in_floating_point = false;
};

/// A facet in no group, left out of every sum: a zero-area facet, whose volume is exactly zero.
inline constexpr std::uint32_t kNoGroup = 0xFFFFFFFFU;

/// @param group_of_facet  the group (shell) of every facet of `mesh`, each < num_groups or
///                        kNoGroup
ExactVolumes exact_signed_volumes(const IndexedMesh& mesh,
                                  const std::vector<std::uint32_t>& group_of_facet,
                                  std::size_t num_groups);

/// The same volumes always summed on integers, as exact_signed_volumes does where its
/// floating-point filter cannot decide (decided_in_floating_point is false).
ExactVolumes integer_signed_volumes(const IndexedMesh& mesh,
                                    const std::vector<std::uint32_t>& group_of_facet,
                                    std::size_t num_groups);

}  // namespace strata::diagnose::detail
