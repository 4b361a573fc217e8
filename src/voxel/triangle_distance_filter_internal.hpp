#pragma once

// A double filter in front of triangle_closer_than(): most (cell, facet) pairs are decided by
// bounds that hold despite rounding, and only the pairs within the rounding bands reach the
// exact predicate.
//  - accept: a computed point q of the triangle (a convex combination) with |p - q| + error < t;
//  - reject: the distance to the facet's bounding box, or to the plane of the facet combined with
//    the half-plane of one of its edges, exceeds t by more than its rounding error.
// Error bounds are forward bounds in units of the unit roundoff u, taken generously (each
// constant is at least twice what the operation count gives).

#include <algorithm>
#include <cmath>
#include <limits>

#include "voxel/point_triangle_distance_internal.hpp"

namespace strata::detail {

class TriangleDistanceFilter {
 public:
  TriangleDistanceFilter(const Vec3& a, const Vec3& b, const Vec3& c, double t)
      : a_(a), b_(b), c_(c), t_(t), t2_(t * t) {
    const Vec3* v[3] = {&a, &b, &c};
    lo_ = hi_ = a;
    for (const Vec3* p : v) {
      lo_ = {std::min(lo_.x, p->x), std::min(lo_.y, p->y), std::min(lo_.z, p->z)};
      hi_ = {std::max(hi_.x, p->x), std::max(hi_.y, p->y), std::max(hi_.z, p->z)};
    }
    e1_ = sub(b, a);
    e2_ = sub(c, a);
    scale_ = std::max({max_abs(e1_), max_abs(e2_), max_abs(sub(c, b))});
    n_ = cross(e1_, e2_);
    nn_ = dot(n_, n_);
    const double l2 = scale_ * scale_;
    err_nn_ = 400.0 * kU * l2 * l2;
    has_plane_ = nn_ > 2.0 * err_nn_;
    len_ = std::sqrt(nn_);
    if (has_plane_) {
      const double err_mm = 6000.0 * kU * l2 * l2 * l2;
      for (int i = 0; i < 3; ++i) {
        const Vec3 e = sub(*v[(i + 1) % 3], *v[i]);
        m_[i] = cross(e, n_);  // outward in-plane normal of edge i
        mm_[i] = dot(m_[i], m_[i]);
        has_edge_[i] = mm_[i] > 2.0 * err_mm;
        inv_mm_[i] = 1.0 / (mm_[i] + err_mm);
      }
      inv_nn_ = 1.0 / (nn_ + err_nn_);
    }
    coord_scale_ = std::max(max_abs(a), max_abs(b));
    coord_scale_ = std::max(coord_scale_, max_abs(c));
  }

  /// Exactly whether the distance from p to the triangle is less than t.
  bool closer_than(const Vec3& p) const {
    const int quick = decide(p);
    if (quick != kUndecided) return quick == kCloser;
    return triangle_closer_than(p, a_, b_, c_, t_);
  }

  /// For tests: 1 closer, 0 not closer, -1 left to the exact predicate.
  int decide(const Vec3& p) const {
    // Reject by the bounding box.
    const double bx = std::max({lo_.x - p.x, 0.0, p.x - hi_.x});
    const double by = std::max({lo_.y - p.y, 0.0, p.y - hi_.y});
    const double bz = std::max({lo_.z - p.z, 0.0, p.z - hi_.z});
    if ((bx * bx + by * by + bz * bz) * (1.0 - 16.0 * kU) > t2_ * (1.0 + 16.0 * kU))
      return kFarther;

    // Reject by the plane and an edge's half-plane: the triangle lies in their intersection.
    // Tried before accepting, as most pairs the shell tests end farther than t.
    bool projection_outside = false;
    if (has_plane_) {
      const double l2 = scale_ * scale_;
      const Vec3 w = sub(p, a_);
      // Bounds every |p - vertex| component: |p - b| <= |p - a| + |b - a|, likewise c.
      const double w_scale = max_abs(w) + scale_;
      const double nw = std::fabs(dot(n_, w));
      const double err_nw = 100.0 * kU * l2 * w_scale;
      const double plane_num = std::max(0.0, nw - err_nw);
      // Multiplying by the rounded reciprocal adds two roundings, far inside the 64 u below.
      const double plane2 = plane_num * plane_num * inv_nn_;
      double edge2 = 0.0;
      const Vec3* v[3] = {&a_, &b_, &c_};
      const double err_m_dot = 600.0 * kU * l2 * scale_ * w_scale;
      for (int i = 0; i < 3; ++i) {
        if (!has_edge_[i]) continue;
        const double mw = dot(m_[i], sub(p, *v[i])) - err_m_dot;
        if (mw > 0.0) edge2 = std::max(edge2, mw * mw * inv_mm_[i]);
      }
      if ((plane2 + edge2) * (1.0 - 64.0 * kU) > t2_ * (1.0 + 64.0 * kU)) return kFarther;
      projection_outside = edge2 > 0.0;
    }

    // Accept by a point of the triangle.
    const double p_scale = max_abs(p);
    const Vec3 q = closest_point_estimate(p);
    const Vec3 d = sub(p, q);
    const double dist = std::sqrt(dot(d, d));
    const double q_error = 16.0 * kU * (coord_scale_ + p_scale + 2.0 * scale_) * 1.7320508075688772;
    if (dist * (1.0 + 16.0 * kU) + q_error < t_ * (1.0 - 16.0 * kU)) return kCloser;
    // Reject by the edges: the bound above takes the line of one edge, and beside a corner the
    // facet is farther than that line. Reached by a few percent of the tests.
    if (projection_outside && edges_farther(p)) return kFarther;
    return kUndecided;
  }

