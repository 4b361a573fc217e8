#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "repair/repair_internal.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::repair::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

/// Passes of the T-junction step; one pass closes every crack whose edges no other crack of the
/// same pass uses, so more than two or three are rare.
constexpr int kMaxTJunctionPasses = 8;
/// Vertices a chain search may visit from one open edge (chains are short; this bounds the search
/// on pathological fans of collinear open edges).
constexpr int kMaxChainVisits = 256;

std::uint64_t edge_key(VertexIndex a, VertexIndex b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

using Triple = std::array<VertexIndex, 3>;

struct TripleHash {
  std::size_t operator()(const Triple& t) const {
    std::uint64_t h = 1469598103934665603ull;
    for (const VertexIndex v : t) h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

Triple sorted(Triple t) {
  std::sort(t.begin(), t.end());
  return t;
}

/// True when (a, b, c) is an even permutation of its sorted order: two facets with the same
/// vertices have the same orientation exactly when their parities agree.
bool even_order(const Triple& t) {
  int inversions = 0;
  inversions += t[0] > t[1];
  inversions += t[0] > t[2];
  inversions += t[1] > t[2];
  return inversions % 2 == 0;
}

/// Step 2: zero-area facets, by the exact collinearity of their corners.
void remove_degenerate(const std::vector<Point>& points, std::vector<WorkFacet>& facets,
                       CleanSoup& out, RepairLog& log) {
  std::vector<WorkFacet> kept;
  kept.reserve(facets.size());
  for (const WorkFacet& f : facets) {
    const bool degenerate = f.v[0] == f.v[1] || f.v[1] == f.v[2] || f.v[0] == f.v[2] ||
                            CGAL::collinear(points[f.v[0]], points[f.v[1]], points[f.v[2]]);
    if (degenerate) {
      out.changes.push_back({f.origin, FacetChangeKind::RemovedDegenerate});
      ++log.degenerate_facets_removed;
    } else {
      kept.push_back(f);
    }
  }
  facets = std::move(kept);
}

/// Step 3: one copy of each set of facets with the same vertices, or none when the copies cancel
/// and removing the last one leaves no edge used by a single facet.
void remove_duplicates(std::vector<WorkFacet>& facets, CleanSoup& out, RepairLog& log) {
  const std::size_t n = facets.size();
  std::vector<Triple> keys(n);
  for (std::size_t i = 0; i < n; ++i) keys[i] = sorted(facets[i].v);
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });

  std::vector<bool> removed(n, false);
  std::vector<std::uint32_t> cancelling;  // kept copies of sets whose orientations cancel
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin + 1;
    while (end < n && keys[order[end]] == keys[order[begin]]) ++end;
    if (end - begin > 1) {
      // `order` keeps input order within a set (stable sort), so order[begin] is the first copy.
      const bool first_parity = even_order(facets[order[begin]].v);
      std::size_t same = 0;
      std::uint32_t first_reverse = 0;
      bool seen_reverse = false;
      for (std::size_t k = begin; k < end; ++k) {
        if (even_order(facets[order[k]].v) == first_parity) {
          ++same;
        } else if (!seen_reverse) {
          first_reverse = order[k];
          seen_reverse = true;
        }
      }
      const std::size_t reverse = (end - begin) - same;
      const std::uint32_t keep = reverse > same ? first_reverse : order[begin];
      for (std::size_t k = begin; k < end; ++k) {
        if (order[k] == keep) continue;
        removed[order[k]] = true;
        out.changes.push_back({facets[order[k]].origin, FacetChangeKind::RemovedDuplicate});
        ++log.duplicate_facets_removed;
      }
      if (reverse == same) cancelling.push_back(keep);
    }
    begin = end;
  }

  if (!cancelling.empty()) {
    // The copies of a cancelling set add nothing to the winding number. Removing the last one too
    // is right where the facet's edges stay closed without it (two solids touching along it), and
    // would open a hole otherwise. All of them are taken out, then those that leave an edge used
    // once are put back until none does (putting one back can only close edges or open edges of
    // other removed facets, which are then put back too).
    std::unordered_map<std::uint64_t, std::uint32_t> uses;
    uses.reserve(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
      if (removed[i]) continue;
      for (int c = 0; c < 3; ++c) ++uses[edge_key(facets[i].v[c], facets[i].v[(c + 1) % 3])];
    }
    std::sort(cancelling.begin(), cancelling.end());
    for (const std::uint32_t i : cancelling) {
      const auto& v = facets[i].v;
      for (int c = 0; c < 3; ++c) --uses[edge_key(v[c], v[(c + 1) % 3])];
    }
    std::vector<bool> put_back(cancelling.size(), false);
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t k = 0; k < cancelling.size(); ++k) {
        if (put_back[k]) continue;
        const auto& v = facets[cancelling[k]].v;
        bool opens = false;
        for (int c = 0; c < 3; ++c) opens |= uses[edge_key(v[c], v[(c + 1) % 3])] == 1;
        if (!opens) continue;
        for (int c = 0; c < 3; ++c) ++uses[edge_key(v[c], v[(c + 1) % 3])];
        put_back[k] = true;
        changed = true;
      }
    }
    for (std::size_t k = 0; k < cancelling.size(); ++k) {
      if (put_back[k]) continue;
      removed[cancelling[k]] = true;
      out.changes.push_back(
          {facets[cancelling[k]].origin, FacetChangeKind::RemovedCancellingDuplicate});
      ++log.cancelling_duplicates_removed;
    }
  }

  std::vector<WorkFacet> kept;
  kept.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!removed[i]) kept.push_back(facets[i]);
  }
  facets = std::move(kept);
}

