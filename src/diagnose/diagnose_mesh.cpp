#include "strata/diagnose/diagnose_mesh.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/group_by_key.hpp"
#include "core/huge_pages.hpp"
#include "diagnose/exact_geometry.hpp"
#include "diagnose/find_near_vertices_internal.hpp"
#include "diagnose/find_self_intersections_internal.hpp"
#include "strata/core/error.hpp"

namespace strata::diagnose {

const char* verdict_name(Verdict verdict) {
  switch (verdict) {
    case Verdict::Printable:
      return "printable";
    case Verdict::PrintableUnderRule:
      return "printable-under-rule";
    case Verdict::NeedsRepair:
      break;
  }
  // The last case shares the return after the switch: no line is left that no value reaches.
  return "needs-repair";
}

namespace {

/// Which occurrences FirstOccurrences keeps, the `limit` with the smallest keys (ties: first
/// added), and how many there were. Not a template, so that coverage counts its branches once
/// rather than once for each type of location.
class FirstKeys {
 public:
  /// Called to put the kept locations in a new order: slot order[i] becomes slot i + 1.
  using Reorder = void (*)(void* owner, std::span<const std::size_t> order);

  explicit FirstKeys(std::size_t limit) : limit_(limit) {}

  /// Counts an occurrence with `key`; returns the slot its location goes to (1, 2, ...), or 0,
  /// a slot of scratch, when it cannot be among the first.
  std::size_t add(std::uint64_t key, Reorder reorder, void* owner) {
    ++count_;
    if (items_.size() >= 4 * std::max<std::size_t>(limit_, 1)) trim(reorder, owner);
    // Keys mostly come in increasing order: once `limit` are kept, a key after them all cannot
    // be among the first (ties keep the first added), and a million defects cost no sorts.
    if (sorted_ && items_.size() >= limit_ && (items_.empty() || key >= items_.back().first)) {
      return 0;
    }
    if (!items_.empty() && key < items_.back().first) sorted_ = false;
    items_.push_back({key, items_.size() + 1});
    return items_.size();
  }

  /// The slots in use, scratch included.
  std::size_t slots() const { return items_.size() + 1; }
  std::size_t count() const { return count_; }

  void trim(Reorder reorder, void* owner) {
    std::stable_sort(items_.begin(), items_.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    if (items_.size() > limit_) items_.resize(limit_);
    std::vector<std::size_t> order(items_.size());
    for (std::size_t i = 0; i < items_.size(); ++i) {
      order[i] = items_[i].second;
      items_[i].second = i + 1;
    }
    reorder(owner, order);
    sorted_ = true;
  }

 private:
  std::size_t limit_;
  std::size_t count_ = 0;
  bool sorted_ = true;  ///< items_ are in increasing order of their keys
  std::vector<std::pair<std::uint64_t, std::size_t>> items_;  ///< key, slot
};

/// Counts occurrences and keeps the locations of the `limit` with the smallest keys (ties: first
/// added). Its own code has no branch: FirstKeys decides.
template <class T>
class FirstOccurrences {
 public:
  explicit FirstOccurrences(std::size_t limit) : keys_(limit), locations_(1) {}

  void add(std::uint64_t key, const T& location) {
    const std::size_t slot = keys_.add(key, &reorder, this);
    locations_.resize(keys_.slots());
    locations_[slot] = location;
  }

  Occurrences<T> finish() {
    keys_.trim(&reorder, this);
    Occurrences<T> out;
    out.count = keys_.count();
    out.locations.assign(std::make_move_iterator(locations_.begin() + 1),
                         std::make_move_iterator(locations_.end()));
    return out;
  }

 private:
  static void reorder(void* owner, std::span<const std::size_t> order) {
    auto& self = *static_cast<FirstOccurrences*>(owner);
    std::vector<T> kept(order.size() + 1);
    std::transform(order.begin(), order.end(), kept.begin() + 1,
                   [&](std::size_t slot) { return std::move(self.locations_[slot]); });
    self.locations_ = std::move(kept);
  }

