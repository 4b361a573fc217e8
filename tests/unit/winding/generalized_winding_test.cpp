#include "strata/winding/generalized_winding.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::winding {
namespace {

IndexedMesh sphere(double radius, int subdivisions) {
  return weld_vertices(mesh::make_sphere(radius, subdivisions));
}

/// Every `step`-th facet removed, starting at `first`.
IndexedMesh without_facets(IndexedMesh m, std::size_t first, std::size_t step, std::size_t count) {
  std::vector<bool> drop(m.triangles.size(), false);
  for (std::size_t n = 0, f = first; n < count && f < drop.size(); ++n, f += step) drop[f] = true;
  std::vector<std::array<VertexIndex, 3>> kept;
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    if (!drop[f]) kept.push_back(m.triangles[f]);
  }
  m.triangles = std::move(kept);
  return m;
}

std::vector<std::array<Vec3, 3>> corners_of(const IndexedMesh& m, std::size_t from = 0) {
  std::vector<std::array<Vec3, 3>> out;
  for (std::size_t f = from; f < m.triangles.size(); ++f) {
    const auto& t = m.triangles[f];
    out.push_back({m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]});
  }
  return out;
}

std::vector<Vec3> random_points(std::size_t n, double half_width, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-half_width, half_width);
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back({u(rng), u(rng), u(rng)});
  return out;
}

TEST(TriangleSolidAngle, OctantTriangleSubtendsAnEighthOfTheSphere) {
  // Seen from the origin, the triangle through the unit axis points covers exactly one octant.
  const double omega = triangle_solid_angle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_NEAR(omega, std::numbers::pi / 2.0, 1e-14);
  EXPECT_NEAR(triangle_solid_angle({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}),
              -std::numbers::pi / 2.0, 1e-14);
}

TEST(TriangleSolidAngle, IsZeroInTheTrianglesPlane) {
  EXPECT_EQ(triangle_solid_angle({5, 5, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}), 0.0);
}

TEST(WindingNumber, IsOneInsideZeroOutsideAndMinusOneInsideAnInvertedSphere) {
  const IndexedMesh s = sphere(10.0, 2);
  EXPECT_NEAR(winding_number(s, {0.5, -1.0, 2.0}), 1.0, 1e-12);
  EXPECT_NEAR(winding_number(s, {15.0, 0.0, 0.0}), 0.0, 1e-12);
  const IndexedMesh inverted = weld_vertices(mesh::flip_orientation(mesh::make_sphere(10.0, 2)));
  EXPECT_NEAR(winding_number(inverted, {0.5, -1.0, 2.0}), -1.0, 1e-12);
}

TEST(CapBoundary, AClosedMeshGetsNoCaps) {
  const BoundaryCaps caps = cap_boundary(sphere(10.0, 2));
  EXPECT_EQ(caps.boundary_edges, 0u);
  EXPECT_EQ(caps.components, 0u);
  EXPECT_EQ(caps.closed.triangles.size(), caps.mesh_facets);
}

TEST(CapBoundary, CapsEveryHoleAndLeaveNoBoundary) {
  const IndexedMesh full = sphere(10.0, 3);
  const IndexedMesh open = without_facets(full, 7, 97, 10);  // ten holes far apart
  const BoundaryCaps caps = cap_boundary(open);
  EXPECT_EQ(caps.boundary_edges, 30u);
  EXPECT_EQ(caps.components, 10u);
  EXPECT_EQ(caps.closed.triangles.size(), open.triangles.size() + 30u);
  EXPECT_EQ(cap_boundary(caps.closed).boundary_edges, 0u);
}

TEST(CapBoundary, AFlippedFacetIsCappedTwice) {
  IndexedMesh m = sphere(10.0, 2);
  std::swap(m.triangles[5][1], m.triangles[5][2]);
  const BoundaryCaps caps = cap_boundary(m);
  EXPECT_EQ(caps.boundary_edges, 6u);  // each of its three edges runs twice the same way
  EXPECT_EQ(cap_boundary(caps.closed).boundary_edges, 0u);
}