/// Finds a chain of open edges a = p0, p1, ..., pk = b (k >= 2) whose inner vertices lie strictly
/// between their predecessor and b on the segment a-b (exact predicates), none of its edges
/// consumed. Depth first, neighbours in increasing index order.
class ChainSearch {
 public:
  ChainSearch(const std::vector<Point>& points,
              const std::unordered_map<VertexIndex, std::vector<VertexIndex>>& open_neighbours,
              const std::unordered_set<std::uint64_t>& consumed)
      : points_(points), open_neighbours_(open_neighbours), consumed_(consumed) {}

  /// The chain from a to b, both included, or an empty vector.
  std::vector<VertexIndex> find(VertexIndex a, VertexIndex b) {
    a_ = a;
    b_ = b;
    visits_ = 0;
    path_.assign(1, a);
    if (!extend(a)) path_.clear();
    return path_;
  }

 private:
  bool extend(VertexIndex current) {
    if (++visits_ > kMaxChainVisits) return false;
    const auto it = open_neighbours_.find(current);
    if (it == open_neighbours_.end()) return false;
    for (const VertexIndex next : it->second) {
      if (consumed_.count(edge_key(current, next))) continue;
      if (next == b_) {
        if (current == a_) continue;  // the edge a-b itself
        path_.push_back(b_);
        return true;
      }
      // collinear_are_strictly_ordered_along_line presumes collinear points.
      if (!CGAL::collinear(points_[current], points_[next], points_[b_]) ||
          !CGAL::collinear_are_strictly_ordered_along_line(points_[current], points_[next],
                                                           points_[b_])) {
        continue;
      }
      path_.push_back(next);
      if (extend(next)) return true;
      path_.pop_back();
    }
    return false;
  }

  const std::vector<Point>& points_;
  const std::unordered_map<VertexIndex, std::vector<VertexIndex>>& open_neighbours_;
  const std::unordered_set<std::uint64_t>& consumed_;
  VertexIndex a_ = 0;
  VertexIndex b_ = 0;
  int visits_ = 0;
  std::vector<VertexIndex> path_;
};

