#include "contour/loop_check.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace strata::detail {
namespace {

/// Loops given by exact rational corners. Segment i of a loop runs from corner i to corner i + 1;
/// a corner is one key (like a crossed mesh edge). The doubles the checker filters with are
/// either the nearest doubles or, with `coarse`, the corners rounded down to a multiple of 2^-10
/// with a margin of 2^-10, so that near ties must be decided exactly.
class TestGeometry {
 public:
  explicit TestGeometry(bool coarse = false) : coarse_(coarse) {}

  /// Adds a loop (or an open chain) and returns its chain.
  SegmentChain add(const std::vector<std::array<mpq_class, 2>>& corners, bool closed = true) {
    SegmentChain chain;
    chain.closed = closed;
    const std::size_t n = corners.size();
    const std::size_t segments = closed ? n : n - 1;
    const std::uint64_t first_key = next_key_;
    next_key_ += n;
    for (std::size_t i = 0; i < segments; ++i) {
      const std::size_t j = (i + 1) % n;
      chain.segments.push_back(static_cast<std::uint32_t>(ends_.size()));
      ends_.push_back({End{corners[i][0], corners[i][1], first_key + i},
                       End{corners[j][0], corners[j][1], first_key + j}});
    }
    return chain;
  }

  Point2 approx(SegmentEnd p) const {
    const End& e = end(p);
    return {round(e.x), round(e.y)};
  }
  double margin() const { return coarse_ ? 0x1p-10 : 0x1p-52 * largest(); }
  std::uint64_t key(SegmentEnd p) const { return end(p).key; }
  int exact_orientation(SegmentEnd a, SegmentEnd b, SegmentEnd c) const {
    const End& pa = end(a);
    const End& pb = end(b);
    const End& pc = end(c);
    return sgn(mpq_class((pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x)));
  }
  int exact_compare_x(SegmentEnd a, SegmentEnd b) const { return cmp(end(a).x, end(b).x); }
  int exact_compare_y(SegmentEnd a, SegmentEnd b) const { return cmp(end(a).y, end(b).y); }

 private:
  struct End {
    mpq_class x, y;
    std::uint64_t key;
  };
  const End& end(SegmentEnd p) const { return ends_[p.segment][p.end]; }
  double round(const mpq_class& v) const {
    // get_d truncates: within an ulp, 2^-52 relative.
    if (!coarse_) return v.get_d();
    return std::floor(v.get_d() * 1024.0) / 1024.0;
  }
  double largest() const {
    double m = 1.0;
    for (const auto& e : ends_) {
      for (const End& p : e) m = std::max({m, std::fabs(p.x.get_d()), std::fabs(p.y.get_d())});
    }
    return m;
  }

  bool coarse_;
  std::vector<std::array<End, 2>> ends_;
  std::uint64_t next_key_ = 0;
};

using Corners = std::vector<std::array<mpq_class, 2>>;

Corners square(mpq_class x0, mpq_class y0, mpq_class x1, mpq_class y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};  // counter-clockwise
}

Corners reversed(Corners c) { return Corners(c.rbegin(), c.rend()); }

LoopCheck check(const TestGeometry& g, const std::vector<SegmentChain>& chains) {
  return check_loops(g, chains);
}

TEST(LoopCheck, LoneSquareIsSimpleAndCounterClockwise) {
  TestGeometry g;
  const std::vector<SegmentChain> chains{g.add(square(0, 0, 1, 1))};
  const LoopCheck r = check(g, chains);
  EXPECT_TRUE(r.simple());
  EXPECT_FALSE(r.contacts);
  ASSERT_TRUE(r.nesting_decided);
  EXPECT_EQ(r.orientation[0], 1);
  EXPECT_EQ(r.depth[0], 0);
}

TEST(LoopCheck, ClockwiseLoneLoopDoesNotAlternate) {
  TestGeometry g;
  const std::vector<SegmentChain> chains{g.add(reversed(square(0, 0, 1, 1)))};
  const LoopCheck r = check(g, chains);
  EXPECT_FALSE(r.contacts);
  EXPECT_EQ(r.orientation[0], -1);
  EXPECT_FALSE(r.alternates);
  EXPECT_FALSE(r.simple());
}

TEST(LoopCheck, ZeroLengthSegmentBetweenPiecesIsNoContact) {
  // The corner (1, 0) appears twice in a row under two keys (a vertex on the plane reached from
  // two edges): the zero-length segment is no piece, its neighbours stay consecutive.
  TestGeometry g(true);
  const std::vector<SegmentChain> chains{g.add({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}})};
  const LoopCheck r = check(g, chains);
  EXPECT_FALSE(r.contacts);
  EXPECT_TRUE(r.simple());
}

TEST(LoopCheck, SquaresTouchingAtACornerTouch) {
  TestGeometry g;
  const std::vector<SegmentChain> chains{g.add(square(0, 0, 1, 1)), g.add(square(1, 1, 2, 2))};
  EXPECT_TRUE(check(g, chains).contacts);
}

TEST(LoopCheck, LoopThroughOneCornerTwiceTouchesItself) {
  TestGeometry g;
  const std::vector<SegmentChain> chains{
      g.add({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}})};
  EXPECT_TRUE(check(g, chains).contacts);
}

