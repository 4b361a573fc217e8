#include "strata/mesh/weld_vertices.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "core/huge_pages.hpp"
#include "core/usable_threads.hpp"
#include "mesh/weld_vertices_internal.hpp"
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
/// power-of-two table of (high half of the hash, vertex + 1) pairs, kept at most half full. Flat
/// and allocated once (and on the rare doubling), where a node-based map allocates a node a
/// vertex; 8 bytes a slot, and in pages of its own, huge where the kernel offers them: the table
/// is read at random, and with 4 KiB pages nearly every probe of a million-facet model's (8 MiB)
/// missed the TLB.
class VertexTable {
 public:
  explicit VertexTable(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    slots_ = ZeroedPageArray<Slot>(capacity);
  }

  /// Starts loading the slot where a key of this hash is looked for.
  void prefetch(std::size_t hash) const { __builtin_prefetch(&slots_[hash & (slots_.size() - 1)]); }

  /// The vertex at `key` (of hash `hash`), or `next` (then inserted) when there is none.
  /// @return (vertex, whether it was inserted)
  std::pair<VertexIndex, bool> find_or_insert(const PointKey& key, std::size_t hash,
                                              const std::vector<Vec3>& vertices, VertexIndex next) {
    Slot& slot = slots_[slot_of(key, hash, vertices)];
    if (slot.vertex_plus_one != 0) return {slot.vertex_plus_one - 1, false};
    if (2 * (size_ + 1) > slots_.size()) {
      // Doubled first: the key is not in the table, and goes where the larger one puts it.
      grow(vertices);
      return find_or_insert(key, hash, vertices, next);
    }
    slot = Slot{static_cast<std::uint32_t>(hash >> 32), next + 1};
    ++size_;
    return {next, true};
  }

  /// The vertex at `key` (of hash `hash`), or kAbsent. Only reads: threads may look up side by
  /// side while nothing is inserted.
  static constexpr VertexIndex kAbsent = std::numeric_limits<VertexIndex>::max();
  VertexIndex find(const PointKey& key, std::size_t hash, const std::vector<Vec3>& vertices) const {
    const Slot& slot = slots_[slot_of(key, hash, vertices)];
    return slot.vertex_plus_one == 0 ? kAbsent : slot.vertex_plus_one - 1;
  }

 private:
  struct Slot {
    std::uint32_t tag = 0;
    VertexIndex vertex_plus_one = 0;  ///< 0: empty
  };

  /// The slot that holds `key`, or else the empty slot where its probe ends.
  std::size_t slot_of(const PointKey& key, std::size_t hash,
                      const std::vector<Vec3>& vertices) const {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash & mask;; i = (i + 1) & mask) {
      const Slot& slot = slots_[i];
      if (slot.vertex_plus_one == 0) return i;
      if (slot.tag == static_cast<std::uint32_t>(hash >> 32) &&
          key_of(vertices[slot.vertex_plus_one - 1]) == key) {
        return i;
      }
    }
  }

  void grow(const std::vector<Vec3>& vertices) {
    ZeroedPageArray<Slot> old(slots_.size() * 2);
    std::swap(old, slots_);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t k = 0; k < old.size(); ++k) {
      const Slot& slot = old[k];
      if (slot.vertex_plus_one == 0) continue;
      std::size_t i = PointKeyHash{}(key_of(vertices[slot.vertex_plus_one - 1])) & mask;
      while (slots_[i].vertex_plus_one != 0) i = (i + 1) & mask;
      slots_[i] = slot;
    }
  }

  ZeroedPageArray<Slot> slots_;
  std::size_t size_ = 0;
};

/// The vertices a weld of `facets` facets is sized for: a closed triangle mesh has about half as
/// many vertices as facets (the table and the vertices grow past it when a soup has more).
std::size_t expected_vertices(std::size_t facets) { return facets / 2 + 3; }

