#include "diagnose/exact_geometry.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "support/mesh_builders.hpp"
#include "support/nearest_double.hpp"

namespace strata::diagnose::detail {
namespace {

TEST(IsCollinear, AcceptsPointsOnOneLine) {
  EXPECT_TRUE(is_collinear({0, 0, 0}, {0.1, 0.3, 0.7}, {0.2, 0.6, 1.4}));
  EXPECT_TRUE(is_collinear({1, 2, 3}, {1, 2, 3}, {5, 5, 5}));
}

TEST(IsCollinear, RejectsPointOffTheLineByOneTinyStep) {
  EXPECT_FALSE(is_collinear({0, 0, 0}, {1, 0, 0}, {0.5, 1e-300, 0}));
}

TEST(NormalAgreementSign, FollowsTheRightHandRule) {
  EXPECT_EQ(normal_agreement_sign({0, 0, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}), 1);
  EXPECT_EQ(normal_agreement_sign({0, 0, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}), -1);
  EXPECT_EQ(normal_agreement_sign({1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}), 0);
}

TEST(NormalAgreementSign, SurvivesCancellationThatFoolsDouble) {
  // From stl-models/misc/multiWordName.bin.stl: the cross product's y component is the
  // difference of two products of about 6e57 that a double evaluation cancels to zero; the
  // exact dot product is -1.4e29, the double one +8e-14.
  const Vec3 n{0.0, -0x1.dep+0, 0x1.fde8p-136};
  const Vec3 a{-0x1p+95, 0x1.7b7ep-134, -0x1.7b7fdep+96};
  const Vec3 b{0x1.7b7ep-134, -0x1.7fdep-4, 0.0};
  const Vec3 c{0.0, 0.0, -0x1.dep+0};
  EXPECT_EQ(normal_agreement_sign(n, a, b, c), -1);
}

/// The cube of edge `size` with its lowest corner at (x0, y0, z0).
IndexedMesh cube_at(double x0, double y0, double z0, double size) {
  return test::indexed_box_lo_hi_diagonals({x0, y0, z0}, {x0 + size, y0 + size, z0 + size});
}

TEST(ExactSignedVolumes, SumsEachGroup) {
  IndexedMesh mesh = cube_at(0, 0, 0, 1);
  test::append_mesh(mesh, cube_at(5, 5, 5, 2));
  std::vector<std::uint32_t> group(24, 0);
  for (int f = 12; f < 24; ++f) group[f] = 1;
  const ExactVolumes v = exact_signed_volumes(mesh, group, 2);
  ASSERT_EQ(v.by_group_mm3.size(), 2U);
  EXPECT_EQ(v.by_group_mm3[0], 1.0);
  EXPECT_EQ(v.by_group_mm3[1], 8.0);
  EXPECT_EQ(v.total_mm3, 9.0);
}

TEST(ExactSignedVolumes, StaysExactFarFromTheOrigin) {
  // The tetrahedra are of order 1e45 and cancel to 1.
  const IndexedMesh mesh = cube_at(1e15, -1e15, 3e15, 1);
  const ExactVolumes v = exact_signed_volumes(mesh, std::vector<std::uint32_t>(12, 0), 1);
  EXPECT_EQ(v.total_mm3, 1.0);
}

TEST(ExactSignedVolumes, MixesTinyAndHugeCoordinates) {
  const IndexedMesh mesh = cube_at(-0x1p-60, 0x1p+20, 0.0, 0x1p-30);
  const ExactVolumes v = exact_signed_volumes(mesh, std::vector<std::uint32_t>(12, 0), 1);
  EXPECT_EQ(v.total_mm3, 0x1p-90);
}

TEST(ExactSignedVolumes, RoundsOnceToNearest) {
  // One facet against the origin: (1/3 of a unit cube's corner) 1/6 exactly, rounded once.
  IndexedMesh mesh;
  mesh.vertices = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 1, 2}};
  const ExactVolumes v = exact_signed_volumes(mesh, {0}, 1);
  EXPECT_EQ(v.total_mm3, 1.0 / 6.0);
}

