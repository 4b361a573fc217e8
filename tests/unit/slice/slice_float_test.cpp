// The layers a facet crosses (SPEC §2: zmin < zk <= zmax), the facets grouped by first layer, and
// the segment a plane cuts from a facet, with the vertex-on-plane rule's ties.
#include "strata/slice/slice_float.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "predicates/grid_search.hpp"

namespace strata {
namespace {

/// Planes at z = 0.5, 1.5, 2.5, 3.5.
GridSpec four_layers() {
  GridSpec g;
  g.x0 = g.y0 = g.z0 = 0.0;
  g.dx = g.dy = g.dz = 1.0;
  g.nx = g.ny = 4;
  g.nz = 4;
  return g;
}

/// One facet per (z_a, z_b, z_c), over the unit right triangle in x and y.
IndexedMesh facets_at_heights(const std::vector<std::array<double, 3>>& heights) {
  IndexedMesh m;
  for (const auto& z : heights) {
    const auto base = static_cast<VertexIndex>(m.vertices.size());
    m.vertices.push_back({0, 0, z[0]});
    m.vertices.push_back({1, 0, z[1]});
    m.vertices.push_back({0, 1, z[2]});
    m.triangles.push_back({base, base + 1, base + 2});
  }
  return m;
}

bool crosses_none(const FacetLayerRanges& r, std::size_t f) { return r.first[f] > r.last[f]; }

TEST(FacetLayerRanges, CrossesThePlanesStrictlyAboveItsLowestCornerUpToItsHighest) {
  const IndexedMesh m = facets_at_heights({
      {0.0, 1.0, 0.2},   // 0: plane 0.5 only
      {0.2, 1.5, 1.0},   // 1: top corner on plane 1.5 counts: planes 0.5 and 1.5
      {1.5, 3.0, 2.0},   // 2: bottom corner on plane 1.5 does not: plane 2.5 only
      {-10, 10.0, 0.0},  // 3: every plane
      {0.5, 0.5, 3.49},  // 4: planes 1.5 and 2.5 (0.5 is its lowest corner)
  });
  const FacetLayerRanges r = facet_layer_ranges(m, four_layers());
  ASSERT_EQ(r.first.size(), 5u);
  EXPECT_EQ(r.first[0], 0u);
  EXPECT_EQ(r.last[0], 0u);
  EXPECT_EQ(r.first[1], 0u);
  EXPECT_EQ(r.last[1], 1u);
  EXPECT_EQ(r.first[2], 2u);
  EXPECT_EQ(r.last[2], 2u);
  EXPECT_EQ(r.first[3], 0u);
  EXPECT_EQ(r.last[3], 3u);
  EXPECT_EQ(r.first[4], 1u);
  EXPECT_EQ(r.last[4], 2u);
}

TEST(FacetLayerRanges, HorizontalBetweenPlanesAndOutsideTheGridCrossNone) {
  const IndexedMesh m = facets_at_heights({
      {1.5, 1.5, 1.5},     // horizontal, on a plane
      {0.6, 1.4, 1.0},     // between two planes
      {-5.0, -4.0, -4.5},  // below the grid
      {3.5, 9.0, 4.0},     // from the top plane upwards (3.5 is its lowest corner)
  });
  const FacetLayerRanges r = facet_layer_ranges(m, four_layers());
  for (std::size_t f = 0; f < 4; ++f) {
    EXPECT_TRUE(crosses_none(r, f)) << f << ": " << r.first[f] << ".." << r.last[f];
    EXPECT_EQ(r.first[f], std::numeric_limits<std::uint32_t>::max());
  }
}

TEST(FacetLayerRanges, TiesAreDecidedOnTheDoublePlaneNotOnAnEstimate) {
  // dz = 0.1: plane 2 is 0.1 * 2.5 = 0.25 exactly, plane 3 is 0.35000000000000003; a corner at
  // 0.35 is below plane 3, one at 0.35000000000000003 is on it (and counts as above).
  GridSpec g = four_layers();
  g.dz = 0.1;
  ASSERT_EQ(g.zk(3), 0.35000000000000003);
  const IndexedMesh m = facets_at_heights({{0.0, 0.35, 0.1}, {0.0, 0.35000000000000003, 0.1}});
  const FacetLayerRanges r = facet_layer_ranges(m, g);
  EXPECT_EQ(r.last[0], 2u);
  EXPECT_EQ(r.last[1], 3u);
}

TEST(FacetLayerRanges, CornersOnAndBesideEveryPlaneCountExactlyWhicheverWayTheGuessRounds) {
  // dz = 0.1 and z0 = 0.3 are not binary fractions: the first guess (z - z0) / dz + 0.5 rounds to
  // the wrong layer for some corners on a plane or one ulp beside it, too high for some and too
  // low for others. The count is the exact one whatever the guess.
  GridSpec g = four_layers();
  g.z0 = 0.3;
  g.dz = 0.1;
  g.nz = 2000;
  const double top = g.zk(g.nz - 1) + 1.0;
  const double bottom = g.z0 - 1.0;
  std::vector<double> corners;
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    for (const double toward : {-1e9, 0.0, 1e9}) {
      corners.push_back(toward == 0.0 ? g.zk(k) : std::nextafter(g.zk(k), toward));
    }
  }
  std::vector<std::array<double, 3>> heights;
  for (const double z : corners) {
    heights.push_back({z, z, top});     // lowest corner z: crosses the planes above z
    heights.push_back({bottom, z, z});  // highest corner z: crosses the planes up to z
  }
  const FacetLayerRanges r = facet_layer_ranges(facets_at_heights(heights), g);
  int guesses_low = 0;
  int guesses_high = 0;
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const double z = corners[c];
    std::uint32_t at_or_below = 0;  // planes zk <= z, counted one by one
    while (at_or_below < g.nz && g.zk(at_or_below) <= z) ++at_or_below;
    const std::uint32_t guess = detail::clamp_guess((z - g.z0) / g.dz + 0.5, g.nz);
    guesses_low += guess < at_or_below ? 1 : 0;
    guesses_high += guess > at_or_below ? 1 : 0;
    if (at_or_below == g.nz) {  // on or above the top plane: no plane above the lowest corner
      EXPECT_TRUE(crosses_none(r, 2 * c)) << "corner " << z;
    } else {
      EXPECT_EQ(r.first[2 * c], at_or_below) << "corner " << z;
      EXPECT_EQ(r.last[2 * c], g.nz - 1) << "corner " << z;
    }
    if (at_or_below == 0) {
      EXPECT_TRUE(crosses_none(r, 2 * c + 1)) << "corner " << z;
    } else {
      EXPECT_EQ(r.first[2 * c + 1], 0u) << "corner " << z;
      EXPECT_EQ(r.last[2 * c + 1], at_or_below - 1) << "corner " << z;
    }
  }
  EXPECT_GT(guesses_low, 0) << "no corner whose first guess is too low: the test lost its point";
  EXPECT_GT(guesses_high, 0) << "no corner whose first guess is too high: the test lost its point";
}