/// Calls visit(i, key, hash) for the n points point(i) in order. The table is larger than the
/// caches: each point's slot is fetched a few points ahead, when its key and hash are computed,
/// and both are kept until the point's turn.
template <class Point, class Visit>
void visit_keys_ahead(std::size_t n, const Point& point, const VertexTable& table,
                      const Visit& visit) {
  constexpr std::size_t kAhead = 16;
  struct Ahead {
    PointKey key;
    std::size_t hash;
  };
  std::array<Ahead, kAhead> ahead{};
  const auto fetch = [&](std::size_t i) {
    const PointKey key = key_of(point(i));
    ahead[i % kAhead] = Ahead{key, PointKeyHash{}(key)};
    table.prefetch(ahead[i % kAhead].hash);
  };
  for (std::size_t i = 0; i < std::min(kAhead, n); ++i) fetch(i);
  for (std::size_t i = 0; i < n; ++i) {
    const Ahead here = ahead[i % kAhead];
    if (i + kAhead < n) fetch(i + kAhead);
    visit(i, here.key, here.hash);
  }
}

/// Welds a sequence of n points, point(i) for i in order: each point not yet in `table` is
/// appended to `vertices` (and to the table), and found(i, its vertex) is called for every point.
template <class Point, class Found>
void weld_sequence(std::size_t n, const Point& point, VertexTable& table,
                   std::vector<Vec3>& vertices, const Found& found) {
  visit_keys_ahead(n, point, table, [&](std::size_t i, const PointKey& key, std::size_t hash) {
    const auto [vertex, inserted] =
        table.find_or_insert(key, hash, vertices, static_cast<VertexIndex>(vertices.size()));
    if (inserted) {
      STRATA_ASSERT(vertices.size() < std::numeric_limits<VertexIndex>::max(),
                    "more distinct vertices than VertexIndex can number");
      vertices.push_back(point(i));
    }
    found(i, vertex);
  });
}

/// Facets [begin, end) of the soup welded into `vertices`, each facet's vertices written to
/// triangles[f].
void weld_facets(const TriangleSoup& soup, std::size_t begin, std::size_t end, VertexTable& table,
                 std::vector<Vec3>& vertices, std::array<VertexIndex, 3>* triangles) {
  const auto corner = [&](std::size_t i) -> const Vec3& {
    return soup.triangles[begin + i / 3][i % 3];
  };
  weld_sequence(3 * (end - begin), corner, table, vertices,
                [&](std::size_t i, VertexIndex v) { triangles[begin + i / 3][i % 3] = v; });
}

}  // namespace

