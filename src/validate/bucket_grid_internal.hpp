#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "strata/mesh/vec3.hpp"

namespace strata::validate::detail {

/// A uniform grid of buckets over a box, each bucket listing the items (points, facets) whose
/// bounding box meets it: the spatial index behind the nearest-item queries of the model
/// figures. About one item a bucket, at most kMaxBuckets buckets on an axis.
class BucketGrid3 {
 public:
  static constexpr double kMaxBuckets = 128.0;

  /// @param cover   box the grid must cover (the items and every point that will be queried)
  /// @param count   number of items
  /// @param box_of  box_of(item) is the bounding box of item 0 .. count-1
  template <class BoxOf>
  BucketGrid3(const Bbox3& cover, std::size_t count, BoxOf&& box_of) : lo_(cover.min) {
    const double ex = cover.max.x - cover.min.x;
    const double ey = cover.max.y - cover.min.y;
    const double ez = cover.max.z - cover.min.z;
    const double side = std::max({ex, ey, ez});
    const double per_side = std::clamp(
        std::cbrt(static_cast<double>(std::max<std::size_t>(1, count))), 1.0, kMaxBuckets);
    h_ = side > 0.0 && std::isfinite(side) ? side / per_side : 1.0;
    if (!(h_ > 0.0) || !std::isfinite(h_)) h_ = 1.0;
    n_[0] = axis_count(ex);
    n_[1] = axis_count(ey);
    n_[2] = axis_count(ez);
    const std::size_t buckets = static_cast<std::size_t>(n_[0] * n_[1] * n_[2]);
    std::vector<std::uint64_t> counts(buckets + 1, 0);
    const auto for_each_bucket = [&](const Bbox3& b, auto&& f) {
      const std::int64_t i0 = index(b.min.x, lo_.x, 0), i1 = index(b.max.x, lo_.x, 0);
      const std::int64_t j0 = index(b.min.y, lo_.y, 1), j1 = index(b.max.y, lo_.y, 1);
      const std::int64_t k0 = index(b.min.z, lo_.z, 2), k1 = index(b.max.z, lo_.z, 2);
      for (std::int64_t k = k0; k <= k1; ++k) {
        for (std::int64_t j = j0; j <= j1; ++j) {
          for (std::int64_t i = i0; i <= i1; ++i) f(bucket(i, j, k));
        }
      }
    };
    for (std::size_t item = 0; item < count; ++item) {
      for_each_bucket(box_of(item), [&](std::size_t q) { ++counts[q + 1]; });
    }
    for (std::size_t q = 1; q < counts.size(); ++q) counts[q] += counts[q - 1];
    offsets_ = counts;
    entries_.resize(offsets_.back());
    for (std::size_t item = 0; item < count; ++item) {
      for_each_bucket(box_of(item), [&](std::size_t q) {
        entries_[counts[q]++] = static_cast<std::uint32_t>(item);
      });
    }
  }

