#pragma once

// Chaining a layer's segments into loops by mesh topology; shared with the exact path, which
// chains its exact crossing points the same way.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
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

/// The segments by the key of one of their edges: a hash table of the keys, each with the list
/// of its segments in segment order, so that candidates are taken in that order and each only
/// once. Flat and built in one pass (a layer has thousands of segments, nearly every key one).
class SegmentEdgeIndex {
 public:
  template <class Segment>
  SegmentEdgeIndex(const std::vector<Segment>& segments, bool by_start)
      : next_(segments.size(), kNone) {
    while ((std::size_t{1} << bits_) < 2 * segments.size()) ++bits_;
    slots_.assign(std::size_t{1} << bits_, Slot{0, kNone, kNone});
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
      const std::uint64_t key =
          crossed_edge_key(by_start ? segments[s].start_edge : segments[s].end_edge);
      Slot& slot = slots_[probe(key)];
      if (slot.first == kNone) {
        slot = Slot{key, s, s};
      } else {
        next_[slot.last] = s;
        slot.last = s;
      }
    }
  }

  /// The first segment with this key that `used` does not mark, or -1.
  std::int64_t take(std::uint64_t key, const std::vector<std::uint8_t>& used) const {
    for (std::uint32_t s = slots_[probe(key)].first; s != kNone; s = next_[s]) {
      if (!used[s]) return s;
    }
    return -1;
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  struct Slot {
    std::uint64_t key;
    std::uint32_t first, last;  ///< the key's first and last segment; kNone: an empty slot
  };

  /// Where `key` is, or the empty slot where it would go (linear probing; the table is at most
  /// half full).
  std::size_t probe(std::uint64_t key) const {
    const std::size_t mask = slots_.size() - 1;
    // Fibonacci hashing: the top bits of the product mix both vertex indices of the key.
    for (std::size_t i = (key * 0x9e3779b97f4a7c15ull) >> (64 - bits_);; i = (i + 1) & mask) {
      if (slots_[i].first == kNone || slots_[i].key == key) return i;
    }
  }

  int bits_ = 4;
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> next_;  ///< the segment after each with the same key, or kNone
};

/// Joins a layer's segments into chains by topology: a segment that ends on mesh edge E is
/// followed by a segment that starts on E; where an edge has several candidates (non-manifold
/// input) they are taken in segment order. A chain that does not close is extended backwards from
/// its first segment as far as it goes. Every segment is in exactly one chain. The fast path
/// (LayerSegment) and the exact path (its exact segments) chain the same facets identically.
/// Complexity: O(s) expected.
template <class Segment>
std::vector<SegmentChain> chain_segments(const std::vector<Segment>& segments) {
  const SegmentEdgeIndex by_start(segments, true);
  // Only an open chain walks backwards: the index by end edge is built on the first (most
  // layers have none).
  std::optional<SegmentEdgeIndex> by_end;
  std::vector<std::uint8_t> used(segments.size(), 0);  // bytes: read on every step, no bit masks
  std::vector<SegmentChain> chains;
  for (std::uint32_t seed = 0; seed < segments.size(); ++seed) {
    if (used[seed]) continue;
    used[seed] = 1;
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
      used[next] = 1;
      chain.segments.push_back(static_cast<std::uint32_t>(next));
    }
    if (!chain.closed) {
      // Backward: extend the open chain at its start as far as it goes.
      std::vector<std::uint32_t> head;
      std::uint64_t key = start_key;
      if (!by_end) by_end.emplace(segments, false);
      while (true) {
        const std::int64_t previous = by_end->take(key, used);
        if (previous < 0) break;
        used[previous] = 1;
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
