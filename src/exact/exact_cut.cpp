#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

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
  ExactPoint2 operator()(const Vec3& lo, const Vec3& hi, double z) {
    if (hi.z == z) return {RoundedRational(Rational(hi.x)), RoundedRational(Rational(hi.y))};
    int e = std::numeric_limits<int>::max();
    for (const double v : {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, z}) lower_to_last_bit(e, v);
    set_scaled(lz_, lo.z, e);
    set_scaled(w_, hi.z, e);
    w_ -= lz_;
    set_scaled(t_, z, e);
    t_ -= lz_;
    return {along(lo.x, hi.x, e), along(lo.y, hi.y, e)};
  }

 private:
  RoundedRational along(double a, double b, int e) {
    if (a == b) return RoundedRational(Rational(a));
    set_scaled(la_, a, e);
    set_scaled(lb_, b, e);
    lb_ -= la_;  // HX - LX
    lb_ *= t_;   // T (HX - LX)
    la_ *= w_;   // LX W
    la_ += lb_;  // numerator
    set_scaled_quotient(q_, la_, w_, e);
    return RoundedRational(Rational(q_));
  }

  mpz_class lz_, w_, t_, la_, lb_;
  mpq_class q_;
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
  // A crossed edge is shared by two facets: its point is computed once.
  std::unordered_map<std::uint64_t, ExactPoint2> points;
  const auto point_on = [&](const CrossedEdge& edge) -> const ExactPoint2& {
    const std::uint64_t key = (std::uint64_t{edge.below} << 32) | edge.above;
    auto it = points.find(key);
    if (it == points.end()) {
      it =
          points
              .emplace(key, crossing_point(mesh.vertices[edge.below], mesh.vertices[edge.above], z))
              .first;
    }
    return it->second;
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
    s.zero_length = compare_xy(s.start, s.end) == 0;
    s.normal_x_sign = normal_x_signs.empty() ? 0 : normal_x_signs[f];
    out.segments.push_back(std::move(s));
  }
  return out;
}

}  // namespace strata::exact::detail