  /// One side of a half-plane of the layer that holds every point closer than t to the
  /// triangle: along the row y, x <= x_ref + slope (y - y_ref) + margin (upper) or
  /// x >= x_ref + slope (y - y_ref) - margin (lower). The margin is relative, 1e-6 of every
  /// quantity involved, far above the rounding of these few double operations, so a bound
  /// leaves out only centres the exact predicate would reject.
  struct RowBound {
    double x_ref, slope, y_ref, margin;
    bool upper;
    /// Narrows [x_lo, x_hi] on row y.
    void clip(double y, double& x_lo, double& x_hi) const {
      const double x = x_ref + slope * (y - y_ref);
      if (upper) {
        x_hi = std::min(x_hi, x + margin);
      } else {
        x_lo = std::max(x_lo, x - margin);
      }
    }
  };
  static constexpr int kMaxRowBounds = 5;

  /// The bounds on the rows of layer z with y in [y_lo, y_hi] and x in [x_lo, x_hi] (the
  /// facet's reach): the slab of the facet's plane (two sides) and, for each edge, the plane
  /// through it perpendicular to the facet, which a point closer than t lies less than t
  /// outside of. Planes nearly parallel to the rows (|m.x| < 1e-3 |m|) give no bound; a facet
  /// without a reliable plane gives none. Returns how many were written to `out`.
  int row_bounds(double z, double y_lo, double y_hi, double x_lo, double x_hi,
                 RowBound* out) const {
    if (!has_plane_) return 0;
    int count = 0;
    const double width = x_hi - x_lo;
    const auto add = [&](const Vec3& m, double len, const Vec3& v, bool two_sided) {
      if (!(std::fabs(m.x) >= 1e-3 * len)) return;
      const double reach = t_ * len;
      const double cz = m.z * (z - v.z);
      const double slope = -m.y / m.x;
      const double y_span = std::max(std::fabs(y_lo - v.y), std::fabs(y_hi - v.y));
      const double scale = std::fabs(v.x) +
                           (reach + std::fabs(cz) + len * scale_) / std::fabs(m.x) +
                           std::fabs(slope) * y_span + width;
      const double margin = 1e-6 * scale;
      // m.x (x - v.x) + m.y (y - v.y) + cz < reach, and > -reach for the plane's other side.
      const double x_at = v.x + (reach - cz) / m.x;
      out[count++] = {x_at, slope, v.y, margin, m.x > 0.0};
      if (two_sided) out[count++] = {v.x + (-reach - cz) / m.x, slope, v.y, margin, m.x < 0.0};
    };
    add(n_, len_, a_, true);
    const Vec3* v[3] = {&a_, &b_, &c_};
    for (int i = 0; i < 3; ++i) {
      if (has_edge_[i]) add(m_[i], std::sqrt(mm_[i]), *v[i], false);
    }
    return count;
  }

  static constexpr int kCloser = 1;
  static constexpr int kFarther = 0;
  static constexpr int kUndecided = -1;

 private:
  static constexpr double kU = 0x1p-53;

  static Vec3 sub(const Vec3& p, const Vec3& q) { return {p.x - q.x, p.y - q.y, p.z - q.z}; }
  static double dot(const Vec3& p, const Vec3& q) { return p.x * q.x + p.y * q.y + p.z * q.z; }
  static Vec3 cross(const Vec3& p, const Vec3& q) {
    return {p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x};
  }
  static double max_abs(const Vec3& p) {
    return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  }