namespace detail {

IndexedMesh weld_vertices_in_blocks(const TriangleSoup& soup, std::size_t blocks) {
  const std::size_t facets = soup.triangles.size();
  blocks = std::clamp<std::size_t>(blocks, 1, std::max<std::size_t>(facets, 1));
  IndexedMesh mesh;
  reserve_huge_pages(mesh.vertices, expected_vertices(facets));
  reserve_huge_pages(mesh.triangles, facets);
  mesh.triangles.resize(facets);
  VertexTable table(expected_vertices(facets));
  if (blocks == 1) {
    weld_facets(soup, 0, facets, table, mesh.vertices, mesh.triangles.data());
    return mesh;
  }
  // The facets in consecutive blocks, each welded on its own (the first into the mesh, the
  // others into vertices of their own, numbered from 0), side by side. The vertices are then
  // numbered in order of first appearance, as one weld of the whole would: block b's vertices,
  // in their own order, are welded into the mesh's after those of the blocks before it, each
  // found there or appended; a block's vertices are far fewer than its corners. Last, each
  // block's facets take the mesh's numbers for its own.
  // Block b starts at b q + min(b, r): q or q + 1 facets a block, at least one.
  const std::size_t q = facets / blocks, r = facets % blocks;
  const auto first_facet = [&](std::size_t b) { return b * q + std::min(b, r); };
  std::vector<std::vector<Vec3>> own_vertices(blocks);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    const std::size_t begin = first_facet(b), end = first_facet(b + 1);
    if (b == 0) {
      weld_facets(soup, begin, end, table, mesh.vertices, mesh.triangles.data());
      return;
    }
    VertexTable own_table(expected_vertices(end - begin));
    own_vertices[b].reserve(expected_vertices(end - begin));
    weld_facets(soup, begin, end, own_table, own_vertices[b], mesh.triangles.data());
  });
  std::vector<std::vector<VertexIndex>> number_of(blocks);
  const std::size_t last = blocks - 1;
  for (std::size_t b = 1; b < last; ++b) {
    const std::vector<Vec3>& own = own_vertices[b];
    number_of[b].resize(own.size());
    weld_sequence(
        own.size(), [&](std::size_t i) -> const Vec3& { return own[i]; }, table, mesh.vertices,
        [&](std::size_t i, VertexIndex v) { number_of[b][i] = v; });
    std::vector<Vec3>().swap(own_vertices[b]);
  }
  // The last block, on the threads (on two threads, half the vertices rather than a few): no
  // block after it looks its vertices up, so the table is only read. Its vertices the mesh
  // already has are found side by side; the others, distinct (its own weld merged them), are
  // new to the mesh and are appended in their own order, as welding them in turn would append
  // them. Each stretch counts its new vertices, then numbers them from the count before it.
  {
    const std::vector<Vec3>& own = own_vertices[last];
    std::vector<VertexIndex>& numbers = number_of[last];
    numbers.resize(own.size());
    constexpr std::size_t kStretch = 1 << 14;
    const std::size_t stretches = (own.size() + kStretch - 1) / kStretch;
    const auto stretch_end = [&](std::size_t k) {
      return std::min(own.size(), (k + 1) * kStretch);
    };
    std::vector<std::size_t> new_before(stretches + 1, 0);
    tbb::parallel_for(std::size_t{0}, stretches, [&](std::size_t k) {
      // Plain variables: clang 14 does not let a lambda capture a structured binding.
      const std::size_t begin = k * kStretch;
      const std::size_t end = stretch_end(k);
      std::size_t found_new = 0;
      visit_keys_ahead(
          end - begin, [&](std::size_t i) -> const Vec3& { return own[begin + i]; }, table,
          [&](std::size_t i, const PointKey& key, std::size_t hash) {
            const VertexIndex v = table.find(key, hash, mesh.vertices);
            numbers[begin + i] = v;
            found_new += v == VertexTable::kAbsent ? 1 : 0;
          });
      new_before[k + 1] = found_new;
    });
    std::partial_sum(new_before.begin(), new_before.end(), new_before.begin());
    const std::size_t had = mesh.vertices.size();
    STRATA_ASSERT(had + new_before[stretches] < std::numeric_limits<VertexIndex>::max(),
                  "more distinct vertices than VertexIndex can number");
    mesh.vertices.resize(had + new_before[stretches]);
    tbb::parallel_for(std::size_t{0}, stretches, [&](std::size_t k) {
      const std::size_t end = stretch_end(k);
      auto next = static_cast<VertexIndex>(had + new_before[k]);
      for (std::size_t i = k * kStretch; i < end; ++i) {
        if (numbers[i] != VertexTable::kAbsent) continue;
        mesh.vertices[next] = own[i];
        numbers[i] = next++;
      }
    });
    std::vector<Vec3>().swap(own_vertices[last]);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first_facet(1), facets, 4096),
                    [&](const auto& range) {
                      // The block of the range's first facet, then each next one as the range
                      // reaches it.
                      std::size_t b = 1;
                      while (first_facet(b + 1) <= range.begin()) ++b;
                      std::size_t block_end = first_facet(b + 1);
                      for (std::size_t f = range.begin(); f < range.end(); ++f) {
                        if (f == block_end) block_end = first_facet(++b + 1);
                        for (VertexIndex& v : mesh.triangles[f]) v = number_of[b][v];
                      }
                    });
  return mesh;
}

}  // namespace detail

IndexedMesh weld_vertices(const TriangleSoup& soup) {
  // Blocks of at least kFacetsABlock facets, one a thread: below that, the numbering pass and the
  // tables' set-up cost more than the threads save.
  constexpr std::size_t kFacetsABlock = 1 << 16;
  return detail::weld_vertices_in_blocks(
      soup,
      std::min(usable_threads(), std::max<std::size_t>(soup.triangles.size() / kFacetsABlock, 1)));
}

}  // namespace strata