TEST(ExactSignedVolumes, SumsManyFacetsInPartsAsExactlyAsInOne) {
  // 3,000 unit cubes far from the origin (36,000 facets, enough to be summed in parts): each
  // cube's tetrahedra are of order 1e45 and cancel to 1 only when summed exactly, and a part's
  // sum cuts through cubes. Two groups are summed in parts, one group a cube in one part.
  IndexedMesh mesh;
  for (int i = 0; i < 3000; ++i) test::append_mesh(mesh, cube_at(1e15 + 4.0 * i, -1e15, 3e15, 1));
  const std::size_t nf = mesh.triangles.size();
  std::vector<std::uint32_t> two_groups(nf), cube_groups(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    two_groups[f] = static_cast<std::uint32_t>(f / 12 % 2);
    cube_groups[f] = static_cast<std::uint32_t>(f / 12);
  }
  const ExactVolumes halves = exact_signed_volumes(mesh, two_groups, 2);
  EXPECT_EQ(halves.by_group_mm3, (std::vector<double>{1500.0, 1500.0}));
  EXPECT_EQ(halves.total_mm3, 3000.0);
  const ExactVolumes cubes = exact_signed_volumes(mesh, cube_groups, 3000);
  EXPECT_EQ(cubes.by_group_mm3, std::vector<double>(3000, 1.0));
  EXPECT_EQ(cubes.total_mm3, 3000.0);
}

/// Random facets whose coordinates are m 2^e, |m| < 2^53, e in [-spread, spread]: the spread sets
/// how wide the coordinates are on one common exponent, and so which arithmetic sums them (four
/// limbs up to 73 bits, six up to 116, GMP's integers beyond).
IndexedMesh random_facets(int spread, std::uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> mantissa(-(std::int64_t{1} << 53) + 1,
                                                       (std::int64_t{1} << 53) - 1);
  std::uniform_int_distribution<int> exponent(-spread, spread);
  IndexedMesh mesh;
  for (int v = 0; v < 600; ++v) {
    Vec3 p;
    for (double* c : {&p.x, &p.y, &p.z}) {
      *c = std::ldexp(static_cast<double>(mantissa(rng)), exponent(rng) - 26);
    }
    if (v % 50 == 7) p.y = 0.0;  // zero coordinates are left out of the common exponent
    mesh.vertices.push_back(p);
  }
  std::uniform_int_distribution<VertexIndex> vertex(0, 599);
  for (int f = 0; f < 40000; ++f) mesh.triangles.push_back({vertex(rng), vertex(rng), vertex(rng)});
  return mesh;
}

/// sum(a · (b x c)) over the facets of each group, as rationals: the definition the sums are held
/// to.
std::vector<mpq_class> rational_determinant_sums(const IndexedMesh& mesh,
                                                 const std::vector<std::uint32_t>& group,
                                                 std::size_t num_groups) {
  std::vector<mpq_class> sums(num_groups);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (group[f] == kNoGroup) continue;
    const Vec3& a = mesh.vertices[mesh.triangles[f][0]];
    const Vec3& b = mesh.vertices[mesh.triangles[f][1]];
    const Vec3& c = mesh.vertices[mesh.triangles[f][2]];
    sums[group[f]] += mpq_class(a.x) * (mpq_class(b.y) * c.z - mpq_class(b.z) * c.y) +
                      mpq_class(a.y) * (mpq_class(b.z) * c.x - mpq_class(b.x) * c.z) +
                      mpq_class(a.z) * (mpq_class(b.x) * c.y - mpq_class(b.y) * c.x);
  }
  return sums;
}

TEST(ExactSignedVolumes, EveryArithmeticSumsAsRationalsDo) {
  // spread 2: at most 57 bits (four limbs); 10: up to 73, four limbs' limit; 20: up to 93 (six
  // limbs); 31: up to 115, near six limbs' limit; 40: up to 133 (GMP). Every fifth facet is in
  // no group. The integers are held to the rationals, and the filter, where it decides, to both.
  for (const int spread : {2, 10, 20, 31, 40}) {
    const auto seed = static_cast<std::uint32_t>(spread);
    const IndexedMesh mesh = random_facets(spread, seed);
    const std::size_t nf = mesh.triangles.size();
    std::vector<std::uint32_t> group(nf);
    for (std::size_t f = 0; f < nf; ++f) {
      group[f] = f % 5 == 4 ? kNoGroup : static_cast<std::uint32_t>((f * 7 + seed) % 3);
    }
    const std::vector<mpq_class> expected = rational_determinant_sums(mesh, group, 3);
    const ExactVolumes v = integer_signed_volumes(mesh, group, 3);
    EXPECT_FALSE(v.decided_in_floating_point);
    mpq_class total;
    for (std::size_t g = 0; g < 3; ++g) {
      EXPECT_EQ(v.by_group_mm3[g], test::nearest_double(expected[g] / 6))
          << "spread " << spread << " seed " << seed << " group " << g;
      total += expected[g];
    }
    EXPECT_EQ(v.total_mm3, test::nearest_double(total / 6)) << "spread " << spread;
    const ExactVolumes either = exact_signed_volumes(mesh, group, 3);
    EXPECT_EQ(either.by_group_mm3, v.by_group_mm3) << "spread " << spread;
    EXPECT_EQ(either.total_mm3, v.total_mm3) << "spread " << spread;
  }
}

