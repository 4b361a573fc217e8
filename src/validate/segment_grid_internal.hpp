#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "strata/contour/contour.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata::validate::detail {

/// A contour set as what the Hausdorff distance needs: its vertices, and its pieces (segments;
/// a lone point is a segment of zero length).
struct PlanarPieces {
  std::vector<Point2> points;
  std::vector<std::pair<Point2, Point2>> segments;
};

inline PlanarPieces contour_pieces(std::span<const Contour> contours) {
  PlanarPieces out;
  for (const Contour& c : contours) {
    const std::size_t n = c.points.size();
    if (n == 0) continue;
    out.points.insert(out.points.end(), c.points.begin(), c.points.end());
    if (n == 1) {
      out.segments.emplace_back(c.points[0], c.points[0]);
      continue;
    }
    for (std::size_t i = 0; i + 1 < n; ++i) out.segments.emplace_back(c.points[i], c.points[i + 1]);
    if (c.is_closed) out.segments.emplace_back(c.points[n - 1], c.points[0]);
  }
  return out;
}

inline double point_segment_distance(const Point2& p, const Point2& a, const Point2& b) {
  const double ux = b.x - a.x;
  const double uy = b.y - a.y;
  const double vx = p.x - a.x;
  const double vy = p.y - a.y;
  const double len2 = ux * ux + uy * uy;
  double t = len2 > 0.0 ? (vx * ux + vy * uy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double dx = vx - t * ux;
  const double dy = vy - t * uy;
  return std::hypot(dx, dy);
}

/// A uniform grid over a set of segments for nearest-segment queries.
class SegmentGrid {
 public:
  /// @param bounds_with points that will be queried, so that the grid covers them too
  SegmentGrid(const PlanarPieces& pieces, std::span<const Point2> bounds_with)
      : segments_(pieces.segments) {
    const auto grow = [&](const Point2& r) {
      min_x_ = std::min(min_x_, r.x);
      min_y_ = std::min(min_y_, r.y);
      max_x_ = std::max(max_x_, r.x);
      max_y_ = std::max(max_y_, r.y);
    };
    for (const auto& [p, q] : segments_) {
      grow(p);
      grow(q);
    }
    for (const Point2& r : bounds_with) grow(r);
    const double width = max_x_ - min_x_;
    const double height = max_y_ - min_y_;
    const double n = static_cast<double>(std::max<std::size_t>(1, segments_.size()));
    // About one segment a bucket on a square grid; capped so the grid stays small.
    const double side = std::max(width, height);
    const double buckets_per_side = std::clamp(std::sqrt(n), 1.0, 1024.0);
    cell_ = side > 0.0 ? side / buckets_per_side : 1.0;
    if (!(cell_ > 0.0) || !std::isfinite(cell_)) cell_ = 1.0;
    nx_ = static_cast<std::int64_t>(std::clamp(std::floor(width / cell_) + 1, 1.0, 1024.0));
    ny_ = static_cast<std::int64_t>(std::clamp(std::floor(height / cell_) + 1, 1.0, 1024.0));
    std::vector<std::uint32_t> counts(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
    const auto for_each_bucket = [&](std::size_t s, auto&& f) {
      const auto& [p, q] = segments_[s];
      const std::int64_t i0 = column(std::min(p.x, q.x));
      const std::int64_t i1 = column(std::max(p.x, q.x));
      const std::int64_t j0 = row(std::min(p.y, q.y));
      const std::int64_t j1 = row(std::max(p.y, q.y));
      for (std::int64_t j = j0; j <= j1; ++j) {
        for (std::int64_t i = i0; i <= i1; ++i) f(static_cast<std::size_t>(j * nx_ + i));
      }
    };
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      for_each_bucket(s, [&](std::size_t b) { ++counts[b + 1]; });
    }
    for (std::size_t b = 1; b < counts.size(); ++b) counts[b] += counts[b - 1];
    offsets_ = counts;
    entries_.resize(offsets_.back());
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      for_each_bucket(
          s, [&](std::size_t b) { entries_[counts[b]++] = static_cast<std::uint32_t>(s); });
    }
  }

  /// max(h, the largest distance from a point to the nearest segment); stops searching for a
  /// point as soon as a segment within the running maximum is found.
  double directed_hausdorff(std::span<const Point2> points, double h) const {
    for (const Point2& p : points) h = std::max(h, nearest(p, h));
    return h;
  }

  /// Distance from p to the nearest segment, or any value <= `enough` once one is found within
  /// `enough`.
  double nearest(const Point2& p, double enough) const {
    const std::int64_t ci = column(p.x);
    const std::int64_t cj = row(p.y);
    double best = std::numeric_limits<double>::infinity();
    const std::int64_t max_ring = std::max(nx_, ny_);
    for (std::int64_t r = 0; r <= max_ring; ++r) {
      const double lower = ring_lower_bound(p, ci, cj, r);
      if (lower > best) break;
      const std::int64_t i0 = ci - r, i1 = ci + r, j0 = cj - r, j1 = cj + r;
      const auto scan = [&](std::int64_t i, std::int64_t j) {
        if (i < 0 || i >= nx_) return;
        const std::size_t b = static_cast<std::size_t>(j * nx_ + i);
        for (std::uint32_t e = offsets_[b]; e < offsets_[b + 1]; ++e) {
          const auto& [a, q] = segments_[entries_[e]];
          best = std::min(best, point_segment_distance(p, a, q));
        }
      };
      for (std::int64_t j = std::max<std::int64_t>(0, j0); j <= std::min(ny_ - 1, j1); ++j) {
        if (j == j0 || j == j1) {
          for (std::int64_t i = i0; i <= i1; ++i) scan(i, j);
        } else {
          scan(i0, j);
          if (i1 != i0) scan(i1, j);
        }
      }
      if (best <= enough) return best;
    }
    return best;
  }

 private:
  std::int64_t column(double x) const {
    const double c = std::floor((x - min_x_) / cell_);
    return static_cast<std::int64_t>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
  }
  std::int64_t row(double y) const {
    const double c = std::floor((y - min_y_) / cell_);
    return static_cast<std::int64_t>(std::clamp(c, 0.0, static_cast<double>(ny_ - 1)));
  }
  /// A lower bound of the distance from p to any bucket at Chebyshev ring r around (ci, cj).
  double ring_lower_bound(const Point2& p, std::int64_t ci, std::int64_t cj, std::int64_t r) const {
    if (r == 0) return 0.0;
    // Bucket (ci, cj) spans [lo, lo + cell) on each axis; a bucket r rings away starts at least
    // (r - 1) cells beyond it on one axis.
    const double x_lo = min_x_ + static_cast<double>(ci) * cell_;
    const double y_lo = min_y_ + static_cast<double>(cj) * cell_;
    const double gap_x = std::min(p.x - x_lo, x_lo + cell_ - p.x);
    const double gap_y = std::min(p.y - y_lo, y_lo + cell_ - p.y);
    const double reach = static_cast<double>(r - 1) * cell_;
    return std::max(0.0, reach + std::min(gap_x, gap_y));
  }

  std::vector<std::pair<Point2, Point2>> segments_;
  double min_x_ = std::numeric_limits<double>::infinity();
  double min_y_ = std::numeric_limits<double>::infinity();
  double max_x_ = -std::numeric_limits<double>::infinity();
  double max_y_ = -std::numeric_limits<double>::infinity();
  double cell_ = 1.0;
  std::int64_t nx_ = 1;
  std::int64_t ny_ = 1;
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> entries_;
};

}  // namespace strata::validate::detail
