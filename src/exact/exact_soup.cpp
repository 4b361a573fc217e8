#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <limits>
#include <set>
#include <utility>

#include "exact/exact_soup_internal.hpp"
#include "soup/orient_soup_visitor.hpp"
#include "soup/polygon_mesh_check.hpp"
#include "soup/position_key.hpp"
#include "strata/core/error.hpp"

namespace strata::exact::detail {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
// The soup's points are the input's doubles, only compared and copied: the repair's tests are
// predicates (exact in Epick), the orientation is combinatorial, and no point is constructed, so
// Epick gives the same soup as Epeck without a lazy number per coordinate.
using Point3 = CGAL::Epick::Point_3;
using Polygon = std::vector<std::size_t>;

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t kReversed = 0x80000000u;

Vec3 to_vec3(const Point3& p) {
  // The soup's points were built from doubles and only copied since.
  return {p.x(), p.y(), p.z()};
}

}  // namespace

bool is_clean_soup(const IndexedMesh& mesh) {
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return false;
  }
  // Positions: sorted by their hash, equal hashes compared; +0 and -0 compare equal, as in CGAL.
  const auto position_hash = [&](std::size_t v) {
    const Vec3& p = mesh.vertices[v];
    return soup::DoublesHash{}(std::array<double, 3>{p.x + 0.0, p.y + 0.0, p.z + 0.0});
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> by_position(mesh.vertices.size());
  for (std::size_t v = 0; v < by_position.size(); ++v) {
    by_position[v] = {position_hash(v), static_cast<std::uint32_t>(v)};
  }
  tbb::parallel_sort(by_position.begin(), by_position.end());
  for (std::size_t a = 0; a < by_position.size(); ++a) {
    for (std::size_t b = a + 1;
         b < by_position.size() && by_position[b].first == by_position[a].first; ++b) {
      if (mesh.vertices[by_position[a].second] == mesh.vertices[by_position[b].second])
        return false;
    }
  }
  std::vector<std::array<VertexIndex, 3>> corners(mesh.triangles.begin(), mesh.triangles.end());
  for (auto& c : corners) std::sort(c.begin(), c.end());
  tbb::parallel_sort(corners.begin(), corners.end());
  return std::adjacent_find(corners.begin(), corners.end()) == corners.end();
}

/// The oriented soup, when it is a polygon mesh of triangles, as a halfedge structure in flat
/// arrays: halfedge 3 f + k runs along face f from its corner k to corner k + 1, so that a
/// halfedge's face and the next one round the face are arithmetic, and only the opposite
/// halfedges are stored: 24 bytes a face, where a CGAL::Surface_mesh took over 80.
struct SoupMesh::Impl {
  const IndexedMesh& input;
  ExactSliceReport report;
  bool usable = false;
  std::vector<std::array<std::uint32_t, 3>> faces;  ///< the oriented soup's triangles
  std::vector<std::uint32_t> opposite;              ///< per halfedge; kNone at a border
  std::vector<Vec3> vertex_position;                ///< per soup point
  std::vector<std::uint32_t> face_facet;            ///< per face: its input facet, or kNone
  /// Per input facet: its face's halfedge along the facet's edge from corner 0 to corner 1, with
  /// kReversed set when the face runs the other way round; kNone when it has no face. A segment
  /// then finds the halfedges of its two edges from their corner numbers alone.
  std::vector<std::uint32_t> facet_edge0;

  explicit Impl(const IndexedMesh& m) : input(m) {}

