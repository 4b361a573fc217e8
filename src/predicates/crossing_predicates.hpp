#pragma once

// The predicates of SPEC §2's exact inside rule. A crossing point P lies on a mesh edge
// (lo -> hi) with lo.z < z <= hi.z; with w = hi.z - lo.z > 0 its coordinates are
//   P.x = lo.x + (z - lo.z) * (hi.x - lo.x) / w   (likewise y),
// so every comparison of P with a grid value c multiplies out to a sign of
//   (lo.x - c) * w + (z - lo.z) * (hi.x - lo.x),
// a polynomial in the input coordinates and the grid's double values, evaluated exactly.

#include <cmath>

#include "predicates/filtered_sign.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata::detail {

/// Sign of (P.y - y) for the crossing P of edge lo -> hi with plane z.
inline int crossing_y_sign(const Vec3& lo, const Vec3& hi, double z, double y) {
  // P.y lies between lo.y and hi.y: most calls are decided without arithmetic.
  if (lo.y > y && hi.y > y) return 1;
  if (lo.y < y && hi.y < y) return -1;
  if (lo.y == y && hi.y == y) return 0;
  return filtered_sign([&](auto tag) {
    using N = decltype(tag);
    N r = (N(lo.y) - N(y)) * (N(hi.z) - N(lo.z)) + (N(z) - N(lo.z)) * (N(hi.y) - N(lo.y));
    return r;
  });
}

/// A bound of |crossing_point(lo, hi, z).y - P.y| (likewise x) from the edge's two coordinates
/// a = lo.y and b = hi.y. crossing_point() rounds six times: t = (z - lo.z) / (hi.z - lo.z) is
/// within a factor 1 + 3.01u of its exact value T in (0, 1] (u = 2^-53), t (b - a) within
/// 5.01u |b - a| of T (b - a), and the sum a + t (b - a) within u (|a| + 1.01 |b - a|) of its
/// own; in all less than 7.1u (|a| + |b|). 2^-49 = 16u leaves a factor of two for the rounding
/// of the bound and of the caller's comparison, and for a subnormal t; the second term covers
/// subnormal results, whose roundings are absolute.
inline double crossing_point_error(double a, double b) {
  return (std::fabs(a) + std::fabs(b)) * 0x1p-49 + 0x1p-1000;
}

/// crossing_y_sign(lo, hi, z, y), given approx_y = crossing_point(lo, hi, z).y: decided by
/// approx_y alone when it lies farther from y than its error bound (nearly always on a grid of
/// cells much wider than an ulp), by the exact predicate otherwise. approx_y overflows only where
/// |lo.y| + |hi.y| does, and the bound is then infinite; a NaN compares false: both go to the
/// predicate.
inline int crossing_y_sign(const Vec3& lo, const Vec3& hi, double z, double y, double approx_y) {
  const double apart = approx_y - y;  // its sign is that of approx_y - y, exactly
  const double bound = crossing_point_error(lo.y, hi.y);
  if (apart > bound) return 1;
  if (apart < -bound) return -1;
  return crossing_y_sign(lo, hi, z, y);
}

/// Sign of (P.x - x) for the crossing P of edge lo -> hi with plane z.
inline int crossing_x_sign(const Vec3& lo, const Vec3& hi, double z, double x) {
  if (lo.x > x && hi.x > x) return 1;
  if (lo.x < x && hi.x < x) return -1;
  if (lo.x == x && hi.x == x) return 0;
  return filtered_sign([&](auto tag) {
    using N = decltype(tag);
    N r = (N(lo.x) - N(x)) * (N(hi.z) - N(lo.z)) + (N(z) - N(lo.z)) * (N(hi.x) - N(lo.x));
    return r;
  });
}

