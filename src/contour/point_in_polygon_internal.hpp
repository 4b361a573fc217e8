#pragma once

#include <vector>

#include "predicates/filtered_sign.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata::detail {

/// Exact sign of the orientation of (a, b, c): +1 counter-clockwise, -1 clockwise, 0 collinear.
inline int orient2d(const Point2& a, const Point2& b, const Point2& c) {
  return filtered_sign([&](auto tag) {
    using N = decltype(tag);
    N r = (N(b.x) - N(a.x)) * (N(c.y) - N(a.y)) - (N(b.y) - N(a.y)) * (N(c.x) - N(a.x));
    return r;
  });
}

/// +1 when p is strictly inside the closed polygon (nonzero winding), 0 on its boundary, -1
/// outside. Decisions are exact on the given double points.
inline int point_in_polygon(const Point2& p, const std::vector<Point2>& polygon) {
  int winding = 0;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    if (a.y <= p.y) {
      if (b.y > p.y) {
        const int o = orient2d(a, b, p);
        if (o == 0) return 0;
        if (o > 0) ++winding;
      } else if (b.y == p.y && a.y == p.y &&
                 ((a.x <= p.x && p.x <= b.x) || (b.x <= p.x && p.x <= a.x))) {
        return 0;
      }
    } else if (b.y <= p.y) {
      const int o = orient2d(a, b, p);
      if (o == 0) return 0;
      if (o < 0) --winding;
    }
  }
  return winding != 0 ? 1 : -1;
}

}  // namespace strata::detail
