// The triangles the view page draws: every facet within the budget, a simplification beyond it.
#include "strata/view/display_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "strata/core/thousands.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::view {
namespace {

/// Two triangles of the unit square in z = 0, the first of them once more.
IndexedMesh square_with_repeated_facet() {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}, {0, 1, 2}};
  return mesh;
}

TEST(MakeDisplayMesh, KeepsEveryFacetWithinTheBudget) {
  const DisplayMesh d = make_display_mesh(square_with_repeated_facet(), 3);
  EXPECT_FALSE(d.simplified);
  EXPECT_EQ(d.facets_in_model, 3u);
  EXPECT_EQ(d.facets(), 3u);
  EXPECT_EQ(d.positions, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}));
  EXPECT_EQ(d.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2, 0, 1, 2}));
}

TEST(MakeDisplayMesh, DropsARepeatedFacetWithoutCollapsingWhenThatMeetsTheBudget) {
  const DisplayMesh d = make_display_mesh(square_with_repeated_facet(), 2);
  EXPECT_TRUE(d.simplified);
  EXPECT_EQ(d.facets_in_model, 3u);
  ASSERT_EQ(d.facets(), 2u) << "the two triangles, not collapsed";
  EXPECT_EQ(d.positions.size(), 12u);
  float area = 0;
  for (std::size_t t = 0; t < 2; ++t) {
    const float* a = &d.positions[3 * d.indices[3 * t]];
    const float* b = &d.positions[3 * d.indices[3 * t + 1]];
    const float* c = &d.positions[3 * d.indices[3 * t + 2]];
    area += 0.5f * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
  }
  EXPECT_FLOAT_EQ(area, 1.0f) << "the unit square, counter-clockwise";
}

TEST(MakeDisplayMesh, CollapsesEdgesToAboutTheBudget) {
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(10.0, 3));
  ASSERT_GT(sphere.triangles.size(), 1000u);
  const DisplayMesh d = make_display_mesh(sphere, 200);
  EXPECT_TRUE(d.simplified);
  EXPECT_EQ(d.facets_in_model, sphere.triangles.size());
  EXPECT_LE(d.facets(), 200u);
  EXPECT_GE(d.facets(), 150u);
  for (const std::uint32_t index : d.indices) EXPECT_LT(3 * index, d.positions.size());
}

