#pragma once

// Shared by the exact path, repair and the reference slicer: every user of CGAL's
// orient_polygon_soup calls it and counts what it did in the same way.

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <set>
#include <utility>

namespace strata::soup {

/// What CGAL's orient_polygon_soup reports while it orients a soup.
struct OrientSoupCounts {
  std::uint64_t reversed = 0;  ///< polygons whose orientation it reversed
  std::set<std::pair<std::size_t, std::size_t>> non_manifold_edges;  ///< point pairs, smaller first
  std::set<std::size_t> non_manifold_vertices;                       ///< points it duplicated
  std::size_t points_added = 0;  ///< copies of points it made to split non-manifold places
  bool oriented = false;         ///< its result: every polygon could be oriented consistently
};

/// The visitor that fills OrientSoupCounts. CGAL copies the visitor, so the counts live outside
/// it: `orient_polygon_soup(points, polygons, CGAL::parameters::visitor(OrientSoupVisitor{&c}))`.
struct OrientSoupVisitor : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  OrientSoupCounts* counts = nullptr;

  explicit OrientSoupVisitor(OrientSoupCounts* c) : counts(c) {}
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t) {
    counts->non_manifold_edges.emplace(std::min(a, b), std::max(a, b));
  }
  void non_manifold_vertex(std::size_t v, std::size_t) { counts->non_manifold_vertices.insert(v); }
  void polygon_orientation_reversed(std::size_t) { ++counts->reversed; }
};

/// Orients the soup in place with CGAL's orient_polygon_soup and returns what it did.
template <class PointRange, class PolygonRange>
OrientSoupCounts orient_soup(PointRange& points, PolygonRange& polygons) {
  OrientSoupCounts counts;
  const std::size_t points_before = points.size();
  counts.oriented = CGAL::Polygon_mesh_processing::orient_polygon_soup(
      points, polygons, CGAL::parameters::visitor(OrientSoupVisitor{&counts}));
  counts.points_added = points.size() - points_before;
  return counts;
}

}  // namespace strata::soup
