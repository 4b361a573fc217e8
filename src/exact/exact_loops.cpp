#include <algorithm>
#include <optional>

#include "exact/exact_loops_internal.hpp"

namespace strata::exact::detail {
namespace {

using Point = Kernel::Point_2;

double shoelace(const std::vector<Point2>& points) {
  // Relative to the first point, so that far-from-origin parts lose no digits to cancellation.
  long double twice = 0.0L;
  const long double ox = points.front().x;
  const long double oy = points.front().y;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const long double ax = points[i].x - ox;
    const long double ay = points[i].y - oy;
    const long double bx = points[i + 1].x - ox;
    const long double by = points[i + 1].y - oy;
    twice += ax * by - bx * ay;
  }
  return static_cast<double>(0.5L * twice);
}

/// +1 counter-clockwise, -1 clockwise, 0 when the smallest vertex does not decide it (the loop
/// is flat there, or passes through it twice).
int orientation_at_smallest_vertex(const std::vector<ExactPoint2>& points) {
  const std::size_t n = points.size();
  std::size_t best = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (compare_xy(points[i], points[best]) < 0) best = i;
  }
  const auto is_best = [&](std::size_t i) { return compare_xy(points[i], points[best]) == 0; };
  std::size_t visits = 0;
  for (std::size_t i = 0; i < n; ++i) visits += is_best(i) ? 1 : 0;
  if (visits == n) return 0;
  // Repeated consecutive points (zero-length segments) are one visit.
  std::size_t first = best;
  while (is_best((first + n - 1) % n)) first = (first + n - 1) % n;
  std::size_t last = best;
  while (is_best((last + 1) % n)) last = (last + 1) % n;
  if ((last + n - first) % n + 1 != visits) return 0;
  const CGAL::Orientation o =
      CGAL::orientation(to_kernel(points[(first + n - 1) % n]), to_kernel(points[best]),
                        to_kernel(points[(last + 1) % n]));
  return o == CGAL::LEFT_TURN ? 1 : (o == CGAL::RIGHT_TURN ? -1 : 0);
}

struct Box {
  double x_min, y_min, x_max, y_max;
};

/// +1 strictly inside (nonzero winding), 0 on the boundary, -1 outside. Exact. Only the edges
/// that straddle p's row become kernel points: a few of the loop's, whatever its length.
int point_in_loop(const ExactPoint2& p, const Point& pk, const std::vector<ExactPoint2>& loop) {
  int winding = 0;
  const auto cmp_y = [](const ExactPoint2& a, const ExactPoint2& b) {
    if (a.y.rounded != b.y.rounded) return a.y.rounded < b.y.rounded ? -1 : 1;
    return a.y.exact() < b.y.exact() ? -1 : (b.y.exact() < a.y.exact() ? 1 : 0);
  };
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    const std::size_t k = (i + 1) % n;
    const int ay = cmp_y(loop[i], p);
    const int by = cmp_y(loop[k], p);
    if (ay <= 0) {
      if (by > 0) {
        const CGAL::Orientation o = CGAL::orientation(to_kernel(loop[i]), to_kernel(loop[k]), pk);
        if (o == CGAL::COLLINEAR) return 0;
        if (o == CGAL::LEFT_TURN) ++winding;
      } else if (ay == 0 && by == 0) {
        const int ax = compare_xy(loop[i], p);
        const int bx = compare_xy(loop[k], p);
        if (ax == 0 || bx == 0 || ax != bx) return 0;
      }
    } else if (by <= 0) {
      const CGAL::Orientation o = CGAL::orientation(to_kernel(loop[i]), to_kernel(loop[k]), pk);
      if (o == CGAL::COLLINEAR) return 0;
      if (o == CGAL::RIGHT_TURN) --winding;
    }
  }
  return winding != 0 ? 1 : -1;
}

/// A point of the loop's first edge of non-zero length (its midpoint), or its first point.
ExactPoint2 probe_of(const std::vector<ExactPoint2>& loop) {
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    const ExactPoint2& a = loop[i];
    const ExactPoint2& b = loop[(i + 1) % n];
    if (compare_xy(a, b) != 0) {
      return {RoundedRational((a.x.exact() + b.x.exact()) / 2),
              RoundedRational((a.y.exact() + b.y.exact()) / 2)};
    }
  }
  return loop.front();
}

}  // namespace

LayerContours finish_contours(std::uint32_t layer, double z_mm, std::vector<ExactLoop> loops,
                              std::uint32_t open_chains) {
  LayerContours out;
  out.layer = layer;
  out.z_mm = z_mm;
  out.open_chains = open_chains;
  out.loops.resize(loops.size());
  std::vector<std::size_t> closed;
  std::vector<Box> boxes(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    Contour& c = out.loops[l];
    c.points.reserve(loops[l].points.size() + 1);
    for (const ExactPoint2& p : loops[l].points) c.points.push_back(p.rounded());
    c.is_closed = loops[l].closed && !c.points.empty();
    if (!c.is_closed) {
      c.kind = LoopKind::Open;
      continue;
    }
    c.signed_area_mm2 = c.points.size() >= 3 ? shoelace(c.points) : 0.0;
    int orientation = c.points.size() >= 3 ? orientation_at_smallest_vertex(loops[l].points) : 0;
    if (orientation == 0) orientation = c.signed_area_mm2 >= 0.0 ? 1 : -1;
    c.kind = orientation > 0 ? LoopKind::Outer : LoopKind::Hole;
    out.area_mm2 += c.signed_area_mm2;
    if (c.points.size() >= 3) {
      closed.push_back(l);
      Box b{c.points[0].x, c.points[0].y, c.points[0].x, c.points[0].y};
      for (const Point2& p : c.points) {
        b.x_min = std::min(b.x_min, p.x);
        b.y_min = std::min(b.y_min, p.y);
        b.x_max = std::max(b.x_max, p.x);
        b.y_max = std::max(b.y_max, p.y);
      }
      boxes[l] = b;
    }
  }
  // Depth: loops of one layer may touch or (overlapping shells) cross, so the probe is a point
  // inside an edge, and a probe on another loop counts as outside it. Rounding to nearest is
  // monotone, so the rounded boxes are a safe first test.
  for (const std::size_t i : closed) {
    const ExactPoint2 probe = probe_of(loops[i].points);
    const Point2 pr = probe.rounded();
    std::optional<Point> probe_k;
    int depth = 0;
    for (const std::size_t j : closed) {
      if (i == j) continue;
      const Box& b = boxes[j];
      if (pr.x < b.x_min || pr.x > b.x_max || pr.y < b.y_min || pr.y > b.y_max) continue;
      if (!probe_k) probe_k = to_kernel(probe);
      if (point_in_loop(probe, *probe_k, loops[j].points) > 0) ++depth;
    }
    out.loops[i].depth = depth;
  }
  return out;
}

}  // namespace strata::exact::detail
