#include "strata/validate/contour_metrics.hpp"

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "validate/segment_grid_internal.hpp"

namespace strata::validate {

namespace {

using Kernel = CGAL::Epeck;
using ExactFT = Kernel::Exact_kernel::FT;

/// The winding number change of each contour set across an edge, relative to the edge taken
/// from its lexicographically smaller end to its larger one: the region on the left of that
/// direction has winding (right) + delta.
struct WindingDelta {
  int a = 0;
  int b = 0;
};

struct MergeDeltas {
  WindingDelta operator()(const WindingDelta& x, const WindingDelta& y) const {
    return {x.a + y.a, x.b + y.b};
  }
};

using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_curve_data_traits_2<SegmentTraits, WindingDelta, MergeDeltas>;
using Arrangement = CGAL::Arrangement_2<Traits>;

struct DirectedEdge {
  Point2 from;
  Point2 to;
};

bool lex_less(const Point2& p, const Point2& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); }

/// The directed edges of the closed loops, zero-length ones left out (they bound nothing).
std::vector<DirectedEdge> loop_edges(std::span<const Contour> contours) {
  std::vector<DirectedEdge> edges;
  for (const Contour& c : contours) {
    if (!c.is_closed || c.points.size() < 2) continue;
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      const Point2& p = c.points[i];
      const Point2& q = c.points[(i + 1) % c.points.size()];
      if (p == q) continue;
      edges.push_back({p, q});
    }
  }
  return edges;
}

bool same_edges(std::vector<DirectedEdge> a, std::vector<DirectedEdge> b) {
  if (a.size() != b.size()) return false;
  const auto key = [](const DirectedEdge& e) {
    return std::make_tuple(e.from.x, e.from.y, e.to.x, e.to.y);
  };
  const auto less = [&](const DirectedEdge& x, const DirectedEdge& y) { return key(x) < key(y); };
  std::sort(a.begin(), a.end(), less);
  std::sort(b.begin(), b.end(), less);
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (key(a[i]) != key(b[i])) return false;
  }
  return true;
}

double net_area(std::span<const Contour> contours) {
  double area = 0.0;
  for (const Contour& c : contours) {
    if (c.is_closed) area += c.signed_area_mm2;
  }
  return area;
}

bool filled(int winding, FillRule rule) {
  return rule == FillRule::EvenOdd ? (winding & 1) != 0 : winding != 0;
}

