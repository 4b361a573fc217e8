#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"

namespace strata {

/// A mesh edge crossed by a cutting plane, as its two vertex indices: `below` has z < plane,
/// `above` has z >= plane (the vertex-on-plane rule of SPEC §2). Two facets sharing the edge
/// name it identically, which is what contour assembly chains by.
struct CrossedEdge {
  VertexIndex below = 0;
  VertexIndex above = 0;

  /// Exact equality of the two vertex indices.
  friend bool operator==(const CrossedEdge&, const CrossedEdge&) = default;
};

/// The two edges by which a facet crosses a cutting plane, in the facet's vertex order: the edge
/// going down through the plane starts its piece in the plane, the edge going up ends it, so that
/// the material lies on the piece's left.
struct FacetCrossing {
  CrossedEdge start_edge;
  CrossedEdge end_edge;
};

/// How facet `f` of `mesh` crosses the plane at height z; std::nullopt when its three vertices
/// lie on one side (a vertex with z == plane counts as above, SPEC §2). The fast and the exact
/// cut both start from it and differ only in how they compute the points on the two edges.
inline std::optional<FacetCrossing> facet_crossing(const IndexedMesh& mesh, FacetIndex f,
                                                   double z) {
  const auto& t = mesh.triangles[f];
  const bool above[3] = {mesh.vertices[t[0]].z >= z, mesh.vertices[t[1]].z >= z,
                         mesh.vertices[t[2]].z >= z};
  const int count = int{above[0]} + int{above[1]} + int{above[2]};
  if (count == 0 || count == 3) return std::nullopt;
  FacetCrossing crossing;
  for (int u = 0; u < 3; ++u) {
    const int v = (u + 1) % 3;
    if (above[u] && !above[v]) crossing.start_edge = CrossedEdge{t[v], t[u]};
    if (!above[u] && above[v]) crossing.end_edge = CrossedEdge{t[u], t[v]};
  }
  return crossing;
}

/// The piece of one facet in one cutting plane. It runs so that the material lies on its left
/// (outer loops counter-clockwise seen from +z, when the facet is oriented outward): it starts
/// on the facet edge that goes down through the plane and ends on the edge that goes up, in the
/// facet's vertex order. Coordinates are the crossing points computed in double from the edge's
/// end points (within a few ulps of the exact point, not always its correctly rounded value);
/// they serve output and first guesses, and settle a decision only where they lie beyond a
/// proven bound of that error from the line in question; every other decision is taken on the
/// exact point.
struct LayerSegment {
  FacetIndex facet = 0;
  CrossedEdge start_edge;
  CrossedEdge end_edge;
  Point2 start;
  Point2 end;
};

/// All segments of one layer, in facet order.
struct LayerSegments {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  std::vector<LayerSegment> segments;
};

}  // namespace strata
