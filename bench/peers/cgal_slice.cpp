// The CGAL peer of bench/compare: CGAL's Polygon_mesh_slicer cuts a binary STL at strata's layer
// planes (z0 + (k + 0.5) dz, z0 the model's lowest z), contours only, with the Epick or the
// Epeck kernel. Prints the number of layers, polylines and points, so the work is not optimised
// away. Usage: strata_peer_cgal_slice MODEL.stl epick|epeck [DZ_MM]
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "binary_stl.hpp"

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

template <class Kernel>
int slice(const strata::bench::BinaryStl& stl, double dz) {
  using Point = typename Kernel::Point_3;
  using Mesh = CGAL::Surface_mesh<Point>;
  std::vector<Point> points;
  points.reserve(stl.vertices.size());
  double z_min = std::numeric_limits<double>::infinity();
  double z_max = -z_min;
  for (const auto& v : stl.vertices) {
    points.emplace_back(v[0], v[1], v[2]);
    z_min = std::min(z_min, double{v[2]});
    z_max = std::max(z_max, double{v[2]});
  }
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(stl.triangles.size());
  for (const auto& t : stl.triangles) polygons.push_back({t[0], t[1], t[2]});
  // CGAL's halfedge meshes need a 2-manifold: orient (and split non-manifold vertices) only when
  // the soup is not one already, as CGAL's own readers do.
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) PMP::orient_polygon_soup(points, polygons);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);

  // strata's layer count and planes (SPEC §2): nz = max(1, ceil((zmax - z0) / dz)).
  const auto layers = std::max<long>(1, static_cast<long>(std::ceil((z_max - z_min) / dz)));
  CGAL::Polygon_mesh_slicer<Mesh, Kernel> slicer(mesh);
  std::vector<std::vector<Point>> polylines;
  std::size_t polyline_count = 0;
  std::size_t point_count = 0;
  for (long k = 0; k < layers; ++k) {
    const double z = z_min + (static_cast<double>(k) + 0.5) * dz;
    polylines.clear();
    slicer(typename Kernel::Plane_3(0, 0, 1, -z), std::back_inserter(polylines));
    polyline_count += polylines.size();
    for (const auto& p : polylines) point_count += p.size();
  }
  std::printf("layers %ld polylines %zu points %zu\n", layers, polyline_count, point_count);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string kernel = argc > 2 ? argv[2] : "";
  if (argc < 3 || argc > 4 || (kernel != "epick" && kernel != "epeck")) {
    std::fputs("usage: strata_peer_cgal_slice MODEL.stl epick|epeck [DZ_MM]\n", stderr);
    return 2;
  }
  try {
    const double dz = argc > 3 ? std::stod(argv[3]) : 0.1;
    const auto stl = strata::bench::read_binary_stl(argv[1]);
    return kernel == "epick" ? slice<CGAL::Epick>(stl, dz) : slice<CGAL::Epeck>(stl, dz);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "strata_peer_cgal_slice: %s\n", e.what());
    return 1;
  }
}