  FirstKeys keys_;
  std::vector<T> locations_;  ///< by slot; slot 0 is scratch
};

/// The i where codes[i] == wanted, listed as FirstOccurrences lists them when they are added in
/// increasing order of i: the first `limit` (location(i) each), and how many there are. A count
/// and a scan that stops early, where adding each occurrence in turn costs a call apiece.
template <class T, class Location>
Occurrences<T> occurrences_in_order(std::span<const std::uint8_t> codes, std::uint8_t wanted,
                                    std::size_t limit, const Location& location) {
  Occurrences<T> out;
  out.count = static_cast<std::size_t>(std::count(codes.begin(), codes.end(), wanted));
  for (std::size_t i = 0; i < codes.size() && out.locations.size() < std::min(limit, out.count);
       ++i) {
    if (codes[i] == wanted) out.locations.push_back(location(i));
  }
  return out;
}

/// What a facet's stored normal is found to be.
enum class NormalFinding : std::uint8_t { None, Flipped, Zero, NonFinite };

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) { reset(n); }

  /// Makes n singletons again, reusing the storage.
  void reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0U);
  }

  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    // The smaller index becomes the root, so a component's root is its lowest member.
    if (a < b) {
      parent_[b] = a;
    } else {
      parent_[a] = b;
    }
  }

 private:
  std::vector<std::uint32_t> parent_;
};

/// One use of an undirected edge by a facet.
struct EdgeUse {
  VertexIndex lo = 0;
  VertexIndex hi = 0;
  FacetIndex facet = 0;
  bool forward = false;  ///< the facet runs the edge from lo to hi
};

/// Items grouped by vertex: those of vertex v are items[start[v] .. start[v + 1]).
template <class Item>
struct ByVertex {
  std::vector<std::size_t> start;
  std::vector<Item> items;
};

/// The facets' items grouped by vertex: `emit(f, visit)` calls visit(vertex, item) for each item
/// of facet f, and a vertex's items keep the facets' order (a counting sort on the threads whose
/// result does not depend on their number).
template <class Item, class Emit>
ByVertex<Item> sort_by_vertex(std::size_t num_vertices, std::size_t num_facets, const Emit& emit) {
  ByVertex<Item> out;
  out.start = group_by_key<std::size_t>(num_vertices, num_facets, emit, [&](std::size_t total) {
    reserve_huge_pages(out.items, total);
    out.items.resize(total);
    return out.items.data();
  });
  return out;
}

/// Sorts a vertex's few items (a dozen about a vertex of a closed mesh) by insertion, where
/// std::sort's set-up costs more than the sort; many items by std::sort.
template <class Iterator, class Less = std::less<>>
void sort_few(Iterator first, Iterator last, Less less = {}) {
  constexpr std::ptrdiff_t kFew = 32;
  if (last - first > kFew) {
    std::sort(first, last, less);
    return;
  }
  for (Iterator i = first; i != last; ++i) {
    auto item = std::move(*i);
    Iterator j = i;
    for (; j != first && less(item, *(j - 1)); --j) *j = std::move(*(j - 1));
    *j = std::move(item);
  }
}

/// Each vertex's uses of the edges to higher vertices, one word a use: hi << 32 | facet << 1 |
/// forward, so that sorting the words sorts them by (hi, facet, forward). The lower vertex is the
/// group the word is in: half the memory of the four fields.
struct EdgeUses {
  std::vector<std::size_t> start;  ///< the uses of lower vertex v: words[start[v] .. start[v + 1])
  std::vector<std::uint64_t> words;

  static std::uint64_t word(VertexIndex hi, FacetIndex facet, bool forward) {
    return std::uint64_t{hi} << 32 | std::uint64_t{facet} << 1 | (forward ? 1U : 0U);
  }
  static VertexIndex hi_of(std::uint64_t word) { return static_cast<VertexIndex>(word >> 32); }
  static FacetIndex facet_of(std::uint64_t word) {
    return static_cast<FacetIndex>((word & 0xFFFFFFFFU) >> 1);
  }
  static EdgeUse use(VertexIndex lo, std::uint64_t word) {
    return {lo, hi_of(word), facet_of(word), (word & 1U) != 0};
  }
};

