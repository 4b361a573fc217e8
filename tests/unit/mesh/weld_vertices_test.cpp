#include "strata/mesh/weld_vertices.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace strata {
namespace {

using Triangle = std::array<Vec3, 3>;

TriangleSoup soup_of(std::vector<Triangle> triangles) {
  TriangleSoup soup;
  soup.triangles = std::move(triangles);
  return soup;
}

TEST(WeldVertices, SharedCornersBecomeOneVertex) {
  const auto mesh = weld_vertices(soup_of({
      {Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
      {Vec3{1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
  }));
  EXPECT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[0], (std::array<VertexIndex, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (std::array<VertexIndex, 3>{1, 3, 2}));
}

TEST(WeldVertices, VerticesAreNumberedInOrderOfFirstAppearance) {
  const auto mesh = weld_vertices(soup_of({{Vec3{5, 5, 5}, {3, 3, 3}, {1, 1, 1}}}));
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0], (Vec3{5, 5, 5}));
  EXPECT_EQ(mesh.vertices[2], (Vec3{1, 1, 1}));
}

TEST(WeldVertices, PositiveAndNegativeZeroWeld) {
  const auto mesh = weld_vertices(soup_of({
      {Vec3{0.0, 0.0, 0.0}, {1, 0, 0}, {0, 1, 0}},
      {Vec3{-0.0, 0.0, -0.0}, {0, 1, 0}, {0, 0, 1}},
  }));
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangles[1][0], mesh.triangles[0][0]);
}

TEST(WeldVertices, OnlyTheTwoZerosAreOnePoint) {
  // The smallest subnormals, either sign, differ from zero and from each other in one bit beside
  // the sign: they stay apart, where -0 and +0 weld.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const auto mesh = weld_vertices(soup_of({
      {Vec3{0.0, 0.0, 0.0}, {tiny, 0.0, 0.0}, {-tiny, 0.0, 0.0}},
      {Vec3{-0.0, 0.0, 0.0}, {0.0, -tiny, -0.0}, {0.0, tiny, 0.0}},
  }));
  EXPECT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.triangles[1][0], mesh.triangles[0][0]);
  EXPECT_NE(mesh.triangles[0][1], mesh.triangles[0][2]);
  EXPECT_NE(mesh.triangles[1][1], mesh.triangles[1][2]);
}

TEST(WeldVertices, NearButUnequalCornersStayDistinct) {
  const double next = std::nextafter(1.0, 2.0);
  const auto mesh = weld_vertices(soup_of({
      {Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
      {Vec3{next, 0, 0}, {1, 1, 0}, {0, 1, 0}},
  }));
  EXPECT_EQ(mesh.vertices.size(), 5u);
  EXPECT_NE(mesh.triangles[1][0], mesh.triangles[0][1]);
}

TEST(WeldVertices, KeepsEveryTriangleIncludingDegenerateAndDuplicate) {
  const Triangle t{Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Triangle point{Vec3{2, 2, 2}, {2, 2, 2}, {2, 2, 2}};
  const auto mesh = weld_vertices(soup_of({t, point, t}));
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[1], (std::array<VertexIndex, 3>{3, 3, 3}));
  EXPECT_EQ(mesh.triangles[2], mesh.triangles[0]);
}

TEST(WeldVertices, KeepsTheCornerOrderOfEachTriangle) {
  const auto mesh = weld_vertices(soup_of({
      {Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
      {Vec3{0, 1, 0}, {1, 0, 0}, {0, 0, 0}},  // the same triangle, flipped
  }));
  EXPECT_EQ(mesh.triangles[1], (std::array<VertexIndex, 3>{2, 1, 0}));
}

TEST(WeldVertices, EmptySoupGivesEmptyMesh) {
  const auto mesh = weld_vertices(TriangleSoup{});
  EXPECT_TRUE(mesh.vertices.empty());
  EXPECT_TRUE(mesh.triangles.empty());
}

TEST(WeldVertices, EveryCornerKeepsItsCoordinatesOnAGrid) {
  const unsigned seed = 7;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate(0, 9);  // a 10^3 grid: many shared corners
  TriangleSoup soup;
  for (int i = 0; i < 5000; ++i) {
    Triangle t;
    for (Vec3& p : t) {
      p = Vec3{coordinate(rng) * 0.1, coordinate(rng) * 0.1, coordinate(rng) * 0.1};
    }
    soup.triangles.push_back(t);
  }
  const auto mesh = weld_vertices(soup);
  ASSERT_EQ(mesh.triangles.size(), soup.triangles.size());
  EXPECT_LE(mesh.vertices.size(), 1000u);
  for (FacetIndex f = 0; f < mesh.triangles.size(); ++f) {
    for (int c = 0; c < 3; ++c) ASSERT_EQ(mesh.corner(f, c), soup.triangles[f][c]);
  }
  // No two vertices are equal: the weld is complete.
  std::vector<Vec3> sorted = mesh.vertices;
  std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  });
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
}

TEST(WeldVertices, ASoupOfLooseFacetsWeldsWhatRepeatsAfterEveryCornerWasNew) {
  // 20,000 loose facets have six times the vertices a closed mesh of as many facets has: the
  // table grows several times, and each facet repeated afterwards still finds its corners, with
  // the vertices numbered in order of first appearance.
  const int n = 20000;
  TriangleSoup soup;
  for (int i = 0; i < n; ++i) {
    const double x = i * 0.25;
    soup.triangles.push_back({Vec3{x, 0, 0}, {x, 1, 0}, {x, 0, -1.0 - i}});
  }
  for (int i = n - 1; i >= 0; i -= 7) soup.triangles.push_back(soup.triangles[i]);
  const auto mesh = weld_vertices(soup);
  ASSERT_EQ(mesh.vertices.size(), 3u * n);
  for (int i = 0; i < n; ++i) {
    const auto first = static_cast<VertexIndex>(3 * i);
    ASSERT_EQ(mesh.triangles[i], (std::array<VertexIndex, 3>{first, first + 1, first + 2}));
  }
  for (std::size_t f = n; f < mesh.triangles.size(); ++f) {
    const std::size_t original = n - 1 - 7 * (f - n);
    ASSERT_EQ(mesh.triangles[f], mesh.triangles[original]) << f;
  }
}

}  // namespace
}  // namespace strata
