#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "exact/exact_cut_internal.hpp"
#include "predicates/crossing_predicates.hpp"

namespace strata::exact::detail {
namespace {

/// Point indices by crossed edge: open addressing on the edge's two vertex indices, sized for
/// every candidate facet's two crossings, so a layer allocates its table once.
class EdgePointTable {
 public:
  explicit EdgePointTable(std::size_t edges) {
    std::size_t size = 16;
    while (size < 2 * edges) size *= 2;
    slots_.assign(size, {kEmpty, 0});
    mask_ = size - 1;
  }

  /// The point index stored for `key`, or stores `next` for it; `added` tells which.
  std::uint32_t find_or_add(std::uint64_t key, std::uint32_t next, bool& added) {
    // Fibonacci hashing spreads the consecutive vertex indices of neighbouring edges.
    std::size_t i = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & mask_;
    while (true) {
      auto& slot = slots_[i];
      if (slot.first == key) {
        added = false;
        return slot.second;
      }
      if (slot.first == kEmpty) {
        slot = {key, next};
        added = true;
        return next;
      }
      i = (i + 1) & mask_;
    }
  }

 private:
  // No crossed edge joins a vertex to itself, so this key is never an edge's.
  static constexpr std::uint64_t kEmpty = std::numeric_limits<std::uint64_t>::max();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> slots_;
  std::size_t mask_ = 0;
};

}  // namespace

std::vector<std::int8_t> facet_normal_x_signs(const IndexedMesh& mesh) {
  // The fast path's exact predicate: n.x = (b.y - a.y)(c.z - a.z) - (b.z - a.z)(c.y - a.y),
  // the orientation of the facet projected on the (y, z) plane.
  std::vector<std::int8_t> signs(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto facet = static_cast<FacetIndex>(f);
    signs[f] = static_cast<std::int8_t>(strata::detail::normal_x_sign(
        mesh.corner(facet, 0), mesh.corner(facet, 1), mesh.corner(facet, 2)));
  }
  return signs;
}

ExactLayer cut_layer(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                     std::span<const std::int8_t> normal_x_signs, std::uint32_t layer, double z) {
  ExactLayer out;
  out.layer = layer;
  out.z_mm = z;
  // A crossed edge is shared by two facets: its point is computed and stored once.
  EdgePointTable table(2 * candidates.size());
  out.points.reserve(2 * candidates.size());
  out.segments.reserve(candidates.size());
  const auto point_on = [&](const CrossedEdge& edge) {
    const std::uint64_t key = (std::uint64_t{edge.below} << 32) | edge.above;
    bool added = false;
    const std::uint32_t index =
        table.find_or_add(key, static_cast<std::uint32_t>(out.points.size()), added);
    if (added) {
      // Rounded now; the exact values only if a comparison ties.
      const Vec3& lo = mesh.vertices[edge.below];
      const Vec3& hi = mesh.vertices[edge.above];
      out.points.push_back(
          {RoundedRational::crossing(lo, hi, z, 0), RoundedRational::crossing(lo, hi, z, 1)});
    }
    return index;
  };
  for (const FacetIndex f : candidates) {
    const std::optional<FacetCrossing> crossing = facet_crossing(mesh, f, z);
    if (!crossing) continue;
    ExactSegment s;
    s.facet = f;
    s.start_edge = crossing->start_edge;
    s.end_edge = crossing->end_edge;
    s.start = point_on(s.start_edge);
    s.end = point_on(s.end_edge);
    s.zero_length = s.start == s.end || compare_xy(out.points[s.start], out.points[s.end]) == 0;
    s.normal_x_sign = normal_x_signs.empty() ? 0 : normal_x_signs[f];
    out.segments.push_back(s);
  }
  return out;
}

}  // namespace strata::exact::detail