/// Step 4: cracks at T-junctions. An edge used by one facet only (open) whose end points are joined
/// by a chain of open edges along the same segment is closed by splitting its facet at the chain's
/// vertices; the pieces cover the same triangle with the same orientation.
void close_t_junctions(const std::vector<Point>& points, std::vector<WorkFacet>& facets,
                       std::size_t num_input_facets, CleanSoup& out, RepairLog& log) {
  std::vector<bool> recorded(num_input_facets, false);
  for (int pass = 0; pass < kMaxTJunctionPasses; ++pass) {
    std::unordered_map<std::uint64_t, std::uint32_t> uses;
    uses.reserve(3 * facets.size());
    for (const WorkFacet& f : facets) {
      for (int c = 0; c < 3; ++c) ++uses[edge_key(f.v[c], f.v[(c + 1) % 3])];
    }
    std::unordered_map<VertexIndex, std::vector<VertexIndex>> open_neighbours;
    for (const auto& [key, count] : uses) {
      if (count != 1) continue;
      const auto lo = static_cast<VertexIndex>(key >> 32);
      const auto hi = static_cast<VertexIndex>(key & 0xffffffffu);
      open_neighbours[lo].push_back(hi);
      open_neighbours[hi].push_back(lo);
    }
    if (open_neighbours.empty()) return;
    for (auto& [v, list] : open_neighbours) std::sort(list.begin(), list.end());

    std::unordered_set<Triple, TripleHash> existing;
    existing.reserve(facets.size());
    for (const WorkFacet& f : facets) existing.insert(sorted(f.v));

    std::unordered_set<std::uint64_t> consumed;
    ChainSearch search(points, open_neighbours, consumed);
    std::vector<WorkFacet> next;
    next.reserve(facets.size());
    bool changed = false;
    for (const WorkFacet& f : facets) {
      bool split = false;
      for (int c = 0; c < 3 && !split; ++c) {
        const VertexIndex a = f.v[c];
        const VertexIndex b = f.v[(c + 1) % 3];
        const VertexIndex x = f.v[(c + 2) % 3];
        if (uses[edge_key(a, b)] != 1 || consumed.count(edge_key(a, b))) continue;
        const std::vector<VertexIndex> chain = search.find(a, b);
        if (chain.empty()) continue;
        // A piece that repeats an existing facet would fold the surface onto itself: leave it.
        bool repeats = false;
        for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
          repeats |= existing.count(sorted({chain[k], chain[k + 1], x})) > 0;
        }
        if (repeats) continue;
        consumed.insert(edge_key(a, b));
        for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
          consumed.insert(edge_key(chain[k], chain[k + 1]));
          const WorkFacet piece{{chain[k], chain[k + 1], x}, f.origin, true};
          existing.insert(sorted(piece.v));
          next.push_back(piece);
        }
        ++log.t_junctions_closed;
        log.t_junction_facets_added += chain.size() - 2;
        if (!recorded[f.origin]) {
          recorded[f.origin] = true;
          out.changes.push_back({f.origin, FacetChangeKind::SplitAtTJunction});
        }
        split = true;
      }
      if (!split) next.push_back(f);
      changed |= split;
    }
    facets = std::move(next);
    if (!changed) return;
  }
}

}  // namespace

CleanSoup clean_soup(const TriangleSoup& soup, const RepairOptions& options, RepairLog& log) {
  CleanSoup out;
  const IndexedMesh welded = weld_vertices(soup);
  log.input_facets = soup.triangles.size();
  log.input_vertices = welded.vertices.size();
  log.points_merged = 3 * soup.triangles.size() - welded.vertices.size();

  std::vector<Point> points;
  points.reserve(welded.vertices.size());
  for (const Vec3& p : welded.vertices) points.emplace_back(p.x, p.y, p.z);

  std::vector<WorkFacet> facets(welded.triangles.size());
  for (std::size_t i = 0; i < facets.size(); ++i) {
    facets[i] = {welded.triangles[i], static_cast<FacetIndex>(i)};
  }
  remove_degenerate(points, facets, out, log);
  remove_duplicates(facets, out, log);
  if (options.close_t_junctions) {
    close_t_junctions(points, facets, soup.triangles.size(), out, log);
  }
  out.vertices = welded.vertices;
  out.facets = std::move(facets);
  return out;
}

}  // namespace strata::repair::detail
