#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
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

/// Two families of 150 large triangles, one in the planes x = i and one in the planes y = j: each
/// of one family crosses each of the other (22,500 pairs, more than a batch of tests), and no two
/// of a family meet. Among them, small triangles at the top whose boxes touch some of the large
/// ones', and which meet none: candidates that do not intersect, all along the sweep.
IndexedMesh crossing_families() {
  constexpr int kEach = 150;
  constexpr double kFar = 3.0 * kEach;
  IndexedMesh mesh;
  const auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    const auto v = static_cast<VertexIndex>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
    mesh.triangles.push_back({v, v + 1, v + 2});
  };
  for (int k = 0; k < kEach; ++k) {
    const double at = k;
    add({at, -1, -1}, {at, kFar, -1}, {at, -1, kFar});
    add({-1, at, -1}, {kFar, at, -1}, {-1, at, kFar});
    if (k % 3 == 0)
      add({at + 0.2, at + 0.2, kFar}, {at + 0.8, at + 0.2, kFar}, {at, at + 0.8, kFar});
  }
  return mesh;
}

/// The sweep's candidate pairs, in its order, each (lower facet, higher facet).
std::vector<FacetPair> candidates_in_sweep_order(const IndexedMesh& mesh) {
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, FacetIndex,
                                                        CGAL::Box_intersection_d::ID_EXPLICIT>;
  std::vector<Box> boxes;
  for (FacetIndex f = 0; f < mesh.triangles.size(); ++f) {
    CGAL::Bbox_3 box;
    for (const VertexIndex v : mesh.triangles[f]) {
      const Vec3& p = mesh.vertices[v];
      box += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
    }
    boxes.emplace_back(box, f);
  }
  std::vector<FacetPair> candidates;
  CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
      boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
        candidates.push_back({std::min(a.info(), b.info()), std::max(a.info(), b.info())});
      });
  return candidates;
}

bool lower_pair(const FacetPair& x, const FacetPair& y) {
  return std::pair{x.first, x.second} < std::pair{y.first, y.second};
}

/// The search by its definition: the candidates taken one by one, in the sweep's order, each
/// intersecting when it is among `intersecting` (sorted), until a limit is reached.
SelfIntersections one_by_one(const std::vector<FacetPair>& candidates,
                             const std::vector<FacetPair>& intersecting, std::size_t max_pairs,
                             std::size_t max_candidates) {
  SelfIntersections out;
  for (std::size_t k = 0; k < candidates.size() && !out.truncated; ++k) {
    if (k == max_candidates) {
      out.truncated = true;
    } else if (std::binary_search(intersecting.begin(), intersecting.end(), candidates[k],
                                  lower_pair)) {
      if (out.pairs.size() == max_pairs) {
        out.truncated = true;
      } else {
        out.pairs.push_back(candidates[k]);
      }
    }
  }
  std::sort(out.pairs.begin(), out.pairs.end(), lower_pair);
  return out;
}

TEST(FindSelfIntersections, LimitsStopAtThePairWhereTestingOneByOneWould) {
  const IndexedMesh mesh = crossing_families();
  const std::vector<bool> none(mesh.triangles.size(), false);
  constexpr std::size_t kAll = std::numeric_limits<std::size_t>::max();
  const SelfIntersections every = find_self_intersections(mesh, none, kAll, kAll);
  ASSERT_FALSE(every.truncated);
  ASSERT_EQ(every.pairs.size(), 150U * 150U);
  for (const FacetPair& pair : every.pairs) {
    // One of each family: the small triangles meet nothing, and a family's planes are apart.
    ASSERT_EQ(mesh.vertices[mesh.triangles[pair.first][0]].z, -1.0);
    ASSERT_EQ(mesh.vertices[mesh.triangles[pair.second][0]].z, -1.0);
    ASSERT_NE(mesh.vertices[mesh.triangles[pair.first][0]].x,
              mesh.vertices[mesh.triangles[pair.second][0]].x);
  }
  const std::vector<FacetPair> candidates = candidates_in_sweep_order(mesh);
  ASSERT_GT(candidates.size(), every.pairs.size());  // the small triangles' candidates among them
  for (const auto& [max_pairs, max_candidates] :
       std::vector<std::pair<std::size_t, std::size_t>>{{1, kAll},
                                                        {16'384, kAll},
                                                        {20'000, kAll},
                                                        {kAll, 16'383},
                                                        {kAll, 20'001},
                                                        {18'000, 20'001}}) {
    SCOPED_TRACE(testing::Message() << max_pairs << " pairs, " << max_candidates << " candidates");
    const SelfIntersections expected =
        one_by_one(candidates, every.pairs, max_pairs, max_candidates);
    EXPECT_TRUE(expected.truncated);
    for (const int threads : {1, 2}) {
      SCOPED_TRACE(threads);
      const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      const SelfIntersections found =
          find_self_intersections(mesh, none, max_pairs, max_candidates);
      EXPECT_EQ(found.truncated, expected.truncated);
      ASSERT_EQ(found.pairs.size(), expected.pairs.size());
      for (std::size_t k = 0; k < found.pairs.size(); ++k) {
        ASSERT_EQ(found.pairs[k].first, expected.pairs[k].first) << k;
        ASSERT_EQ(found.pairs[k].second, expected.pairs[k].second) << k;
      }
    }
  }
}

}  // namespace
}  // namespace strata::diagnose::detail
