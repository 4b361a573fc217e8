#pragma once

// Chaining a layer's segments into loops by mesh topology; shared with the exact path, which
// chains its exact crossing points the same way.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "strata/slice/layer_segments.hpp"

namespace strata::detail {

/// One chain of a layer's segments, as indices into the layer's segment list, in walking order.
struct SegmentChain {
  std::vector<std::uint32_t> segments;
  bool closed = false;  ///< the last segment ends on the edge the first one starts on
};

inline std::uint64_t crossed_edge_key(const CrossedEdge& e) {
  return (std::uint64_t{e.below} << 32) | e.above;
}

/// Segments sorted by the key of one of their edges, with a cursor per key so that candidates
/// are taken in facet order and each only once.
class SegmentEdgeIndex {
 public:
  template <class Segment>
  SegmentEdgeIndex(const std::vector<Segment>& segments, bool by_start) {
    entries_.reserve(segments.size());
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
      entries_.push_back(
          {crossed_edge_key(by_start ? segments[s].start_edge : segments[s].end_edge), s});
    }
    std::sort(entries_.begin(), entries_.end());
  }

  /// The first segment with this key that `used` does not mark, or -1.
  std::int64_t take(std::uint64_t key, const std::vector<bool>& used) const {
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

/// Joins a layer's segments into chains by topology: a segment that ends on mesh edge E is
/// followed by a segment that starts on E; where an edge has several candidates (non-manifold
/// input) they are taken in segment order. A chain that does not close is extended backwards from
/// its first segment as far as it goes. Every segment is in exactly one chain. The fast path
/// (LayerSegment) and the exact path (its exact segments) chain the same facets identically.
/// Complexity: O(s log s).
template <class Segment>
std::vector<SegmentChain> chain_segments(const std::vector<Segment>& segments) {
  const SegmentEdgeIndex by_start(segments, true);
  const SegmentEdgeIndex by_end(segments, false);
  std::vector<bool> used(segments.size(), false);
  std::vector<SegmentChain> chains;
  for (std::uint32_t seed = 0; seed < segments.size(); ++seed) {
    if (used[seed]) continue;
    used[seed] = true;
    SegmentChain chain;
    chain.segments.push_back(seed);
    const std::uint64_t start_key = crossed_edge_key(segments[seed].start_edge);
    // Forward: follow the segment that starts on the edge where the current one ends.
    while (true) {
      const std::uint64_t key = crossed_edge_key(segments[chain.segments.back()].end_edge);
      if (key == start_key) {
        chain.closed = true;
        break;
      }
      const std::int64_t next = by_start.take(key, used);
      if (next < 0) break;
      used[next] = true;
      chain.segments.push_back(static_cast<std::uint32_t>(next));
    }
    if (!chain.closed) {
      // Backward: extend the open chain at its start as far as it goes.
      std::vector<std::uint32_t> head;
      std::uint64_t key = start_key;
      while (true) {
        const std::int64_t previous = by_end.take(key, used);
        if (previous < 0) break;
        used[previous] = true;
        head.push_back(static_cast<std::uint32_t>(previous));
        key = crossed_edge_key(segments[previous].start_edge);
      }
      chain.segments.insert(chain.segments.begin(), head.rbegin(), head.rend());
    }
    chains.push_back(std::move(chain));
  }
  return chains;
}

}  // namespace strata::detail