TEST(FacetLayerRanges, SharedVerticesGiveEachFacetTheRangeOfItsOwnCorners) {
  // Vertices shared by many facets, on planes, one ulp beside them and between them, with every
  // corner order: each facet's range is that of its own lowest and highest corner, counted plane
  // by plane here.
  GridSpec g = four_layers();
  g.z0 = 0.3;
  g.dz = 0.1;
  g.nz = 6;
  IndexedMesh m;
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    for (const double z :
         {std::nextafter(g.zk(k), -1.0), g.zk(k), std::nextafter(g.zk(k), 2.0), g.zk(k) + 0.05}) {
      m.vertices.push_back({static_cast<double>(m.vertices.size()), z * z, z});
    }
    // On the plane, just above it and between it and the next: above the plane, below the next.
    const VertexIndex on = 4 * k + 1;
    m.triangles.push_back({on, on + 1, on + 2});
    m.triangles.push_back({on + 2, on, on + 1});
  }
  m.vertices.push_back({-1.0, 0.0, -5.0});  // below every plane
  m.vertices.push_back({-2.0, 0.0, 5.0});   // above every plane
  const auto nv = static_cast<VertexIndex>(m.vertices.size());
  for (VertexIndex a = 0; a < nv; ++a) {
    for (VertexIndex b = 0; b < nv; b += 3) {
      m.triangles.push_back({a, b, (a + b + 1) % nv});
      m.triangles.push_back({(a + 2 * b + 5) % nv, a, b});
    }
  }
  const auto at_or_below = [&](double z) {
    std::uint32_t count = 0;
    while (count < g.nz && g.zk(count) <= z) ++count;
    return count;
  };
  const FacetLayerRanges r = facet_layer_ranges(m, g);
  ASSERT_EQ(r.first.size(), m.triangles.size());
  int crossing = 0;
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    const auto& t = m.triangles[f];
    const double z0 = m.vertices[t[0]].z, z1 = m.vertices[t[1]].z, z2 = m.vertices[t[2]].z;
    const std::uint32_t first = at_or_below(std::min({z0, z1, z2}));
    const std::uint32_t end = at_or_below(std::max({z0, z1, z2}));
    if (first < end) {
      ++crossing;
      EXPECT_EQ(r.first[f], first) << "facet " << f;
      EXPECT_EQ(r.last[f], end - 1) << "facet " << f;
    } else {
      EXPECT_TRUE(crosses_none(r, f)) << "facet " << f;
    }
  }
  EXPECT_GT(crossing, 0);
  EXPECT_LT(crossing, static_cast<int>(m.triangles.size())) << "no facet between two planes";
}