/// The edge uses of every facet not in `skip` (zero-length edges left out), grouped by lower
/// vertex and sorted by edge and then facet. A counting sort by the lower vertex, then a sort of
/// each vertex's few uses: linear but for those small sorts, and no copy of the uses.
EdgeUses collect_edge_uses(const IndexedMesh& mesh, const std::vector<bool>& skip) {
  ByVertex<std::uint64_t> by_lo = sort_by_vertex<std::uint64_t>(
      mesh.vertices.size(), mesh.triangles.size(), [&](std::size_t f, auto&& visit) {
        if (skip[f]) return;
        const auto& t = mesh.triangles[f];
        for (int c = 0; c < 3; ++c) {
          const VertexIndex a = t[c];
          const VertexIndex b = t[(c + 1) % 3];
          if (a == b) continue;  // a zero-length edge joins nothing
          visit(std::min(a, b), EdgeUses::word(std::max(a, b), static_cast<FacetIndex>(f), a < b));
        }
      });
  EdgeUses uses{std::move(by_lo.start), std::move(by_lo.items)};
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, mesh.vertices.size(), 4096), [&](const auto& range) {
        for (std::size_t v = range.begin(); v < range.end(); ++v) {
          sort_few(uses.words.begin() + static_cast<std::ptrdiff_t>(uses.start[v]),
                   uses.words.begin() + static_cast<std::ptrdiff_t>(uses.start[v + 1]));
        }
      });
  return uses;
}

/// Calls visit(first use, uses, forward uses) for each edge of `all`, in order of (lo, hi);
/// the first use is the lowest facet's.
template <class Visit>
void visit_edges(const EdgeUses& all, const Visit& visit) {
  const std::size_t nv = all.start.size() - 1;
  for (std::size_t lo = 0; lo < nv; ++lo) {
    const std::size_t stop = all.start[lo + 1];
    for (std::size_t begin = all.start[lo]; begin < stop;) {
      const std::uint64_t first = all.words[begin];
      std::size_t end = begin + 1;
      std::size_t forward = first & 1U;
      while (end < stop && EdgeUses::hi_of(all.words[end]) == EdgeUses::hi_of(first)) {
        forward += all.words[end] & 1U;
        ++end;
      }
      visit(EdgeUses::use(static_cast<VertexIndex>(lo), first), end - begin, forward);
      begin = end;
    }
  }
}

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  return 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
}

bool strictly_inside(const Bbox3& inner, const Bbox3& outer) {
  return outer.min.x < inner.min.x && outer.min.y < inner.min.y && outer.min.z < inner.min.z &&
         inner.max.x < outer.max.x && inner.max.y < outer.max.y && inner.max.z < outer.max.z;
}

/// Whether `facets` (a few, each holding vertex v once) run around v as one cycle, as about a
/// vertex of a closed, consistently oriented mesh. Each facet is taken as (v, after, before) in
/// its own orientation; the next is the one whose `after` is this one's `before`, and the walk
/// from the first comes back to it after visiting every facet. Consecutive facets share a corner
/// besides v, so they make one fan. False when that cannot be told so simply (more than 16 facets,
/// a walk that stops or closes early): the fans are then counted in general.
bool one_cycle_of_facets(const IndexedMesh& mesh, VertexIndex v,
                         std::span<const FacetIndex> facets) {
  constexpr std::size_t kMost = 16;
  const std::size_t n = facets.size();
  if (n > kMost) return false;
  // Facet k as (v, after[k], before[k]) in its own orientation.
  VertexIndex after[kMost];
  VertexIndex before[kMost];
  for (std::size_t k = 0; k < n; ++k) {
    const auto& t = mesh.triangles[facets[k]];
    const int at = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
    after[k] = t[(at + 1) % 3];
    before[k] = t[(at + 2) % 3];
  }
  std::size_t k = 0;
  for (std::size_t step = 1; step <= n; ++step) {
    std::size_t next = n;
    for (std::size_t j = 0; j < n; ++j) {
      if (after[j] == before[k]) {
        next = j;
        break;
      }
    }
    if (next == n) return false;
    k = next;
    if (k == 0) return step == n;
  }
  return false;
}

