#include "strata/contour/assemble_contours.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "contour/point_in_polygon_internal.hpp"

namespace strata {

namespace {

std::uint64_t edge_key(const CrossedEdge& e) { return (std::uint64_t{e.below} << 32) | e.above; }

/// Segments sorted by the key of one of their edges, with a cursor per key so that candidates
/// are taken in facet order and each only once.
class EdgeIndex {
 public:
  EdgeIndex(const std::vector<LayerSegment>& segments, bool by_start) {
    entries_.reserve(segments.size());
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
      entries_.push_back({edge_key(by_start ? segments[s].start_edge : segments[s].end_edge), s});
    }
    std::sort(entries_.begin(), entries_.end());
  }

  /// The first segment with this key that `used` does not mark, or -1.
  std::int64_t take(std::uint64_t key, const std::vector<bool>& used) {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), Entry{key, 0});
    for (; it != entries_.end() && it->key == key; ++it) {
      if (!used[it->segment]) return it->segment;
    }
    return -1;
  }

 private:
  struct Entry {
    std::uint64_t key;
    std::uint32_t segment;
    friend bool operator<(const Entry& a, const Entry& b) {
      return a.key != b.key ? a.key < b.key : a.segment < b.segment;
    }
  };
  std::vector<Entry> entries_;
};

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
      // Loops of one layer do not cross (they come from a surface cut by a plane), so one vertex
      // decides containment; a vertex on the other loop counts as outside.
      if (detail::point_in_polygon(probe, loops[j].points) > 0) ++depth;
    }
    loops[i].depth = depth;
  }
}

}  // namespace

LayerContours assemble_contours(const LayerSegments& layer) {
  const auto& segments = layer.segments;
  LayerContours out;
  out.layer = layer.layer;
  out.z_mm = layer.z_mm;
  EdgeIndex by_start(segments, true);
  EdgeIndex by_end(segments, false);
  std::vector<bool> used(segments.size(), false);

  for (std::uint32_t seed = 0; seed < segments.size(); ++seed) {
    if (used[seed]) continue;
    used[seed] = true;
    std::vector<std::uint32_t> chain{seed};
    const std::uint64_t start_key = edge_key(segments[seed].start_edge);
    bool closed = false;
    // Forward: follow the segment that starts on the edge where the current one ends.
    while (true) {
      const std::uint64_t key = edge_key(segments[chain.back()].end_edge);
      if (key == start_key) {
        closed = true;
        break;
      }
      const std::int64_t next = by_start.take(key, used);
      if (next < 0) break;
      used[next] = true;
      chain.push_back(static_cast<std::uint32_t>(next));
    }
    Contour contour;
    if (!closed) {
      // Backward: extend the open chain at its start as far as it goes.
      std::vector<std::uint32_t> head;
      std::uint64_t key = start_key;
      while (true) {
        const std::int64_t previous = by_end.take(key, used);
        if (previous < 0) break;
        used[previous] = true;
        head.push_back(static_cast<std::uint32_t>(previous));
        key = edge_key(segments[previous].start_edge);
      }
      chain.insert(chain.begin(), head.rbegin(), head.rend());
    }
    contour.points.reserve(chain.size() + 1);
    for (const std::uint32_t s : chain) contour.points.push_back(segments[s].start);
    contour.is_closed = closed;
    if (closed) {
      contour.signed_area_mm2 = shoelace(contour.points);
      contour.kind = contour.signed_area_mm2 >= 0.0 ? LoopKind::Outer : LoopKind::Hole;
      out.area_mm2 += contour.signed_area_mm2;
    } else {
      contour.points.push_back(segments[chain.back()].end);
      contour.kind = LoopKind::Open;
      ++out.open_chains;
    }
    out.loops.push_back(std::move(contour));
  }
  assign_nesting_depths(out.loops);
  return out;
}

}  // namespace strata
