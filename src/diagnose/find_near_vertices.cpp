#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include "core/usable_threads.hpp"
#include "diagnose/find_near_vertices_internal.hpp"

namespace strata::diagnose::detail {
namespace {

struct CellKey {
  std::int64_t x, y, z;
  friend bool operator==(const CellKey&, const CellKey&) = default;
};

std::uint64_t hash_of(const CellKey& k) {
  std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ULL;
  h ^= static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4FULL + (h << 6) + (h >> 2);
  h ^= static_cast<std::uint64_t>(k.z) * 0x165667B19E3779F9ULL + (h << 6) + (h >> 2);
  // The high bits mixed down: the table takes the low ones.
  return h ^ (h >> 29);
}

std::int64_t cell_coordinate(double offset, double cell) {
  // Clamped so that absurd tolerances cannot overflow; clamping only merges far cells, which
  // costs time, never a missed pair.
  const double q = std::floor(offset / cell);
  constexpr double kLimit = 4.0e18;
  return static_cast<std::int64_t>(std::clamp(q, -kLimit, kLimit));
}

/// A vertex and its cell, sorted by cell and then vertex.
struct Entry {
  CellKey cell;
  VertexIndex vertex;
};

/// The occupied cells, each a run of the sorted entries, found by their key: open addressing over
/// a power-of-two table at most half full, each slot holding its cell's key and run. Most cells a
/// ball meets hold no vertex, and a probe of the table for one reads memory the caches do not
/// hold: a filter of 16 bits an occupied cell (a bit set at another hash of each), small enough
/// for the caches, answers for nearly all of those first. (A node-based map's lookups that missed
/// took most of a million-vertex model's search.)
class CellRuns {
 public:
  explicit CellRuns(const std::vector<Entry>& entries) {
    std::size_t cells = 0;
    for (std::size_t k = 0; k < entries.size(); ++k) {
      cells += k == 0 || !(entries[k].cell == entries[k - 1].cell) ? 1 : 0;
    }
    std::size_t capacity = 64;
    while (capacity < 2 * cells) capacity *= 2;
    mask_ = capacity - 1;
    slots_.resize(capacity);
    taken_.assign(capacity / 64, 0);
    filter_mask_ = 8 * capacity - 1;
    filter_.assign(8 * capacity / 64, 0);
    for (std::size_t begin = 0; begin < entries.size();) {
      std::size_t end = begin + 1;
      while (end < entries.size() && entries[end].cell == entries[begin].cell) ++end;
      const std::uint64_t hash = hash_of(entries[begin].cell);
      std::size_t i = hash & mask_;
      while (is_set(taken_, i)) i = (i + 1) & mask_;
      slots_[i] = {entries[begin].cell, static_cast<std::uint32_t>(begin),
                   static_cast<std::uint32_t>(end)};
      set(taken_, i);
      set(filter_, filter_bit(hash));
      begin = end;
    }
  }

  /// The entries of `cell`, [first, last); empty when no vertex is in it.
  std::pair<std::size_t, std::size_t> find(const CellKey& cell) const {
    const std::uint64_t hash = hash_of(cell);
    if (!is_set(filter_, filter_bit(hash))) return {0, 0};
    for (std::size_t i = hash & mask_; is_set(taken_, i); i = (i + 1) & mask_) {
      if (slots_[i].cell == cell) return {slots_[i].begin, slots_[i].end};
    }
    return {0, 0};
  }

 private:
  struct Slot {
    CellKey cell{};
    std::uint32_t begin = 0;  // entries are vertices, numbered on 32 bits
    std::uint32_t end = 0;
  };

  static bool is_set(const std::vector<std::uint64_t>& bits, std::size_t i) {
    return (bits[i / 64] >> (i % 64) & 1U) != 0;
  }
  static void set(std::vector<std::uint64_t>& bits, std::size_t i) {
    bits[i / 64] |= std::uint64_t{1} << (i % 64);
  }
  /// The filter's bit: from the hash's high bits, where the table's slot is from its low ones.
  std::size_t filter_bit(std::uint64_t hash) const { return (hash >> 32) & filter_mask_; }

