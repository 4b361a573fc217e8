#include "strata/contour/assemble_contours.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "contour/chain_segments.hpp"
#include "contour/loop_check.hpp"
#include "contour/point_in_polygon_internal.hpp"
#include "predicates/crossing_predicates.hpp"

namespace strata {

namespace {

double shoelace(const std::vector<Point2>& points) {
  double twice = 0.0;
  for (std::size_t i = 0, n = points.size(); i < n; ++i) {
    const Point2& a = points[i];
    const Point2& b = points[(i + 1) % n];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

struct Box2 {
  double x_min, y_min, x_max, y_max;
  bool contains(const Point2& p) const {
    return p.x >= x_min && p.x <= x_max && p.y >= y_min && p.y <= y_max;
  }
};

Box2 box_of(const std::vector<Point2>& points) {
  Box2 b{points[0].x, points[0].y, points[0].x, points[0].y};
  for (const auto& p : points) {
    b.x_min = std::min(b.x_min, p.x);
    b.y_min = std::min(b.y_min, p.y);
    b.x_max = std::max(b.x_max, p.x);
    b.y_max = std::max(b.y_max, p.y);
  }
  return b;
}

void assign_nesting_depths(std::vector<Contour>& loops) {
  std::vector<std::size_t> closed;
  std::vector<Box2> boxes(loops.size());
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (loops[i].is_closed && loops[i].points.size() >= 3) {
      closed.push_back(i);
      boxes[i] = box_of(loops[i].points);
    }
  }
  for (const std::size_t i : closed) {
    const Point2& probe = loops[i].points.front();
    int depth = 0;
    for (const std::size_t j : closed) {
      if (i == j || !boxes[j].contains(probe)) continue;
      // One vertex decides containment when loops do not cross; a vertex on the other loop
      // counts as outside.
      if (detail::point_in_polygon(probe, loops[j].points) > 0) ++depth;
    }
    loops[i].depth = depth;
  }
}

/// The contours of the chains, as today: points are the segments' double start points (and the
/// end of an open chain's last segment); kind by the sign of the shoelace area.
LayerContours contours_of_chains(const LayerSegments& layer,
                                 const std::vector<detail::SegmentChain>& chains) {
  const auto& segments = layer.segments;
  LayerContours out;
  out.layer = layer.layer;
  out.z_mm = layer.z_mm;
  out.loops.reserve(chains.size());
  for (const detail::SegmentChain& chain : chains) {
    Contour contour;
    contour.points.reserve(chain.segments.size() + 1);
    for (const std::uint32_t s : chain.segments) contour.points.push_back(segments[s].start);
    contour.is_closed = chain.closed;
    if (chain.closed) {
      contour.signed_area_mm2 = shoelace(contour.points);
      contour.kind = contour.signed_area_mm2 >= 0.0 ? LoopKind::Outer : LoopKind::Hole;
      out.area_mm2 += contour.signed_area_mm2;
    } else {
      contour.points.push_back(segments[chain.segments.back()].end);
      contour.kind = LoopKind::Open;
      ++out.open_chains;
    }
    out.loops.push_back(std::move(contour));
  }
  return out;
}

/// The fast path's crossing points as a LoopChecker geometry. The exact point of a segment end
/// on edge lo -> hi is P = lo + (z - lo.z) / (hi.z - lo.z) * (hi - lo) (hi itself when
/// hi.z == z); in homogeneous form (X, Y, W) with W = hi.z - lo.z > 0, every predicate is the
/// sign of a polynomial in the input coordinates, evaluated on GMP rationals. The double points
/// of LayerSegment are within margin() of P.
class CrossingPointGeometry {
 public:
  CrossingPointGeometry(const IndexedMesh& mesh, const LayerSegments& layer)
      : mesh_(mesh), layer_(layer) {
    double largest = 0.0;
    for (const LayerSegment& s : layer.segments) {
      for (const CrossedEdge& e : {s.start_edge, s.end_edge}) {
        for (const VertexIndex v : {e.below, e.above}) {
          largest =
              std::max({largest, std::fabs(mesh.vertices[v].x), std::fabs(mesh.vertices[v].y)});
        }
      }
    }
    // Each coordinate of a crossing point is within crossing_point_error(a, b) of the exact one,
    // a and b its edge's, so within crossing_point_error(largest, largest); written as twice the
    // bound for (largest, 0), which is no smaller and stays finite up to the largest double.
    margin_ = 2.0 * detail::crossing_point_error(largest, 0.0);
  }

  Point2 approx(detail::SegmentEnd p) const {
    const LayerSegment& s = layer_.segments[p.segment];
    return p.end == 0 ? s.start : s.end;
  }
  double margin() const { return margin_; }
  std::uint64_t key(detail::SegmentEnd p) const {
    const CrossedEdge& e = edge(p);
    // A crossing at the upper vertex is that vertex, whichever edge it is found on.
    if (mesh_.vertices[e.above].z == layer_.z_mm) return (std::uint64_t{e.above} << 32) | e.above;
    return detail::crossed_edge_key(e);
  }
  int exact_orientation(detail::SegmentEnd a, detail::SegmentEnd b, detail::SegmentEnd c) const {
    const Homogeneous pa = homogeneous(a);
    const Homogeneous pb = homogeneous(b);
    const Homogeneous pc = homogeneous(c);
    // det [pa; pb; pc] = Wa Wb Wc ((b - a) x (c - a)), and every W > 0.
    const mpq_class det = pa.x * (pb.y * pc.w - pc.y * pb.w) - pa.y * (pb.x * pc.w - pc.x * pb.w) +
                          pa.w * (pb.x * pc.y - pc.x * pb.y);
    return sgn(det);
  }
  int exact_compare_x(detail::SegmentEnd a, detail::SegmentEnd b) const {
    return exact_compare(a, b, 0);
  }
  int exact_compare_y(detail::SegmentEnd a, detail::SegmentEnd b) const {
    return exact_compare(a, b, 1);
  }

 private:
  struct Homogeneous {
    mpq_class x, y, w;
  };

  const CrossedEdge& edge(detail::SegmentEnd p) const {
    const LayerSegment& s = layer_.segments[p.segment];
    return p.end == 0 ? s.start_edge : s.end_edge;
  }

  /// The end's coordinate on `axis` (0 for x, 1 for y) when it is a double itself: the upper
  /// vertex on the plane, or an edge that keeps the coordinate all along.
  std::optional<double> as_double(detail::SegmentEnd p, int axis) const {
    const CrossedEdge& e = edge(p);
    const Vec3& lo = mesh_.vertices[e.below];
    const Vec3& hi = mesh_.vertices[e.above];
    const double from = axis == 0 ? lo.x : lo.y;
    const double to = axis == 0 ? hi.x : hi.y;
    if (hi.z == layer_.z_mm) return to;
    if (from == to) return from;
    return std::nullopt;
  }

  /// The sign of a - b on `axis`: by the doubles when both ends are doubles (ends of vertical
  /// edges, and vertices on the plane, tie often), else on the one coordinate in homogeneous
  /// form, X / W.
  int exact_compare(detail::SegmentEnd a, detail::SegmentEnd b, int axis) const {
    const std::optional<double> da = as_double(a, axis);
    const std::optional<double> db = da ? as_double(b, axis) : std::nullopt;
    if (da && db) return (*da > *db) - (*da < *db);
    const auto [xa, wa] = homogeneous_coordinate(a, axis);
    const auto [xb, wb] = homogeneous_coordinate(b, axis);
    return sgn(mpq_class(xa * wb - xb * wa));
  }

  std::pair<mpq_class, mpq_class> homogeneous_coordinate(detail::SegmentEnd p, int axis) const {
    const CrossedEdge& e = edge(p);
    const Vec3& lo = mesh_.vertices[e.below];
    const Vec3& hi = mesh_.vertices[e.above];
    const double from = axis == 0 ? lo.x : lo.y;
    const double to = axis == 0 ? hi.x : hi.y;
    if (hi.z == layer_.z_mm) return {mpq_class(to), mpq_class(1)};
    const mpq_class w = mpq_class(hi.z) - mpq_class(lo.z);
    const mpq_class t = mpq_class(layer_.z_mm) - mpq_class(lo.z);
    return {mpq_class(mpq_class(from) * w + t * (mpq_class(to) - mpq_class(from))), w};
  }

  Homogeneous homogeneous(detail::SegmentEnd p) const {
    const CrossedEdge& e = edge(p);
    const Vec3& lo = mesh_.vertices[e.below];
    const Vec3& hi = mesh_.vertices[e.above];
    if (hi.z == layer_.z_mm) return {mpq_class(hi.x), mpq_class(hi.y), mpq_class(1)};
    const mpq_class w = mpq_class(hi.z) - mpq_class(lo.z);
    const mpq_class t = mpq_class(layer_.z_mm) - mpq_class(lo.z);
    return {mpq_class(mpq_class(lo.x) * w + t * (mpq_class(hi.x) - mpq_class(lo.x))),
            mpq_class(mpq_class(lo.y) * w + t * (mpq_class(hi.y) - mpq_class(lo.y))), w};
  }

  const IndexedMesh& mesh_;
  const LayerSegments& layer_;
  double margin_ = 0.0;
};

}  // namespace

LayerContours assemble_contours(const LayerSegments& layer) {
  LayerContours out = contours_of_chains(layer, detail::chain_segments(layer.segments));
  assign_nesting_depths(out.loops);
  return out;
}

LayerContours assemble_contours(const IndexedMesh& mesh, const LayerSegments& layer) {
  const std::vector<detail::SegmentChain> chains = detail::chain_segments(layer.segments);
  LayerContours out = contours_of_chains(layer, chains);
  const detail::LoopCheck check = detail::check_loops(CrossingPointGeometry(mesh, layer), chains);
  out.loops_cross = check.contacts;
  out.misnested = check.nesting_decided && !check.alternates;
  if (!check.nesting_decided) {
    assign_nesting_depths(out.loops);
    return out;
  }
  // Loops that neither cross nor touch: kind and depth as decided exactly.
  for (std::size_t c = 0; c < chains.size(); ++c) {
    Contour& loop = out.loops[c];
    loop.depth = check.depth[c];
    if (check.orientation[c] != 0) {
      loop.kind = check.orientation[c] > 0 ? LoopKind::Outer : LoopKind::Hole;
    }
  }
  return out;
}

}  // namespace strata
