#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "strata/mesh/vec3.hpp"

namespace strata {

/// A vertex of IndexedMesh::vertices.
using VertexIndex = std::uint32_t;
/// A facet, counted from 0 in the input's order.
using FacetIndex = std::uint32_t;

/// Vertices shared by exact equality of their coordinates, and triangles indexing them.
/// Facet order and each facet's vertex order (its orientation) are those of the input.
struct IndexedMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<VertexIndex, 3>> triangles;

  /// Corner c (0, 1 or 2) of facet f.
  const Vec3& corner(FacetIndex f, int c) const { return vertices[triangles[f][c]]; }

  /// The bounding box of the vertices (empty for a mesh without vertices): the box that adding
  /// them to it one by one, in order, gives (of two equal bounds, -0 and +0, the first), computed
  /// on the threads for a large mesh.
  Bbox3 bounds() const;
};

}  // namespace strata
