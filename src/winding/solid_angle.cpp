#include <cmath>
#include <numbers>

#include "strata/winding/generalized_winding.hpp"

namespace strata::winding {

double triangle_solid_angle(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ax = a.x - q.x, ay = a.y - q.y, az = a.z - q.z;
  const double bx = b.x - q.x, by = b.y - q.y, bz = b.z - q.z;
  const double cx = c.x - q.x, cy = c.y - q.y, cz = c.z - q.z;
  const double la = std::sqrt(ax * ax + ay * ay + az * az);
  const double lb = std::sqrt(bx * bx + by * by + bz * bz);
  const double lc = std::sqrt(cx * cx + cy * cy + cz * cz);
  const double det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  const double ab = ax * bx + ay * by + az * bz;
  const double bc = bx * cx + by * cy + bz * cz;
  const double ca = cx * ax + cy * ay + cz * az;
  const double den = la * lb * lc + ab * lc + bc * la + ca * lb;
  if (det == 0.0) return 0.0;  // q in the triangle's plane (or on it): no solid angle
  return 2.0 * std::atan2(det, den);
}

double winding_number(const IndexedMesh& mesh, const Vec3& q) {
  double sum = 0.0;
  for (const auto& t : mesh.triangles) {
    sum += triangle_solid_angle(q, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
  }
  return sum / (4.0 * std::numbers::pi);
}

}  // namespace strata::winding
