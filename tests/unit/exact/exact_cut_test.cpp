// The exact cut holds one point per crossed edge, each the exact crossing, and the halfedge
// chaining hands every loop its own copy of a point that starts several segments.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "exact/exact_cut_internal.hpp"
#include "exact/exact_soup_internal.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "support/exact_crossing.hpp"
#include "support/mesh_builders.hpp"

namespace strata::exact::detail {
namespace {

/// Whether d is a double nearest to q.
bool is_nearest(const mpq_class& q, double d) {
  const mpq_class gap = abs(q - mpq_class(d));
  for (const double toward : {-HUGE_VAL, HUGE_VAL}) {
    if (abs(q - mpq_class(std::nextafter(d, toward))) < gap) return false;
  }
  return true;
}

TEST(CutLayer, HoldsOnePointPerCrossedEdgeAtItsExactCrossing) {
  // A welded ring: a closed surface, whose every crossed edge is shared by two facets. The
  // plane lies off the vertices, so the side walls' diagonals are crossed inside.
  const IndexedMesh mesh = weld_vertices(mesh::make_ring(10.0, 6.0, 3.0, 24));
  const double z = 1.1;
  const ExactLayer layer =
      cut_layer(mesh, test::all_facets(mesh), facet_normal_x_signs(mesh), 0, z);
  ASSERT_EQ(layer.segments.size(), 96u);  // 24 sectors, two triangles on each of two walls
  EXPECT_EQ(layer.points.size(), layer.segments.size());
  std::vector<int> starts(layer.points.size(), 0);
  std::vector<int> ends(layer.points.size(), 0);
  for (const ExactSegment& s : layer.segments) {
    ++starts.at(s.start);
    ++ends.at(s.end);
    for (const auto& [edge, index] : {std::pair{s.start_edge, s.start}, {s.end_edge, s.end}}) {
      const Vec3& lo = mesh.vertices[edge.below];
      const Vec3& hi = mesh.vertices[edge.above];
      const ExactPoint2& p = layer.points[index];
      EXPECT_EQ(p.x.exact(), test::crossing_as_written(lo, hi, z, 0));
      EXPECT_EQ(p.y.exact(), test::crossing_as_written(lo, hi, z, 1));
      EXPECT_TRUE(is_nearest(p.x.exact(), p.x.rounded));
      EXPECT_TRUE(is_nearest(p.y.exact(), p.y.rounded));
    }
  }
  for (std::size_t p = 0; p < layer.points.size(); ++p) {
    EXPECT_EQ(starts[p], 1) << "point " << p;
    EXPECT_EQ(ends[p], 1) << "point " << p;
  }
}

TEST(ChainLayer, APointThatStartsTwoSegmentsIsInBothLoops) {
  // Two boxes that share the vertical edge x = y = 1: the four facets around it cross the plane
  // at one point, which starts a segment of each box.
  TriangleSoup soup = mesh::make_box({0, 0, 0}, {1, 1, 1});
  const TriangleSoup second = mesh::make_box({1, 1, 0}, {2, 2, 1});
  soup.triangles.insert(soup.triangles.end(), second.triangles.begin(), second.triangles.end());
  const IndexedMesh mesh = weld_vertices(soup);
  ASSERT_EQ(mesh.vertices.size(), 14u);  // the shared edge's two vertices are welded
  ExactLayer layer = cut_layer(mesh, test::all_facets(mesh), facet_normal_x_signs(mesh), 0, 0.5);
  std::vector<int> starts(layer.points.size(), 0);
  for (const ExactSegment& s : layer.segments) ++starts[s.start];
  ASSERT_EQ(std::count(starts.begin(), starts.end(), 2), 1);

  const SoupMesh soup_mesh(mesh);
  std::optional<std::vector<ExactLoop>> loops = soup_mesh.chain_layer(layer);
  ASSERT_TRUE(loops.has_value());
  ASSERT_EQ(loops->size(), 2u);
  for (const ExactLoop& loop : *loops) {
    int shared = 0;
    mpq_class x_sum = 0;
    for (const ExactPoint2& p : loop.points) {
      if (p.x.exact() == 1 && p.y.exact() == 1) ++shared;
      EXPECT_TRUE(is_nearest(p.x.exact(), p.x.rounded));
      x_sum += p.x.exact();
    }
    EXPECT_EQ(shared, 1);
    // Every point of a loop is one of its box's: x all in [0, 1] or all in [1, 2].
    const bool first_box = x_sum <= mpq_class(static_cast<long>(loop.points.size()));
    for (const ExactPoint2& p : loop.points) {
      EXPECT_TRUE(first_box ? (p.x.exact() >= 0 && p.x.exact() <= 1)
                            : (p.x.exact() >= 1 && p.x.exact() <= 2));
    }
  }
}

}  // namespace
}  // namespace strata::exact::detail