/// The facets with area around each vertex, in increasing order.
ByVertex<FacetIndex> facets_around_vertices(const IndexedMesh& mesh,
                                            const std::vector<bool>& degenerate) {
  return sort_by_vertex<FacetIndex>(mesh.vertices.size(), mesh.triangles.size(),
                                    [&](std::size_t f, auto&& visit) {
                                      if (degenerate[f]) return;
                                      for (VertexIndex v : mesh.triangles[f]) {
                                        visit(v, static_cast<FacetIndex>(f));
                                      }
                                    });
}

/// Vertices whose non-degenerate facets split into several fans (edge-connected around it), and
/// extra copies of a facet with area (same three vertices in any order). Each vertex is decided
/// on its own, a duplicate by the lowest of its vertices: the vertices are shared out among the
/// threads, and the findings listed in vertex and facet order after.
void find_vertex_defects_and_duplicates(const IndexedMesh& mesh,
                                        const std::vector<bool>& degenerate, std::size_t limit,
                                        MeshReport& report) {
  const std::size_t nv = mesh.vertices.size();
  const ByVertex<FacetIndex> around = facets_around_vertices(mesh, degenerate);
  std::vector<std::uint8_t> is_non_manifold(nv, 0);
  std::vector<std::uint8_t> is_duplicate(mesh.triangles.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 2048), [&](const auto& range) {
    std::vector<std::uint64_t> neighbours;  // other vertex << 32 | local facet
    std::vector<std::pair<std::uint64_t, FacetIndex>> lowest_here;  // (other two vertices, facet)
    UnionFind fans(0);
    for (std::size_t v = range.begin(); v < range.end(); ++v) {
      const std::size_t first = around.start[v];
      const std::size_t n = around.start[v + 1] - first;
      lowest_here.clear();
      for (std::size_t k = 0; k < n; ++k) {
        const FacetIndex f = around.items[first + k];
        auto t = mesh.triangles[f];
        // Three compare-exchanges put the corners in order.
        if (t[1] < t[0]) std::swap(t[0], t[1]);
        if (t[2] < t[1]) std::swap(t[1], t[2]);
        if (t[1] < t[0]) std::swap(t[0], t[1]);
        if (t[0] == v) lowest_here.push_back({(std::uint64_t{t[1]} << 32) | t[2], f});
      }
      if (lowest_here.size() > 1) {
        sort_few(lowest_here.begin(), lowest_here.end());  // copies follow their first, by facet
        for (std::size_t s = 1; s < lowest_here.size(); ++s) {
          if (lowest_here[s].first == lowest_here[s - 1].first)
            is_duplicate[lowest_here[s].second] = 1;
        }
      }
      if (n < 2 || one_cycle_of_facets(mesh, v, std::span(around.items).subspan(first, n))) {
        continue;
      }
      neighbours.clear();
      for (std::size_t k = 0; k < n; ++k) {
        for (VertexIndex w : mesh.triangles[around.items[first + k]]) {
          if (w != v) neighbours.push_back((std::uint64_t{w} << 32) | k);
        }
      }
      sort_few(neighbours.begin(), neighbours.end());
      fans.reset(n);
      for (std::size_t s = 1; s < neighbours.size(); ++s) {
        if ((neighbours[s] >> 32) == (neighbours[s - 1] >> 32)) {
          fans.unite(static_cast<std::uint32_t>(neighbours[s]),
                     static_cast<std::uint32_t>(neighbours[s - 1]));
        }
      }
      std::size_t num_fans = 0;
      for (std::uint32_t k = 0; k < n; ++k) num_fans += fans.find(k) == k ? 1 : 0;
      is_non_manifold[v] = num_fans > 1 ? 1 : 0;
    }
  });
  report.non_manifold_vertices = occurrences_in_order<Vec3>(
      is_non_manifold, 1, limit, [&](std::size_t v) { return mesh.vertices[v]; });
  report.duplicate_facets = occurrences_in_order<FacetIndex>(
      is_duplicate, 1, limit, [](std::size_t f) { return static_cast<FacetIndex>(f); });
}

