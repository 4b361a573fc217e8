#include "strata/mesh/weld_vertices.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/huge_pages.hpp"
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

/// The vertices seen so far, found by their key: open addressing with linear probing over a
/// power-of-two table of (hash, vertex + 1) pairs, kept at most half full. Flat and allocated
/// once (and on the rare doubling), where a node-based map allocates a node a vertex.
class VertexTable {
 public:
  explicit VertexTable(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    reserve_huge_pages(slots_, capacity);
    slots_.assign(capacity, Slot{});
  }

  /// Starts loading the slot where a key of this hash is looked for.
  void prefetch(std::size_t hash) const { __builtin_prefetch(&slots_[hash & (slots_.size() - 1)]); }

  /// The vertex at `key` (of hash `hash`), or `next` (then inserted) when there is none.
  /// @return (vertex, whether it was inserted)
  std::pair<VertexIndex, bool> find_or_insert(const PointKey& key, std::size_t hash,
                                              const std::vector<Vec3>& vertices, VertexIndex next) {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash & mask;; i = (i + 1) & mask) {
      Slot& slot = slots_[i];
      if (slot.vertex_plus_one == 0) {
        slot = Slot{hash, next + 1};
        if (2 * ++size_ > slots_.size()) grow();
        return {next, true};
      }
      if (slot.hash == hash && key_of(vertices[slot.vertex_plus_one - 1]) == key) {
        return {slot.vertex_plus_one - 1, false};
      }
    }
  }

 private:
  struct Slot {
    std::size_t hash = 0;
    VertexIndex vertex_plus_one = 0;  ///< 0: empty
  };

  void grow() {
    std::vector<Slot> old(slots_.size() * 2);
    old.swap(slots_);
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& slot : old) {
      if (slot.vertex_plus_one == 0) continue;
      std::size_t i = slot.hash & mask;
      while (slots_[i].vertex_plus_one != 0) i = (i + 1) & mask;
      slots_[i] = slot;
    }
  }

  std::vector<Slot> slots_;
  std::size_t size_ = 0;
};

}  // namespace

IndexedMesh weld_vertices(const TriangleSoup& soup) {
  IndexedMesh mesh;
  reserve_huge_pages(mesh.triangles, soup.triangles.size());
  // A closed triangle mesh has about half as many vertices as triangles.
  reserve_huge_pages(mesh.vertices, soup.triangles.size() / 2 + 3);
  VertexTable index_of(soup.triangles.size() / 2 + 3);

  // The table is larger than the caches: each corner's slot is fetched a few corners ahead.
  constexpr std::size_t kAhead = 16;
  const std::size_t corners = 3 * soup.triangles.size();
  const auto corner = [&](std::size_t c) -> const Vec3& { return soup.triangles[c / 3][c % 3]; };
  std::array<std::size_t, kAhead> hashes{};
  for (std::size_t c = 0; c < std::min(kAhead, corners); ++c) {
    hashes[c] = PointKeyHash{}(key_of(corner(c)));
    index_of.prefetch(hashes[c]);
  }
  std::array<VertexIndex, 3> facet{};
  for (std::size_t c = 0; c < corners; ++c) {
    const std::size_t hash = hashes[c % kAhead];
    if (c + kAhead < corners) {
      const std::size_t later = PointKeyHash{}(key_of(corner(c + kAhead)));
      hashes[c % kAhead] = later;
      index_of.prefetch(later);
    }
    const Vec3& p = corner(c);
    const auto [vertex, inserted] = index_of.find_or_insert(
        key_of(p), hash, mesh.vertices, static_cast<VertexIndex>(mesh.vertices.size()));
    if (inserted) {
      STRATA_ASSERT(mesh.vertices.size() < std::numeric_limits<VertexIndex>::max(),
                    "more distinct vertices than VertexIndex can number");
      mesh.vertices.push_back(p);
    }
    facet[c % 3] = vertex;
    if (c % 3 == 2) mesh.triangles.push_back(facet);
  }
  return mesh;
}

}  // namespace strata
