#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "exact/exact_arrangement_internal.hpp"
#include "strata/core/error.hpp"

namespace strata::exact::detail {
namespace {

using Point = Kernel::Point_2;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;

/// Overlapping pieces carry the sum of their weights.
struct AddWeights {
  long long operator()(long long a, long long b) const { return a + b; }
};

// An edge's data is its weight in the left-to-right direction (lexicographic xy order).
using Traits = CGAL::Arr_curve_data_traits_2<SegmentTraits, long long, AddWeights>;
using Dcel = CGAL::Arr_face_extended_dcel<Traits, long long>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;
using Halfedge = Arrangement::Halfedge_const_handle;

constexpr long long kUnset = std::numeric_limits<long long>::min();

ExactPoint2 from_kernel(const Point& p) {
  // The exact point's own coordinates: p.x() would be a lazy number of its own, its interval
  // computed again from the rational.
  const auto& exact = CGAL::exact(p);
  return {RoundedRational(exact.x()), RoundedRational(exact.y())};
}

struct PointLess {
  bool operator()(const ExactPoint2* a, const ExactPoint2* b) const {
    return compare_xy(*a, *b) < 0;
  }
};

/// A segment between points held elsewhere (the layer's, or those made for it): a point is
/// never copied, and a rational copied is an allocation or more.
struct WeightedSegment {
  const ExactPoint2* from;
  const ExactPoint2* to;
  long long weight = 1;
};

bool is_inside(FillRule rule, long long winding) {
  return rule == FillRule::EvenOdd ? (winding & 1) != 0 : winding != 0;
}

/// Adds, for every end point where segments start more often than they end (or the reverse), a
/// horizontal edge from x_left to it carrying the difference, and the vertical pieces on x_left
/// that close these edges up; x_left is the smallest of `left_of` and the end points' x. Returns
/// the number of chain starts. The points on x_left are added to `made`.
std::uint32_t close_open_chains(std::vector<WeightedSegment>& segments, double left_of,
                                std::deque<ExactPoint2>& made) {
  std::map<const ExactPoint2*, long long, PointLess> balance;
  const std::size_t original = segments.size();
  RoundedRational left{Rational(left_of)};
  const auto take_min = [&](const RoundedRational& x) {
    if (compare(x, left) < 0) left = x;
  };
  for (std::size_t i = 0; i < original; ++i) {
    balance[segments[i].from] += 1;
    balance[segments[i].to] -= 1;
    take_min(segments[i].from->x);
    take_min(segments[i].to->x);
  }
  std::uint32_t starts = 0;
  std::vector<std::pair<const ExactPoint2*, long long>> unbalanced;
  for (const auto& [p, w] : balance) {
    if (w == 0) continue;
    unbalanced.emplace_back(p, w);
    if (w > 0) starts += static_cast<std::uint32_t>(w);
  }
  if (unbalanced.empty()) return 0;
  std::sort(unbalanced.begin(), unbalanced.end(),
            [](const auto& a, const auto& b) { return compare(a.first->y, b.first->y) < 0; });
  std::vector<WeightedSegment> added;
  long long carried = 0;                      // weight of the vertical piece arriving from below
  const ExactPoint2* corner_above = nullptr;  // (x_left, y) of the next y, once made
  for (std::size_t i = 0; i < unbalanced.size();) {
    const RoundedRational& y = unbalanced[i].first->y;
    long long here = 0;
    std::size_t k = i;
    for (; k < unbalanced.size() && compare(unbalanced[k].first->y, y) == 0; ++k) {
      here += unbalanced[k].second;
    }
    // The edges from (x_left, y) to each end point at this y, as pieces between consecutive end
    // points: the piece ending at the i-th carries the weights of the i-th and every later one.
    // The same winding numbers, without the overlapping edges (a horizontal side of a section
    // with hundreds of end points on it would give hundreds of mutually overlapping edges). An
    // end point on x_left needs no edge: the vertical pieces meet it there.
    std::sort(unbalanced.begin() + static_cast<std::ptrdiff_t>(i),
              unbalanced.begin() + static_cast<std::ptrdiff_t>(k),
              [](const auto& a, const auto& b) { return compare_xy(*a.first, *b.first) < 0; });
    long long remaining = here;
    const ExactPoint2* corner =
        corner_above != nullptr ? corner_above : &made.emplace_back(ExactPoint2{left, y});
    corner_above = nullptr;
    const ExactPoint2* from = corner;
    for (std::size_t j = i; j < k; ++j) {
      const ExactPoint2* to = unbalanced[j].first;
      if (remaining != 0 && compare_xy(*from, *to) != 0) added.push_back({from, to, remaining});
      remaining -= unbalanced[j].second;
      from = to;
    }
    carried -= here;  // the rays leaving this point take `here`, the piece above takes the rest
    if (carried != 0 && k < unbalanced.size()) {
      corner_above = &made.emplace_back(ExactPoint2{left, unbalanced[k].first->y});
      added.push_back({corner, corner_above, carried});
    }
    i = k;
  }
  STRATA_ASSERT(carried == 0, "unbalanced segment chains do not sum to zero");
  segments.insert(segments.end(), added.begin(), added.end());
  return starts;
}

void drop_collinear(std::vector<Point>& loop) {
  std::vector<Point> out;
  out.reserve(loop.size());
  for (const Point& p : loop) {
    while (out.size() >= 2 && CGAL::collinear(out[out.size() - 2], out.back(), p)) out.pop_back();
    out.push_back(p);
  }
  std::size_t front = 0;
  while (out.size() - front >= 3) {
    if (CGAL::collinear(out[out.size() - 2], out.back(), out[front])) {
      out.pop_back();
    } else if (CGAL::collinear(out.back(), out[front], out[front + 1])) {
      ++front;
    } else {
      break;
    }
  }
  loop.assign(out.begin() + static_cast<std::ptrdiff_t>(front), out.end());
}

}  // namespace

ArrangementContours arrangement_contours(const ExactLayer& layer, FillRule rule, double left_of) {
  ArrangementContours result;
  std::vector<WeightedSegment> segments;
  segments.reserve(layer.segments.size());
  for (const ExactSegment& s : layer.segments) {
    if (!s.zero_length) segments.push_back({&layer.start_of(s), &layer.end_of(s), 1});
  }
  if (segments.empty()) return result;
  std::deque<ExactPoint2> made;
  result.open_chains = close_open_chains(segments, left_of, made);

  // Segments with the same two end points become one curve carrying the sum of their weights
  // (left to right), and a sum of zero no curve at all: it changes no face's winding number.
  // CGAL would merge such overlaps itself, but pair by pair; a fan of repeated facets puts
  // hundreds of copies of one segment into a layer.
  struct Oriented {
    const ExactPoint2* left;
    const ExactPoint2* right;
    long long weight;
  };
  std::vector<Oriented> oriented;
  oriented.reserve(segments.size());
  for (const WeightedSegment& s : segments) {
    const int order = compare_xy(*s.from, *s.to);
    STRATA_ASSERT(order != 0, "zero-length segment handed to the arrangement");
    if (order < 0) {
      oriented.push_back({s.from, s.to, s.weight});
    } else {
      oriented.push_back({s.to, s.from, -s.weight});
    }
  }
  const auto compare_ends = [](const Oriented& a, const Oriented& b) {
    const int first = compare_xy(*a.left, *b.left);
    return first != 0 ? first : compare_xy(*a.right, *b.right);
  };
  std::sort(oriented.begin(), oriented.end(),
            [&](const Oriented& a, const Oriented& b) { return compare_ends(a, b) < 0; });
  std::vector<Traits::X_monotone_curve_2> curves;
  curves.reserve(oriented.size());
  // A point ends several curves: it is made a kernel point once (from its rational, an interval
  // computed with MPFR), and the curves share it.
  std::unordered_map<const ExactPoint2*, Point> kernel_points;
  kernel_points.reserve(2 * oriented.size());
  const auto kernel_point = [&](const ExactPoint2* p) -> const Point& {
    auto [at, added] = kernel_points.try_emplace(p);
    if (added) at->second = to_kernel(*p);
    return at->second;
  };
  for (std::size_t i = 0; i < oriented.size();) {
    long long weight = 0;
    std::size_t k = i;
    for (; k < oriented.size() && compare_ends(oriented[i], oriented[k]) == 0; ++k) {
      weight += oriented[k].weight;
    }
    if (weight != 0) {
      curves.emplace_back(SegmentTraits::X_monotone_curve_2(kernel_point(oriented[i].left),
                                                            kernel_point(oriented[i].right)),
                          weight);
    }
    i = k;
  }
  Arrangement arr;
  CGAL::insert(arr, curves.begin(), curves.end());

  // Winding numbers: 0 on the unbounded face; crossing a halfedge from its face (on its left) to
  // the other side subtracts the weight running along it.
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) f->set_data(kUnset);
  arr.unbounded_face()->set_data(0);
  const auto along = [](Halfedge h) {
    const long long w = h->curve().data();
    return h->direction() == CGAL::ARR_LEFT_TO_RIGHT ? w : -w;
  };
  std::deque<Arrangement::Face_handle> queue{arr.unbounded_face()};
  const auto visit_ccb = [&](Arrangement::Ccb_halfedge_circulator first, long long winding) {
    auto h = first;
    do {
      const long long expected = winding - along(h);
      Arrangement::Face_handle g = h->twin()->face();
      if (g->data() == kUnset) {
        g->set_data(expected);
        queue.push_back(g);
      } else {
        STRATA_ASSERT(g->data() == expected, "winding numbers of the arrangement disagree");
      }
    } while (++h != first);
  };
  while (!queue.empty()) {
    const Arrangement::Face_handle f = queue.front();
    queue.pop_front();
    for (auto c = f->outer_ccbs_begin(); c != f->outer_ccbs_end(); ++c) visit_ccb(*c, f->data());
    for (auto c = f->inner_ccbs_begin(); c != f->inner_ccbs_end(); ++c) visit_ccb(*c, f->data());
  }

  const auto is_boundary = [&](Halfedge h) {
    return is_inside(rule, h->face()->data()) && !is_inside(rule, h->twin()->face()->data());
  };
  std::unordered_set<const void*> walked;
  for (auto e = arr.halfedges_begin(); e != arr.halfedges_end(); ++e) {
    const Halfedge start = e;
    if (!is_boundary(start) || walked.count(&*start) != 0) continue;
    std::vector<Point> points;
    Halfedge h = start;
    do {
      STRATA_ASSERT(walked.insert(&*h).second, "a boundary halfedge is walked twice");
      points.push_back(h->source()->point());
      // Turn around the target through inside faces to the next boundary halfedge: the one that
      // bounds the same corner of the inside region.
      Halfedge next = h->next();
      while (!is_boundary(next)) next = next->twin()->next();
      h = next;
    } while (h != start);
    drop_collinear(points);
    if (points.size() < 3) continue;
    ExactLoop loop;
    loop.points.reserve(points.size());
    for (const Point& p : points) loop.points.push_back(from_kernel(p));
    result.loops.push_back(std::move(loop));
  }
  return result;
}

}  // namespace strata::exact::detail