TEST(ExactSignedVolumes, IntegersSumZeroCoordinatesToZero) {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {0, -0.0, 0}, {0, 0, -0.0}};
  mesh.triangles = {{0, 1, 2}, {2, 1, 0}};
  const ExactVolumes v = integer_signed_volumes(mesh, {0, 1}, 2);
  EXPECT_EQ(v.by_group_mm3, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(v.total_mm3, 0.0);
}

TEST(ExactSignedVolumes, SubnormalAndNegativeCoordinatesSumAsRationalsDo) {
  // The coordinates are read from their bits: subnormal ones have no implicit leading bit.
  IndexedMesh mesh;
  mesh.vertices = {{5e-324, -1.0, 0.0},
                   {-3e-310, 1.0, 0.75},
                   {2.0, -2.5e-320, -1.0},
                   {-0.1, 0.3, std::numeric_limits<double>::min()}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 3, 2}, {3, 1, 0}};
  mpq_class expected;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    expected += mpq_class(a.x) * (mpq_class(b.y) * c.z - mpq_class(b.z) * c.y) +
                mpq_class(a.y) * (mpq_class(b.z) * c.x - mpq_class(b.x) * c.z) +
                mpq_class(a.z) * (mpq_class(b.x) * c.y - mpq_class(b.y) * c.x);
  }
  const ExactVolumes v = exact_signed_volumes(mesh, std::vector<std::uint32_t>(4, 0), 1);
  EXPECT_EQ(v.total_mm3, test::nearest_double(expected / 6));
  EXPECT_NE(v.total_mm3, 0.0);
}

TEST(ExactSignedVolumes, FacetsInNoGroupAreLeftOut) {
  IndexedMesh mesh = cube_at(0.5, 0.25, 0.125, 2);
  // A facet with area, in no group: were it summed, the volume would change.
  mesh.vertices.push_back({3, 0, 0});
  mesh.triangles.push_back({0, 1, static_cast<VertexIndex>(mesh.vertices.size() - 1)});
  std::vector<std::uint32_t> group(mesh.triangles.size(), 0);
  group.back() = kNoGroup;
  const ExactVolumes v = exact_signed_volumes(mesh, group, 1);
  EXPECT_EQ(v.by_group_mm3, std::vector<double>{8.0});
  EXPECT_EQ(v.total_mm3, 8.0);
}

TEST(ExactSignedVolumes, FloatingPointDecidesWellConditionedSums) {
  // Coordinates of a few bits' spread and no cancellation to speak of: the filter's bound leaves
  // one rounding, which must be the rationals' (40,000 facets in three groups).
  const IndexedMesh mesh = random_facets(2, 7);
  std::vector<std::uint32_t> group(mesh.triangles.size());
  for (std::size_t f = 0; f < group.size(); ++f) group[f] = static_cast<std::uint32_t>(f % 3);
  const ExactVolumes v = exact_signed_volumes(mesh, group, 3);
  EXPECT_TRUE(v.decided_in_floating_point);
  const std::vector<mpq_class> expected = rational_determinant_sums(mesh, group, 3);
  for (std::size_t g = 0; g < 3; ++g) {
    EXPECT_EQ(v.by_group_mm3[g], test::nearest_double(expected[g] / 6)) << "group " << g;
  }
  EXPECT_EQ(v.total_mm3, test::nearest_double((expected[0] + expected[1] + expected[2]) / 6));
}

