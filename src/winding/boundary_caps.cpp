#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "strata/winding/generalized_winding.hpp"

namespace strata::winding {

namespace {

/// Spokes longer than this many mean boundary edges are cut more coarsely (bounds the caps' size).
constexpr std::uint32_t kMaxSpokeLevels = 64;

/// Disjoint sets over vertex indices, for the boundary's connected components.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), VertexIndex{0});
  }
  VertexIndex find(VertexIndex v) {
    while (parent_[v] != v) {
      parent_[v] = parent_[parent_[v]];
      v = parent_[v];
    }
    return v;
  }
  void join(VertexIndex a, VertexIndex b) { parent_[find(a)] = find(b); }

 private:
  std::vector<VertexIndex> parent_;
};

}  // namespace

BoundaryCaps cap_boundary(const IndexedMesh& mesh) {
  // Net multiplicity of every undirected edge, counted in the direction low -> high index.
  std::unordered_map<std::uint64_t, std::int64_t> net;
  net.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      const VertexIndex u = t[e];
      const VertexIndex v = t[(e + 1) % 3];
      if (u == v) continue;  // a collapsed edge bounds nothing
      const VertexIndex lo = std::min(u, v);
      const VertexIndex hi = std::max(u, v);
      net[(std::uint64_t{lo} << 32) | hi] += u < v ? 1 : -1;
    }
  }
  struct BoundaryEdge {
    VertexIndex from, to;
    std::uint64_t multiplicity;
  };
  std::vector<BoundaryEdge> edges;
  for (const auto& [key, m] : net) {
    if (m == 0) continue;
    const auto lo = static_cast<VertexIndex>(key >> 32);
    const auto hi = static_cast<VertexIndex>(key & 0xffffffffu);
    edges.push_back(m > 0 ? BoundaryEdge{lo, hi, static_cast<std::uint64_t>(m)}
                          : BoundaryEdge{hi, lo, static_cast<std::uint64_t>(-m)});
  }
  // Hash order is not reproducible across library versions; facet order must be.
  std::sort(edges.begin(), edges.end(), [](const BoundaryEdge& a, const BoundaryEdge& b) {
    return a.from != b.from ? a.from < b.from : a.to < b.to;
  });

  BoundaryCaps caps;
  caps.closed = mesh;
  caps.mesh_facets = static_cast<std::uint32_t>(mesh.triangles.size());
  if (edges.empty()) return caps;

  DisjointSets sets(mesh.vertices.size());
  for (const BoundaryEdge& e : edges) sets.join(e.from, e.to);
  // One apex per component: the mean of the component's distinct vertices.
  std::unordered_map<VertexIndex, VertexIndex> apex_of_root;
  std::vector<Vec3> sums;
  std::vector<std::uint64_t> counts;
  std::vector<std::uint8_t> seen(mesh.vertices.size(), 0);
  const auto component_slot = [&](VertexIndex v) {
    const auto [it, added] =
        apex_of_root.emplace(sets.find(v), static_cast<VertexIndex>(sums.size()));
    if (added) {
      sums.push_back({});
      counts.push_back(0);
    }
    return it->second;
  };
  for (const BoundaryEdge& e : edges) {
    for (const VertexIndex v : {e.from, e.to}) {
      if (seen[v]) continue;
      seen[v] = 1;
      const VertexIndex slot = component_slot(v);
      sums[slot].x += mesh.vertices[v].x;
      sums[slot].y += mesh.vertices[v].y;
      sums[slot].z += mesh.vertices[v].z;
      ++counts[slot];
    }
  }
  const auto first_apex = static_cast<VertexIndex>(mesh.vertices.size());
  for (std::size_t s = 0; s < sums.size(); ++s) {
    const double n = static_cast<double>(counts[s]);
    caps.closed.vertices.push_back({sums[s].x / n, sums[s].y / n, sums[s].z / n});
  }
  caps.components = static_cast<std::uint32_t>(sums.size());

  // A fan of long thin triangles would make every node of the evaluation tree as wide as the
  // hole, so each spoke apex -> v is cut into `levels` pieces and the fan into strips whose
  // triangles are about as long as they are wide. Boundary edges are never split: they must
  // cancel the mesh's own edges exactly.
  std::vector<double> longest_spoke(sums.size(), 0.0);
  std::vector<double> edge_length_sum(sums.size(), 0.0);
  std::vector<std::uint64_t> edge_count(sums.size(), 0);
  const auto length = [](const Vec3& a, const Vec3& b) {
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                     (a.z - b.z) * (a.z - b.z));
  };
  for (const BoundaryEdge& e : edges) {
    const VertexIndex slot = component_slot(e.from);
    const Vec3& apex = caps.closed.vertices[first_apex + slot];
    longest_spoke[slot] = std::max({longest_spoke[slot], length(apex, mesh.vertices[e.from]),
                                    length(apex, mesh.vertices[e.to])});
    edge_length_sum[slot] += length(mesh.vertices[e.from], mesh.vertices[e.to]);
    ++edge_count[slot];
  }
  std::vector<std::uint32_t> levels(sums.size(), 1);
  for (std::size_t s = 0; s < sums.size(); ++s) {
    const double mean_edge = edge_length_sum[s] / static_cast<double>(edge_count[s]);
    if (mean_edge > 0.0) {
      levels[s] = static_cast<std::uint32_t>(
          std::clamp(std::ceil(longest_spoke[s] / mean_edge), 1.0, double{kMaxSpokeLevels}));
    }
  }
  // The points on each boundary vertex's spoke, levels 1 .. levels-1 (level 0 is the apex,
  // the last level the vertex itself).
  std::unordered_map<VertexIndex, VertexIndex> spoke_base;
  const auto spoke_point = [&](VertexIndex v, std::uint32_t level) -> VertexIndex {
    const VertexIndex slot = component_slot(v);
    const std::uint32_t n = levels[slot];
    if (level == 0) return first_apex + slot;
    if (level == n) return v;
    auto [it, added] = spoke_base.emplace(v, static_cast<VertexIndex>(caps.closed.vertices.size()));
    if (added) {
      const Vec3 a = caps.closed.vertices[first_apex + slot];
      const Vec3& b = mesh.vertices[v];
      for (std::uint32_t l = 1; l < n; ++l) {
        const double t = static_cast<double>(l) / n;
        caps.closed.vertices.push_back(
            {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t});
      }
    }
    return it->second + (level - 1);
  };
  for (const BoundaryEdge& e : edges) {
    const std::uint32_t n = levels[component_slot(e.from)];
    for (std::uint64_t m = 0; m < e.multiplicity; ++m) {
      // The strips of facet (apex, to, from), each with the facet's orientation.
      caps.closed.triangles.push_back(
          {spoke_point(e.to, 0), spoke_point(e.to, 1), spoke_point(e.from, 1)});
      for (std::uint32_t l = 1; l < n; ++l) {
        const VertexIndex a = spoke_point(e.to, l);
        const VertexIndex b = spoke_point(e.to, l + 1);
        const VertexIndex c = spoke_point(e.from, l + 1);
        const VertexIndex d = spoke_point(e.from, l);
        caps.closed.triangles.push_back({a, b, c});
        caps.closed.triangles.push_back({a, c, d});
      }
    }
    caps.boundary_edges += e.multiplicity;
  }
  return caps;
}

}  // namespace strata::winding