std::string plural(std::size_t n, const char* singular, const char* plural_form) {
  return fmt::format("{} {}", n, n == 1 ? singular : plural_form);
}

void judge(MeshReport& r) {
  std::vector<std::string> reasons;
  if (r.num_facets == 0) {
    r.verdict = Verdict::NeedsRepair;
    r.verdict_reason = "the mesh has no facets";
    return;
  }
  const std::string open_edges =
      fmt::format("{} in {}", plural(r.boundary_edges.count, "open edge", "open edges"),
                  plural(r.num_boundary_loops, "loop", "loops"));
  const std::string inconsistent = plural(
      r.inconsistent_edges.count, "inconsistently oriented edge", "inconsistently oriented edges");
  if (!r.unbalanced_edges.empty()) {
    if (!r.boundary_edges.empty()) reasons.push_back(open_edges);
    if (!r.inconsistent_edges.empty()) reasons.push_back(inconsistent);
    if (reasons.empty()) {
      // Facets repeated without their counterpart, or open edges of zero-area facets.
      reasons.push_back(fmt::format("{} used more often in one direction than the other",
                                    plural(r.unbalanced_edges.count, "edge", "edges")));
    }
    r.verdict = Verdict::NeedsRepair;
    r.verdict_reason =
        fmt::format("{}: the inside of the solid is not defined there", fmt::join(reasons, "; "));
    return;
  }
  // Balanced over all facets, yet open or inconsistent among the facets with area: zero-area
  // facets seal the gaps (T-junctions), which the slicer's topology follows.
  if (!r.boundary_edges.empty()) reasons.push_back(open_edges + " sealed by zero-area facets");
  if (!r.inconsistent_edges.empty())
    reasons.push_back(inconsistent + " sealed by zero-area facets");
  if (!r.duplicate_facets.empty()) {
    reasons.push_back(plural(r.duplicate_facets.count, "duplicate facet", "duplicate facets"));
  }
  if (!r.degenerate_facets.empty()) {
    reasons.push_back(plural(r.degenerate_facets.count, "degenerate facet", "degenerate facets"));
  }
  if (!r.non_manifold_edges.empty()) {
    reasons.push_back(
        plural(r.non_manifold_edges.count, "non-manifold edge", "non-manifold edges"));
  }
  if (!r.non_manifold_vertices.empty()) {
    reasons.push_back(
        plural(r.non_manifold_vertices.count, "non-manifold vertex", "non-manifold vertices"));
  }
  if (!r.self_intersections.empty()) {
    reasons.push_back(fmt::format("{}{}", r.self_intersections_truncated ? "at least " : "",
                                  plural(r.self_intersections.count, "self-intersecting facet pair",
                                         "self-intersecting facet pairs")));
  } else if (r.self_intersections_truncated) {
    reasons.push_back("self-intersection search cut short");
  }
  if (!r.inverted_shells.empty()) {
    reasons.push_back(plural(r.inverted_shells.count, "inverted shell", "inverted shells"));
  }
  if (!reasons.empty()) {
    r.verdict = Verdict::PrintableUnderRule;
    r.verdict_reason =
        fmt::format("{}; every edge is balanced, so the nonzero fill rule slices it as intended",
                    fmt::join(reasons, "; "));
    return;
  }
  r.verdict = Verdict::Printable;
  r.verdict_reason = fmt::format(
      "closed, consistently oriented and manifold, {}",
      r.self_intersections_checked ? "no self-intersections" : "self-intersections not checked");
}

}  // namespace

