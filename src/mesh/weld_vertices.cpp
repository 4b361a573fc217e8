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
  // Only the two zeros have no bit set but the sign: an integer test, without a branch.
  const auto bits = std::bit_cast<std::uint64_t>(value);
  return (bits << 1) == 0 ? 0 : bits;
}

PointKey key_of(const Vec3& p) {
  return {coordinate_bits(p.x), coordinate_bits(p.y), coordinate_bits(p.z)};
}

struct PointKeyHash {
  std::size_t operator()(const PointKey& key) const noexcept {
    // Each word multiplied by its own odd constant and turned to its own place, the three
    // combined and then mixed (the finaliser of MurmurHash3): the low bits of a coordinate read
    // from a float are all zero, and the table's index is taken from the low bits of the hash.
    std::uint64_t h = key[0] * 0x9e3779b97f4a7c15ull ^
                      std::rotl(key[1] * 0xc2b2ae3d27d4eb4full, 21) ^
                      std::rotl(key[2] * 0x165667b19e3779f9ull, 42);
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
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

  // The table is larger than the caches: each corner's slot is fetched a few corners ahead,
  // when its key and hash are computed, and both are kept until the corner's turn.
  constexpr std::size_t kAhead = 16;
  struct Ahead {
    PointKey key;
    std::size_t hash;
  };
  std::array<Ahead, kAhead> ahead{};
  const std::size_t facets = soup.triangles.size();
  const std::size_t corners = 3 * facets;
  std::size_t ahead_facet = 0;  // the corner kAhead ahead, as (facet, corner)
  int ahead_corner = 0;
  const auto fetch_ahead = [&](std::size_t slot) {
    const PointKey key = key_of(soup.triangles[ahead_facet][ahead_corner]);
    ahead[slot] = Ahead{key, PointKeyHash{}(key)};
    index_of.prefetch(ahead[slot].hash);
    if (++ahead_corner == 3) {
      ahead_corner = 0;
      ++ahead_facet;
    }
  };
  for (std::size_t c = 0; c < std::min(kAhead, corners); ++c) fetch_ahead(c);
  std::size_t c = 0;
  for (std::size_t f = 0; f < facets; ++f) {
    std::array<VertexIndex, 3> facet{};
    for (int k = 0; k < 3; ++k, ++c) {
      const Ahead here = ahead[c % kAhead];
      if (c + kAhead < corners) fetch_ahead(c % kAhead);
      const auto [vertex, inserted] = index_of.find_or_insert(
          here.key, here.hash, mesh.vertices, static_cast<VertexIndex>(mesh.vertices.size()));
      if (inserted) {
        STRATA_ASSERT(mesh.vertices.size() < std::numeric_limits<VertexIndex>::max(),
                      "more distinct vertices than VertexIndex can number");
        mesh.vertices.push_back(soup.triangles[f][k]);
      }
      facet[k] = vertex;
    }
    mesh.triangles.push_back(facet);
  }
  return mesh;
}

}  // namespace strata
