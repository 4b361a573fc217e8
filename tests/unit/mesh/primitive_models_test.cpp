#include "strata/mesh/primitive_models.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "strata/core/error.hpp"

namespace strata::mesh {
namespace {

using Key = std::tuple<double, double, double>;
using DirectedEdge = std::pair<Key, Key>;

Key key(const Vec3& p) { return {p.x, p.y, p.z}; }

Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// Divergence theorem: the volume is the sum over facets of a . (b x c) / 6, positive when the
/// facets face outward.
double signed_volume(const TriangleSoup& soup) {
  double six_v = 0.0;
  for (const auto& t : soup.triangles) six_v += dot(t[0], cross(t[1], t[2]));
  return six_v / 6.0;
}

/// Closed and consistently oriented: every directed edge (by exact corner coordinates) occurs once
/// and its reverse occurs once, so each undirected edge has exactly two uses in opposite
/// directions. Returns a description of the first offending edge, or "" when closed.
std::string closedness_defect(const TriangleSoup& soup) {
  std::map<DirectedEdge, int> uses;
  for (const auto& t : soup.triangles) {
    for (int i = 0; i < 3; ++i) ++uses[{key(t[i]), key(t[(i + 1) % 3])}];
  }
  for (const auto& [edge, count] : uses) {
    const auto reverse = uses.find({edge.second, edge.first});
    const int reverse_count = reverse == uses.end() ? 0 : reverse->second;
    if (count != 1 || reverse_count != 1) {
      const auto [x, y, z] = edge.first;
      return "edge from (" + std::to_string(x) + ", " + std::to_string(y) + ", " +
             std::to_string(z) + ") used " + std::to_string(count) + " times, reversed " +
             std::to_string(reverse_count) + " times";
    }
  }
  return "";
}

std::set<Key> corner_set(const TriangleSoup& soup) {
  std::set<Key> corners;
  for (const auto& t : soup.triangles) {
    for (const auto& p : t) corners.insert(key(p));
  }
  return corners;
}

bool is_float32(double v) { return static_cast<double>(static_cast<float>(v)) == v; }

/// For a convex solid around `centre`: the number of facets whose normal does not point away.
int inward_facets(const TriangleSoup& soup, const Vec3& centre) {
  int inward = 0;
  for (const auto& t : soup.triangles) {
    const Vec3 n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    const Vec3 c{(t[0].x + t[1].x + t[2].x) / 3, (t[0].y + t[1].y + t[2].y) / 3,
                 (t[0].z + t[1].z + t[2].z) / 3};
    if (!(dot(n, sub(c, centre)) > 0)) ++inward;
  }
  return inward;
}

/// Volume of the regular-n-gon prism that approximates a disc of radius r.
double polygon_prism_volume(double r, double height, int n) {
  return height * (n / 2.0) * std::sin(2 * std::numbers::pi / n) * r * r;
}

std::vector<std::array<Vec3, 3>> sorted_triangles(const TriangleSoup& soup) {
  auto t = soup.triangles;
  std::sort(t.begin(), t.end(), [](const auto& a, const auto& b) {
    return std::make_tuple(key(a[0]), key(a[1]), key(a[2])) <
           std::make_tuple(key(b[0]), key(b[1]), key(b[2]));
  });
  return t;
}

/// The message of the InternalError that `make` throws ("" when it throws none): the violated
/// precondition's text follows "failed: ".
template <class Make>
std::string precondition_message(const Make& make) {
  try {
    make();
  } catch (const InternalError& e) {
    const std::string what = e.what();
    const std::size_t at = what.find("failed: ");
    return at == std::string::npos ? what : what.substr(at + 8);
  }
  return "";
}

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// --- make_box -------------------------------------------------------------------------------

TEST(MakeBox, HasTwelveTriangles) {
  EXPECT_EQ(make_box({0, 0, 0}, {1, 2, 3}).triangles.size(), 12U);
}

TEST(MakeBox, IsClosed) { EXPECT_EQ(closedness_defect(make_box({0, 0, 0}, {1, 2, 3})), ""); }

TEST(MakeBox, EveryFacetFacesOutward) {
  EXPECT_EQ(inward_facets(make_box({-1, 0, 2}, {3, 5, 4}), {1, 2.5, 3}), 0);
}

TEST(MakeBox, VolumeIsExact) {
  // Dyadic corners: every product in the divergence sum is exact.
  EXPECT_EQ(signed_volume(make_box({-1.5, 2, 0.25}, {3, 4.5, 8})), 4.5 * 2.5 * 7.75);
}

TEST(MakeBox, UsesEightCornersAtTheGivenBounds) {
  const auto corners = corner_set(make_box({-1, -2, -3}, {1, 2, 3}));
  ASSERT_EQ(corners.size(), 8U);
  EXPECT_EQ(*corners.begin(), Key(-1, -2, -3));
  EXPECT_EQ(*corners.rbegin(), Key(1, 2, 3));
}

TEST(MakeBox, RoundsCornersToFloat32) {
  const auto soup = make_box({0.1, 0.2, 0.3}, {1.1, 1.2, 1.3});
  for (const auto& [x, y, z] : corner_set(soup)) {
    EXPECT_TRUE(is_float32(x) && is_float32(y) && is_float32(z));
  }
  EXPECT_EQ(soup.triangles[0][0].x, static_cast<double>(0.1F));
}

TEST(MakeBox, RejectsEmptyBox) { EXPECT_THROW(make_box({0, 0, 0}, {1, 0, 1}), InternalError); }

TEST(MakeBox, RejectsANonFiniteCoordinateOfEitherCorner) {
  const std::string message = "box corners must be finite";
  EXPECT_EQ(precondition_message([] { make_box({kNan, 0, 0}, {1, 1, 1}); }), message);
  EXPECT_EQ(precondition_message([] { make_box({0, kInf, 0}, {1, 1, 1}); }), message);
  EXPECT_EQ(precondition_message([] { make_box({0, 0, -kInf}, {1, 1, 1}); }), message);
  EXPECT_EQ(precondition_message([] { make_box({0, 0, 0}, {1, 1, kNan}); }), message);
}

TEST(MakeBox, RejectsMinNotBelowMaxOnEachAxis) {
  const std::string message = "box min must be below max";
  EXPECT_EQ(precondition_message([] { make_box({1, 0, 0}, {1, 1, 1}); }), message);
  EXPECT_EQ(precondition_message([] { make_box({0, 2, 0}, {1, 1, 1}); }), message);
  EXPECT_EQ(precondition_message([] { make_box({0, 0, 1}, {1, 1, 0.5}); }), message);
  EXPECT_EQ(precondition_message([] { make_box({0, 0, 0}, {1, 1, 1}); }), "");
}

// --- make_tetrahedron ------------------------------------------------------------------------

TEST(MakeTetrahedron, DefaultIsTheTenMillimetreCorner) {
  const auto soup = make_tetrahedron();
  EXPECT_EQ(soup.triangles.size(), 4U);
  EXPECT_EQ(corner_set(soup), (std::set<Key>{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}}));
  EXPECT_DOUBLE_EQ(signed_volume(soup), 1000.0 / 6.0);
}

TEST(MakeTetrahedron, IsClosed) { EXPECT_EQ(closedness_defect(make_tetrahedron()), ""); }

TEST(MakeTetrahedron, EveryFacetFacesOutward) {
  EXPECT_EQ(inward_facets(make_tetrahedron(), {2.5, 2.5, 2.5}), 0);
}

TEST(MakeTetrahedron, OrientsOutwardWhateverTheCornerOrder) {
  const auto soup = make_tetrahedron({0, 0, 0}, {0, 10, 0}, {10, 0, 0}, {0, 0, 10});
  EXPECT_DOUBLE_EQ(signed_volume(soup), 1000.0 / 6.0);
  EXPECT_EQ(closedness_defect(soup), "");
}

TEST(MakeTetrahedron, RejectsCoplanarCorners) {
  EXPECT_THROW(make_tetrahedron({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}), InternalError);
}

TEST(MakeTetrahedron, RejectsANonFiniteCorner) {
  const std::string message = "tetrahedron corners must be finite";
  const Vec3 bad{0, kNan, 0};
  EXPECT_EQ(precondition_message([&] {
              make_tetrahedron(bad, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
            }),
            message);
  EXPECT_EQ(precondition_message([&] {
              make_tetrahedron({0, 0, 0}, bad, {0, 1, 0}, {0, 0, 1});
            }),
            message);
  EXPECT_EQ(precondition_message([&] {
              make_tetrahedron({0, 0, 0}, {1, 0, 0}, bad, {0, 0, 1});
            }),
            message);
  EXPECT_EQ(precondition_message([&] {
              make_tetrahedron({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, bad);
            }),
            message);
}

// --- make_ring -------------------------------------------------------------------------------

TEST(MakeRing, HasEightTrianglesPerSegment) {
  EXPECT_EQ(make_ring(20, 12, 10, 128).triangles.size(), 8U * 128U);
}

TEST(MakeRing, IsClosed) { EXPECT_EQ(closedness_defect(make_ring(20, 12, 10, 128)), ""); }

TEST(MakeRing, IsClosedWithOddSegmentCount) {
  EXPECT_EQ(closedness_defect(make_ring(5, 3, 2, 7)), "");
}

TEST(MakeRing, IsOrientedOutward) { EXPECT_GT(signed_volume(make_ring(20, 12, 10, 128)), 0.0); }

TEST(MakeRing, VolumeMatchesThePolygonalRing) {
  const double expected = polygon_prism_volume(20, 10, 128) - polygon_prism_volume(12, 10, 128);
  // Only the float32 rounding of the corners (relative 2^-24) separates the two.
  EXPECT_NEAR(signed_volume(make_ring(20, 12, 10, 128)), expected, expected * 1e-6);
}

TEST(MakeRing, VolumeIsWithinTheDiscretisationErrorOfTheTrueRing) {
  const int n = 128;
  const double true_volume = std::numbers::pi * (20.0 * 20.0 - 12.0 * 12.0) * 10.0;
  const double x = 2 * std::numbers::pi / n;
  const double deficit = 1 - std::sin(x) / x;  // inscribed n-gon vs circle, ~ x^2 / 6
  const double relative = (true_volume - signed_volume(make_ring(20, 12, 10, n))) / true_volume;
  EXPECT_NEAR(relative, deficit, 1e-6);
  EXPECT_LT(relative, x * x / 6);
}

TEST(MakeRing, CornersLieOnTheCircles) {
  for (const auto& [x, y, z] : corner_set(make_ring(20, 12, 10, 128))) {
    const double r = std::hypot(x, y);
    const double nearest = std::abs(r - 20) < std::abs(r - 12) ? 20.0 : 12.0;
    EXPECT_NEAR(r, nearest, nearest * 1e-7) << "corner (" << x << ", " << y << ", " << z << ")";
    EXPECT_TRUE(z == 0.0 || z == 10.0);
  }
}

TEST(MakeRing, QuarterTurnCornersAreExact) {
  const auto corners = corner_set(make_ring(20, 12, 10, 128));
  for (const Key& k : {Key(20, 0, 0), Key(0, 20, 0), Key(-20, 0, 0), Key(0, -20, 0), Key(12, 0, 10),
                       Key(0, -12, 10)}) {
    EXPECT_EQ(corners.count(k), 1U);
  }
}

TEST(MakeRing, QuarterTurnMapsTheCornersOntoThemselves) {
  const auto ring = make_ring(20, 12, 10, 128);
  EXPECT_EQ(corner_set(rotate_soup_z90(ring)), corner_set(ring));
}

TEST(MakeRing, RejectsInnerRadiusNotBelowOuter) {
  EXPECT_THROW(make_ring(10, 10, 5, 32), InternalError);
}

TEST(MakeRing, RejectsEachInvalidParameterWithItsMessage) {
  const std::string finite = "ring sizes must be finite";
  EXPECT_EQ(precondition_message([] { make_ring(kInf, 12, 10, 32); }), finite);
  EXPECT_EQ(precondition_message([] { make_ring(20, kNan, 10, 32); }), finite);
  EXPECT_EQ(precondition_message([] { make_ring(20, 12, kInf, 32); }), finite);
  EXPECT_EQ(precondition_message([] { make_ring(20, 0, 10, 32); }),
            "ring needs 0 < r_inner < r_outer");
  EXPECT_EQ(precondition_message([] { make_ring(20, 12, 0, 32); }), "ring height must be positive");
  EXPECT_EQ(precondition_message([] { make_ring(20, 12, 10, 2); }),
            "ring needs at least 3 segments");
  EXPECT_EQ(make_ring(20, 12, 10, 3).triangles.size(), 24U);
}

// --- make_cylinder ---------------------------------------------------------------------------

TEST(MakeCylinder, HasFourTrianglesPerSegment) {
  EXPECT_EQ(make_cylinder(5, 10, 64).triangles.size(), 4U * 64U);
}

TEST(MakeCylinder, IsClosed) { EXPECT_EQ(closedness_defect(make_cylinder(5, 10, 64)), ""); }

TEST(MakeCylinder, EveryFacetFacesOutward) {
  EXPECT_EQ(inward_facets(make_cylinder(5, 10, 64), {0, 0, 5}), 0);
}

TEST(MakeCylinder, VolumeMatchesThePolygonalPrism) {
  const double expected = polygon_prism_volume(5, 10, 64);
  EXPECT_NEAR(signed_volume(make_cylinder(5, 10, 64)), expected, expected * 1e-6);
}

TEST(MakeCylinder, RejectsEachInvalidParameterWithItsMessage) {
  const std::string finite = "cylinder sizes must be finite";
  EXPECT_EQ(precondition_message([] { make_cylinder(kNan, 10, 16); }), finite);
  EXPECT_EQ(precondition_message([] { make_cylinder(5, kInf, 16); }), finite);
  const std::string positive = "cylinder radius and height must be positive";
  EXPECT_EQ(precondition_message([] { make_cylinder(-5, 10, 16); }), positive);
  EXPECT_EQ(precondition_message([] { make_cylinder(5, 0, 16); }), positive);
  EXPECT_EQ(precondition_message([] { make_cylinder(5, 10, 2); }),
            "cylinder needs at least 3 segments");
  EXPECT_EQ(make_cylinder(5, 10, 3).triangles.size(), 12U);
}

// --- make_sphere -----------------------------------------------------------------------------

TEST(MakeSphere, RejectsEachInvalidParameterWithItsMessage) {
  const std::string radius = "sphere radius must be positive";
  EXPECT_EQ(precondition_message([] { make_sphere(kInf, 1); }), radius);
  EXPECT_EQ(precondition_message([] { make_sphere(0, 1); }), radius);
  const std::string subdivisions = "sphere subdivisions must be in [0, 7]";
  EXPECT_EQ(precondition_message([] { make_sphere(1, -1); }), subdivisions);
  EXPECT_EQ(precondition_message([] { make_sphere(1, 8); }), subdivisions);
}

TEST(MakeSphere, HasTwentyTimesFourToTheSubdivisionsTriangles) {
  EXPECT_EQ(make_sphere(1, 0).triangles.size(), 20U);
  EXPECT_EQ(make_sphere(1, 3).triangles.size(), 20U * 64U);
}

TEST(MakeSphere, IsClosed) { EXPECT_EQ(closedness_defect(make_sphere(10, 3)), ""); }

TEST(MakeSphere, EveryFacetFacesOutward) {
  EXPECT_EQ(inward_facets(make_sphere(10, 3), {0, 0, 0}), 0);
}

TEST(MakeSphere, CornersLieOnTheSphere) {
  for (const auto& [x, y, z] : corner_set(make_sphere(10, 3))) {
    EXPECT_NEAR(std::sqrt(x * x + y * y + z * z), 10.0, 10.0 * 2e-7);
  }
}

TEST(MakeSphere, VolumeIsBetweenTheInscribedAndTheCircumscribedBall) {
  const double r = 10;
  for (int s = 0; s <= 4; ++s) {
    const auto soup = make_sphere(r, s);
    // Each face plane lies at sqrt(r^2 - rho^2) from the centre (rho = the face's
    // circumradius), so the polyhedron contains the ball of the smallest such distance.
    double h_min = r;
    for (const auto& t : soup.triangles) {
      const double a = std::sqrt(dot(sub(t[1], t[2]), sub(t[1], t[2])));
      const double b = std::sqrt(dot(sub(t[2], t[0]), sub(t[2], t[0])));
      const double c = std::sqrt(dot(sub(t[0], t[1]), sub(t[0], t[1])));
      const Vec3 n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
      const double rho = a * b * c / (2 * std::sqrt(dot(n, n)));
      h_min = std::min(h_min, std::sqrt(r * r - rho * rho));
    }
    const double ball = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    const double v = signed_volume(soup);
    EXPECT_LE(v, ball * (1 + 1e-6)) << "subdivisions " << s;
    EXPECT_GE(v, ball * std::pow(h_min / r, 3) * (1 - 1e-6)) << "subdivisions " << s;
  }
}

TEST(MakeSphere, FourSubdivisionsMissTheBallByLessThanOnePercent) {
  const double ball = 4.0 / 3.0 * std::numbers::pi * 1000.0;
  EXPECT_LT((ball - signed_volume(make_sphere(10, 4))) / ball, 0.01);
}

// --- transforms ------------------------------------------------------------------------------

TEST(RotateSoupZ90, MapsXyToMinusYX) {
  const auto tet = make_tetrahedron({1, 2, 3}, {4, 2, 3}, {1, 7, 3}, {1, 2, 9});
  const auto turned = rotate_soup_z90(tet);
  ASSERT_EQ(turned.triangles.size(), tet.triangles.size());
  for (std::size_t f = 0; f < tet.triangles.size(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const Vec3& p = tet.triangles[f][c];
      EXPECT_EQ(turned.triangles[f][c], (Vec3{-p.y, p.x, p.z}));
    }
  }
}

TEST(RotateSoupZ90, RotatesTheStoredNormalsToo) {
  TriangleSoup soup;
  soup.triangles.push_back({Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  soup.triangles.push_back({Vec3{0, 0, 0}, {0, 0, 1}, {1, 0, 0}});
  soup.stored_normals = {{0, 0, 1}, {0, -1, 0}};
  const auto turned = rotate_soup_z90(soup);
  EXPECT_EQ(turned.stored_normals, (std::vector<Vec3>{{0, 0, 1}, {1, 0, 0}}));
  EXPECT_EQ(turned.triangles[1], (std::array<Vec3, 3>{Vec3{0, 0, 0}, {0, 0, 1}, {0, 1, 0}}));
}

TEST(RotateSoupZ90, FourQuarterTurnsGiveTheSameBits) {
  const auto sphere = make_sphere(10, 2);
  const auto back = rotate_soup_z90(rotate_soup_z90(rotate_soup_z90(rotate_soup_z90(sphere))));
  EXPECT_EQ(back.triangles, sphere.triangles);
}

TEST(RotateSoupZ90, KeepsTheSolidClosedAndOutward) {
  const auto turned = rotate_soup_z90(make_ring(20, 12, 10, 64));
  EXPECT_EQ(closedness_defect(turned), "");
  EXPECT_GT(signed_volume(turned), 0.0);
}

TEST(TranslateSoup, MovesEveryCornerByTheOffset) {
  const auto box = make_box({0, 0, 0}, {1, 2, 3});
  const auto moved = translate_soup(box, {10, -20, 0.5});
  EXPECT_EQ(corner_set(moved).size(), 8U);
  EXPECT_EQ(*corner_set(moved).begin(), Key(10, -20, 0.5));
  EXPECT_EQ(closedness_defect(moved), "");
  EXPECT_DOUBLE_EQ(signed_volume(moved), 6.0);
}

TEST(ScaleSoup, RejectsAFactorThatIsNotPositiveAndFinite) {
  const auto box = make_box({0, 0, 0}, {1, 1, 1});
  const std::string message = "scale factor must be positive";
  EXPECT_EQ(precondition_message([&] { scale_soup(box, kInf); }), message);
  EXPECT_EQ(precondition_message([&] { scale_soup(box, -2.0); }), message);
  EXPECT_EQ(precondition_message([&] { scale_soup(box, 0.0); }), message);
}

TEST(ScaleSoup, ScalingByTwoMultipliesTheVolumeByEightExactly) {
  const auto sphere = make_sphere(10, 2);
  EXPECT_EQ(signed_volume(scale_soup(sphere, 2.0)), 8.0 * signed_volume(sphere));
}

TEST(ShuffleFacets, KeepsTheSameTriangles) {
  const auto ring = make_ring(20, 12, 10, 32);
  EXPECT_EQ(sorted_triangles(shuffle_facets(ring, 42)), sorted_triangles(ring));
}

TEST(ShuffleFacets, ChangesTheOrder) {
  const auto ring = make_ring(20, 12, 10, 32);
  EXPECT_NE(shuffle_facets(ring, 42).triangles, ring.triangles);
}

TEST(ShuffleFacets, SameSeedGivesSameOrder) {
  const auto ring = make_ring(20, 12, 10, 32);
  EXPECT_EQ(shuffle_facets(ring, 7).triangles, shuffle_facets(ring, 7).triangles);
  EXPECT_NE(shuffle_facets(ring, 7).triangles, shuffle_facets(ring, 8).triangles);
}

TEST(ShuffleFacets, MovesStoredNormalsWithTheirTriangles) {
  auto box = make_box({0, 0, 0}, {1, 1, 1});
  for (std::size_t f = 0; f < box.triangles.size(); ++f) {
    box.stored_normals.push_back({static_cast<double>(f), 0, 0});
  }
  const auto shuffled = shuffle_facets(box, 3);
  ASSERT_EQ(shuffled.stored_normals.size(), box.triangles.size());
  for (std::size_t f = 0; f < shuffled.triangles.size(); ++f) {
    const auto original = static_cast<std::size_t>(shuffled.stored_normals[f].x);
    EXPECT_EQ(shuffled.triangles[f], box.triangles[original]);
  }
}

TEST(RotateCorners, KeepsGeometryAndOrientation) {
  const auto ring = make_ring(20, 12, 10, 32);
  const auto cycled = rotate_corners(ring);
  EXPECT_EQ(closedness_defect(cycled), "");
  EXPECT_EQ(cycled.triangles[0][0], ring.triangles[0][1]);
  EXPECT_NEAR(signed_volume(cycled), signed_volume(ring), 1e-9 * signed_volume(ring));
}

TEST(FlipOrientation, NegatesTheVolumeExactly) {
  const auto sphere = make_sphere(10, 2);
  EXPECT_EQ(signed_volume(flip_orientation(sphere)), -signed_volume(sphere));
}

TEST(FlipOrientation, KeepsTheSurfaceClosed) {
  EXPECT_EQ(closedness_defect(flip_orientation(make_ring(20, 12, 10, 16))), "");
}

TEST(FlipOrientation, NegatesTheStoredNormals) {
  TriangleSoup soup;
  soup.triangles.push_back({Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  soup.stored_normals = {{0, 0.5, 1}};
  const auto flipped = flip_orientation(soup);
  EXPECT_EQ(flipped.triangles[0], (std::array<Vec3, 3>{Vec3{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}));
  EXPECT_EQ(flipped.stored_normals, (std::vector<Vec3>{{0, -0.5, -1}}));
}

TEST(FlipOrientation, TwiceIsTheIdentity) {
  const auto ring = make_ring(20, 12, 10, 16);
  EXPECT_EQ(flip_orientation(flip_orientation(ring)).triangles, ring.triangles);
}

}  // namespace
}  // namespace strata::mesh
