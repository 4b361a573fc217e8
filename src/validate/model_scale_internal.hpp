#pragma once

#include <algorithm>
#include <cmath>

#include "strata/mesh/vec3.hpp"

namespace strata::validate::detail {

/// The model's coordinate scale that the near-tie tolerance is relative to: the largest absolute
/// coordinate or the bounding box diagonal, whichever is larger (0 for an empty box).
inline double coordinate_scale(const Bbox3& bounds) {
  if (bounds.empty()) return 0.0;
  return std::max({std::fabs(bounds.min.x), std::fabs(bounds.min.y), std::fabs(bounds.min.z),
                   std::fabs(bounds.max.x), std::fabs(bounds.max.y), std::fabs(bounds.max.z),
                   std::hypot(bounds.max.x - bounds.min.x, bounds.max.y - bounds.min.y,
                              bounds.max.z - bounds.min.z)});
}

}  // namespace strata::validate::detail
