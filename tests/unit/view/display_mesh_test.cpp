// The triangles the view page draws: every facet within the budget, a simplification beyond it.
#include "strata/view/display_mesh.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace strata::view
