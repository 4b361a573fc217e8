#pragma once

#include <cstdint>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"

namespace strata {

/// A mesh edge crossed by a cutting plane, as its two vertex indices: `below` has z < plane,
/// `above` has z >= plane (the vertex-on-plane rule of SPEC §2). Two facets sharing the edge
/// name it identically, which is what contour assembly chains by.
struct CrossedEdge {
  VertexIndex below = 0;
  VertexIndex above = 0;

  friend bool operator==(const CrossedEdge&, const CrossedEdge&) = default;
};

/// The piece of one facet in one cutting plane. It runs so that the material lies on its left
/// (outer loops counter-clockwise seen from +z, when the facet is oriented outward): it starts
/// on the facet edge that goes down through the plane and ends on the edge that goes up, in the
/// facet's vertex order. Coordinates are the crossing points computed in double from the edge's
/// end points (within a few ulps of the exact point, not always its correctly rounded value);
/// they serve output and first guesses only, every decision is taken on the exact point.
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
