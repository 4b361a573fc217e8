// A clean soup (is_clean_soup) is one CGAL's whole repair only takes unused points from, and
// the exact path's soup reports the same repair either way.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "exact/exact_soup_internal.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::exact::detail {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Point = CGAL::Epick::Point_3;
using Polygon = std::vector<std::size_t>;

struct Soup {
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  bool operator==(const Soup&) const = default;
};

Soup soup_of(const IndexedMesh& mesh) {
  Soup s;
  for (const Vec3& v : mesh.vertices) s.points.emplace_back(v.x, v.y, v.z);
  for (const auto& t : mesh.triangles) s.polygons.push_back({t[0], t[1], t[2]});
  return s;
}

TEST(IsCleanSoup, NamedCases) {
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(5.0, 2));
  EXPECT_TRUE(is_clean_soup(sphere));
  IndexedMesh isolated = sphere;
  isolated.vertices.push_back({100, 100, 100});
  EXPECT_TRUE(is_clean_soup(isolated)) << "an unused point is the one thing left to the repair";
  IndexedMesh repeated_corner = sphere;
  repeated_corner.triangles.push_back({0, 0, 1});
  EXPECT_FALSE(is_clean_soup(repeated_corner));
  IndexedMesh twice = sphere;
  twice.triangles.push_back(sphere.triangles[3]);
  EXPECT_FALSE(is_clean_soup(twice));
  IndexedMesh reversed = sphere;
  reversed.triangles.push_back(
      {sphere.triangles[3][1], sphere.triangles[3][0], sphere.triangles[3][2]});
  EXPECT_FALSE(is_clean_soup(reversed)) << "the same three vertices, either way round";
  IndexedMesh unwelded = sphere;
  unwelded.vertices.push_back(sphere.vertices[7]);
  EXPECT_FALSE(is_clean_soup(unwelded)) << "two vertices at one position";
  IndexedMesh signed_zero;
  signed_zero.vertices = {{0.0, 1, 2}, {-0.0, 1, 2}, {3, 4, 5}, {6, 7, 9}};
  signed_zero.triangles = {{1, 2, 3}};
  EXPECT_FALSE(is_clean_soup(signed_zero)) << "+0 and -0 are one position";
}

TEST(IsCleanSoup, WhereItHoldsTheWholeRepairOnlyRemovesUnusedPoints) {
  // Small random soups over few positions: repeated corners, repeated facets (either way
  // round), repeated positions and unused points are all common.
  std::mt19937 random(7);
  int clean = 0;
  for (int trial = 0; trial < 3'000; ++trial) {
    IndexedMesh mesh;
    const int positions = 4 + static_cast<int>(random() % 5);
    const int vertices = positions + static_cast<int>(random() % 3);
    for (int v = 0; v < vertices; ++v) {
      const int at = v < positions ? v : static_cast<int>(random() % positions);
      mesh.vertices.push_back({static_cast<double>(at % 3), static_cast<double>(at / 3), at * 0.5});
    }
    const int facets = 1 + static_cast<int>(random() % 7);
    for (int f = 0; f < facets; ++f) {
      std::array<VertexIndex, 3> t{};
      for (auto& c : t) c = static_cast<VertexIndex>(random() % vertices);
      if (random() % 4 != 0 && (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])) continue;
      mesh.triangles.push_back(t);
    }
    if (!is_clean_soup(mesh)) continue;
    ++clean;
    Soup repaired = soup_of(mesh);
    PMP::repair_polygon_soup(repaired.points, repaired.polygons);
    Soup trimmed = soup_of(mesh);
    PMP::remove_isolated_points_in_polygon_soup(trimmed.points, trimmed.polygons);
    ASSERT_EQ(repaired, trimmed) << "trial " << trial;
  }
  EXPECT_GT(clean, 300);
  EXPECT_LT(clean, 2'700);
}

}  // namespace
}  // namespace strata::exact::detail