/// Sign of (X - xc), X being where segment PQ meets the line y = yr, for P = crossing of edge
/// p_lo -> p_hi and Q = crossing of q_lo -> q_hi with plane z.
/// @pre P.y < yr <= Q.y (P strictly below the line, Q on or above it).
inline int scanline_crossing_x_sign(const Vec3& p_lo, const Vec3& p_hi, const Vec3& q_lo,
                                    const Vec3& q_hi, double z, double yr, double xc) {
  // X is a convex combination of P.x and Q.x, each of its edge's end points.
  const double min_x = std::fmin(std::fmin(p_lo.x, p_hi.x), std::fmin(q_lo.x, q_hi.x));
  const double max_x = std::fmax(std::fmax(p_lo.x, p_hi.x), std::fmax(q_lo.x, q_hi.x));
  if (min_x > xc) return 1;
  if (max_x < xc) return -1;
  // With w = edge height: (X - xc) * (Q.y - P.y) * wP * wQ = NPx * NQy - NQx * NPy, where
  // NPx = (P.x - xc) * wP and so on; Q.y - P.y > 0 and w > 0 by the precondition.
  return filtered_sign([&](auto tag) {
    using N = decltype(tag);
    const N wp = N(p_hi.z) - N(p_lo.z);
    const N tp = N(z) - N(p_lo.z);
    const N wq = N(q_hi.z) - N(q_lo.z);
    const N tq = N(z) - N(q_lo.z);
    const N npx = (N(p_lo.x) - N(xc)) * wp + tp * (N(p_hi.x) - N(p_lo.x));
    const N npy = (N(p_lo.y) - N(yr)) * wp + tp * (N(p_hi.y) - N(p_lo.y));
    const N nqx = (N(q_lo.x) - N(xc)) * wq + tq * (N(q_hi.x) - N(q_lo.x));
    const N nqy = (N(q_lo.y) - N(yr)) * wq + tq * (N(q_hi.y) - N(q_lo.y));
    N r = npx * nqy - nqx * npy;
    return r;
  });
}

/// Where the scanline y = yr meets segment PQ, from the segment's rounded end points
/// below = crossing_point(p_lo, p_hi, z) and above = crossing_point(q_lo, q_hi, z): with
/// Q.y - P.y > 0 (scanline_crossing_x_sign's precondition), X - xc has the sign of
///   D = (P.x - xc) (Q.y - P.y) + (yr - P.y) (Q.x - P.x),
/// evaluated here with each rounded coordinate carrying crossing_point_error() as its error, so
/// that a sign it proves is D's at the exact P and Q. A row's scanline probes several centres:
/// the parts without xc are taken once.
class RoundedScanlineCrossing {
 public:
  RoundedScanlineCrossing(const Vec3& p_lo, const Vec3& p_hi, Point2 below, const Vec3& q_lo,
                          const Vec3& q_hi, Point2 above, double yr)
      : px_(below.x, crossing_point_error(p_lo.x, p_hi.x)) {
    const ErrorBoundedDouble py(below.y, crossing_point_error(p_lo.y, p_hi.y));
    const ErrorBoundedDouble qx(above.x, crossing_point_error(q_lo.x, q_hi.x));
    const ErrorBoundedDouble qy(above.y, crossing_point_error(q_lo.y, q_hi.y));
    rise_ = qy - py;
    offset_ = (ErrorBoundedDouble(yr) - py) * (qx - px_);
  }

  /// The sign of X - xc, or 2 when the rounding leaves it open (an overflow or a NaN included).
  int x_sign(double xc) const {
    return certain_sign((px_ - ErrorBoundedDouble(xc)) * rise_ + offset_);
  }

 private:
  ErrorBoundedDouble px_;
  ErrorBoundedDouble rise_;    ///< Q.y - P.y
  ErrorBoundedDouble offset_;  ///< (yr - P.y) (Q.x - P.x)
};

/// scanline_crossing_x_sign() decided from the rounded end points when they can, by the exact
/// predicate otherwise. `rounded` is the same segment's and scanline's.
inline int scanline_crossing_x_sign(const Vec3& p_lo, const Vec3& p_hi, const Vec3& q_lo,
                                    const Vec3& q_hi, double z, double yr, double xc,
                                    const RoundedScanlineCrossing& rounded) {
  const int sign = rounded.x_sign(xc);
  if (sign != 2) return sign;
  return scanline_crossing_x_sign(p_lo, p_hi, q_lo, q_hi, z, yr, xc);
}

/// Sign of the x component of the facet normal n = (b - a) x (c - a).
inline int normal_x_sign(const Vec3& a, const Vec3& b, const Vec3& c) {
  return filtered_sign([&](auto tag) {
    using N = decltype(tag);
    N r = (N(b.y) - N(a.y)) * (N(c.z) - N(a.z)) - (N(b.z) - N(a.z)) * (N(c.y) - N(a.y));
    return r;
  });
}

/// The crossing point of edge lo -> hi with plane z, rounded to double (for output and for
/// first guesses only; decisions use the predicates above).
inline Point2 crossing_point(const Vec3& lo, const Vec3& hi, double z) {
  const double t = (z - lo.z) / (hi.z - lo.z);
  return {lo.x + t * (hi.x - lo.x), lo.y + t * (hi.y - lo.y)};
}

}  // namespace strata::detail