  /// The smallest distance(item) over the items, searching buckets ring by ring around p; once
  /// a ring is done with a value <= `enough`, that value is returned (it may not be the
  /// smallest). +infinity when there are no items.
  template <class Distance>
  double nearest(const Vec3& p, Distance&& distance,
                 double enough = -std::numeric_limits<double>::infinity()) const {
    const std::int64_t c[3] = {index(p.x, lo_.x, 0), index(p.y, lo_.y, 1), index(p.z, lo_.z, 2)};
    const double pc[3] = {p.x, p.y, p.z};
    const double lc[3] = {lo_.x, lo_.y, lo_.z};
    double gap = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      const double b_lo = lc[a] + static_cast<double>(c[a]) * h_;
      gap = std::min({gap, pc[a] - b_lo, b_lo + h_ - pc[a]});
    }
    gap = std::max(0.0, gap);
    double best = std::numeric_limits<double>::infinity();
    const std::int64_t max_ring = std::max({n_[0], n_[1], n_[2]});
    for (std::int64_t r = 0; r <= max_ring; ++r) {
      if (r > 0 && static_cast<double>(r - 1) * h_ + gap > best) break;
      for (std::int64_t k = std::max<std::int64_t>(0, c[2] - r); k <= std::min(n_[2] - 1, c[2] + r);
           ++k) {
        for (std::int64_t j = std::max<std::int64_t>(0, c[1] - r);
             j <= std::min(n_[1] - 1, c[1] + r); ++j) {
          const bool face = std::abs(k - c[2]) == r || std::abs(j - c[1]) == r;
          const std::int64_t step = face ? 1 : std::max<std::int64_t>(1, 2 * r);
          for (std::int64_t i = c[0] - r; i <= c[0] + r; i += step) {
            if (i < 0 || i >= n_[0]) continue;
            const std::size_t q = bucket(i, j, k);
            for (std::uint64_t e = offsets_[q]; e < offsets_[q + 1]; ++e) {
              best = std::min(best, distance(entries_[e]));
            }
          }
        }
      }
      if (best <= enough) return best;
    }
    return best;
  }

 private:
  std::int64_t axis_count(double extent) const {
    const double n = std::floor(extent / h_) + 1.0;
    return static_cast<std::int64_t>(std::clamp(n, 1.0, kMaxBuckets + 1.0));
  }
  std::int64_t index(double v, double lo, int axis) const {
    const double c = std::floor((v - lo) / h_);
    if (!(c >= 0.0)) return 0;  // also NaN
    return static_cast<std::int64_t>(std::min(c, static_cast<double>(n_[axis] - 1)));
  }
  std::size_t bucket(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return static_cast<std::size_t>((k * n_[1] + j) * n_[0] + i);
  }

  Vec3 lo_;
  double h_ = 1.0;
  std::int64_t n_[3] = {1, 1, 1};
  std::vector<std::uint64_t> offsets_;
  std::vector<std::uint32_t> entries_;
};

/// Euclidean distance from p to the triangle (a, b, c), in double (closest point by regions of
/// the triangle's plane, as in Ericson, Real-Time Collision Detection, 5.1.5).
inline double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto sub = [](const Vec3& u, const Vec3& v) {
    return Vec3{u.x - v.x, u.y - v.y, u.z - v.z};
  };
  const auto dot = [](const Vec3& u, const Vec3& v) { return u.x * v.x + u.y * v.y + u.z * v.z; };
  const auto at = [&](const Vec3& o, const Vec3& u, double s, const Vec3& v, double t) {
    return Vec3{o.x + s * u.x + t * v.x, o.y + s * u.y + t * v.y, o.z + s * u.z + t * v.z};
  };
  const auto dist = [&](const Vec3& q) {
    const Vec3 d = sub(p, q);
    return std::sqrt(dot(d, d));
  };
  const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return dist(a);
  const Vec3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return dist(b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return dist(at(a, ab, v, ac, 0));
  }
  const Vec3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return dist(c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return dist(at(a, ab, 0, ac, w));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return dist(Vec3{b.x + w * (c.x - b.x), b.y + w * (c.y - b.y), b.z + w * (c.z - b.z)});
  }
  const double denom = va + vb + vc;
  if (!(denom != 0.0)) {
    // Degenerate triangle (its regions are not defined): the nearest of its three edges.
    const auto seg = [&](const Vec3& u, const Vec3& v) {
      const Vec3 uv = sub(v, u);
      const double l2 = dot(uv, uv);
      const double t = l2 > 0 ? std::clamp(dot(sub(p, u), uv) / l2, 0.0, 1.0) : 0.0;
      return dist(Vec3{u.x + t * uv.x, u.y + t * uv.y, u.z + t * uv.z});
    };
    return std::min({seg(a, b), seg(b, c), seg(c, a)});
  }
  const double v = vb / denom, w = vc / denom;
  return dist(at(a, ab, v, ac, w));
}

}  // namespace strata::validate::detail
