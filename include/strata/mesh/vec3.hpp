#pragma once

#include <limits>

namespace strata {

/// A point or vector in millimetres.
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  /// Exact equality of the coordinates.
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

/// A point in a layer's plane, in millimetres.
struct Point2 {
  double x = 0.0;
  double y = 0.0;

  /// Exact equality of the coordinates.
  friend bool operator==(const Point2&, const Point2&) = default;
};

/// Axis-aligned bounding box; `empty()` until a point is added.
struct Bbox3 {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  Vec3 min{kInf, kInf, kInf};
  Vec3 max{-kInf, -kInf, -kInf};

  /// True until a point is added.
  bool empty() const { return !(min.x <= max.x); }
  /// Grows the box to contain `p`.
  void add(const Vec3& p) {
    if (p.x < min.x) min.x = p.x;
    if (p.y < min.y) min.y = p.y;
    if (p.z < min.z) min.z = p.z;
    if (p.x > max.x) max.x = p.x;
    if (p.y > max.y) max.y = p.y;
    if (p.z > max.z) max.z = p.z;
  }
};

}  // namespace strata
