#include "strata/mesh/indexed_mesh.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cstddef>

namespace strata {
namespace {

/// `box` grown by `later`, the box of vertices that come after its own: a bound of `later`
/// replaces one of `box` only when strictly beyond it, as adding those vertices one by one would
/// (an equal bound, -0 against +0, stays the first seen).
Bbox3 followed_by(Bbox3 box, const Bbox3& later) {
  const auto lower = [](double& here, double there) {
    if (there < here) here = there;
  };
  const auto higher = [](double& here, double there) {
    if (there > here) here = there;
  };
  lower(box.min.x, later.min.x);
  lower(box.min.y, later.min.y);
  lower(box.min.z, later.min.z);
  higher(box.max.x, later.max.x);
  higher(box.max.y, later.max.y);
  higher(box.max.z, later.max.z);
  return box;
}

}  // namespace

Bbox3 IndexedMesh::bounds() const {
  // Below this many vertices one pass takes less than handing the work to the threads.
  constexpr std::size_t kVerticesAPiece = 1 << 16;
  // parallel_reduce joins each piece with the one after it: the result is the one pass's.
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, vertices.size(), kVerticesAPiece), Bbox3{},
      [&](const tbb::blocked_range<std::size_t>& range, Bbox3 box) {
        for (std::size_t v = range.begin(); v < range.end(); ++v) box.add(vertices[v]);
        return box;
      },
      followed_by);
}

}  // namespace strata
