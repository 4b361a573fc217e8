#include "strata/view/display_mesh.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "soup/position_key.hpp"
#include "view/flat_index_map_internal.hpp"

namespace strata::view {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SMS = CGAL::Surface_mesh_simplification;

DisplayMesh whole(const IndexedMesh& mesh) {
  DisplayMesh out;
  out.facets_in_model = mesh.triangles.size();
  out.positions.reserve(3 * mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) {
    out.positions.insert(out.positions.end(), {static_cast<float>(v.x), static_cast<float>(v.y),
                                               static_cast<float>(v.z)});
  }
  out.indices.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) out.indices.insert(out.indices.end(), t.begin(), t.end());
  return out;
}

constexpr std::uint32_t kUnused = 0xffffffffu;

Vec3 normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u{b.x - a.x, b.y - a.y, b.z - a.z};
  const Vec3 v{c.x - a.x, c.y - a.y, c.z - a.z};
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

struct KeyHash {
  std::size_t operator()(std::uint64_t k) const {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    return static_cast<std::size_t>(k);
  }
};

struct TriangleHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& t) const {
    const std::uint64_t h = (std::uint64_t{t[0]} * 0x9e3779b97f4a7c15ULL) ^
                            (std::uint64_t{t[1]} * 0xc2b2ae3d27d4eb4fULL) ^
                            (std::uint64_t{t[2]} * 0x165667b19e3779f9ULL);
    return KeyHash{}(h);
  }
};

/// Vertices grouped into the cubes of a grid of side `cell` from `lo`; cell 0 groups only
/// vertices at the same position. Each vertex gets its group's key.
class Clustering {
 public:
  explicit Clustering(const IndexedMesh& mesh) : mesh_(mesh) {
    lo_ = hi_ = mesh.vertices.empty() ? Vec3{0, 0, 0} : mesh.vertices.front();
    for (const Vec3& v : mesh.vertices) {
      lo_ = {std::min(lo_.x, v.x), std::min(lo_.y, v.y), std::min(lo_.z, v.z)};
      hi_ = {std::max(hi_.x, v.x), std::max(hi_.y, v.y), std::max(hi_.z, v.z)};
      finite_ = finite_ && std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    }
    keys_.resize(mesh.vertices.size());
  }

  /// The largest side of the vertices' box; not finite when a coordinate is not (there are then
  /// no cubes to group by).
  double extent() const {
    if (!finite_) return std::numeric_limits<double>::quiet_NaN();
    return std::max({hi_.x - lo_.x, hi_.y - lo_.y, hi_.z - lo_.z});
  }

  /// Groups the vertices by cubes of side `cell` (> 0; at most 2^20 cubes an axis).
  void group_by_cell(double cell) {
    const double inv = 1.0 / cell;
    const auto index = [&](double x, double base) {
      // Truncation is the floor here: the offset from the lowest corner is not negative.
      return static_cast<std::uint64_t>(std::clamp((x - base) * inv, 0.0, 2097151.0));
    };
    for (std::size_t v = 0; v < keys_.size(); ++v) {
      const Vec3& p = mesh_.vertices[v];
      keys_[v] = index(p.x, lo_.x) | index(p.y, lo_.y) << 21 | index(p.z, lo_.z) << 42;
    }
  }

