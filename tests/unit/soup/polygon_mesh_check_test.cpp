// soup::is_polygon_mesh gives CGAL's answer (is_polygon_soup_a_polygon_mesh) on every soup.
#include "soup/polygon_mesh_check.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "soup/orient_soup_visitor.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::soup {
namespace {

using Polygon = std::vector<std::size_t>;
using Soup = std::vector<Polygon>;

bool cgal_says(const Soup& polygons) {
  return CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
}

std::size_t point_count(const Soup& polygons) {
  std::size_t n = 0;
  for (const Polygon& p : polygons) {
    for (const std::size_t v : p) n = std::max(n, v + 1);
  }
  return n;
}

TEST(IsPolygonMesh, NamedCases) {
  struct Case {
    const char* name;
    Soup polygons;
    bool expected;
  };
  const std::vector<Case> cases = {
      {"tetrahedron", {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}, true},
      {"one triangle", {{0, 1, 2}}, true},
      {"open fan around 0", {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}, true},
      {"closed fan around 0 (a cone's side)", {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}}, true},
      {"quad and triangle", {{0, 1, 2, 3}, {0, 3, 4}}, true},
      {"bow tie: two triangles meeting at a vertex", {{0, 1, 2}, {0, 3, 4}}, false},
      {"two tetrahedra sharing a vertex",
       {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 5, 4}, {0, 4, 6}, {4, 5, 6}, {0, 6, 5}},
       false},
      {"an edge in two polygons the same way", {{0, 1, 2}, {0, 1, 3}}, false},
      {"an edge in three polygons", {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}}, false},
      {"a vertex twice in a polygon", {{0, 1, 0, 2}}, false},
      {"a polygon of two vertices", {{0, 1}}, false},
      {"opposite orientations across an edge", {{0, 1, 2}, {0, 1, 3}, {3, 1, 4}}, false},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(cgal_says(c.polygons), c.expected) << c.name << " (CGAL)";
    EXPECT_EQ(is_polygon_mesh(c.polygons, point_count(c.polygons)), c.expected) << c.name;
  }
}

TEST(IsPolygonMesh, AgreesWithCgalOnRandomSoups) {
  // Few vertices and polygons, so that shared edges, fans, borders, bow ties and repeats are
  // all common; sizes 2 to 4 and an occasional repeated vertex.
  std::mt19937 random(20261125);
  std::size_t meshes = 0;
  for (int trial = 0; trial < 20'000; ++trial) {
    const std::size_t vertex_count = 3 + random() % 6;
    const std::size_t polygon_count = 1 + random() % 8;
    Soup polygons(polygon_count);
    for (Polygon& p : polygons) {
      const std::size_t size = random() % 16 == 0 ? 2 : (random() % 8 == 0 ? 4 : 3);
      while (p.size() < size) {
        const std::size_t v = random() % vertex_count;
        if (random() % 32 != 0 && std::find(p.begin(), p.end(), v) != p.end()) continue;
        p.push_back(v);
      }
    }
    const bool expected = cgal_says(polygons);
    meshes += expected;
    ASSERT_EQ(is_polygon_mesh(polygons, vertex_count), expected) << "trial " << trial;
  }
  // Both answers must be common for the comparison to mean something.
  EXPECT_GT(meshes, 2'000u);
  EXPECT_LT(meshes, 18'000u);
}

TEST(IsPolygonMesh, AgreesWithCgalOnASphereAndItsDamage) {
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(10.0, 3));
  Soup polygons;
  for (const auto& t : sphere.triangles) polygons.push_back({t[0], t[1], t[2]});
  EXPECT_TRUE(is_polygon_mesh(polygons, sphere.vertices.size()));
  EXPECT_TRUE(cgal_says(polygons));
  // A hole: still a mesh. A flipped facet: its edges repeat their neighbours' direction.
  Soup holed(polygons.begin() + 1, polygons.end());
  EXPECT_TRUE(is_polygon_mesh(holed, sphere.vertices.size()));
  Soup flipped = polygons;
  std::swap(flipped[7][0], flipped[7][1]);
  EXPECT_FALSE(is_polygon_mesh(flipped, sphere.vertices.size()));
  EXPECT_FALSE(cgal_says(flipped));
  // Two facets around one vertex taken out on either side: the vertex's fan splits in two.
  const std::size_t v = polygons[0][0];
  Soup split;
  int removed = 0;
  for (const Polygon& p : polygons) {
    const bool around = std::find(p.begin(), p.end(), v) != p.end();
    if (around && (removed == 0 || removed == 3)) {
      ++removed;
      continue;
    }
    removed += around ? 1 : 0;
    split.push_back(p);
  }
  EXPECT_EQ(is_polygon_mesh(split, sphere.vertices.size()), cgal_says(split));
}

TEST(IsPolygonMesh, ASoupThatIsOneIsLeftAsItIsByCgalsOrientation) {
  // What lets the exact path skip the orientation of such a soup: nothing reversed, split or
  // reported, on random soups and on a sphere.
  std::mt19937 random(99);
  std::size_t meshes = 0;
  for (int trial = 0; trial < 20'000; ++trial) {
    const std::size_t vertex_count = 3 + random() % 6;
    Soup polygons(1 + random() % 8);
    for (Polygon& p : polygons) {
      while (p.size() < 3) {
        const std::size_t v = random() % vertex_count;
        if (std::find(p.begin(), p.end(), v) == p.end()) p.push_back(v);
      }
    }
    if (!is_polygon_mesh(polygons, vertex_count)) continue;
    ++meshes;
    std::vector<CGAL::Epick::Point_3> points;
    for (std::size_t v = 0; v < vertex_count; ++v) points.emplace_back(v, v * v, 1.0 / (v + 1));
    const Soup before = polygons;
    const OrientSoupCounts counts = orient_soup(points, polygons);
    ASSERT_EQ(polygons, before) << "trial " << trial;
    ASSERT_EQ(points.size(), vertex_count) << "trial " << trial;
    ASSERT_EQ(counts.reversed, 0u) << "trial " << trial;
    ASSERT_TRUE(counts.non_manifold_edges.empty()) << "trial " << trial;
    ASSERT_EQ(counts.points_added, 0u) << "trial " << trial;
  }
  EXPECT_GT(meshes, 2'000u);
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(10.0, 3));
  Soup polygons;
  for (const auto& t : sphere.triangles) polygons.push_back({t[0], t[1], t[2]});
  std::vector<CGAL::Epick::Point_3> points;
  for (const Vec3& v : sphere.vertices) points.emplace_back(v.x, v.y, v.z);
  const Soup before = polygons;
  const OrientSoupCounts counts = orient_soup(points, polygons);
  EXPECT_EQ(polygons, before);
  EXPECT_EQ(counts.reversed, 0u);
  EXPECT_EQ(counts.points_added, 0u);
}

}  // namespace
}  // namespace strata::soup
