#pragma once

// Exact rationals of the exact path: the exact number type of CGAL's Epeck (GMP rationals), so
// values built here feed Epeck points without conversion.

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "exact/exact_rounding.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/layer_segments.hpp"

namespace strata::exact::detail {

/// Lowers `e` to the exponent of v's last mantissa bit, ilogb(v) - 52, unless v is zero: with e
/// lowered over several doubles, each of them is an integer times 2^e (start from INT_MAX).
inline void lower_to_last_bit(int& e, double v) {
  if (v != 0.0) e = std::min(e, std::ilogb(v) - 52);
}

/// out = v / 2^e, an integer: v is a multiple of 2^e (e lowered over v by lower_to_last_bit).
void set_scaled(mpz_class& out, double v, int e);

/// out = 2^e num / den, reduced. @pre den is not zero.
void set_scaled_quotient(mpq_class& out, const mpz_class& num, const mpz_class& den, int e);

/// The crossing of the edge from `lo` (below z) to `hi` (above z) with the plane at height z,
/// on one axis: its exact value, and its nearest double without building that value (no rational
/// is reduced or allocated). NaN when the nearest double lies below the normal range, where only
/// the rational rounds it right. Any crossing; RoundedRational::crossing takes those that are
/// doubles (crossing_on_a_vertex) without them.
Rational exact_crossing(const Vec3& lo, const Vec3& hi, double z, int axis);
double rounded_crossing(const Vec3& lo, const Vec3& hi, double z, int axis);

/// The crossing when it is a double itself: the upper end's coordinate when that end lies on the
/// plane, or the coordinate the edge keeps all along; otherwise none.
inline std::optional<double> crossing_on_a_vertex(const Vec3& lo, const Vec3& hi, double z,
                                                  int axis) {
  const double a = axis == 0 ? lo.x : lo.y;
  const double b = axis == 0 ? hi.x : hi.y;
  if (hi.z == z) return b;
  if (a == b) return a;
  return std::nullopt;
}

/// An exact value with its nearest double, so comparisons with doubles are decided by the double
/// unless they tie (rounding to nearest is monotone: round(q) < d implies q < d). A crossing's
/// exact value is computed when first asked for: most comparisons never ask.
class RoundedRational {
 public:
  double rounded = 0.0;

  /// Zero.
  RoundedRational() = default;
  explicit RoundedRational(Rational q)
      : rounded(round_to_double(q)), exact_(std::make_unique<Rational>(std::move(q))) {}
  /// The double v, exactly (-0 held as +0, as a rational holds it).
  static RoundedRational of_double(double v) {
    RoundedRational out;
    out.rounded = v + 0.0;
    out.is_double_ = true;
    return out;
  }
  /// The crossing of the edge from lo (below z) to hi (above z) with the plane z on `axis` (0
  /// for x, 1 for y); the vertices must outlive this value.
  static RoundedRational crossing(const Vec3& lo, const Vec3& hi, double z, int axis) {
    if (const std::optional<double> v = crossing_on_a_vertex(lo, hi, z, axis)) {
      return of_double(*v);
    }
    const double rounded = rounded_crossing(lo, hi, z, axis);
    if (std::isnan(rounded)) return RoundedRational(exact_crossing(lo, hi, z, axis));
    RoundedRational out;
    out.rounded = rounded;
    out.lo_ = &lo;
    out.hi_ = &hi;
    out.z_ = z;
    out.axis_ = axis;
    return out;
  }

  // The rational, when there is one, is held apart: moving a value moves a pointer (gmpxx's
  // rational move allocates, and is not noexcept), and the many values that never need it
  // stay small.
  RoundedRational(const RoundedRational& other)
      : rounded(other.rounded),
        exact_(other.exact_ ? std::make_unique<Rational>(*other.exact_) : nullptr),
        lo_(other.lo_),
        hi_(other.hi_),
        z_(other.z_),
        axis_(other.axis_),
        is_double_(other.is_double_) {}
  RoundedRational& operator=(const RoundedRational& other) {
    if (this != &other) *this = RoundedRational(other);
    return *this;
  }
  RoundedRational(RoundedRational&&) noexcept = default;
  RoundedRational& operator=(RoundedRational&&) noexcept = default;

  /// Whether the value is known to be `rounded` itself (then two such values that round alike
  /// are equal, with no rational built). False says nothing.
  bool is_double() const { return is_double_; }

  /// The exact value (computed on the first call; not to be called from two threads at once).
  const Rational& exact() const {
    if (!exact_) {
      exact_ = std::make_unique<Rational>(lo_ != nullptr ? exact_crossing(*lo_, *hi_, z_, axis_)
                                                         : Rational(rounded));
    }
    return *exact_;
  }

 private:
  mutable std::unique_ptr<Rational> exact_;
  // The crossing the value is, while exact_ is not computed; no crossing: the double `rounded`.
  const Vec3* lo_ = nullptr;
  const Vec3* hi_ = nullptr;
  double z_ = 0.0;
  int axis_ = 0;
  bool is_double_ = false;
};

/// Sign of (q - d), exact.
int compare_with_double(const RoundedRational& q, double d);

/// A point in a layer plane, exact.
struct ExactPoint2 {
  RoundedRational x;
  RoundedRational y;

  Point2 rounded() const { return {x.rounded, y.rounded}; }
};

/// The point in the exact kernel, its exact value held from the start: a point built from two
/// exact numbers would compute its exact value again, under a lock, the first time a comparison
/// of its intervals ties.
inline Kernel::Point_2 to_kernel(const ExactPoint2& p) {
  using Point = Kernel::Point_2;
  return Point(Point::Rep(Kernel::Exact_kernel::Point_2(p.x.exact(), p.y.exact())));
}

/// Exact comparison of two values: -1, 0, +1.
int compare(const RoundedRational& u, const RoundedRational& v);

/// Exact lexicographic (x, then y) comparison: -1, 0, +1.
int compare_xy(const ExactPoint2& a, const ExactPoint2& b);

/// The piece of one facet in a cutting plane (SPEC §2, layer_segments.hpp): from the crossing on
/// the edge that goes down through the plane to the crossing on the edge that goes up, in the
/// facet's own vertex order, so the material lies on its left. Points are exact, held once per
/// crossed edge by the layer (two facets share each crossing of a closed surface).
struct ExactSegment {
  FacetIndex facet = 0;
  CrossedEdge start_edge;
  CrossedEdge end_edge;
  std::uint32_t start = 0;  ///< index of the start point in ExactLayer::points
  std::uint32_t end = 0;    ///< index of the end point in ExactLayer::points
  /// Sign of the x component of the facet normal (b - a) x (c - a), exact.
  int normal_x_sign = 0;
  /// Start and end are the same point (the facet meets the plane in one point).
  bool zero_length = false;
};

/// The exact cut of one layer, segments in facet order.
struct ExactLayer {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  std::vector<ExactPoint2> points;  ///< one per crossed edge
  std::vector<ExactSegment> segments;

  const ExactPoint2& start_of(const ExactSegment& s) const { return points[s.start]; }
  const ExactPoint2& end_of(const ExactSegment& s) const { return points[s.end]; }
};

/// A contour before rounding: exact points, no repeated closing point.
struct ExactLoop {
  std::vector<ExactPoint2> points;
  bool closed = true;
};

}  // namespace strata::exact::detail