TEST(BucketFacetsByFirstLayer, GroupsFacetsByTheirFirstLayerInFacetOrder) {
  FacetLayerRanges r;
  // Facets 0..4: first layers 2, none, 0, 2, 3.
  r.first = {2, std::numeric_limits<std::uint32_t>::max(), 0, 2, 3};
  r.last = {3, 0, 1, 2, 3};
  const FacetBuckets b = bucket_facets_by_first_layer(r, 4);
  EXPECT_EQ(b.offsets, (std::vector<std::uint32_t>{0, 1, 1, 3, 4}));
  EXPECT_EQ(b.facets, (std::vector<FacetIndex>{2, 0, 3, 4}));
}

TEST(BucketFacetsByFirstLayer, NoCrossingFacetGivesEmptyBuckets) {
  FacetLayerRanges r;
  r.first = {std::numeric_limits<std::uint32_t>::max()};
  r.last = {0};
  const FacetBuckets b = bucket_facets_by_first_layer(r, 3);
  EXPECT_EQ(b.offsets, (std::vector<std::uint32_t>{0, 0, 0, 0}));
  EXPECT_TRUE(b.facets.empty());
}

TEST(BucketFacetsByFirstLayer, ManyFacetsAreBucketedInFacetOrderWhateverTheNumberOfThreads) {
  // 200,000 facets of random ranges over 500 layers, a tenth crossing none: several ranges of
  // facets for the threads to count and place.
  constexpr std::uint32_t kLayers = 500;
  std::mt19937 random(3);
  FacetLayerRanges r;
  for (int f = 0; f < 200'000; ++f) {
    const auto first = static_cast<std::uint32_t>(random() % kLayers);
    const bool none = random() % 10 == 0;
    r.first.push_back(none ? std::numeric_limits<std::uint32_t>::max() : first);
    r.last.push_back(
        none ? 0 : std::min(kLayers - 1, first + static_cast<std::uint32_t>(random() % 3)));
  }
  std::vector<std::vector<FacetIndex>> expected(kLayers);
  for (FacetIndex f = 0; f < r.first.size(); ++f) {
    if (r.first[f] <= r.last[f]) expected[r.first[f]].push_back(f);
  }
  for (const int threads : {1, 2, 4}) {
    SCOPED_TRACE(threads);
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const FacetBuckets b = bucket_facets_by_first_layer(r, kLayers);
    ASSERT_EQ(b.offsets.size(), kLayers + 1U);
    for (std::uint32_t k = 0; k < kLayers; ++k) {
      const std::vector<FacetIndex> bucket(b.facets.begin() + b.offsets[k],
                                           b.facets.begin() + b.offsets[k + 1]);
      ASSERT_EQ(bucket, expected[k]) << "layer " << k;
    }
    EXPECT_EQ(b.offsets[kLayers], b.facets.size());
  }
}

