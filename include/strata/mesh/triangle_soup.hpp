#pragma once

#include <array>
#include <string>
#include <vector>

#include "strata/core/diagnostic.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata {

/// Triangles as read from a file, in file order, each with its own three corners (no sharing).
/// Coordinates are finite millimetres; STL input has been rounded to float32 (SPEC §2).
struct TriangleSoup {
  std::vector<std::array<Vec3, 3>> triangles;
  /// The normal stored with each triangle (STL only; empty when the format has none).
  std::vector<Vec3> stored_normals;
  /// Warnings raised while reading (odd but readable input).
  Diagnostics diagnostics;
  /// What the file was, e.g. "stl-binary", "stl-ascii", "obj", "off", "ply"; "+gz" when compressed.
  std::string format;
};

}  // namespace strata
