#pragma once

#include <gmpxx.h>

#include "strata/mesh/vec3.hpp"

namespace strata::test {

/// The crossing of the edge lo-hi with the plane z on one axis (0 for x, 1 for y), on GMP
/// rationals as the formula is written: the value the exact path's crossings are held to.
inline mpq_class crossing_as_written(const Vec3& lo, const Vec3& hi, double z, int axis) {
  const double a = axis == 0 ? lo.x : lo.y;
  const double b = axis == 0 ? hi.x : hi.y;
  return mpq_class(a) + (mpq_class(z) - lo.z) / (mpq_class(hi.z) - lo.z) * (mpq_class(b) - a);
}

}  // namespace strata::test