  /// Groups the vertices by position.
  void group_by_position() {
    // The first vertex of each hash; the later ones of a hash, rare but for equal positions,
    // in a list of their own (a welded mesh has none).
    detail::FlatIndexMap<std::uint64_t, KeyHash> first_of_hash(keys_.size());
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>, KeyHash> more_of_hash;
    for (std::size_t v = 0; v < keys_.size(); ++v) {
      const Vec3& p = mesh_.vertices[v];
      // +0.0: the two zeros, which compare equal, hash alike.
      const std::uint64_t h =
          soup::DoublesHash{}(std::array<double, 3>{p.x + 0.0, p.y + 0.0, p.z + 0.0});
      keys_[v] = v;
      const auto [first, inserted] = first_of_hash.try_emplace(h, static_cast<std::uint32_t>(v));
      if (inserted) continue;
      const auto same = [&](std::uint32_t w) {
        const Vec3& q = mesh_.vertices[w];
        return q.x == p.x && q.y == p.y && q.z == p.z;
      };
      if (same(first)) {
        keys_[v] = keys_[first];
        continue;
      }
      std::vector<std::uint32_t>& more = more_of_hash[h];
      for (const std::uint32_t w : more) {
        if (same(w)) {
          keys_[v] = keys_[w];
          break;
        }
      }
      if (keys_[v] == v) more.push_back(static_cast<std::uint32_t>(v));
    }
  }

  /// Facets whose corners fall in three different groups (repeats counted).
  std::size_t count_kept() const {
    std::size_t kept = 0;
    for (const auto& t : mesh_.triangles) {
      const std::uint64_t a = keys_[t[0]], b = keys_[t[1]], c = keys_[t[2]];
      kept += (a != b) & (b != c) & (a != c);
    }
    return kept;
  }

  /// The display mesh of the current grouping: one vertex a group at the mean of its vertices,
  /// the facets with three groups, each set of three groups once, in the model's order. A facet
  /// the grouping folds over (its normal turned by more than a right angle) is left out: the page
  /// paints back faces as a defect of the model, which a fold is not.
  IndexedMesh build() const {
    IndexedMesh out;
    detail::FlatIndexMap<std::uint64_t, KeyHash> group_index(keys_.size());
    std::vector<std::array<double, 4>> sums;  // x, y, z, count
    std::vector<std::uint32_t> vertex_group(keys_.size());
    for (std::size_t v = 0; v < keys_.size(); ++v) {
      const auto [group, inserted] =
          group_index.try_emplace(keys_[v], static_cast<std::uint32_t>(sums.size()));
      if (inserted) sums.push_back({0.0, 0.0, 0.0, 0.0});
      vertex_group[v] = group;
      const Vec3& p = mesh_.vertices[v];
      std::array<double, 4>& s = sums[group];
      s[0] += p.x;
      s[1] += p.y;
      s[2] += p.z;
      s[3] += 1.0;
    }
    std::vector<Vec3> mean(sums.size());
    for (std::size_t g = 0; g < sums.size(); ++g) {
      const auto& s = sums[g];
      mean[g] = {s[0] / s[3], s[1] / s[3], s[2] / s[3]};
    }
    detail::FlatIndexMap<std::array<std::uint32_t, 3>, TriangleHash> seen;
    std::vector<std::uint32_t> used(sums.size(), kUnused);
    for (const auto& t : mesh_.triangles) {
      const std::array<std::uint32_t, 3> g = {vertex_group[t[0]], vertex_group[t[1]],
                                              vertex_group[t[2]]};
      if (g[0] == g[1] || g[1] == g[2] || g[0] == g[2]) continue;
      const Vec3 before = normal(mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]);
      const Vec3 after = normal(mean[g[0]], mean[g[1]], mean[g[2]]);
      if (!(before.x * after.x + before.y * after.y + before.z * after.z > 0.0)) continue;
      std::array<std::uint32_t, 3> sorted = g;
      std::sort(sorted.begin(), sorted.end());
      if (!seen.try_emplace(sorted, 0).second) continue;
      for (const std::uint32_t group : g) {
        if (used[group] == kUnused) {
          used[group] = static_cast<std::uint32_t>(out.vertices.size());
          out.vertices.push_back(mean[group]);
        }
      }
      out.triangles.push_back({used[g[0]], used[g[1]], used[g[2]]});
    }
    return out;
  }

 private:
  const IndexedMesh& mesh_;
  Vec3 lo_, hi_;
  bool finite_ = true;
  std::vector<std::uint64_t> keys_;
};

