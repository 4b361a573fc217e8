#pragma once

// "Is point p closer than t to triangle abc?" decided exactly: the squared distance from a point
// to a triangle is a rational function of the coordinates, so every branch below is the sign of
// a polynomial in the input doubles (and t), taken by the filtered evaluation.

#include "predicates/filtered_sign.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata::detail {

/// |p - q|^2 < t^2, exactly.
inline bool point_closer_than(const Vec3& p, const Vec3& q, double t) {
  return filtered_sign([&](auto tag) {
           using N = decltype(tag);
           const N dx = N(p.x) - N(q.x);
           const N dy = N(p.y) - N(q.y);
           const N dz = N(p.z) - N(q.z);
           N r = N(t) * N(t) - (dx * dx + dy * dy + dz * dz);
           return r;
         }) > 0;
}

/// Distance from p to segment ab is less than t, exactly (a == b allowed).
inline bool segment_closer_than(const Vec3& p, const Vec3& a, const Vec3& b, double t) {
  // s = (p - a) . (b - a) places the foot of the perpendicular: before a, after b, or between.
  const int s_sign = filtered_sign([&](auto tag) {
    using N = decltype(tag);
    N r = (N(p.x) - N(a.x)) * (N(b.x) - N(a.x)) + (N(p.y) - N(a.y)) * (N(b.y) - N(a.y)) +
          (N(p.z) - N(a.z)) * (N(b.z) - N(a.z));
    return r;
  });
  if (s_sign <= 0) return point_closer_than(p, a, t);
  const int beyond_b = filtered_sign([&](auto tag) {
    using N = decltype(tag);
    // (p - a).(b - a) - |b - a|^2 = (p - b).(b - a)
    N r = (N(p.x) - N(b.x)) * (N(b.x) - N(a.x)) + (N(p.y) - N(b.y)) * (N(b.y) - N(a.y)) +
          (N(p.z) - N(b.z)) * (N(b.z) - N(a.z));
    return r;
  });
  if (beyond_b >= 0) return point_closer_than(p, b, t);
  // Between: |u|^2 - s^2 / |e|^2 < t^2  <=>  t^2 |e|^2 - (|u|^2 |e|^2 - s^2) > 0.
  return filtered_sign([&](auto tag) {
           using N = decltype(tag);
           const N ux = N(p.x) - N(a.x), uy = N(p.y) - N(a.y), uz = N(p.z) - N(a.z);
           const N ex = N(b.x) - N(a.x), ey = N(b.y) - N(a.y), ez = N(b.z) - N(a.z);
           const N uu = ux * ux + uy * uy + uz * uz;
           const N ee = ex * ex + ey * ey + ez * ez;
           const N s = ux * ex + uy * ey + uz * ez;
           N r = N(t) * N(t) * ee - (uu * ee - s * s);
           return r;
         }) > 0;
}

/// Distance from p to the (closed, solid) triangle abc is less than t, exactly. Degenerate
/// triangles are the union of their edges.
inline bool triangle_closer_than(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                 double t) {
  const auto normal_component = [&](int axis) {
    return filtered_sign([&](auto tag) {
      using N = decltype(tag);
      const N e1[3] = {N(b.x) - N(a.x), N(b.y) - N(a.y), N(b.z) - N(a.z)};
      const N e2[3] = {N(c.x) - N(a.x), N(c.y) - N(a.y), N(c.z) - N(a.z)};
      const int i = (axis + 1) % 3, j = (axis + 2) % 3;
      N r = e1[i] * e2[j] - e1[j] * e2[i];
      return r;
    });
  };
  const bool flat =
      normal_component(0) == 0 && normal_component(1) == 0 && normal_component(2) == 0;
  if (!flat) {
    // The foot of the perpendicular lies in the triangle when p is on the inner side of all
    // three edges' planes: ((v1 - v0) x (p - v0)) . n >= 0 for each edge v0 -> v1.
    const auto edge_side = [&](const Vec3& v0, const Vec3& v1) {
      return filtered_sign([&](auto tag) {
        using N = decltype(tag);
        const N e1x = N(b.x) - N(a.x), e1y = N(b.y) - N(a.y), e1z = N(b.z) - N(a.z);
        const N e2x = N(c.x) - N(a.x), e2y = N(c.y) - N(a.y), e2z = N(c.z) - N(a.z);
        const N nx = e1y * e2z - e1z * e2y;
        const N ny = e1z * e2x - e1x * e2z;
        const N nz = e1x * e2y - e1y * e2x;
        const N ex = N(v1.x) - N(v0.x), ey = N(v1.y) - N(v0.y), ez = N(v1.z) - N(v0.z);
        const N wx = N(p.x) - N(v0.x), wy = N(p.y) - N(v0.y), wz = N(p.z) - N(v0.z);
        const N cx = ey * wz - ez * wy;
        const N cy = ez * wx - ex * wz;
        const N cz = ex * wy - ey * wx;
        N r = cx * nx + cy * ny + cz * nz;
        return r;
      });
    };
    if (edge_side(a, b) >= 0 && edge_side(b, c) >= 0 && edge_side(c, a) >= 0) {
      // Distance to the plane: (n . (p - a))^2 < t^2 |n|^2.
      return filtered_sign([&](auto tag) {
               using N = decltype(tag);
               const N e1x = N(b.x) - N(a.x), e1y = N(b.y) - N(a.y), e1z = N(b.z) - N(a.z);
               const N e2x = N(c.x) - N(a.x), e2y = N(c.y) - N(a.y), e2z = N(c.z) - N(a.z);
               const N nx = e1y * e2z - e1z * e2y;
               const N ny = e1z * e2x - e1x * e2z;
               const N nz = e1x * e2y - e1y * e2x;
               const N d = nx * (N(p.x) - N(a.x)) + ny * (N(p.y) - N(a.y)) + nz * (N(p.z) - N(a.z));
               N r = N(t) * N(t) * (nx * nx + ny * ny + nz * nz) - d * d;
               return r;
             }) > 0;
    }
  }
  return segment_closer_than(p, a, b, t) || segment_closer_than(p, b, c, t) ||
         segment_closer_than(p, c, a, t);
}

}  // namespace strata::detail