MeshReport diagnose_mesh(const IndexedMesh& mesh, const TriangleSoup& soup,
                         const DiagnoseOptions& options) {
  const std::size_t limit = options.max_locations;
  const std::size_t nf = mesh.triangles.size();
  const std::size_t nv = mesh.vertices.size();
  for (const auto& t : mesh.triangles) {
    STRATA_ASSERT(t[0] < nv && t[1] < nv && t[2] < nv, "facet refers to a missing vertex");
  }
  STRATA_ASSERT(nf <= 0x7FFFFFFFU, "facet indices are 31-bit (an edge use packs one with a bit)");

  MeshReport report;
  report.num_input_facets = soup.triangles.size();
  report.num_facets = nf;
  report.num_vertices = nv;
  report.bounds = mesh.bounds();

  // ---- facets: degenerate, area, duplicates
  std::vector<bool> degenerate(nf, false);
  {
    // The predicate and the facets' areas run in parallel; the areas are summed in facet order,
    // one result. A degenerate facet's is -1 (an area is +0 or more, or NaN on overflow): it is not
    // summed.
    const auto area_of = std::make_unique_for_overwrite<double[]>(nf);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nf, 4096), [&](const auto& range) {
      for (std::size_t f = range.begin(); f < range.end(); ++f) {
        const auto& t = mesh.triangles[f];
        const Vec3& a = mesh.vertices[t[0]];
        const Vec3& b = mesh.vertices[t[1]];
        const Vec3& c = mesh.vertices[t[2]];
        const bool flat =
            t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || detail::is_collinear(a, b, c);
        area_of[f] = flat ? -1.0 : triangle_area(a, b, c);
      }
    });
    FirstOccurrences<FacetIndex> found{limit};
    double area = 0.0;
    for (std::size_t f = 0; f < nf; ++f) {
      if (area_of[f] < 0.0) {
        degenerate[f] = true;
        found.add(f, static_cast<FacetIndex>(f));
      } else {
        area += area_of[f];
      }
    }
    report.degenerate_facets = found.finish();
    report.surface_area_mm2 = area;
  }
  // The checks below read the mesh and write fields of the report of their own: they run side
  // by side.
  const auto find_edges_and_shells = [&] {
    // ---- edges and shells
    // The reported topology is that of the facets with area: a zero-area facet bounds nothing, and
    // repair tools drop it first. The balance that decides whether the winding number is defined
    // takes every facet, since zero-area facets can seal cracks (T-junctions) for the slicer.
    const EdgeUses uses = collect_edge_uses(mesh, degenerate);
    UnionFind facet_sets(nf);
    for (std::size_t lo = 0; lo < nv; ++lo) {
      for (std::size_t s = uses.start[lo] + 1; s < uses.start[lo + 1]; ++s) {
        const std::uint64_t here = uses.words[s], before = uses.words[s - 1];
        if (EdgeUses::hi_of(here) == EdgeUses::hi_of(before)) {
          facet_sets.unite(EdgeUses::facet_of(here), EdgeUses::facet_of(before));
        }
      }
    }
    constexpr std::uint32_t kNone = 0xFFFFFFFFU;
    std::vector<std::uint32_t> shell_of_facet(nf, kNone);
    std::vector<std::uint32_t> shell_of_root(nf, kNone);
    std::vector<ShellReport> shells;
    for (std::size_t f = 0; f < nf; ++f) {
      if (degenerate[f]) continue;
      const std::uint32_t root = facet_sets.find(static_cast<std::uint32_t>(f));
      if (shell_of_root[root] == kNone) {
        shell_of_root[root] = static_cast<std::uint32_t>(shells.size());
        ShellReport shell;
        shell.first_facet = static_cast<FacetIndex>(f);
        shell.is_closed = true;
        shell.is_balanced = true;
        shells.push_back(shell);
      }
      shell_of_facet[f] = shell_of_root[root];
      ++shells[shell_of_facet[f]].num_facets;
    }
    const auto& v = mesh.vertices;
    const auto as_run = [&v](const EdgeUse& use) {
      return use.forward ? EdgeLocation{v[use.lo], v[use.hi]} : EdgeLocation{v[use.hi], v[use.lo]};
    };
    {
      FirstOccurrences<EdgeLocation> unbalanced{limit};
      const auto find_unbalanced = [&](const EdgeUse& first, std::size_t n, std::size_t forward) {
        if (2 * forward != n) unbalanced.add(first.facet, as_run(first));
      };
      FirstOccurrences<EdgeLocation> boundary{limit}, non_manifold{limit}, inconsistent{limit};
      std::vector<std::pair<VertexIndex, VertexIndex>> boundary_pairs;
      const auto judge_edge = [&](const EdgeUse& first, std::size_t n, std::size_t forward) {
        // `first` is the use by the lowest facet.
        ShellReport& shell = shells[shell_of_facet[first.facet]];
        if (n == 1) {
          boundary.add(first.facet, as_run(first));
          boundary_pairs.emplace_back(first.lo, first.hi);
        }
        if (n > 2) non_manifold.add(first.facet, {v[first.lo], v[first.hi]});
        if (n == 2 && forward != 1) inconsistent.add(first.facet, as_run(first));
        if (2 * forward != n) shell.is_balanced = false;
        if (n % 2 == 1) shell.is_closed = false;
      };
      if (report.degenerate_facets.empty()) {
        // Without degenerate facets every facet's uses are those already collected: one pass.
        visit_edges(uses, [&](const EdgeUse& first, std::size_t n, std::size_t forward) {
          find_unbalanced(first, n, forward);
          judge_edge(first, n, forward);
        });
      } else {
        visit_edges(collect_edge_uses(mesh, std::vector<bool>(nf, false)), find_unbalanced);
        visit_edges(uses, judge_edge);
      }
      report.unbalanced_edges = unbalanced.finish();
      report.boundary_edges = boundary.finish();
      report.non_manifold_edges = non_manifold.finish();
      report.inconsistent_edges = inconsistent.finish();

      // Boundary loops: connected components of the graph of boundary edges.
      std::vector<VertexIndex> ends;
      ends.reserve(2 * boundary_pairs.size());
      for (const auto& [a, b] : boundary_pairs) {
        ends.push_back(a);
        ends.push_back(b);
      }
      std::sort(ends.begin(), ends.end());
      ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
      const auto local = [&](VertexIndex x) {
        return static_cast<std::uint32_t>(std::lower_bound(ends.begin(), ends.end(), x) -
                                          ends.begin());
      };
      UnionFind loops(ends.size());
      for (const auto& [a, b] : boundary_pairs) loops.unite(local(a), local(b));
      std::size_t num_loops = 0;
      for (std::uint32_t k = 0; k < ends.size(); ++k) num_loops += loops.find(k) == k ? 1 : 0;
      report.num_boundary_loops = num_loops;
    }

    // ---- volumes and shell judgement
    {
      // Zero-area facets, in no shell, add exactly zero volume: they are left out.
      static_assert(kNone == detail::kNoGroup);
      const detail::ExactVolumes volumes =
          detail::exact_signed_volumes(mesh, shell_of_facet, shells.size());
      report.volume_mm3 = volumes.total_mm3;
      std::vector<std::size_t> positive;
      bool any_negative = false;
      for (std::size_t s = 0; s < shells.size(); ++s) {
        ShellReport& shell = shells[s];
        shell.signed_volume_mm3 = volumes.by_group_mm3[s];
        shell.is_balanced = shell.is_balanced && shell.is_closed;
        if (shell.is_closed) ++report.num_closed_shells;
        if (shell.is_balanced && shell.signed_volume_mm3 > 0.0) positive.push_back(s);
        if (shell.is_balanced && shell.signed_volume_mm3 < 0.0) any_negative = true;
      }
      // The shells' boxes serve the negative shells below alone: a mesh without one, as most
      // are, is spared a pass over every facet's corners.
      std::vector<Bbox3> shell_bounds;
      if (any_negative) {
        shell_bounds.resize(shells.size());
        for (std::size_t f = 0; f < nf; ++f) {
          if (shell_of_facet[f] == kNone) continue;
          for (VertexIndex x : mesh.triangles[f])
            shell_bounds[shell_of_facet[f]].add(mesh.vertices[x]);
        }
      }
      // A negative shell inside a positive one is the inner wall of a hollow part; the bounding
      // boxes decide, and the comparisons are capped for meshes made of very many shells.
      constexpr std::size_t kMaxContainmentTests = 50'000'000;
      std::size_t tests = 0;
      FirstOccurrences<std::size_t> inverted{limit};
      for (std::size_t s = 0; s < shells.size(); ++s) {
        ShellReport& shell = shells[s];
        if (!shell.is_balanced || !(shell.signed_volume_mm3 < 0.0)) continue;
        for (std::size_t p : positive) {
          if (++tests > kMaxContainmentTests) break;
          if (strictly_inside(shell_bounds[s], shell_bounds[p])) {
            shell.is_cavity = true;
            break;
          }
        }
        if (!shell.is_cavity) {
          shell.is_inverted = true;
          inverted.add(s, s);
        }
      }
      report.inverted_shells = inverted.finish();
    }
    report.shells = std::move(shells);
  };

  const auto find_vertex_defects = [&] {
    // ---- vertices
    find_vertex_defects_and_duplicates(mesh, degenerate, limit, report);
    if (!report.bounds.empty() && nv >= 2) {
      const Vec3 lo = report.bounds.min, hi = report.bounds.max;
      const double diagonal =
          std::sqrt((hi.x - lo.x) * (hi.x - lo.x) + (hi.y - lo.y) * (hi.y - lo.y) +
                    (hi.z - lo.z) * (hi.z - lo.z));
      const double tolerance = options.near_vertex_mm.value_or(1e-6 * diagonal);
      report.near_vertex_tolerance_mm = tolerance;
      if (tolerance > 0.0 && std::isfinite(tolerance)) {
        detail::NearVertices near = detail::find_near_vertices(
            mesh, report.bounds, tolerance, options.max_near_vertex_checks, limit);
        report.near_vertices = std::move(near.pairs);
        report.near_vertices_truncated = near.truncated;
      }
    }
  };

  const auto check_stored_normals = [&] {
    // ---- stored normals
    if (!soup.stored_normals.empty() && soup.stored_normals.size() == nf) {
      report.normals_checked = true;
      // Each facet's finding on the threads, listed in facet order after: many files store a
      // zero normal for every facet.
      const auto finding = std::make_unique_for_overwrite<std::uint8_t[]>(nf);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nf, 4096), [&](const auto& range) {
        for (std::size_t f = range.begin(); f < range.end(); ++f) {
          const Vec3& n = soup.stored_normals[f];
          NormalFinding found = NormalFinding::None;
          if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) {
            found = NormalFinding::NonFinite;
          } else if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) {
            found = NormalFinding::Zero;
          } else if (!degenerate[f]) {
            const auto& t = mesh.triangles[f];
            if (detail::normal_agreement_sign(n, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                              mesh.vertices[t[2]]) < 0) {
              found = NormalFinding::Flipped;
            }
          }
          finding[f] = static_cast<std::uint8_t>(found);
        }
      });
      const std::span<const std::uint8_t> findings(finding.get(), nf);
      const auto facet = [](std::size_t f) { return static_cast<FacetIndex>(f); };
      report.flipped_normals = occurrences_in_order<FacetIndex>(
          findings, static_cast<std::uint8_t>(NormalFinding::Flipped), limit, facet);
      report.zero_normals = occurrences_in_order<FacetIndex>(
          findings, static_cast<std::uint8_t>(NormalFinding::Zero), limit, facet);
      report.non_finite_normals = occurrences_in_order<FacetIndex>(
          findings, static_cast<std::uint8_t>(NormalFinding::NonFinite), limit, facet);
    }
  };

  const auto find_self_intersections = [&] {
    // ---- self-intersections
    if (!options.check_self_intersections) return;
    report.self_intersections_checked = true;
    const detail::SelfIntersections found =
        detail::find_self_intersections(mesh, degenerate, options.max_self_intersection_pairs,
                                        options.max_self_intersection_candidates);
    report.self_intersections.count = found.pairs.size();
    const std::size_t kept = std::min(found.pairs.size(), limit);
    report.self_intersections.locations.assign(found.pairs.begin(), found.pairs.begin() + kept);
    report.self_intersections_truncated = found.truncated;
  };

  // The longest first, so that they start at once while the other threads take the rest: the
  // self-intersections' sweep when they are asked for, then the edges and shells (their
  // volumes' parts run in parallel again).
  tbb::parallel_invoke(find_self_intersections, find_edges_and_shells, find_vertex_defects,
                       check_stored_normals);

  judge(report);
  return report;
}

}  // namespace strata::diagnose
