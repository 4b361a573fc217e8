#include <gtest/gtest.h>

#include <vector>

#include "diagnose/find_self_intersections_internal.hpp"

namespace strata::diagnose::detail {
namespace {

/// Facet 0 in the plane z = 0, facet 1 piercing it, facet 2 far away.
IndexedMesh piercing_pair() {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {4, 0, 0},    {0, 4, 0},    {1, 1, -1},  {1, 1, 1},
                   {2, 1, 1}, {10, 10, 10}, {11, 10, 10}, {10, 11, 10}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  return mesh;
}

TEST(FindSelfIntersections, FindsPiercingPair) {
  const SelfIntersections found =
      find_self_intersections(piercing_pair(), std::vector<bool>(3, false), 100, 1000);
  ASSERT_EQ(found.pairs.size(), 1U);
  EXPECT_EQ(found.pairs[0].first, 0U);
  EXPECT_EQ(found.pairs[0].second, 1U);
  EXPECT_FALSE(found.truncated);
}

TEST(FindSelfIntersections, LeavesSkippedFacetsOut) {
  const SelfIntersections found =
      find_self_intersections(piercing_pair(), {false, true, false}, 100, 1000);
  EXPECT_TRUE(found.pairs.empty());
}

TEST(FindSelfIntersections, IgnoresSameFacetRepeated) {
  IndexedMesh mesh = piercing_pair();
  mesh.triangles = {{0, 1, 2}, {2, 1, 0}};
  const SelfIntersections found =
      find_self_intersections(mesh, std::vector<bool>(2, false), 100, 1000);
  EXPECT_TRUE(found.pairs.empty());
}

TEST(FindSelfIntersections, TouchingAtAVertexWithoutSharingItIntersects) {
  // The same point under two vertex indices (not welded) is a contact, not a shared vertex.
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {-1, 0, 1}, {0, -1, 1}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  const SelfIntersections found =
      find_self_intersections(mesh, std::vector<bool>(2, false), 100, 1000);
  EXPECT_EQ(found.pairs.size(), 1U);
}

TEST(FindSelfIntersections, StopsAtCandidateLimit) {
  const SelfIntersections found =
      find_self_intersections(piercing_pair(), std::vector<bool>(3, false), 100, 0);
  EXPECT_TRUE(found.pairs.empty());
  EXPECT_TRUE(found.truncated);
}

}  // namespace
}  // namespace strata::diagnose::detail