TEST(CapBoundary, MeshWindingIsTheClosedIntegerMinusTheCaps) {
  const IndexedMesh open = without_facets(sphere(10.0, 3), 3, 41, 25);
  const BoundaryCaps caps = cap_boundary(open);
  IndexedMesh only_caps;
  only_caps.vertices = caps.closed.vertices;
  only_caps.triangles.assign(caps.closed.triangles.begin() + caps.mesh_facets,
                             caps.closed.triangles.end());
  for (const Vec3& q : random_points(200, 14.0, 11)) {
    const double closed = winding_number(caps.closed, q);
    EXPECT_NEAR(closed, std::round(closed), 1e-9) << q.x << " " << q.y << " " << q.z;
    EXPECT_NEAR(winding_number(open, q), std::round(closed) - winding_number(only_caps, q), 1e-9);
  }
}

TEST(CapBoundary, ALargeHoleIsClosedByCompactStrips) {
  IndexedMesh open = sphere(10.0, 4);
  std::erase_if(open.triangles, [&](const auto& t) {
    return open.vertices[t[0]].z + open.vertices[t[1]].z + open.vertices[t[2]].z > 3 * 6.0;
  });
  const BoundaryCaps caps = cap_boundary(open);
  ASSERT_EQ(caps.components, 1u);
  EXPECT_EQ(cap_boundary(caps.closed).boundary_edges, 0u);
  // The hole is 16 mm wide with edges of about 0.6 mm: the fan is cut into short strips.
  double longest = 0.0;
  for (std::size_t f = caps.mesh_facets; f < caps.closed.triangles.size(); ++f) {
    const auto& t = caps.closed.triangles[f];
    for (int e = 0; e < 3; ++e) {
      const Vec3& a = caps.closed.vertices[t[e]];
      const Vec3& b = caps.closed.vertices[t[(e + 1) % 3]];
      longest = std::max(longest, std::hypot(a.x - b.x, a.y - b.y, a.z - b.z));
    }
  }
  EXPECT_LT(longest, 1.5);
  IndexedMesh only_caps;
  only_caps.vertices = caps.closed.vertices;
  only_caps.triangles.assign(caps.closed.triangles.begin() + caps.mesh_facets,
                             caps.closed.triangles.end());
  for (const Vec3& q : random_points(100, 12.0, 17)) {
    const double closed = winding_number(caps.closed, q);
    EXPECT_NEAR(closed, std::round(closed), 1e-9);
    EXPECT_NEAR(winding_number(open, q), std::round(closed) - winding_number(only_caps, q), 1e-9);
  }
}

TEST(WindingNumberTree, MatchesTheDirectSumWithinTheMeasuredBound) {
  // A sphere with 1 % of its facets removed: the winding number varies smoothly near the holes.
  const IndexedMesh open = without_facets(sphere(10.0, 4), 0, 100, 51);
  const WindingNumberTree tree(corners_of(open));
  double worst = 0.0;
  double worst_guard = 0.0;
  for (const Vec3& q : random_points(2000, 13.0, 5)) {
    const double direct = winding_number(open, q);
    worst = std::max(worst, std::abs(tree.evaluate(q) - direct));
    worst_guard = std::max(worst_guard, std::abs(tree.evaluate(q, 16.0) - direct));
  }
  // The winding fill re-evaluates every estimate within 0.1 of 1/2: beta 2 must stay inside it.
  EXPECT_LT(worst, 0.1);
  EXPECT_LT(worst_guard, 1e-4);
  EXPECT_LE(worst_guard, worst);
}

TEST(WindingNumberTree, DirectEvaluationEqualsTheMeshSum) {
  const IndexedMesh s = sphere(5.0, 2);
  const WindingNumberTree tree(corners_of(s));
  EXPECT_EQ(tree.facet_count(), s.triangles.size());
  for (const Vec3& q : random_points(20, 7.0, 3)) {
    EXPECT_NEAR(tree.evaluate_direct(q), winding_number(s, q), 1e-12);
  }
}

TEST(WindingNumberTree, EmptyTreeIsZero) {
  const WindingNumberTree tree({});
  EXPECT_TRUE(tree.empty());
  EXPECT_EQ(tree.evaluate({1, 2, 3}), 0.0);
}

}  // namespace
}  // namespace strata::winding
