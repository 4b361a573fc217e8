#pragma once

// Is a layer's chained set of loops "simple" (issue 3)? Every chain closed, no two pieces of the
// loops crossing or touching (except consecutive pieces of one chain at their shared end), and
// orientations alternating with nesting depth (outer loops counter-clockwise at even depth,
// holes clockwise at odd depth). Only then is every loop a boundary of the region the fill rule
// fills, under nonzero and evenodd alike; otherwise both paths take the outline of that region.
//
// The points are crossing points known exactly to a Geometry (the fast path's mesh edges, the
// exact path's rationals) and approximately in double. Every decision is exact: the doubles with
// a rigorous error bound decide what they can, the Geometry's exact predicates the rest.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contour/chain_segments.hpp"
#include "predicates/filtered_sign.hpp"
#include "strata/mesh/vec3.hpp"

namespace strata::detail {

/// One end of one segment of a layer.
struct SegmentEnd {
  std::uint32_t segment = 0;
  std::uint32_t end = 0;  ///< 0 its start, 1 its end
};

/// What check_loops finds about a layer's chains.
struct LoopCheck {
  bool all_closed = true;
  /// Two pieces cross or touch: pieces of different chains, or of one chain that are not
  /// consecutive in it (zero-length segments are no pieces; consecutive pieces share an end).
  bool contacts = false;
  /// Orientation alternates with nesting depth; decided only for closed chains without contacts
  /// (`nesting_decided`), true otherwise.
  bool alternates = true;
  bool nesting_decided = false;
  /// Per chain, when nesting_decided: +1 counter-clockwise, -1 clockwise, decided exactly at the
  /// loop's lexicographically smallest vertex; 0 for a loop that bounds nothing (fewer than three
  /// pieces, or flat there).
  std::vector<int> orientation;
  /// Per chain, when nesting_decided: the number of loops of non-zero orientation containing it.
  std::vector<int> depth;

  bool simple() const { return all_closed && !contacts && alternates; }
};

/// The checker over a Geometry, which provides for SegmentEnd points:
///   Point2 approx(SegmentEnd) const;          double coordinates, within margin() of the exact
///   double margin() const;                    bound on |approx - exact| per coordinate
///   std::uint64_t key(SegmentEnd) const;      equal keys imply equal exact points
///   int exact_orientation(a, b, c) const;     sign of (b - a) x (c - a), exact
///   int exact_compare_x(a, b) const;          sign of a.x - b.x, exact (likewise _y)
template <class Geometry>
class LoopChecker {
 public:
  LoopChecker(const Geometry& geometry, const std::vector<SegmentChain>& chains)
      : g_(geometry), chains_(chains), m_(geometry.margin()) {}

  LoopCheck run() {
    LoopCheck out;
    for (const SegmentChain& c : chains_) out.all_closed = out.all_closed && c.closed;
    build_pieces();
    out.contacts = find_contacts();
    if (out.all_closed && !out.contacts) nest(out);
    return out;
  }

  /// Exact comparisons, filtered (public for tests).
  int compare_x(SegmentEnd a, SegmentEnd b) const {
    const double d = g_.approx(a).x - g_.approx(b).x;
    if (d > 2.5 * m_) return 1;
    if (-d > 2.5 * m_) return -1;
    ++exact_fallback_counter();
    return g_.exact_compare_x(a, b);
  }
  int compare_y(SegmentEnd a, SegmentEnd b) const {
    const double d = g_.approx(a).y - g_.approx(b).y;
    if (d > 2.5 * m_) return 1;
    if (-d > 2.5 * m_) return -1;
    ++exact_fallback_counter();
    return g_.exact_compare_y(a, b);
  }
  int compare_xy(SegmentEnd a, SegmentEnd b) const {
    const int cx = compare_x(a, b);
    return cx != 0 ? cx : compare_y(a, b);
  }
  bool same_point(SegmentEnd a, SegmentEnd b) const {
    return g_.key(a) == g_.key(b) || compare_xy(a, b) == 0;
  }
  int orientation(SegmentEnd a, SegmentEnd b, SegmentEnd c) const {
    using E = ErrorBoundedDouble;
    const Point2 pa = g_.approx(a);
    const Point2 pb = g_.approx(b);
    const Point2 pc = g_.approx(c);
    const E ax(pa.x, m_), ay(pa.y, m_), bx(pb.x, m_), by(pb.y, m_), cx(pc.x, m_), cy(pc.y, m_);
    const E r = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    const int s = certain_sign(r);
    if (s != 2) return s;
    ++exact_fallback_counter();
    return g_.exact_orientation(a, b, c);
  }

