#pragma once

// Shared by the exact path and repair, which find a triangle again by where its corners are
// (whatever their order and the vertex indices), and the view's display mesh, which finds
// vertices at one position.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "strata/mesh/vec3.hpp"

namespace strata::soup {

/// A triangle by the set of its corner positions (+0 and -0 alike).
using PositionKey = std::array<double, 9>;

inline PositionKey position_key(std::array<Vec3, 3> corners) {
  for (Vec3& c : corners) c = {c.x + 0.0, c.y + 0.0, c.z + 0.0};
  std::sort(corners.begin(), corners.end(), [](const Vec3& a, const Vec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
  });
  return {corners[0].x, corners[0].y, corners[0].z, corners[1].x, corners[1].y,
          corners[1].z, corners[2].x, corners[2].y, corners[2].z};
}

/// FNV-style hash of an array of doubles by their bits (keys hold no -0: +0.0 was added).
struct DoublesHash {
  template <std::size_t N>
  std::size_t operator()(const std::array<double, N>& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (const double d : k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &d, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h);
  }
};

}  // namespace strata::soup