  static std::uint32_t face_of(std::uint32_t h) { return h / 3; }
  static std::uint32_t next(std::uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
  std::uint32_t source(std::uint32_t h) const { return faces[h / 3][h % 3]; }
  std::uint32_t target(std::uint32_t h) const { return source(next(h)); }

  /// Fills `opposite`: the halfedge from v to u of each halfedge from u to v, found among v's
  /// outgoing halfedges (a polygon mesh has at most one).
  void link_opposites(std::size_t point_count) {
    const std::size_t halfedges = 3 * faces.size();
    std::vector<std::uint32_t> first(point_count + 1, 0);
    for (std::uint32_t h = 0; h < halfedges; ++h) ++first[source(h) + 1];
    for (std::size_t v = 0; v < point_count; ++v) first[v + 1] += first[v];
    std::vector<std::uint32_t> outgoing(halfedges);
    {
      std::vector<std::uint32_t> at(first.begin(), first.end() - 1);
      for (std::uint32_t h = 0; h < halfedges; ++h) outgoing[at[source(h)]++] = h;
    }
    opposite.assign(halfedges, kNone);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, static_cast<std::uint32_t>(halfedges)),
                      [&](const auto& range) {
                        for (std::uint32_t h = range.begin(); h < range.end(); ++h) {
                          const std::uint32_t u = source(h);
                          const std::uint32_t v = target(h);
                          for (std::uint32_t i = first[v]; i < first[v + 1]; ++i) {
                            if (target(outgoing[i]) == u) {
                              opposite[h] = outgoing[i];
                              break;
                            }
                          }
                        }
                      });
  }
};