  /// Do the closed segments [a, b] and [c, d] (each of non-zero length) share a point? Exact.
  bool segments_meet(SegmentEnd a, SegmentEnd b, SegmentEnd c, SegmentEnd d) const {
    if (g_.key(a) == g_.key(c) || g_.key(a) == g_.key(d) || g_.key(b) == g_.key(c) ||
        g_.key(b) == g_.key(d)) {
      return true;
    }
    const int o1 = orientation(a, b, c);
    const int o2 = orientation(a, b, d);
    if (o1 * o2 > 0) return false;
    const int o3 = orientation(c, d, a);
    const int o4 = orientation(c, d, b);
    if (o3 * o4 > 0) return false;
    if (o1 == 0 && o2 == 0) {
      // Collinear: they meet when their spans overlap, in lexicographic order along the line.
      const bool ab = compare_xy(a, b) < 0;
      const bool cd = compare_xy(c, d) < 0;
      const SegmentEnd lo1 = ab ? a : b, hi1 = ab ? b : a;
      const SegmentEnd lo2 = cd ? c : d, hi2 = cd ? d : c;
      return compare_xy(hi1, lo2) >= 0 && compare_xy(hi2, lo1) >= 0;
    }
    // Not collinear, and each segment's ends are on both sides of (or on) the other's line.
    return true;
  }

 private:
  struct Piece {
    std::uint32_t segment;
    std::uint32_t chain;
    std::uint32_t position;  ///< among the chain's pieces
    double x_min, x_max, y_min, y_max;
  };

  static SegmentEnd start_of(std::uint32_t s) { return {s, 0}; }
  static SegmentEnd end_of(std::uint32_t s) { return {s, 1}; }

  void build_pieces() {
    chain_first_.assign(chains_.size() + 1, 0);
    std::size_t segments = 0;
    for (const SegmentChain& c : chains_) segments += c.segments.size();
    pieces_.reserve(segments);  // grown a piece at a time, it was copied a dozen times a layer
    for (std::uint32_t c = 0; c < chains_.size(); ++c) {
      chain_first_[c] = static_cast<std::uint32_t>(pieces_.size());
      std::uint32_t position = 0;
      for (const std::uint32_t s : chains_[c].segments) {
        if (same_point(start_of(s), end_of(s))) continue;
        const Point2 p = g_.approx(start_of(s));
        const Point2 q = g_.approx(end_of(s));
        pieces_.push_back({s, c, position++, std::min(p.x, q.x) - m_, std::max(p.x, q.x) + m_,
                           std::min(p.y, q.y) - m_, std::max(p.y, q.y) + m_});
      }
    }
    chain_first_[chains_.size()] = static_cast<std::uint32_t>(pieces_.size());
  }

  std::uint32_t piece_count(std::uint32_t chain) const {
    return chain_first_[chain + 1] - chain_first_[chain];
  }

  bool consecutive(const Piece& p, const Piece& q) const {
    if (p.chain != q.chain) return false;
    const std::uint32_t lo = std::min(p.position, q.position);
    const std::uint32_t hi = std::max(p.position, q.position);
    if (hi - lo == 1) return true;
    return chains_[p.chain].closed && lo == 0 && hi + 1 == piece_count(p.chain);
  }

  bool pieces_meet(const Piece& p, const Piece& q) const {
    return segments_meet(start_of(p.segment), end_of(p.segment), start_of(q.segment),
                         end_of(q.segment));
  }