  /// Whether every edge (as a segment) is certainly farther than t from p. Only valid when p's
  /// projection on the plane is certainly outside the triangle: then the closest point is on an
  /// edge. An edge's distance is at least that to its line, |w x e| / |e| (w = p - start), and
  /// is that to an end when p lies certainly beyond it along the edge.
  bool edges_farther(const Vec3& p) const {
    const Vec3* v[3] = {&a_, &b_, &c_};
    Vec3 w[3];
    double w_len[3];
    double w_scale[3];
    for (int i = 0; i < 3; ++i) {
      w[i] = sub(p, *v[i]);
      w_scale[i] = max_abs(w[i]);
      // |p - v_i| from below: each component of w is within u of its value.
      w_len[i] = std::sqrt(dot(w[i], w[i])) * (1.0 - 16.0 * kU) - 4.0 * kU * w_scale[i];
    }
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const Vec3 e = sub(*v[j], *v[i]);
      const double e_scale = max_abs(e);
      const double err_dot = 32.0 * kU * std::max(w_scale[i], w_scale[j]) * e_scale;
      double bound = 0.0;
      if (dot(w[i], e) < -err_dot) {
        bound = w_len[i];  // before the start: the start is the nearest point
      } else if (dot(w[j], e) > err_dot) {
        bound = w_len[j];  // past the end
      }
      const Vec3 c = cross(w[i], e);
      const double c_error = 64.0 * kU * w_scale[i] * e_scale;
      const double c_len = std::sqrt(dot(c, c)) * (1.0 - 16.0 * kU) - c_error;
      const double e_len = std::sqrt(dot(e, e)) * (1.0 + 16.0 * kU) + 4.0 * kU * e_scale;
      if (c_len > 0.0 && e_len > 0.0) bound = std::max(bound, c_len / e_len * (1.0 - 4.0 * kU));
      nearest = std::min(nearest, bound);
    }
    return nearest > t_ * (1.0 + 16.0 * kU);
  }

  /// A point of the triangle near the closest one (Voronoi regions of the triangle), returned as
  /// a + v e1 + w e2 with v, w >= 0 and v + w <= 1, so it is a convex combination whatever the
  /// rounding in the region tests.
  Vec3 closest_point_estimate(const Vec3& p) const {
    const Vec3 ap = sub(p, a_);
    const double d1 = dot(e1_, ap);
    const double d2 = dot(e2_, ap);
    double v = 0.0, w = 0.0;
    if (d1 <= 0.0 && d2 <= 0.0) return combine(0.0, 0.0);
    const Vec3 bp = sub(p, b_);
    const double d3 = dot(e1_, bp);
    const double d4 = dot(e2_, bp);
    if (d3 >= 0.0 && d4 <= d3) return combine(1.0, 0.0);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
      v = d1 - d3 != 0.0 ? d1 / (d1 - d3) : 0.0;
      return combine(v, 0.0);
    }
    const Vec3 cp = sub(p, c_);
    const double d5 = dot(e1_, cp);
    const double d6 = dot(e2_, cp);
    if (d6 >= 0.0 && d5 <= d6) return combine(0.0, 1.0);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
      w = d2 - d6 != 0.0 ? d2 / (d2 - d6) : 0.0;
      return combine(0.0, w);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
      const double denom = (d4 - d3) + (d5 - d6);
      w = denom != 0.0 ? (d4 - d3) / denom : 0.0;
      return combine(1.0 - w, w);
    }
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) return combine(0.0, 0.0);
    v = vb / sum;
    w = vc / sum;
    return combine(v, w);
  }

  Vec3 combine(double v, double w) const {
    v = std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0);
    w = std::clamp(std::isfinite(w) ? w : 0.0, 0.0, 1.0);
    if (v + w > 1.0) {
      const double s = v + w;
      v /= s;
      w /= s;
      // Division may round v + w just above 1: take w as what is left.
      w = std::min(w, 1.0 - v);
    }
    return {a_.x + v * e1_.x + w * e2_.x, a_.y + v * e1_.y + w * e2_.y,
            a_.z + v * e1_.z + w * e2_.z};
  }

  Vec3 a_, b_, c_;
  double t_, t2_;
  Vec3 lo_, hi_;
  Vec3 e1_, e2_, n_;
  double nn_ = 0.0, err_nn_ = 0.0, scale_ = 0.0, coord_scale_ = 0.0;
  double len_ = 0.0;  ///< |n|
  bool has_plane_ = false;
  Vec3 m_[3];
  double mm_[3] = {0.0, 0.0, 0.0};
  /// Whether edge i's |m|^2 is reliably above its rounding (6000 u l^6): only then does the edge
  /// bound a rejection or a row.
  bool has_edge_[3] = {false, false, false};
  double inv_mm_[3] = {0.0, 0.0, 0.0};  ///< 1 / (mm_ + its error bound)
  double inv_nn_ = 0.0;                 ///< 1 / (nn_ + err_nn_)
};

}  // namespace strata::detail