/// The mesh clustered to at most `target` facets (more than zero): repeats and repeated
/// corners dropped, and if that is not enough, the smallest cube (to 1 part in 4096 of the
/// model's size) whose clustering keeps at most `target`.
IndexedMesh cluster_to(const IndexedMesh& mesh, std::size_t target) {
  Clustering clusters(mesh);
  clusters.group_by_position();
  // Tried when at most half of the facets left would have to be repeats.
  if (clusters.count_kept() <= 2 * target) {
    IndexedMesh exact = clusters.build();
    if (exact.triangles.size() <= target) return exact;
  }
  // Searched between 2^-20 of the extent and twice it, where every vertex is in one cube.
  const double extent = clusters.extent();
  if (!(extent > 0.0) || !std::isfinite(extent)) return IndexedMesh{};
  double fine = extent * 0x1p-20;
  double coarse = extent * 2.0;
  for (int step = 0; step < 40 && coarse / fine > 1.0 + 0x1p-12; ++step) {
    const double cell = std::sqrt(fine * coarse);
    clusters.group_by_cell(cell);
    const std::size_t kept = clusters.count_kept();
    if (kept <= target) {
      coarse = cell;
      // Close enough to the target: a finer grid would gain little.
      if (kept >= target - target / 16) break;
    } else {
      fine = cell;
    }
  }
  clusters.group_by_cell(coarse);
  return clusters.build();
}

/// The mesh simplified to about `max_facets` by edge collapse (CGAL), on the mesh oriented and
/// made manifold by CGAL's polygon soup functions.
DisplayMesh collapse_to(const IndexedMesh& mesh, std::size_t max_facets) {
  // Edge collapse needs a manifold surface: the soup functions drop degenerate facets, orient
  // the rest and duplicate the vertices where the surface is not a manifold.
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  Mesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);

  const double ratio =
      static_cast<double>(max_facets) / static_cast<double>(surface.number_of_faces());
  if (ratio < 1.0) {
    SMS::Count_ratio_stop_predicate<Mesh> stop(ratio);
    SMS::edge_collapse(surface, stop,
                       CGAL::parameters::get_cost(SMS::Edge_length_cost<Mesh>())
                           .get_placement(SMS::Midpoint_placement<Mesh>()));
    surface.collect_garbage();
  }

  DisplayMesh out;
  out.facets_in_model = mesh.triangles.size();
  out.simplified = true;
  std::vector<std::uint32_t> index(surface.num_vertices(), 0);
  std::uint32_t next = 0;
  for (Mesh::Vertex_index v : surface.vertices()) {
    const Point& p = surface.point(v);
    index[v] = next++;
    out.positions.insert(out.positions.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                               static_cast<float>(p.z())});
  }
  out.indices.reserve(3 * surface.number_of_faces());
  for (Mesh::Face_index f : surface.faces()) {
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(surface.halfedge(f), surface)) {
      out.indices.push_back(index[v]);
    }
  }
  return out;
}

}  // namespace

DisplayMesh make_display_mesh(const IndexedMesh& mesh, std::size_t max_facets,
                              std::size_t collapse_at_most) {
  if (mesh.triangles.size() <= max_facets) return whole(mesh);
  // Edge collapse keeps the shape best but costs microseconds a facet (5 s on a million);
  // clustering is linear and, at a cube of 1/400 of the model or less, looks the same. So a
  // large mesh is clustered first, to the budget or to collapse_at_most facets, whichever is more.
  const std::size_t cluster_target = std::max(max_facets, collapse_at_most);
  if (mesh.triangles.size() <= cluster_target) return collapse_to(mesh, max_facets);
  IndexedMesh clustered = cluster_to(mesh, cluster_target);
  DisplayMesh out = clustered.triangles.size() <= max_facets ? whole(clustered)
                                                             : collapse_to(clustered, max_facets);
  out.facets_in_model = mesh.triangles.size();
  out.simplified = true;
  return out;
}

}  // namespace strata::view
