#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "exact/exact_cut_internal.hpp"

namespace strata::exact::detail {
namespace {

/// Exact crossing points, computed on integers: every double is an integer times a power of
/// two, so with all inputs of one edge scaled to the smallest exponent E,
///   x = 2^E (LX W + T (HX - LX)) / W,  W = HZ - LZ,  T = Z - LZ,
/// needs four integer operations and one reduction a coordinate. Scratch values keep their
/// storage from one point to the next.
class CrossingCalculator {
 public:
  /// Sets `out` to the crossing of the edge from lo (below z) to hi (at or above z).
  void operator()(const Vec3& lo, const Vec3& hi, double z, ExactPoint2& out) {
    if (hi.z == z) {
      set_double(out.x, hi.x);
      set_double(out.y, hi.y);
      return;
    }
    int e = std::numeric_limits<int>::max();
    for (const double v : {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, z}) lower_to_last_bit(e, v);
    set_scaled(lz_, lo.z, e);
    set_scaled(w_, hi.z, e);
    w_ -= lz_;
    set_scaled(t_, z, e);
    t_ -= lz_;
    along(lo.x, hi.x, e, out.x);
    along(lo.y, hi.y, e, out.y);
  }

 private:
  static void set_double(RoundedRational& out, double v) {
    out.exact = v;
    out.rounded = v + 0.0;  // the double itself, but -0 as +0, as the rational holds it
  }

  void along(double a, double b, int e, RoundedRational& out) {
    if (a == b) {
      set_double(out, a);
      return;
    }
    set_scaled(la_, a, e);
    set_scaled(lb_, b, e);
    lb_ -= la_;  // HX - LX
    lb_ *= t_;   // T (HX - LX)
    la_ *= w_;   // LX W
    la_ += lb_;  // numerator
    set_scaled_quotient(out.exact, la_, w_, e);
    out.rounded = round_to_double(out.exact);
  }

  mpz_class lz_, w_, t_, la_, lb_;
};

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
  // n.x = (b.y - a.y)(c.z - a.z) - (b.z - a.z)(c.y - a.y): the orientation of the facet projected
  // on the (y, z) plane, taken by CGAL's filtered predicate.
  std::vector<std::int8_t> signs(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Vec3& a = mesh.corner(static_cast<FacetIndex>(f), 0);
    const Vec3& b = mesh.corner(static_cast<FacetIndex>(f), 1);
    const Vec3& c = mesh.corner(static_cast<FacetIndex>(f), 2);
    const CGAL::Orientation o = CGAL::orientation(
        Kernel::Point_2(a.y, a.z), Kernel::Point_2(b.y, b.z), Kernel::Point_2(c.y, c.z));
    signs[f] = static_cast<std::int8_t>(o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0));
  }
  return signs;
}

ExactLayer cut_layer(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                     std::span<const std::int8_t> normal_x_signs, std::uint32_t layer, double z) {
  ExactLayer out;
  out.layer = layer;
  out.z_mm = z;
  CrossingCalculator crossing_point;
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
      crossing_point(mesh.vertices[edge.below], mesh.vertices[edge.above], z,
                     out.points.emplace_back());
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