TEST(ExactSignedVolumes, TiesAndCancellationGoToTheIntegers) {
  // Two facets against the origin with determinants 6 and 6 2^-53: the volume 1 + 2^-53 lies
  // halfway between two doubles, which no error bound can decide; it rounds to even, 1.
  IndexedMesh tie;
  tie.vertices = {{1, 0, 0}, {0, 1, 0}, {0, 0, 6}, {0, 0, 0x3p-52}};
  tie.triangles = {{0, 1, 2}, {0, 1, 3}};
  const ExactVolumes halfway = exact_signed_volumes(tie, {0, 0}, 1);
  EXPECT_FALSE(halfway.decided_in_floating_point);
  EXPECT_EQ(halfway.total_mm3, 1.0);
  // Tetrahedra of order 1e45 that cancel to 1: beyond any double-double's reach.
  const IndexedMesh far = cube_at(1e15, -1e15, 3e15, 1);
  const ExactVolumes cancelled = exact_signed_volumes(far, std::vector<std::uint32_t>(12, 0), 1);
  EXPECT_FALSE(cancelled.decided_in_floating_point);
  EXPECT_EQ(cancelled.total_mm3, 1.0);
}

TEST(ExactSignedVolumes, EmptyGroupsAndCancellingSheetsAreExactlyZero) {
  // Group 1 has no facet: zero without doubt. The sheet's two sides cancel exactly, which the
  // filter's bound cannot tell from a tiny volume: the integers say zero.
  IndexedMesh mesh;
  mesh.vertices = {{0.1, 0.2, 0.3}, {1.7, 0.25, 0.35}, {0.15, 1.9, 0.45}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 1}};
  const ExactVolumes empty_group = exact_signed_volumes(mesh, {kNoGroup, kNoGroup}, 2);
  EXPECT_TRUE(empty_group.decided_in_floating_point);
  EXPECT_EQ(empty_group.by_group_mm3, (std::vector<double>{0.0, 0.0}));
  const ExactVolumes sheet = exact_signed_volumes(mesh, {0, 0}, 1);
  EXPECT_FALSE(sheet.decided_in_floating_point);
  EXPECT_EQ(sheet.total_mm3, 0.0);
}

TEST(ExactSignedVolumes, CoordinatesBeyondTheFiltersRangeGoToTheIntegers) {
  // A cube of edge 2^290 at x = 2^300: its products of coordinates would overflow the filter's
  // bounds; its volume 2^870 is exact.
  const IndexedMesh huge = cube_at(0x1p300, 0.0, 0.0, 0x1p290);
  const ExactVolumes v = exact_signed_volumes(huge, std::vector<std::uint32_t>(12, 0), 1);
  EXPECT_FALSE(v.decided_in_floating_point);
  EXPECT_EQ(v.total_mm3, 0x1p870);
  // 2,000 unit cubes and one vertex no facet uses, with a coordinate below the filter's range:
  // every vertex is looked at, and the sums go to the integers.
  IndexedMesh cubes;
  for (int i = 0; i < 2000; ++i) test::append_mesh(cubes, cube_at(3.0 * i, 0.5, -2.0, 1));
  const std::vector<std::uint32_t> group(cubes.triangles.size(), 0);
  EXPECT_TRUE(exact_signed_volumes(cubes, group, 1).decided_in_floating_point);
  cubes.vertices.push_back({1.0, 0x1p-300, 2.0});
  const ExactVolumes tiny = exact_signed_volumes(cubes, group, 1);
  EXPECT_FALSE(tiny.decided_in_floating_point);
  EXPECT_EQ(tiny.total_mm3, 2000.0);
}

TEST(ExactSignedVolumes, EitherWayTheSumIsTheRationalOne) {
  // Closed boxes with jittered corners, moved ever farther from the origin: the cancellation
  // grows until the filter gives way to the integers. Every volume is held to the rationals,
  // and both ways must have been taken.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  int by_filter = 0, by_integers = 0;
  for (int k = 0; k <= 60; k += 2) {
    const double offset = std::ldexp(1.0, k);
    IndexedMesh mesh = cube_at(offset, -0.75 * offset, 0.5 * offset, 0.7);
    for (Vec3& p : mesh.vertices) {
      p.x += jitter(rng);
      p.y += jitter(rng);
      p.z += jitter(rng);
    }
    const std::vector<std::uint32_t> group(mesh.triangles.size(), 0);
    const ExactVolumes v = exact_signed_volumes(mesh, group, 1);
    EXPECT_EQ(v.total_mm3, test::nearest_double(rational_determinant_sums(mesh, group, 1)[0] / 6))
        << "offset 2^" << k;
    ++(v.decided_in_floating_point ? by_filter : by_integers);
  }
  EXPECT_GT(by_filter, 5);
  EXPECT_GT(by_integers, 5);
}

}  // namespace
}  // namespace strata::diagnose::detail