  /// Pairs are found on a uniform grid of about one piece a bucket; within a bucket, pieces are
  /// swept in x. A pair is tested only in the bucket holding the lower-left corner of the
  /// intersection of their boxes, so once. O(n) buckets and insertions for pieces no longer than
  /// a bucket; the first contact ends the search.
  bool find_contacts() const {
    const std::size_t n = pieces_.size();
    if (n < 2) return false;
    double x0 = pieces_[0].x_min, x1 = pieces_[0].x_max;
    double y0 = pieces_[0].y_min, y1 = pieces_[0].y_max;
    for (const Piece& p : pieces_) {
      x0 = std::min(x0, p.x_min);
      x1 = std::max(x1, p.x_max);
      y0 = std::min(y0, p.y_min);
      y1 = std::max(y1, p.y_max);
    }
    const double w = x1 - x0;
    const double h = y1 - y0;
    constexpr double kMaxBucketsPerSide = 1024.0;
    double cell = std::sqrt(w * h / static_cast<double>(n));
    cell = std::max(cell, std::max(w, h) / kMaxBucketsPerSide);
    if (!(cell > 0.0) || !std::isfinite(cell)) cell = 1.0;
    const auto count_of = [&](double extent) {
      return static_cast<std::int64_t>(
          std::clamp(std::floor(extent / cell) + 1.0, 1.0, kMaxBucketsPerSide + 1.0));
    };
    const std::int64_t nx = count_of(w);
    const std::int64_t ny = count_of(h);
    const auto column = [&](double x) {
      return std::clamp<std::int64_t>(static_cast<std::int64_t>((x - x0) / cell), 0, nx - 1);
    };
    const auto row = [&](double y) {
      return std::clamp<std::int64_t>(static_cast<std::int64_t>((y - y0) / cell), 0, ny - 1);
    };
    // Each piece's buckets, found once: its columns i0..i1 and rows j0..j1.
    struct Span {
      std::int64_t i0, i1, j0, j1;
    };
    std::vector<Span> spans(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Piece& p = pieces_[k];
      spans[k] = {column(p.x_min), column(p.x_max), row(p.y_min), row(p.y_max)};
    }
    // Most pieces are shorter than a bucket and lie in one: those skip the loops over buckets.
    const auto single = [](const Span& s) { return s.i0 == s.i1 && s.j0 == s.j1; };
    std::vector<std::uint32_t> offsets(static_cast<std::size_t>(nx * ny) + 1, 0);
    for (const Span& s : spans) {
      if (single(s)) {
        ++offsets[s.j0 * nx + s.i0 + 1];
        continue;
      }
      for (std::int64_t j = s.j0; j <= s.j1; ++j) {
        for (std::int64_t i = s.i0; i <= s.i1; ++i) ++offsets[j * nx + i + 1];
      }
    }
    for (std::size_t b = 1; b < offsets.size(); ++b) offsets[b] += offsets[b - 1];
    std::vector<std::uint32_t> items(offsets.back());
    {
      std::vector<std::uint32_t> cursor(offsets.begin(), offsets.end() - 1);
      for (std::uint32_t k = 0; k < n; ++k) {
        const Span& s = spans[k];
        if (single(s)) {
          items[cursor[s.j0 * nx + s.i0]++] = k;
          continue;
        }
        for (std::int64_t j = s.j0; j <= s.j1; ++j) {
          for (std::int64_t i = s.i0; i <= s.i1; ++i) items[cursor[j * nx + i]++] = k;
        }
      }
    }
    for (std::int64_t b = 0; b < nx * ny; ++b) {
      const auto first = items.begin() + offsets[b];
      const auto last = items.begin() + offsets[b + 1];
      if (last - first < 2) continue;
      std::sort(first, last, [&](std::uint32_t u, std::uint32_t v) {
        return pieces_[u].x_min < pieces_[v].x_min;
      });
      for (auto u = first; u != last; ++u) {
        const Piece& p = pieces_[*u];
        for (auto v = u + 1; v != last && pieces_[*v].x_min <= p.x_max; ++v) {
          const Piece& q = pieces_[*v];
          if (q.y_min > p.y_max || p.y_min > q.y_max) continue;
          // Most pairs found are neighbours in a chain: that test first, it is the cheaper.
          if (consecutive(p, q)) continue;
          // A pair is looked at in one bucket only: the one holding the lower left corner of
          // their boxes' overlap (row and column grow with y and x, so the larger of the two
          // pieces' first rows and columns).
          const Span& sp = spans[*u];
          const Span& sq = spans[*v];
          if (std::max(sp.j0, sq.j0) * nx + std::max(sp.i0, sq.i0) != b) continue;
          if (pieces_meet(p, q)) return true;
        }
      }
    }
    return false;
  }

