#include "strata/mesh/weld_vertices.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "strata/core/error.hpp"

namespace strata {
namespace {

/// The bit patterns of a point's coordinates, -0 replaced by +0 so that the two zeros, which
/// compare equal, weld (SPEC §2b: exact equality of the input coordinates).
using PointKey = std::array<std::uint64_t, 3>;

std::uint64_t coordinate_bits(double value) {
  return std::bit_cast<std::uint64_t>(value == 0.0 ? 0.0 : value);
}

PointKey key_of(const Vec3& p) {
  return {coordinate_bits(p.x), coordinate_bits(p.y), coordinate_bits(p.z)};
}

struct PointKeyHash {
  std::size_t operator()(const PointKey& key) const noexcept {
    // splitmix64-style mixing of the three words; coordinates of one mesh share high bits.
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (const std::uint64_t word : key) {
      h ^= word + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h ^= h >> 30;
      h *= 0xbf58476d1ce4e5b9ull;
      h ^= h >> 27;
      h *= 0x94d049bb133111ebull;
      h ^= h >> 31;
    }
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

IndexedMesh weld_vertices(const TriangleSoup& soup) {
  IndexedMesh mesh;
  mesh.triangles.reserve(soup.triangles.size());
  // A closed triangle mesh has about half as many vertices as triangles.
  mesh.vertices.reserve(soup.triangles.size() / 2 + 3);
  std::unordered_map<PointKey, VertexIndex, PointKeyHash> index_of;
  index_of.reserve(soup.triangles.size() / 2 + 3);

  for (const auto& triangle : soup.triangles) {
    std::array<VertexIndex, 3> corners{};
    for (int c = 0; c < 3; ++c) {
      const auto [it, inserted] =
          index_of.try_emplace(key_of(triangle[c]), static_cast<VertexIndex>(mesh.vertices.size()));
      if (inserted) {
        STRATA_ASSERT(mesh.vertices.size() < std::numeric_limits<VertexIndex>::max(),
                      "more distinct vertices than VertexIndex can number");
        mesh.vertices.push_back(triangle[c]);
      }
      corners[c] = it->second;
    }
    mesh.triangles.push_back(corners);
  }
  return mesh;
}

}  // namespace strata
