#include "strata/view/display_mesh.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <algorithm>
#include <array>

namespace strata::view {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SMS = CGAL::Surface_mesh_simplification;

DisplayMesh whole(const IndexedMesh& mesh) {
  DisplayMesh out;
  out.facets_in_model = mesh.triangles.size();
  out.positions.reserve(3 * mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) {
    out.positions.insert(out.positions.end(), {static_cast<float>(v.x), static_cast<float>(v.y),
                                               static_cast<float>(v.z)});
  }
  out.indices.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) out.indices.insert(out.indices.end(), t.begin(), t.end());
  return out;
}

}  // namespace

DisplayMesh make_display_mesh(const IndexedMesh& mesh, std::size_t max_facets) {
  if (mesh.triangles.size() <= max_facets) return whole(mesh);

  // Edge collapse needs a manifold surface: the soup functions drop degenerate facets, orient
  // the rest and duplicate the vertices where the surface is not a manifold.
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  Mesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);

  const double ratio =
      static_cast<double>(max_facets) / static_cast<double>(surface.number_of_faces());
  if (ratio < 1.0) {
    SMS::Count_ratio_stop_predicate<Mesh> stop(ratio);
    SMS::edge_collapse(surface, stop,
                       CGAL::parameters::get_cost(SMS::Edge_length_cost<Mesh>())
                           .get_placement(SMS::Midpoint_placement<Mesh>()));
    surface.collect_garbage();
  }

  DisplayMesh out;
  out.facets_in_model = mesh.triangles.size();
  out.simplified = true;
  std::vector<std::uint32_t> index(surface.num_vertices(), 0);
  std::uint32_t next = 0;
  for (Mesh::Vertex_index v : surface.vertices()) {
    const Point& p = surface.point(v);
    index[v] = next++;
    out.positions.insert(out.positions.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                               static_cast<float>(p.z())});
  }
  out.indices.reserve(3 * surface.number_of_faces());
  for (Mesh::Face_index f : surface.faces()) {
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(surface.halfedge(f), surface)) {
      out.indices.push_back(index[v]);
    }
  }
  return out;
}

}  // namespace strata::view
