#pragma once

// Exact rationals of the exact path: the exact number type of CGAL's Epeck (GMP rationals), so
// values built here feed Epeck points without conversion.

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
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

/// An exact value with its nearest double, so comparisons with doubles are decided by the double
/// unless they tie (rounding to nearest is monotone: round(q) < d implies q < d).
struct RoundedRational {
  Rational exact;
  double rounded = 0.0;

  RoundedRational() = default;
  explicit RoundedRational(Rational q) : exact(std::move(q)), rounded(round_to_double(exact)) {}
};

/// Sign of (q - d), exact.
int compare_with_double(const RoundedRational& q, double d);

/// A point in a layer plane, exact.
struct ExactPoint2 {
  RoundedRational x;
  RoundedRational y;

  Point2 rounded() const { return {x.rounded, y.rounded}; }
};

/// Exact lexicographic (x, then y) comparison: -1, 0, +1.
int compare_xy(const ExactPoint2& a, const ExactPoint2& b);

/// The piece of one facet in a cutting plane (SPEC §2, layer_segments.hpp): from the crossing on
/// the edge that goes down through the plane to the crossing on the edge that goes up, in the
/// facet's own vertex order, so the material lies on its left. Points are exact.
struct ExactSegment {
  FacetIndex facet = 0;
  CrossedEdge start_edge;
  CrossedEdge end_edge;
  ExactPoint2 start;
  ExactPoint2 end;
  /// Sign of the x component of the facet normal (b - a) x (c - a), exact.
  int normal_x_sign = 0;
  /// Start and end are the same point (the facet meets the plane in one point).
  bool zero_length = false;
};

/// The exact cut of one layer, segments in facet order.
struct ExactLayer {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  std::vector<ExactSegment> segments;
};

/// A contour before rounding: exact points, no repeated closing point.
struct ExactLoop {
  std::vector<ExactPoint2> points;
  bool closed = true;
};

}  // namespace strata::exact::detail