  /// Exact: is point r strictly inside the loop of `chain` (nonzero winding)? r is not on it
  /// (there are no contacts); a point found on it counts as outside.
  bool inside_loop(SegmentEnd r, std::uint32_t chain) const {
    int winding = 0;
    for (std::uint32_t k = chain_first_[chain]; k < chain_first_[chain + 1]; ++k) {
      const SegmentEnd a = start_of(pieces_[k].segment);
      const SegmentEnd b = end_of(pieces_[k].segment);
      const int ya = compare_y(a, r);
      const int yb = compare_y(b, r);
      if (ya <= 0 && yb > 0) {
        const int o = orientation(a, b, r);
        if (o == 0) return false;
        if (o > 0) ++winding;
      } else if (ya > 0 && yb <= 0) {
        const int o = orientation(a, b, r);
        if (o == 0) return false;
        if (o < 0) --winding;
      }
    }
    return winding != 0;
  }

  void nest(LoopCheck& out) const {
    out.nesting_decided = true;
    const std::uint32_t chains = static_cast<std::uint32_t>(chains_.size());
    out.orientation.assign(chains, 0);
    out.depth.assign(chains, 0);
    struct Box {
      double x_min, x_max, y_min, y_max;
    };
    std::vector<Box> boxes(chains);
    std::vector<std::uint32_t> bounding;  // loops of non-zero orientation
    for (std::uint32_t c = 0; c < chains; ++c) {
      const std::uint32_t n = piece_count(c);
      if (n < 3) continue;
      const std::uint32_t first = chain_first_[c];
      std::uint32_t best = first;
      Box box{pieces_[first].x_min, pieces_[first].x_max, pieces_[first].y_min,
              pieces_[first].y_max};
      for (std::uint32_t k = first + 1; k < first + n; ++k) {
        const Piece& p = pieces_[k];
        box = {std::min(box.x_min, p.x_min), std::max(box.x_max, p.x_max),
               std::min(box.y_min, p.y_min), std::max(box.y_max, p.y_max)};
        // Cheap first: only pieces whose start may be the smallest need the exact comparison.
        if (g_.approx(start_of(p.segment)).x - 2.5 * m_ >
            g_.approx(start_of(pieces_[best].segment)).x) {
          continue;
        }
        if (compare_xy(start_of(p.segment), start_of(pieces_[best].segment)) < 0) best = k;
      }
      const std::uint32_t previous = best == first ? first + n - 1 : best - 1;
      const int o = orientation(start_of(pieces_[previous].segment),
                                start_of(pieces_[best].segment), end_of(pieces_[best].segment));
      out.orientation[c] = o;
      boxes[c] = box;
      if (o != 0) bounding.push_back(c);
    }
    if (bounding.size() > 1) {
      for (const std::uint32_t c : bounding) {
        const SegmentEnd probe = start_of(pieces_[chain_first_[c]].segment);
        const Point2 p = g_.approx(probe);
        int depth = 0;
        for (const std::uint32_t d : bounding) {
          if (d == c) continue;
          const Box& b = boxes[d];
          if (p.x < b.x_min || p.x > b.x_max || p.y < b.y_min || p.y > b.y_max) continue;
          if (inside_loop(probe, d)) ++depth;
        }
        out.depth[c] = depth;
      }
    }
    for (const std::uint32_t c : bounding) {
      if ((out.depth[c] % 2 == 0) != (out.orientation[c] > 0)) {
        out.alternates = false;
        break;
      }
    }
  }

  const Geometry& g_;
  const std::vector<SegmentChain>& chains_;
  double m_;
  std::vector<Piece> pieces_;
  std::vector<std::uint32_t> chain_first_;  ///< pieces of chain c: [chain_first_[c], [c + 1])
};

/// Checks a layer's chains (see LoopChecker) exactly.
template <class Geometry>
LoopCheck check_loops(const Geometry& geometry, const std::vector<SegmentChain>& chains) {
  return LoopChecker<Geometry>(geometry, chains).run();
}

}  // namespace strata::detail