SoupMesh::SoupMesh(const IndexedMesh& input) : impl_(std::make_unique<Impl>(input)) {
  Impl& d = *impl_;
  d.report.input_points = input.vertices.size();
  d.report.input_polygons = input.triangles.size();

  std::vector<Point3> points;
  points.reserve(input.vertices.size());
  for (const Vec3& v : input.vertices) points.emplace_back(v.x, v.y, v.z);

  // What follows the repair. The soup's triangles are held as arrays, not as a heap list each
  // (56 MB less for a million facets).
  using Triangles = std::vector<std::array<std::size_t, 3>>;
  const auto finish = [&](Triangles& polygons, bool clean) {
    d.report.points_merged = input.vertices.size() - points.size();
    d.report.polygons_removed = input.triangles.size() - polygons.size();

    // A clean soup that is already a polygon mesh has every shared edge used both ways and no
    // singular vertex: CGAL's orientation would reverse, split and report nothing, so it is not
    // run.
    const bool already_mesh =
        clean && !polygons.empty() && soup::is_polygon_mesh(polygons, points.size());
    const soup::OrientSoupCounts counters =
        already_mesh ? soup::OrientSoupCounts{} : soup::orient_soup(points, polygons);
    d.report.points_duplicated = counters.points_added;
    d.report.polygons_reversed = counters.reversed;
    d.report.non_manifold_edges = counters.non_manifold_edges.size();

    // Orientation reverses and splits, but neither drops nor reorders polygons: checked.
    const bool facet_order = clean && polygons.size() == input.triangles.size();
    d.facet_edge0.assign(input.triangles.size(), kNone);
    // CGAL's own check (PMP::is_polygon_soup_a_polygon_mesh) gives the same answer with a tree
    // node per halfedge: the largest allocation of the exact path.
    if (polygons.empty() || !(already_mesh || soup::is_polygon_mesh(polygons, points.size()))) {
      return;
    }
    // Halfedges are numbered below kReversed; orientation leaves triangles triangles.
    if (polygons.size() >= kReversed / 3) return;
    d.faces.resize(polygons.size());
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      const auto& p = polygons[i];
      if (p.size() != 3) return;
      d.faces[i] = {static_cast<std::uint32_t>(p[0]), static_cast<std::uint32_t>(p[1]),
                    static_cast<std::uint32_t>(p[2])};
    }
    d.link_opposites(points.size());
    d.vertex_position.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) d.vertex_position[i] = to_vec3(points[i]);

    // Input facets by corner positions; a position set shared by several facets (duplicates,
    // unwelded copies) maps to none of them. Held as (hash of the positions, facet), sorted, and
    // the positions compared again on a match: 16 bytes a facet, not a hash map node of 96.
    const auto key_of_facet = [&](std::uint32_t f) {
      const auto& t = input.triangles[f];
      return soup::position_key({input.vertices[t[0]], input.vertices[t[1]], input.vertices[t[2]]});
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> by_hash(
        facet_order ? 0 : input.triangles.size());
    for (std::size_t f = 0; f < by_hash.size(); ++f) {
      const auto facet = static_cast<std::uint32_t>(f);
      by_hash[f] = {soup::DoublesHash{}(key_of_facet(facet)), facet};
    }
    std::sort(by_hash.begin(), by_hash.end());
    const auto facet_at = [&](const soup::PositionKey& k) {
      const std::uint64_t h = soup::DoublesHash{}(k);
      std::uint32_t found = kNone;
      for (auto it = std::lower_bound(by_hash.begin(), by_hash.end(), std::make_pair(h, 0u));
           it != by_hash.end() && it->first == h; ++it) {
        if (key_of_facet(it->second) != k) continue;
        if (found != kNone) return kNone;  // shared
        found = it->second;
      }
      return found;
    };
    // The face's halfedge on the facet's edge 0, found by positions (the repair may have merged
    // the facet's vertices into other indices); kNone unless the face's corners are the facet's.
    const auto edge0_of = [&](std::uint32_t facet, std::uint32_t face) {
      const auto& t = input.triangles[facet];
      const Vec3* corner[3] = {&input.vertices[t[0]], &input.vertices[t[1]], &input.vertices[t[2]]};
      const std::uint32_t h[3] = {3 * face, 3 * face + 1, 3 * face + 2};
      for (int k = 0; k < 3; ++k) {
        const Vec3& source = d.vertex_position[d.source(h[k])];
        const Vec3& s1 = d.vertex_position[d.source(h[(k + 1) % 3])];
        const Vec3& s2 = d.vertex_position[d.source(h[(k + 2) % 3])];
        if (source != *corner[0]) continue;
        if (s1 == *corner[1] && s2 == *corner[2]) return h[k];
        // Reversed, the face runs corner 0, 2, 1: its edge 0 is the halfedge from corner 1.
        if (s1 == *corner[2] && s2 == *corner[1]) return h[(k + 2) % 3] | kReversed;
      }
      return kNone;
    };
    d.face_facet.assign(polygons.size(), kNone);
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      const auto& p = polygons[i];
      const auto face = static_cast<std::uint32_t>(i);
      const std::uint32_t facet =
          facet_order
              ? static_cast<std::uint32_t>(i)
              : facet_at(soup::position_key(
                    {d.vertex_position[p[0]], d.vertex_position[p[1]], d.vertex_position[p[2]]}));
      if (facet == kNone) continue;
      d.face_facet[face] = facet;
      d.facet_edge0[facet] = edge0_of(facet, face);
    }
    d.usable = true;
    d.report.polygon_mesh = true;
  };

  // A clean soup (the usual one: welded, no facet with a repeated corner, none twice) is one
  // CGAL's repair would only take its unused points from; the facets then keep their indices,
  // and face i of the mesh is input facet i.
  if (is_clean_soup(input)) {
    Triangles polygons;
    polygons.reserve(input.triangles.size());
    for (const auto& t : input.triangles) polygons.push_back({t[0], t[1], t[2]});
    PMP::remove_isolated_points_in_polygon_soup(points, polygons);
    finish(polygons, true);
    return;
  }
  // The whole repair needs lists it can shorten. It leaves triangles triangles or removes them
  // (merged points, then repeated corners dropped, then fewer than three corners removed; a
  // pinched polygon has four corners at least).
  std::vector<Polygon> repaired;
  repaired.reserve(input.triangles.size());
  for (const auto& t : input.triangles) repaired.push_back({t[0], t[1], t[2]});
  PMP::repair_polygon_soup(points, repaired);
  Triangles polygons(repaired.size());
  for (std::size_t i = 0; i < repaired.size(); ++i) {
    STRATA_ASSERT(repaired[i].size() == 3, "the soup repair keeps triangles triangles");
    std::copy(repaired[i].begin(), repaired[i].end(), polygons[i].begin());
  }
  repaired = {};
  finish(polygons, false);
}

SoupMesh::~SoupMesh() = default;

const ExactSliceReport& SoupMesh::repair_report() const { return impl_->report; }

