// Chaining by topology, held to its definition: a segment ending on edge E is followed by the
// first unused segment (in segment order) starting on E; an open chain is then extended backwards
// the same way. The reference below searches every segment for each step.
#include "contour/chain_segments.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace strata {
namespace {

using detail::SegmentChain;

std::vector<SegmentChain> chain_by_search(const std::vector<LayerSegment>& segments) {
  std::vector<bool> used(segments.size(), false);
  const auto first_unused = [&](const CrossedEdge& edge, bool by_start) -> std::int64_t {
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
      if (!used[s] && (by_start ? segments[s].start_edge : segments[s].end_edge) == edge) return s;
    }
    return -1;
  };
  std::vector<SegmentChain> chains;
  for (std::uint32_t seed = 0; seed < segments.size(); ++seed) {
    if (used[seed]) continue;
    used[seed] = true;
    SegmentChain chain;
    chain.segments.push_back(seed);
    while (true) {
      const CrossedEdge& end = segments[chain.segments.back()].end_edge;
      if (end == segments[seed].start_edge) {
        chain.closed = true;
        break;
      }
      const std::int64_t next = first_unused(end, true);
      if (next < 0) break;
      used[next] = true;
      chain.segments.push_back(static_cast<std::uint32_t>(next));
    }
    if (!chain.closed) {
      while (true) {
        const std::int64_t previous =
            first_unused(segments[chain.segments.front()].start_edge, false);
        if (previous < 0) break;
        used[previous] = true;
        chain.segments.insert(chain.segments.begin(), static_cast<std::uint32_t>(previous));
      }
    }
    chains.push_back(std::move(chain));
  }
  return chains;
}

void expect_same_chains(const std::vector<LayerSegment>& segments, const char* what) {
  const std::vector<SegmentChain> got = detail::chain_segments(segments);
  const std::vector<SegmentChain> want = chain_by_search(segments);
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t c = 0; c < got.size(); ++c) {
    EXPECT_EQ(got[c].segments, want[c].segments) << what << ", chain " << c;
    EXPECT_EQ(got[c].closed, want[c].closed) << what << ", chain " << c;
  }
}

LayerSegment segment(VertexIndex a0, VertexIndex a1, VertexIndex b0, VertexIndex b1) {
  LayerSegment s;
  s.start_edge = {a0, a1};
  s.end_edge = {b0, b1};
  return s;
}

TEST(ChainSegments, ClosedRingsOpenChainsAndSharedEdgesAsTheDefinitionSays) {
  // A ring of four, an open chain whose seed is in its middle, and an edge three segments start
  // on (a non-manifold fan): the first unused in segment order is taken each time.
  const std::vector<LayerSegment> segments = {
      segment(20, 21, 22, 23), segment(0, 1, 2, 3),     segment(4, 5, 6, 7),
      segment(6, 7, 0, 1),     segment(2, 3, 4, 5),     segment(10, 11, 20, 21),
      segment(22, 23, 30, 31), segment(30, 31, 40, 41), segment(30, 31, 42, 43),
      segment(30, 31, 44, 45), segment(42, 43, 30, 31),
  };
  expect_same_chains(segments, "hand-made");
  const std::vector<SegmentChain> chains = detail::chain_segments(segments);
  ASSERT_GE(chains.size(), 2u);
  EXPECT_EQ(chains[0].segments, (std::vector<std::uint32_t>{5, 0, 6, 7}));
  EXPECT_FALSE(chains[0].closed);
  EXPECT_EQ(chains[1].segments, (std::vector<std::uint32_t>{1, 4, 2, 3}));
  EXPECT_TRUE(chains[1].closed);
}

TEST(ChainSegments, RandomSegmentsOnFewEdgesChainAsTheDefinitionSays) {
  // Few distinct edges, so that most keys are shared by several segments and most chains meet
  // taken candidates; sizes across the table's growth (16 slots and up).
  std::mt19937 random(11);
  for (const std::size_t count : {0u, 1u, 7u, 8u, 9u, 60u, 500u, 3000u}) {
    for (const VertexIndex pool : {3u, 12u, 200u}) {
      std::uniform_int_distribution<VertexIndex> vertex(0, pool - 1);
      std::vector<LayerSegment> segments;
      for (std::size_t s = 0; s < count; ++s) {
        segments.push_back(segment(vertex(random), vertex(random), vertex(random), vertex(random)));
      }
      expect_same_chains(segments, "random");
    }
  }
  // Keys that differ only in one vertex's high bits, or only in the order of the two.
  std::vector<LayerSegment> close_keys;
  for (VertexIndex v = 0; v < 63; ++v) {
    close_keys.push_back(segment(v << 26, 1, 1, (v + 1) << 26));
    close_keys.push_back(segment(1, (v + 1) << 26, v << 26, 1));
  }
  expect_same_chains(close_keys, "close keys");
}

}  // namespace
}  // namespace strata