  std::size_t mask_ = 0;
  std::vector<Slot> slots_;
  std::vector<std::uint64_t> taken_;  ///< a bit a slot
  std::size_t filter_mask_ = 0;
  std::vector<std::uint64_t> filter_;  ///< 8 bits a slot, 16 an occupied cell at the most
};

/// What a stretch of vertices found: its checks (at most its budget), whether it had more to
/// check, how many pairs, and the first few of them.
struct Found {
  std::size_t checks = 0;
  bool ran_out = false;
  std::size_t count = 0;
  std::vector<PointPair> first;
};

}  // namespace

NearVertices find_near_vertices(const IndexedMesh& mesh, const Bbox3& bounds, double tolerance,
                                std::size_t max_checks, std::size_t limit) {
  const std::size_t nv = mesh.vertices.size();
  const double cell = 2.0 * tolerance;
  const auto offset = [&](const Vec3& p) {
    return Vec3{p.x - bounds.min.x, p.y - bounds.min.y, p.z - bounds.min.z};
  };
  std::vector<Entry> entries(nv);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const Vec3 o = offset(mesh.vertices[i]);
      entries[i] = {
          {cell_coordinate(o.x, cell), cell_coordinate(o.y, cell), cell_coordinate(o.z, cell)},
          static_cast<VertexIndex>(i)};
    }
  });
  // A total order (the vertex breaks ties): any sort gives the one result.
  tbb::parallel_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.cell.x, a.cell.y, a.cell.z, a.vertex) <
           std::tie(b.cell.x, b.cell.y, b.cell.z, b.vertex);
  });
  const CellRuns runs(entries);

  const double tolerance2 = tolerance * tolerance;
  // Vertices [begin, end) in order, each checked against the higher vertices of the cells its
  // ball meets, until `budget` checks are spent (the next check would exceed it).
  const auto scan = [&](std::size_t begin, std::size_t end, std::size_t budget, std::size_t keep) {
    Found found;
    for (std::size_t i = begin; i < end && !found.ran_out; ++i) {
      const Vec3& p = mesh.vertices[i];
      const Vec3 o = offset(p);
      const CellKey lo{cell_coordinate(o.x - tolerance, cell),
                       cell_coordinate(o.y - tolerance, cell),
                       cell_coordinate(o.z - tolerance, cell)};
      const CellKey hi{cell_coordinate(o.x + tolerance, cell),
                       cell_coordinate(o.y + tolerance, cell),
                       cell_coordinate(o.z + tolerance, cell)};
      for (std::int64_t cx = lo.x; cx <= hi.x && !found.ran_out; ++cx) {
        for (std::int64_t cy = lo.y; cy <= hi.y && !found.ran_out; ++cy) {
          for (std::int64_t cz = lo.z; cz <= hi.z && !found.ran_out; ++cz) {
            const auto [first, last] = runs.find({cx, cy, cz});
            for (std::size_t s = first; s < last; ++s) {
              const VertexIndex j = entries[s].vertex;
              if (j <= i) continue;  // each pair once, from its lower vertex
              if (found.checks == budget) {
                found.ran_out = true;
                break;
              }
              ++found.checks;
              const Vec3& q = mesh.vertices[j];
              const double ex = q.x - p.x, ey = q.y - p.y, ez = q.z - p.z;
              if (ex * ex + ey * ey + ez * ez < tolerance2) {
                if (found.first.size() < keep) found.first.push_back({p, q});
                ++found.count;
              }
            }
          }
        }
      }
    }
    return found;
  };

  // The vertices in stretches on the threads, a round of them at a time, each stretch with the
  // checks left before the round: the work stays within a round's stretches times the limit.
  // Their findings are then taken in order; the stretch where the checks run out is scanned again
  // with what is left of them, and ends the search where scanning in one pass would.
  constexpr std::size_t kVerticesAStretch = 8192;
  const std::size_t stretches_a_round = 4 * std::max<std::size_t>(usable_threads(), 1);
  const std::size_t stretches = (nv + kVerticesAStretch - 1) / kVerticesAStretch;
  const auto scan_stretch = [&](std::size_t k, std::size_t budget, std::size_t keep) {
    return scan(k * kVerticesAStretch, std::min(nv, (k + 1) * kVerticesAStretch), budget, keep);
  };
  NearVertices out;
  std::size_t checks_left = max_checks;
  for (std::size_t round = 0; round < stretches && !out.truncated; round += stretches_a_round) {
    const std::size_t round_end = std::min(stretches, round + stretches_a_round);
    std::vector<Found> found(round_end - round);
    const std::size_t keep = limit - out.pairs.locations.size();
    tbb::parallel_for(round, round_end, [&](std::size_t k) {
      found[k - round] = scan_stretch(k, checks_left, keep);
    });
    for (std::size_t k = round; k < round_end; ++k) {
      Found& here = found[k - round];
      if (here.ran_out || here.checks > checks_left) {
        here = scan_stretch(k, checks_left, limit - out.pairs.locations.size());
      }
      checks_left -= here.checks;
      out.pairs.count += here.count;
      const std::size_t room = limit - out.pairs.locations.size();
      out.pairs.locations.insert(
          out.pairs.locations.end(), here.first.begin(),
          here.first.begin() + static_cast<std::ptrdiff_t>(std::min(room, here.first.size())));
      if (here.ran_out) {
        out.truncated = true;
        break;
      }
    }
  }
  return out;
}

}  // namespace strata::diagnose::detail
