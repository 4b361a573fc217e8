#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata::winding {

/// The signed solid angle (steradians) that triangle abc subtends at q (Van Oosterom and
/// Strackee 1983): positive when q sees the triangle's back, i.e. when q lies on the side its
/// normal (b - a) x (c - a) points away from. 0 when q lies in the triangle's plane.
double triangle_solid_angle(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c);

/// The generalized winding number of the mesh's facets at q (Jacobson et al. 2013): the sum of
/// their solid angles over 4 pi. 1 inside and 0 outside a closed, outward-oriented surface;
/// between the two near the holes of an open one. Direct sum, O(facets).
double winding_number(const IndexedMesh& mesh, const Vec3& q);

/// A mesh's boundary closed by caps, so that the integer crossing rule of SPEC §2 applies.
///
/// The boundary of a triangle soup is the 1-chain of its directed edges where the facets do not
/// cancel: edge u -> v counted +1 by every facet that runs u -> v and -1 by every facet that runs
/// v -> u. It is a cycle (every vertex has as many boundary edges in as out), so adding, for each
/// boundary edge u -> v of multiplicity m, m fan facets (apex, v, u), with one apex per connected
/// component of the boundary (the mean of its vertices), gives a surface with no boundary at all.
/// Each fan facet is cut into strips along its spokes (about one mean boundary edge long, at most
/// 64), so that the caps' facets are compact and the evaluation tree can treat them as far away.
/// Then, with P the caps: w_mesh(q) = w_closed(q) - w_P(q), where w_closed is an integer given
/// exactly by the crossing rule and only w_P, usually small and local, has to be approximated.
struct BoundaryCaps {
  /// The mesh's vertices and facets first (same indices), then the apexes and the caps.
  IndexedMesh closed;
  std::uint32_t mesh_facets = 0;
  /// Boundary edges with their multiplicity (the number of fans' facets before cutting).
  std::uint64_t boundary_edges = 0;
  /// Connected components of the boundary (the number of apexes).
  std::uint32_t components = 0;
};

/// Builds the caps of `mesh` (see BoundaryCaps). A closed, consistently oriented mesh (every
/// non-manifold edge balanced too) gets none.
BoundaryCaps cap_boundary(const IndexedMesh& mesh);

/// The fast hierarchical evaluation of the generalized winding number (Barill et al. 2018): a
/// bounding volume hierarchy over the facets, each node holding the area-weighted normal sum and
/// its first moment about the node's centre, so that a node seen from farther than beta times its
/// radius contributes its dipole expansion (to second order) instead of its facets' exact solid
/// angles. Larger beta: fewer far-field nodes, more accuracy, more time.
class WindingNumberTree {
 public:
  static constexpr double kDefaultBeta = 2.0;

  /// Builds the hierarchy over `triangles` (each a facet's corners, in its orientation).
  explicit WindingNumberTree(std::vector<std::array<Vec3, 3>> triangles);

  /// The hierarchical approximation of the winding number at q.
  double evaluate(const Vec3& q, double beta = kDefaultBeta) const;
  /// The direct sum over every facet (the reference the approximation is measured against).
  double evaluate_direct(const Vec3& q) const;
  /// Facets in the hierarchy.
  std::size_t facet_count() const { return triangles_.size(); }
  /// True without facets (the winding number is then 0 everywhere).
  bool empty() const { return triangles_.empty(); }

 private:
  struct Node {
    Vec3 centre;
    double radius = 0.0;
    Vec3 normal_sum;                     ///< sum of the facets' area vectors
    std::array<double, 9> moment{};      ///< sum of area vector (x) (centroid - centre), row-major
    std::uint32_t first = 0, count = 0;  ///< facet range, when a leaf
    std::uint32_t left = 0, right = 0;   ///< children, when count == 0
  };

  std::uint32_t build(std::uint32_t first, std::uint32_t count);
  double direct_sum(std::uint32_t first, std::uint32_t count, const Vec3& q) const;

  std::vector<std::array<Vec3, 3>> triangles_;
  std::vector<Node> nodes_;
};

}  // namespace strata::winding