SymmetricDifference overlay(const std::vector<DirectedEdge>& a, const std::vector<DirectedEdge>& b,
                            FillRule rule) {
  std::vector<Traits::Curve_2> curves;
  curves.reserve(a.size() + b.size());
  const auto add = [&](const DirectedEdge& e, bool is_a) {
    const int sign = lex_less(e.from, e.to) ? 1 : -1;
    const WindingDelta delta = is_a ? WindingDelta{sign, 0} : WindingDelta{0, sign};
    curves.emplace_back(SegmentTraits::Curve_2(Kernel::Point_2(e.from.x, e.from.y),
                                               Kernel::Point_2(e.to.x, e.to.y)),
                        delta);
  };
  for (const DirectedEdge& e : a) add(e, true);
  for (const DirectedEdge& e : b) add(e, false);

  Arrangement arrangement;
  CGAL::insert(arrangement, curves.begin(), curves.end());

  // Winding numbers, face by face from the unbounded face (0 for both sets).
  std::unordered_map<Arrangement::Face_const_handle, WindingDelta, CGAL::Handle_hash_function>
      winding;
  std::vector<Arrangement::Face_const_handle> stack;
  winding.emplace(arrangement.unbounded_face(), WindingDelta{});
  stack.push_back(arrangement.unbounded_face());
  ExactFT only_a = 0, only_b = 0, region_a = 0, region_b = 0;
  const auto visit_ccb = [&](Arrangement::Ccb_halfedge_const_circulator first,
                             const WindingDelta& w, ExactFT& twice_area) {
    auto h = first;
    do {
      const auto& p = CGAL::exact(h->source()->point());
      const auto& q = CGAL::exact(h->target()->point());
      twice_area += p.x() * q.y() - q.x() * p.y();
      const WindingDelta d = h->curve().data();
      const int s = h->direction() == CGAL::ARR_LEFT_TO_RIGHT ? 1 : -1;
      // h has its face on the left: w(face) = w(twin face) + s * d.
      const WindingDelta across{w.a - s * d.a, w.b - s * d.b};
      const auto g = h->twin()->face();
      if (winding.emplace(g, across).second) stack.push_back(g);
    } while (++h != first);
  };
  while (!stack.empty()) {
    const auto f = stack.back();
    stack.pop_back();
    const WindingDelta w = winding.at(f);
    ExactFT twice_area = 0;
    for (auto it = f->outer_ccbs_begin(); it != f->outer_ccbs_end(); ++it) {
      visit_ccb(*it, w, twice_area);
    }
    for (auto it = f->inner_ccbs_begin(); it != f->inner_ccbs_end(); ++it) {
      visit_ccb(*it, w, twice_area);
    }
    if (f->is_unbounded()) continue;
    const bool in_a = filled(w.a, rule);
    const bool in_b = filled(w.b, rule);
    if (in_a) region_a += twice_area;
    if (in_b) region_b += twice_area;
    if (in_a && !in_b) only_a += twice_area;
    if (in_b && !in_a) only_b += twice_area;
  }
  SymmetricDifference result;
  result.method = AreaMethod::Arrangement;
  result.area_mm2 = CGAL::to_double((only_a + only_b) / 2);
  result.area_a_mm2 = CGAL::to_double(region_a / 2);
  result.area_b_mm2 = CGAL::to_double(region_b / 2);
  return result;
}

}  // namespace

SymmetricDifference symmetric_difference(std::span<const Contour> a, std::span<const Contour> b,
                                         FillRule rule) {
  const std::vector<DirectedEdge> edges_a = loop_edges(a);
  const std::vector<DirectedEdge> edges_b = loop_edges(b);
  if (same_edges(edges_a, edges_b)) {
    SymmetricDifference same;
    same.method = AreaMethod::Identical;
    // Equal edge sets bound equal regions; the net area stands for both.
    same.area_a_mm2 = net_area(a);
    same.area_b_mm2 = same.area_a_mm2;
    return same;
  }
  try {
    return overlay(edges_a, edges_b, rule);
  } catch (const std::exception&) {
    // CGAL reports failed preconditions by throwing (make_cgal_failures_throw); the comparison
    // then falls back to what can be said without the overlay.
    SymmetricDifference fallback;
    fallback.method = AreaMethod::AreaOnly;
    fallback.area_a_mm2 = net_area(a);
    fallback.area_b_mm2 = net_area(b);
    fallback.area_mm2 = std::fabs(fallback.area_a_mm2 - fallback.area_b_mm2);
    return fallback;
  }
}

bool same_loop_edges(std::span<const Contour> a, std::span<const Contour> b) {
  return same_edges(loop_edges(a), loop_edges(b));
}

double hausdorff_distance(std::span<const Contour> a, std::span<const Contour> b) {
  const detail::PlanarPieces pieces_a = detail::contour_pieces(a);
  const detail::PlanarPieces pieces_b = detail::contour_pieces(b);
  const bool empty_a = pieces_a.points.empty();
  const bool empty_b = pieces_b.points.empty();
  if (empty_a && empty_b) return 0.0;
  if (empty_a || empty_b) return std::numeric_limits<double>::infinity();
  // Each grid covers the other set's points too, so that every query starts inside it.
  const detail::SegmentGrid grid_a(pieces_a, pieces_b.points);
  const detail::SegmentGrid grid_b(pieces_b, pieces_a.points);
  double h = 0.0;
  h = grid_b.directed_hausdorff(pieces_a.points, h);
  h = grid_a.directed_hausdorff(pieces_b.points, h);
  return h;
}

}  // namespace strata::validate