TEST(LoopCheck, CollinearOverlappingEdgesTouch) {
  // The top edge of the first square and the bottom edge of the second share [1, 2] x {1}.
  TestGeometry g;
  const std::vector<SegmentChain> chains{g.add(square(0, 0, 2, 1)), g.add(square(1, 1, 3, 2))};
  EXPECT_TRUE(check(g, chains).contacts);
}

TEST(LoopCheck, CollinearEdgesApartByLessThanTheFilterMarginDoNotTouch) {
  // y = 1 carries [0, 1] of the first square and [1 + 2^-30, 2] of the second: the doubles the
  // filter sees are equal, the exact ends are not.
  TestGeometry g(true);
  const mpq_class gap = mpq_class(1) + mpq_class(mpz_class(1), mpz_class(1) << 30);
  const std::vector<SegmentChain> chains{g.add(square(0, 0, 1, 1)), g.add(square(gap, 1, 2, 2))};
  exact_fallback_counter() = 0;
  const LoopCheck r = check(g, chains);
  EXPECT_FALSE(r.contacts);
  EXPECT_GT(exact_fallback_counter(), 0u);
  EXPECT_TRUE(r.simple());
}

TEST(LoopCheck, EdgesCrossingAtARepresentablePointCross) {
  // The squares' edges cross at (2, 1) and (1, 2).
  TestGeometry g;
  const std::vector<SegmentChain> chains{g.add(square(0, 0, 2, 2)), g.add(square(1, 1, 3, 3))};
  const LoopCheck r = check(g, chains);
  EXPECT_TRUE(r.contacts);
  EXPECT_FALSE(r.nesting_decided);
  EXPECT_FALSE(r.simple());
}

/// A triangle on the side x + y < 1 whose corner is (1/3 - delta, 2/3), and one on the side
/// x + y > 1 with the edge from (0, 1) to (1, 0).
std::vector<SegmentChain> corner_against_edge(TestGeometry& g, const mpq_class& delta) {
  const mpq_class third(mpz_class(1), mpz_class(3));
  const mpq_class two_thirds(mpz_class(2), mpz_class(3));
  return {g.add({{third - delta, two_thirds}, {-2, 2}, {-1, 0}}), g.add({{0, 1}, {1, 0}, {2, 2}})};
}

TEST(LoopCheck, CornerExactlyOnAnEdgeAtAnUnrepresentablePointTouches) {
  TestGeometry g;
  EXPECT_TRUE(check(g, corner_against_edge(g, 0)).contacts);
}

TEST(LoopCheck, CornerJustOffAnEdgeAtAnUnrepresentablePointDoesNotTouch) {
  TestGeometry g;
  const mpq_class delta(mpz_class(1), mpz_class(1) << 70);  // far below the doubles' resolution
  EXPECT_FALSE(check(g, corner_against_edge(g, delta)).contacts);
}

TEST(LoopCheck, HoleInsideOuterAlternates) {
  TestGeometry g;
  const std::vector<SegmentChain> chains{g.add(square(0, 0, 10, 10)),
                                         g.add(reversed(square(2, 2, 4, 4)))};
  const LoopCheck r = check(g, chains);
  EXPECT_TRUE(r.simple());
  EXPECT_EQ(r.orientation[1], -1);
  EXPECT_EQ(r.depth[1], 1);
  EXPECT_EQ(r.depth[0], 0);
}

TEST(LoopCheck, NestedLoopsOfOneOrientationDoNotAlternate) {
  TestGeometry g;
  const std::vector<SegmentChain> chains{g.add(square(0, 0, 10, 10)), g.add(square(2, 2, 4, 4))};
  const LoopCheck r = check(g, chains);
  EXPECT_FALSE(r.contacts);
  ASSERT_TRUE(r.nesting_decided);
  EXPECT_EQ(r.depth[1], 1);
  EXPECT_FALSE(r.alternates);
  EXPECT_FALSE(r.simple());
}

TEST(LoopCheck, OpenChainIsNotSimple) {
  TestGeometry g;
  const std::vector<SegmentChain> chains{g.add(square(0, 0, 1, 1), false)};
  const LoopCheck r = check(g, chains);
  EXPECT_FALSE(r.all_closed);
  EXPECT_FALSE(r.contacts);
  EXPECT_FALSE(r.simple());
}

TEST(LoopCheck, ManyDisjointLoopsHaveNoContact) {
  // A 30 x 30 array of small squares, far more pieces than one bucket holds.
  TestGeometry g;
  std::vector<SegmentChain> chains;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j)
      chains.push_back(g.add(square(3 * i, 3 * j, 3 * i + 2, 3 * j + 2)));
  }
  EXPECT_TRUE(check(g, chains).simple());
  chains.push_back(g.add(square(mpq_class(mpz_class(5), mpz_class(2)),
                                mpq_class(mpz_class(5), mpz_class(2)), 4, 4)));  // overlaps one
  EXPECT_TRUE(check(g, chains).contacts);
}

}  // namespace
}  // namespace strata::detail