std::optional<std::vector<ExactLoop>> SoupMesh::chain_layer(ExactLayer& layer) const {
  const Impl& d = *impl_;
  if (!d.usable) return std::nullopt;
  const auto& segments = layer.segments;
  const std::size_t n = segments.size();
  constexpr std::size_t kInactive = std::numeric_limits<std::size_t>::max();
  std::vector<std::uint32_t> start_h(n);
  std::vector<std::uint32_t> end_h(n);
  std::vector<bool> active(n, false);

  // The halfedge of edge k (from corner k to corner k + 1) of a facet whose edge 0 is h0: k steps
  // along the face, or 3 - k when the face runs against the facet.
  const auto edge_halfedge = [&](std::uint32_t edge0, int k) {
    std::uint32_t h = edge0 & ~kReversed;
    const int steps = (edge0 & kReversed) != 0 ? (3 - k) % 3 : k;
    for (int i = 0; i < steps; ++i) h = Impl::next(h);
    return h;
  };
  for (std::size_t s = 0; s < n; ++s) {
    const ExactSegment& seg = segments[s];
    const std::uint32_t edge0 = d.facet_edge0[seg.facet];
    if (edge0 == kNone) {
      // Facets the repair dropped with a repeated corner meet the plane in one point and bound
      // nothing; any other missing facet leaves a gap the mesh cannot walk.
      if (seg.zero_length) continue;
      return std::nullopt;
    }
    // The segment starts on the edge k going down (corner k above, k + 1 below) and ends on the
    // edge going up (corner k below): facet_crossing's edges, named by the facet's own corners.
    const auto& t = d.input.triangles[seg.facet];
    int start_k = -1;
    int end_k = -1;
    for (int k = 0; k < 3; ++k) {
      const int next = (k + 1) % 3;
      if (t[k] == seg.start_edge.above && t[next] == seg.start_edge.below) start_k = k;
      if (t[k] == seg.end_edge.below && t[next] == seg.end_edge.above) end_k = k;
    }
    if (start_k < 0 || end_k < 0) return std::nullopt;
    start_h[s] = edge_halfedge(edge0, start_k);
    end_h[s] = edge_halfedge(edge0, end_k);
    active[s] = true;
  }

  // The segment that follows another starts where it ends, at the same crossed edge's point:
  // found by that point first, by the facet (segments are in facet order) where a point starts
  // several segments.
  std::vector<std::uint32_t> starting_at(layer.points.size(), kNone);
  for (std::size_t s = 0; s < n; ++s)
    starting_at[segments[s].start] = static_cast<std::uint32_t>(s);
  const auto segment_of = [&](std::uint32_t facet, std::uint32_t point) -> std::size_t {
    const std::uint32_t s = starting_at[point];
    if (s != kNone && segments[s].facet == facet) return s;
    const auto it =
        std::lower_bound(segments.begin(), segments.end(), facet,
                         [](const ExactSegment& seg, std::uint32_t f) { return seg.facet < f; });
    if (it == segments.end() || it->facet != facet) return kInactive;
    return static_cast<std::size_t>(it - segments.begin());
  };

  // The loops are first found as point indices, so that nothing is taken from the layer unless
  // every chain closes.
  std::vector<bool> used(n, false);
  std::vector<std::vector<std::uint32_t>> loop_points;
  std::vector<std::uint32_t> uses(layer.points.size(), 0);
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (!active[seed] || used[seed]) continue;
    std::vector<std::uint32_t> loop;
    std::size_t current = seed;
    while (true) {
      used[current] = true;
      loop.push_back(segments[current].start);
      ++uses[segments[current].start];
      const std::uint32_t across = d.opposite[end_h[current]];
      if (across == kNone) return std::nullopt;  // a border: the chain is open
      const std::uint32_t facet = d.face_facet[Impl::face_of(across)];
      if (facet == kNone) return std::nullopt;
      const std::size_t next = segment_of(facet, segments[current].end);
      if (next == kInactive || !active[next] || start_h[next] != across) return std::nullopt;
      if (next == seed) break;
      if (used[next]) return std::nullopt;
      current = next;
    }
    loop_points.push_back(std::move(loop));
  }
  // A point is moved at its last use and copied before (a point starts two segments only where
  // the input's facets meet along an edge in the same direction).
  std::vector<ExactLoop> loops(loop_points.size());
  for (std::size_t l = 0; l < loop_points.size(); ++l) {
    loops[l].points.reserve(loop_points[l].size());
    for (const std::uint32_t p : loop_points[l]) {
      if (--uses[p] == 0) {
        loops[l].points.push_back(std::move(layer.points[p]));
      } else {
        loops[l].points.push_back(layer.points[p]);
      }
    }
  }
  return loops;
}

}  // namespace strata::exact::detail