TEST(MakeDisplayMesh, ClustersALargeMeshToTheBudgetWithoutFoldsOrRepeats) {
  // An icosphere of 81,920 facets, over what edge collapse is given here: it is clustered, and a
  // clustering that meets the budget is the display mesh.
  constexpr double kRadius = 10.0;
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(kRadius, 6));
  ASSERT_EQ(sphere.triangles.size(), 81'920u);
  const DisplayMesh d = make_display_mesh(sphere, 60'000, 60'000);
  EXPECT_TRUE(d.simplified);
  EXPECT_EQ(d.facets_in_model, sphere.triangles.size());
  EXPECT_LE(d.facets(), 60'000u);
  EXPECT_GE(d.facets(), 50'000u) << "the smallest cube that keeps few enough";

  const auto vertex = [&](std::uint32_t i) {
    return std::array<double, 3>{d.positions[3 * i], d.positions[3 * i + 1],
                                 d.positions[3 * i + 2]};
  };
  std::vector<bool> used(d.positions.size() / 3, false);
  std::set<std::array<std::uint32_t, 3>> corner_sets;
  double volume = 0.0;
  std::size_t inward = 0;
  for (std::size_t t = 0; t < d.facets(); ++t) {
    std::array<std::uint32_t, 3> corners = {d.indices[3 * t], d.indices[3 * t + 1],
                                            d.indices[3 * t + 2]};
    for (const std::uint32_t c : corners) {
      ASSERT_LT(3 * c, d.positions.size());
      used[c] = true;
    }
    const auto a = vertex(corners[0]), b = vertex(corners[1]), c = vertex(corners[2]);
    const std::array<double, 3> u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const std::array<double, 3> v = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const std::array<double, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                     u[0] * v[1] - u[1] * v[0]};
    // Outward on a sphere about the origin: no facet folded over.
    if (n[0] * (a[0] + b[0] + c[0]) + n[1] * (a[1] + b[1] + c[1]) + n[2] * (a[2] + b[2] + c[2]) <=
        0.0) {
      ++inward;
    }
    volume += (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6.0;
    std::sort(corners.begin(), corners.end());
    EXPECT_TRUE(corner_sets.insert(corners).second) << "facet " << t << " repeats another";
  }
  EXPECT_EQ(inward, 0u);
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << "every vertex is a corner";
  for (std::size_t i = 0; i < used.size(); ++i) {
    const auto p = vertex(static_cast<std::uint32_t>(i));
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    ASSERT_NEAR(r, kRadius, 0.1) << "vertex " << i << " off the sphere";
  }
  const double ball = 4.0 / 3.0 * M_PI * kRadius * kRadius * kRadius;
  EXPECT_NEAR(volume, ball, 0.005 * ball);
}

TEST(MakeDisplayMesh, DropsRepeatsBeforeClustering) {
  // Every facet twice: leaving out the copies meets the budget, and nothing moves.
  const IndexedMesh once = weld_vertices(mesh::make_sphere(10.0, 5));
  IndexedMesh twice = once;
  twice.triangles.insert(twice.triangles.end(), once.triangles.begin(), once.triangles.end());
  const DisplayMesh d = make_display_mesh(twice, 30'000, 30'000);
  EXPECT_TRUE(d.simplified);
  EXPECT_EQ(d.facets_in_model, 2 * once.triangles.size());
  ASSERT_EQ(d.facets(), once.triangles.size());
  ASSERT_EQ(d.positions.size(), 3 * once.vertices.size());
  for (std::size_t t = 0; t < d.facets(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const Vec3& v = once.vertices[once.triangles[t][c]];
      const float* p = &d.positions[3 * d.indices[3 * t + c]];
      EXPECT_EQ(p[0], static_cast<float>(v.x));
      EXPECT_EQ(p[1], static_cast<float>(v.y));
      EXPECT_EQ(p[2], static_cast<float>(v.z));
    }
  }
}

TEST(MakeDisplayMesh, LeavesOutTheFacetsClusteringFoldsOver) {
  // A flat sheet in z = 0 facing +z, of jittered squares: moving its vertices to their cubes'
  // means turns some small triangles over, and those are left out.
  IndexedMesh sheet;
  constexpr int kSide = 200;
  std::uint32_t state = 12345;
  const auto jitter = [&]() {
    state = state * 1664525u + 1013904223u;
    return (static_cast<double>(state >> 8) / 16777216.0 - 0.5) * 0.4;
  };
  for (int j = 0; j <= kSide; ++j) {
    for (int i = 0; i <= kSide; ++i) {
      const bool border = i == 0 || j == 0 || i == kSide || j == kSide;
      sheet.vertices.push_back({i + (border ? 0.0 : jitter()), j + (border ? 0.0 : jitter()), 0});
    }
  }
  const auto at = [](int i, int j) { return static_cast<VertexIndex>(j * (kSide + 1) + i); };
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      sheet.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      sheet.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  for (const auto& t : sheet.triangles) {
    const Vec3& a = sheet.vertices[t[0]];
    const Vec3& b = sheet.vertices[t[1]];
    const Vec3& c = sheet.vertices[t[2]];
    ASSERT_GT((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y), 0.0) << "the model faces +z";
  }
  const DisplayMesh d = make_display_mesh(sheet, 20'000, 20'000);
  ASSERT_TRUE(d.simplified);
  ASSERT_GT(d.facets(), 10'000u);
  double area = 0.0;
  for (std::size_t t = 0; t < d.facets(); ++t) {
    const float* a = &d.positions[3 * d.indices[3 * t]];
    const float* b = &d.positions[3 * d.indices[3 * t + 1]];
    const float* c = &d.positions[3 * d.indices[3 * t + 2]];
    const double twice_area = (double{b[0]} - a[0]) * (double{c[1]} - a[1]) -
                              (double{c[0]} - a[0]) * (double{b[1]} - a[1]);
    EXPECT_GT(twice_area, 0.0) << "facet " << t << " faces -z";
    area += 0.5 * twice_area;
  }
  EXPECT_NEAR(area, kSide * kSide, 0.02 * kSide * kSide) << "the sheet, without holes to speak of";
}

TEST(MakeDisplayMesh, DrawsNothingOfAModelWithoutAFiniteExtent) {
  // Clustering searches cube sizes between fractions of the model's extent: with a coordinate
  // that is not a number, or an extent beyond the doubles, there is no size to search, and the
  // picture is empty rather than wrong. A NaN position is never merged with another, not even
  // with itself.
  const double nan = std::nan("");
  for (const Vec3& odd : {Vec3{nan, 0, 0}, Vec3{0, nan, 0}, Vec3{0, 0, nan}, Vec3{1e308, 0, 0}}) {
    IndexedMesh mesh;
    mesh.vertices = {odd, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1e308, 1, 1}, odd};
    mesh.triangles = {{0, 1, 2}, {5, 2, 3}, {0, 3, 1}, {5, 1, 4}, {1, 2, 4}};
    const DisplayMesh d = make_display_mesh(mesh, 1, 1);
    EXPECT_TRUE(d.simplified);
    EXPECT_EQ(d.facets_in_model, 5u);
    EXPECT_EQ(d.facets(), 0u);
    EXPECT_TRUE(d.positions.empty());
  }
}

TEST(MakeNotedDisplayMesh, SaysWhenAndHowMuchThePictureWasSimplified) {
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(10.0, 3));
  ASSERT_GT(sphere.triangles.size(), 1000u);
  const NotedDisplayMesh whole = make_noted_display_mesh(
      sphere, sphere.triangles.size(), SliceStage::Sliced, CountDigits::GroupedByThousands);
  EXPECT_FALSE(whole.note.has_value());
  const NotedDisplayMesh before =
      make_noted_display_mesh(sphere, 200, SliceStage::NotSlicedYet, CountDigits::Plain);
  ASSERT_TRUE(before.note.has_value());
  EXPECT_EQ(*before.note, "display mesh simplified from " +
                              std::to_string(sphere.triangles.size()) + " to " +
                              std::to_string(before.mesh.facets()) +
                              " facets for the browser; slicing uses every facet");
  const NotedDisplayMesh after =
      make_noted_display_mesh(sphere, 200, SliceStage::Sliced, CountDigits::GroupedByThousands);
  ASSERT_TRUE(after.note.has_value());
  EXPECT_EQ(*after.note, "display mesh simplified from " + with_thousands(sphere.triangles.size()) +
                             " to " + std::to_string(after.mesh.facets()) +
                             " facets for the browser; slicing used every facet");
  EXPECT_NE(with_thousands(sphere.triangles.size()), std::to_string(sphere.triangles.size()));
}

}  // namespace
}  // namespace strata::view
