#include <algorithm>
#include <cmath>
#include <numbers>

#include "strata/winding/generalized_winding.hpp"

namespace strata::winding {

namespace {

constexpr std::uint32_t kLeafFacets = 8;
constexpr double kFourPi = 4.0 * std::numbers::pi;

Vec3 centroid(const std::array<Vec3, 3>& t) {
  return {(t[0].x + t[1].x + t[2].x) / 3.0, (t[0].y + t[1].y + t[2].y) / 3.0,
          (t[0].z + t[1].z + t[2].z) / 3.0};
}

/// Half the cross product (b - a) x (c - a): the facet's area times its unit normal.
Vec3 area_vector(const std::array<Vec3, 3>& t) {
  const double ux = t[1].x - t[0].x, uy = t[1].y - t[0].y, uz = t[1].z - t[0].z;
  const double vx = t[2].x - t[0].x, vy = t[2].y - t[0].y, vz = t[2].z - t[0].z;
  return {0.5 * (uy * vz - uz * vy), 0.5 * (uz * vx - ux * vz), 0.5 * (ux * vy - uy * vx)};
}

double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                   (a.z - b.z) * (a.z - b.z));
}

}  // namespace

WindingNumberTree::WindingNumberTree(std::vector<std::array<Vec3, 3>> triangles)
    : triangles_(std::move(triangles)) {
  if (triangles_.empty()) return;
  nodes_.reserve(2 * (triangles_.size() / kLeafFacets + 1));
  build(0, static_cast<std::uint32_t>(triangles_.size()));
}

std::uint32_t WindingNumberTree::build(std::uint32_t first, std::uint32_t count) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  // Centre: the area-weighted mean of the facets' centroids (their plain mean when all facets
  // are degenerate), which makes the first-order term of the expansion small.
  double area = 0.0;
  Vec3 weighted{}, plain{};
  for (std::uint32_t f = first; f < first + count; ++f) {
    const Vec3 c = centroid(triangles_[f]);
    const Vec3 n = area_vector(triangles_[f]);
    const double a = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    weighted = {weighted.x + a * c.x, weighted.y + a * c.y, weighted.z + a * c.z};
    plain = {plain.x + c.x, plain.y + c.y, plain.z + c.z};
    area += a;
    node.normal_sum = {node.normal_sum.x + n.x, node.normal_sum.y + n.y, node.normal_sum.z + n.z};
  }
  node.centre = area > 0.0 ? Vec3{weighted.x / area, weighted.y / area, weighted.z / area}
                           : Vec3{plain.x / count, plain.y / count, plain.z / count};
  for (std::uint32_t f = first; f < first + count; ++f) {
    const Vec3 c = centroid(triangles_[f]);
    const Vec3 n = area_vector(triangles_[f]);
    const double d[3] = {c.x - node.centre.x, c.y - node.centre.y, c.z - node.centre.z};
    const double nv[3] = {n.x, n.y, n.z};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) node.moment[3 * i + j] += nv[i] * d[j];
    }
    for (const Vec3& p : triangles_[f])
      node.radius = std::max(node.radius, distance(p, node.centre));
  }

  if (count <= kLeafFacets) {
    node.first = first;
    node.count = count;
    nodes_[index] = node;
    return index;
  }
  // Split at the median centroid along the longest axis of the centroids' box.
  Bbox3 box;
  for (std::uint32_t f = first; f < first + count; ++f) box.add(centroid(triangles_[f]));
  const double ex = box.max.x - box.min.x, ey = box.max.y - box.min.y, ez = box.max.z - box.min.z;
  const int axis = ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
  const auto key = [axis](const std::array<Vec3, 3>& t) {
    const Vec3 c = centroid(t);
    return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
  };
  const std::uint32_t half = count / 2;
  std::nth_element(triangles_.begin() + first, triangles_.begin() + first + half,
                   triangles_.begin() + first + count,
                   [&](const auto& a, const auto& b) { return key(a) < key(b); });
  node.left = build(first, half);
  node.right = build(first + half, count - half);
  nodes_[index] = node;
  return index;
}

double WindingNumberTree::direct_sum(std::uint32_t first, std::uint32_t count,
                                     const Vec3& q) const {
  double sum = 0.0;
  for (std::uint32_t f = first; f < first + count; ++f) {
    const auto& t = triangles_[f];
    sum += triangle_solid_angle(q, t[0], t[1], t[2]);
  }
  return sum / kFourPi;
}

double WindingNumberTree::evaluate(const Vec3& q, double beta) const {
  if (nodes_.empty()) return 0.0;
  double sum = 0.0;
  std::uint32_t stack[80];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    const double d[3] = {node.centre.x - q.x, node.centre.y - q.y, node.centre.z - q.z};
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (r2 > beta * beta * node.radius * node.radius) {
      // Far field: the dipole term and its first correction (Barill et al. 2018, eq. 9-10).
      const double r = std::sqrt(r2);
      const double inv_r3 = 1.0 / (r2 * r);
      const double inv_r5 = inv_r3 / r2;
      const double dipole =
          (node.normal_sum.x * d[0] + node.normal_sum.y * d[1] + node.normal_sum.z * d[2]) * inv_r3;
      const auto& m = node.moment;
      const double trace = m[0] + m[4] + m[8];
      double dmd = 0.0;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) dmd += d[i] * m[3 * i + j] * d[j];
      }
      sum += (dipole + trace * inv_r3 - 3.0 * dmd * inv_r5) / kFourPi;
    } else if (node.count > 0) {
      sum += direct_sum(node.first, node.count, q);
    } else {
      // Median splits keep the depth below 33 for 2^32 facets: the stack holds at most depth + 1.
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  return sum;
}

double WindingNumberTree::evaluate_direct(const Vec3& q) const {
  return direct_sum(0, static_cast<std::uint32_t>(triangles_.size()), q);
}

}  // namespace strata::winding