/// The facets of `m` whose range holds layer k, in facet order, found one by one.
std::vector<FacetIndex> crossing_layer(const FacetLayerRanges& r, std::uint32_t k) {
  std::vector<FacetIndex> out;
  for (std::size_t f = 0; f < r.first.size(); ++f) {
    if (r.first[f] <= k && k <= r.last[f]) out.push_back(static_cast<FacetIndex>(f));
  }
  return out;
}

TEST(FacetSweep, EachLayerOfEachBatchGetsTheFacetsThatCrossItInFacetOrder) {
  // Facets of random heights over 40 layers (so their indices are in no order of height): many
  // cross one or two planes, some none, some many; swept from several first layers (a layer range)
  // in batches of several sizes, so that facets start before a batch, end after it and span whole
  // batches.
  GridSpec g = four_layers();
  g.nz = 40;
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / static_cast<double>(1ULL << 53);
  };
  std::vector<std::array<double, 3>> heights;
  for (int f = 0; f < 2000; ++f) {
    const double base = -2.0 + 44.0 * next();
    const double spread = f % 10 == 0 ? 30.0 * next() : 2.5 * next();
    heights.push_back({base, base + spread * next(), base + spread});
  }
  const IndexedMesh m = facets_at_heights(heights);
  const FacetLayerRanges r = facet_layer_ranges(m, g);
  std::size_t checked = 0;
  for (const std::uint32_t first : {0u, 7u}) {
    for (const std::uint32_t batch : {1u, 3u, 16u, 64u}) {
      FacetSweep sweep;
      sweep.group(m, g);
      ASSERT_TRUE(sweep.grouped());
      for (std::uint32_t k0 = first; k0 < g.nz; k0 += batch) {
        const std::uint32_t k1 = std::min(g.nz, k0 + batch);
        sweep.advance(k0, k1);
        for (std::uint32_t k = k0; k < k1; ++k) {
          const std::vector<FacetIndex> crossing = crossing_layer(r, k);
          EXPECT_EQ(sweep.candidates(k), crossing)
              << "layer " << k << ", batches of " << batch << " from " << first;
          checked += crossing.size();
        }
      }
    }
  }
  EXPECT_GT(checked, 8u * 2000u) << "most facets cross a layer or more";
}

/// Mesh `m` cut by plane 0 of four_layers() moved up by half a layer: the plane z = 1.
LayerSegments slice_at_z1(const IndexedMesh& m, std::span<const FacetIndex> candidates) {
  GridSpec g = four_layers();
  g.z0 = 0.5;
  return slice_layer(m, candidates, g, 0);
}

/// A mesh of one facet, its corners in the order given.
IndexedMesh one_facet(const std::array<Vec3, 3>& corners) {
  IndexedMesh m;
  m.vertices = {corners[0], corners[1], corners[2]};
  m.triangles = {{0, 1, 2}};
  return m;
}

