#pragma once

// Whether a polygon soup is a polygon mesh, with the answer of CGAL's
// Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh() (the precondition of
// polygon_soup_to_polygon_mesh) in flat, sorted arrays: CGAL's check keeps a std::set node per
// halfedge and a flat_map per vertex, 300 bytes a facet at its peak (300 MB for a million).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace strata::soup {

/// True when every polygon has three vertices or more, none twice, no ordered edge (u, v) is in
/// two polygons, and the polygons around each vertex form one fan: walking from one of them to
/// the polygon across each edge at the vertex, both ways until a border, meets them all.
/// Vertex ids must be below `point_count`.
template <class PolygonRange>
bool is_polygon_mesh(const PolygonRange& polygons, std::size_t point_count) {
  // Corners: polygon p meets vertex v between prev and next.
  struct Corner {
    std::uint32_t vertex, prev, next, polygon;
  };
  std::size_t corner_count = 0;
  for (const auto& polygon : polygons) {
    if (polygon.size() < 3) return false;
    corner_count += polygon.size();
  }
  if (point_count > UINT32_MAX || polygons.size() > UINT32_MAX) return false;
  // Corners by vertex, then polygon (the order CGAL visits a vertex's polygons in): a counting
  // sort by vertex, the polygons taken in order.
  std::vector<std::size_t> first(point_count + 1, 0);
  for (const auto& polygon : polygons) {
    for (const auto v : polygon) {
      if (static_cast<std::size_t>(v) >= point_count) return false;
      ++first[static_cast<std::size_t>(v) + 1];
    }
  }
  for (std::size_t v = 0; v < point_count; ++v) first[v + 1] += first[v];
  std::vector<Corner> corners(corner_count);
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const auto& polygon = polygons[p];
    const std::size_t n = polygon.size();
    for (std::size_t j = 0; j < n; ++j) {
      const auto v = static_cast<std::size_t>(polygon[j]);
      corners[first[v]++] = {
          static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(polygon[(j + n - 1) % n]),
          static_cast<std::uint32_t>(polygon[(j + 1) % n]), static_cast<std::uint32_t>(p)};
    }
  }
  first = {};
  std::vector<bool> visited;
  std::vector<std::uint32_t> by_prev, by_next;  // a vertex's corners (offsets) by prev, by next
  for (std::size_t begin = 0; begin < corners.size();) {
    std::size_t end = begin + 1;
    while (end < corners.size() && corners[end].vertex == corners[begin].vertex) ++end;
    const std::size_t count = end - begin;
    const Corner* around = corners.data() + begin;
    // A vertex twice in a polygon (the corners are by polygon).
    for (std::size_t a = 1; a < count; ++a) {
      if (around[a].polygon == around[a - 1].polygon) return false;
    }
    by_prev.resize(count);
    by_next.resize(count);
    for (std::uint32_t a = 0; a < count; ++a) by_prev[a] = by_next[a] = a;
    std::sort(by_prev.begin(), by_prev.end(),
              [&](std::uint32_t a, std::uint32_t b) { return around[a].prev < around[b].prev; });
    std::sort(by_next.begin(), by_next.end(),
              [&](std::uint32_t a, std::uint32_t b) { return around[a].next < around[b].next; });
    // An ordered edge (v, next) in two polygons.
    for (std::size_t a = 1; a < count; ++a) {
      if (around[by_next[a]].next == around[by_next[a - 1]].next) return false;
    }
    // The polygon after corner c around the vertex has c.next as its prev (the edge (next, v));
    // the one before has c.prev as its next. Each is unique once no ordered edge repeats (an
    // edge (u, v) twice would be a repeated (v, next) at u).
    const std::size_t none = count;
    const auto after = [&](std::size_t c) -> std::size_t {
      const auto it = std::lower_bound(
          by_prev.begin(), by_prev.end(), around[c].next,
          [&](std::uint32_t q, std::uint32_t value) { return around[q].prev < value; });
      return it != by_prev.end() && around[*it].prev == around[c].next ? *it : none;
    };
    const auto before = [&](std::size_t c) -> std::size_t {
      const auto it = std::lower_bound(
          by_next.begin(), by_next.end(), around[c].prev,
          [&](std::uint32_t q, std::uint32_t value) { return around[q].next < value; });
      return it != by_next.end() && around[*it].next == around[c].prev ? *it : none;
    };
    visited.assign(count, false);
    visited[0] = true;
    std::size_t seen = 1;
    std::size_t c = after(0);
    while (c != none && !visited[c]) {
      visited[c] = true;
      ++seen;
      c = after(c);
    }
    if (c == none) {  // a border: walk the other way from the first polygon
      c = before(0);
      while (c != none && !visited[c]) {
        visited[c] = true;
        ++seen;
        c = before(c);
      }
    }
    if (seen != count) return false;
    begin = end;
  }
  return true;
}

}  // namespace strata::soup
