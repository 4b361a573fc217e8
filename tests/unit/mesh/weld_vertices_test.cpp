#include "strata/mesh/weld_vertices.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "mesh/weld_vertices_internal.hpp"

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

/// n loose facets (every corner new), then every `step`-th of them again from the last back.
TriangleSoup loose_facets_then_repeats(int n, int step) {
  TriangleSoup soup;
  for (int i = 0; i < n; ++i) {
    const double x = i * 0.25;
    soup.triangles.push_back({Vec3{x, 0, 0}, {x, 1, 0}, {x, 0, -1.0 - i}});
  }
  for (int i = n - 1; i >= 0; i -= step) soup.triangles.push_back(soup.triangles[i]);
  return soup;
}

TEST(WeldVertices, ASoupOfLooseFacetsWeldsWhatRepeatsAfterEveryCornerWasNew) {
  // 20,000 loose facets have six times the vertices a closed mesh of as many facets has: the
  // table grows several times, and each facet repeated afterwards still finds its corners, with
  // the vertices numbered in order of first appearance.
  const int n = 20000;
  const TriangleSoup soup = loose_facets_then_repeats(n, 7);
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

/// The weld as the definition says it, by a sorted map of the coordinates' bits (-0 as +0): the
/// vertices in order of first appearance, each corner the vertex of its coordinates.
IndexedMesh reference_weld(const TriangleSoup& soup) {
  const auto bits = [](double v) {
    return v == 0.0 ? std::uint64_t{0} : std::bit_cast<std::uint64_t>(v);
  };
  std::map<std::tuple<std::uint64_t, std::uint64_t, std::uint64_t>, VertexIndex> number;
  IndexedMesh mesh;
  for (const auto& t : soup.triangles) {
    std::array<VertexIndex, 3> facet{};
    for (int c = 0; c < 3; ++c) {
      const auto [at, inserted] =
          number.try_emplace({bits(t[c].x), bits(t[c].y), bits(t[c].z)},
                             static_cast<VertexIndex>(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back(t[c]);
      facet[c] = at->second;
    }
    mesh.triangles.push_back(facet);
  }
  return mesh;
}

/// A soup whose corners repeat across the whole of it (a small grid of points, either zero's
/// sign), with runs of facets whose corners are all new between them: a block's vertices are
/// partly its own, partly first seen in the block before, partly in blocks further back.
TriangleSoup soup_repeating_across_blocks(std::size_t facets, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate(-3, 3);
  std::uniform_int_distribution<int> kind(0, 9);
  const auto grid = [&] {
    const int k = coordinate(rng);
    // Zero of either sign: the two weld.
    return k == 0 ? (kind(rng) < 5 ? 0.0 : -0.0) : k * 0.5;
  };
  TriangleSoup soup;
  for (std::size_t f = 0; f < facets; ++f) {
    Triangle t;
    if (kind(rng) < 3) {
      for (int c = 0; c < 3; ++c) t[c] = Vec3{static_cast<double>(f), static_cast<double>(c), 7.0};
    } else {
      for (Vec3& p : t) p = Vec3{grid(), grid(), grid()};
    }
    soup.triangles.push_back(t);
  }
  return soup;
}

/// The same vertices, coordinate bit for coordinate bit (a vertex keeps the coordinates of its
/// first appearance, the zero's sign too), and the same facets. One check an array, which names
/// the first difference: a check an element would cost more than the weld under the sanitizers.
void expect_same_mesh(const IndexedMesh& got, const IndexedMesh& want) {
  ASSERT_EQ(got.vertices.size(), want.vertices.size());
  ASSERT_EQ(got.triangles.size(), want.triangles.size());
  const auto same_bits = [](const Vec3& a, const Vec3& b) {
    return std::bit_cast<std::array<std::uint64_t, 3>>(a) ==
           std::bit_cast<std::array<std::uint64_t, 3>>(b);
  };
  const auto vertex =
      std::mismatch(got.vertices.begin(), got.vertices.end(), want.vertices.begin(), same_bits);
  EXPECT_TRUE(vertex.first == got.vertices.end())
      << "vertex " << (vertex.first - got.vertices.begin()) << " differs";
  const auto facet =
      std::mismatch(got.triangles.begin(), got.triangles.end(), want.triangles.begin());
  EXPECT_TRUE(facet.first == got.triangles.end())
      << "facet " << (facet.first - got.triangles.begin()) << " differs";
}

TEST(WeldVertices, WeldedInBlocksTheMeshIsTheOneTheDefinitionGivesWhateverTheirNumber) {
  for (const unsigned seed : {1U, 2U, 3U}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const TriangleSoup soup = soup_repeating_across_blocks(3000, seed);
    const IndexedMesh want = reference_weld(soup);
    // One block a facet and more blocks than facets too (taken as one a facet).
    for (const std::size_t blocks : {1U, 2U, 3U, 7U, 64U, 2999U, 3000U, 5000U}) {
      SCOPED_TRACE("blocks " + std::to_string(blocks));
      expect_same_mesh(detail::weld_vertices_in_blocks(soup, blocks), want);
    }
  }
}

TEST(WeldVertices, LooseFacetsInBlocksGrowTheTablesAndKeepTheirNumbers) {
  // Every corner new: each block's table and the mesh's grow past what a closed mesh needs.
  const TriangleSoup soup = loose_facets_then_repeats(4000, 5);
  const IndexedMesh want = reference_weld(soup);
  ASSERT_EQ(want.vertices.size(), 12000U);
  for (const std::size_t blocks : {1U, 2U, 4U}) {
    SCOPED_TRACE("blocks " + std::to_string(blocks));
    expect_same_mesh(detail::weld_vertices_in_blocks(soup, blocks), want);
  }
}

TEST(WeldVertices, AModelLargeEnoughToWeldInBlocksGivesTheSameMeshOnOneThreadOrMore) {
  // Above two blocks' worth of facets, weld_vertices welds a block a thread; on one thread it is
  // one block, the weld the tests above hold to the definition.
  const TriangleSoup soup = soup_repeating_across_blocks(140'000, 11);
  IndexedMesh one_thread;
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one_thread = weld_vertices(soup);
  }
  for (const std::size_t threads : {2U, 4U}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    expect_same_mesh(weld_vertices(soup), one_thread);
  }
}

TEST(WeldVertices, NoFacetsInBlocksGiveEmptyMesh) {
  const IndexedMesh mesh = detail::weld_vertices_in_blocks(TriangleSoup{}, 4);
  EXPECT_TRUE(mesh.vertices.empty());
  EXPECT_TRUE(mesh.triangles.empty());
}

}  // namespace
}  // namespace strata