/// The only segment of `s`, with its crossed edges and end points; fails the test otherwise.
void expect_one_segment(const LayerSegments& s, CrossedEdge start_edge, CrossedEdge end_edge,
                        Point2 start, Point2 end) {
  ASSERT_EQ(s.segments.size(), 1u);
  EXPECT_EQ(s.segments[0].start_edge, start_edge);
  EXPECT_EQ(s.segments[0].end_edge, end_edge);
  EXPECT_EQ(s.segments[0].start, start);
  EXPECT_EQ(s.segments[0].end, end);
}

constexpr FacetIndex kFacet0[] = {0};

TEST(SliceLayer, SegmentRunsWithTheMaterialOnItsLeft) {
  // Corner a below the plane, b and c above; the facet's normal points to -x -y, so the material
  // lies towards +x +y: the segment runs from edge c-a to edge a-b.
  const LayerSegments s = slice_at_z1(one_facet({{{0, 0, 0}, {2, 0, 2}, {0, 2, 2}}}), kFacet0);
  EXPECT_EQ(s.layer, 0u);
  EXPECT_EQ(s.z_mm, 1.0);
  expect_one_segment(s, CrossedEdge{0, 2}, CrossedEdge{0, 1}, Point2{0, 1}, Point2{1, 0});
  EXPECT_EQ(s.segments.at(0).facet, 0u);
}

TEST(SliceLayer, ReversedFacetGivesTheReversedSegment) {
  IndexedMesh m = one_facet({{{0, 0, 0}, {2, 0, 2}, {0, 2, 2}}});
  m.triangles = {{0, 2, 1}};
  expect_one_segment(slice_at_z1(m, kFacet0), CrossedEdge{0, 1}, CrossedEdge{0, 2}, Point2{1, 0},
                     Point2{0, 1});
}

TEST(SliceLayer, CornerOnThePlaneCountsAsAbove) {
  // b lies on the plane z = 1: edge a-b ends the segment at b itself.
  expect_one_segment(slice_at_z1(one_facet({{{0, 0, 0}, {2, 0, 1}, {0, 2, 2}}}), kFacet0),
                     CrossedEdge{0, 2}, CrossedEdge{0, 1}, Point2{0, 1}, Point2{2, 0});
}

TEST(SliceLayer, FacetTouchingThePlaneFromAboveOrLyingInItGivesNoSegment) {
  IndexedMesh m;
  m.vertices = {{0, 0, 1}, {1, 0, 2}, {0, 1, 2}, {1, 1, 1}, {2, 1, 1}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};  // touching from above; lying in the plane
  const FacetIndex candidates[] = {0, 1};
  EXPECT_TRUE(slice_at_z1(m, candidates).segments.empty());
}

TEST(SliceLayer, FacetTouchingThePlaneFromBelowGivesAPointSegmentAtTheCorner) {
  // Only b reaches the plane; as it counts as above, both crossed edges end at b.
  expect_one_segment(slice_at_z1(one_facet({{{0, 0, 0}, {1, 0, 1}, {0, 1, 0}}}), kFacet0),
                     CrossedEdge{2, 1}, CrossedEdge{0, 1}, Point2{1, 0}, Point2{1, 0});
}

TEST(SliceLayer, OnlyTheCandidatesAreCutInTheirOrder) {
  IndexedMesh m = one_facet({{{0, 0, 0}, {2, 0, 2}, {0, 2, 2}}});
  m.triangles = {{0, 1, 2}, {0, 2, 1}, {0, 1, 2}};
  const FacetIndex candidates[] = {2, 1};
  const LayerSegments s = slice_at_z1(m, candidates);
  ASSERT_EQ(s.segments.size(), 2u);
  EXPECT_EQ(s.segments[0].facet, 2u);
  EXPECT_EQ(s.segments[1].facet, 1u);
  EXPECT_TRUE(slice_at_z1(m, {}).segments.empty());
}

}  // namespace
}  // namespace strata
