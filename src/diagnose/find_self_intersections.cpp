#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "diagnose/find_self_intersections_internal.hpp"

namespace strata::diagnose::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, FacetIndex,
                                                      CGAL::Box_intersection_d::ID_EXPLICIT>;

/// Thrown from the box callback to stop the sweep at a limit.
struct StopSearch {};

Point to_point(const Vec3& p) { return {p.x, p.y, p.z}; }

class PairTester {
 public:
  explicit PairTester(const IndexedMesh& mesh) : mesh_(mesh) {}

  bool intersect(FacetIndex f, FacetIndex g) const {
    const auto& tf = mesh_.triangles[f];
    const auto& tg = mesh_.triangles[g];
    // Shared corners by welded index: shared_f[i] is the corner of g equal to corner i of f.
    std::array<int, 3> shared_f{-1, -1, -1};
    int num_shared = 0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (tf[i] == tg[j]) {
          shared_f[i] = j;
          ++num_shared;
          break;
        }
      }
    }
    if (num_shared == 3) return false;  // the same facet again: a duplicate, reported as such
    if (num_shared == 2) {
      // Shared edge (p, q); r opposite in f, s opposite in g. They overlap only when coplanar
      // with r and s on the same side of the edge.
      int lone_f = 0;
      while (shared_f[lone_f] != -1) ++lone_f;
      int lone_g = 0;
      while (lone_g == shared_f[0] || lone_g == shared_f[1] || lone_g == shared_f[2]) ++lone_g;
      const Point p = point(tf[(lone_f + 1) % 3]);
      const Point q = point(tf[(lone_f + 2) % 3]);
      const Point r = point(tf[lone_f]);
      const Point s = point(tg[lone_g]);
      return CGAL::coplanar(p, q, r, s) && CGAL::coplanar_orientation(p, q, r, s) == CGAL::POSITIVE;
    }
    const Triangle t1(point(tf[0]), point(tf[1]), point(tf[2]));
    const Triangle t2(point(tg[0]), point(tg[1]), point(tg[2]));
    if (num_shared == 1) {
      // Shared vertex: they meet elsewhere exactly when an edge opposite the shared vertex meets
      // the other triangle.
      int i = 0;
      while (shared_f[i] == -1) ++i;
      const int j = shared_f[i];
      const Segment opposite_f(point(tf[(i + 1) % 3]), point(tf[(i + 2) % 3]));
      const Segment opposite_g(point(tg[(j + 1) % 3]), point(tg[(j + 2) % 3]));
      return CGAL::do_intersect(t1, opposite_g) || CGAL::do_intersect(t2, opposite_f);
    }
    return CGAL::do_intersect(t1, t2);
  }

 private:
  Point point(VertexIndex v) const { return to_point(mesh_.vertices[v]); }

  const IndexedMesh& mesh_;
};

}  // namespace

SelfIntersections find_self_intersections(const IndexedMesh& mesh, const std::vector<bool>& skip,
                                          std::size_t max_pairs, std::size_t max_candidates) {
  SelfIntersections result;
  std::vector<Box> boxes;
  boxes.reserve(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (skip[f]) continue;
    const auto& t = mesh.triangles[f];
    const CGAL::Bbox_3 bbox = to_point(mesh.vertices[t[0]]).bbox() +
                              to_point(mesh.vertices[t[1]]).bbox() +
                              to_point(mesh.vertices[t[2]]).bbox();
    boxes.emplace_back(bbox, static_cast<FacetIndex>(f));
  }
  if (max_pairs == 0 || max_candidates == 0) {
    result.truncated = !boxes.empty();
    return result;
  }

  // The sweep reports the candidate pairs in an order of its own, one at a time: they are tested
  // a batch at a time on the threads, and taken in that order, so that the limits stop the
  // search at the very pair where testing them one by one would.
  const PairTester tester(mesh);
  constexpr std::size_t kBatch = 1 << 14;
  std::vector<FacetPair> batch;
  batch.reserve(kBatch);
  std::vector<std::uint8_t> meets(kBatch);
  const auto test_batch = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch.size(), 256),
                      [&](const auto& range) {
                        for (std::size_t k = range.begin(); k < range.end(); ++k) {
                          meets[k] = tester.intersect(batch[k].first, batch[k].second) ? 1 : 0;
                        }
                      });
    for (std::size_t k = 0; k < batch.size(); ++k) {
      if (meets[k] == 0) continue;
      if (result.pairs.size() == max_pairs) throw StopSearch{};
      result.pairs.push_back(
          {std::min(batch[k].first, batch[k].second), std::max(batch[k].first, batch[k].second)});
    }
    batch.clear();
  };
  std::size_t candidates = 0;
  // A limit stops the search only when there is more to do than it allows.
  auto callback = [&](const Box& a, const Box& b) {
    if (candidates == max_candidates) {
      test_batch();
      throw StopSearch{};
    }
    ++candidates;
    batch.push_back({a.info(), b.info()});
    if (batch.size() == kBatch) test_batch();
  };
  try {
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(boxes.begin(), boxes.end(), callback);
    test_batch();
  } catch (const StopSearch&) {
    result.truncated = true;
  }
  std::sort(result.pairs.begin(), result.pairs.end(), [](const FacetPair& x, const FacetPair& y) {
    return x.first != y.first ? x.first < y.first : x.second < y.second;
  });
  return result;
}

}  // namespace strata::diagnose::detail
