#include "strata/diagnose/diagnose_mesh.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "strata/core/error.hpp"
#include "strata/diagnose/mesh_report_json.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "support/mesh_builders.hpp"

namespace strata::diagnose {
namespace {

using Triangle = test::Facet;
using test::box_facets_lo_hi_diagonals;
using test::joined;
using test::reversed;

Vec3 cross_of(const Triangle& t) {
  const Vec3 u{t[1].x - t[0].x, t[1].y - t[0].y, t[1].z - t[0].z};
  const Vec3 v{t[2].x - t[0].x, t[2].y - t[0].y, t[2].z - t[0].z};
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

/// A soup whose stored normals follow the vertex order.
TriangleSoup soup_of(const std::vector<Triangle>& triangles) {
  TriangleSoup soup;
  soup.triangles = triangles;
  for (const Triangle& t : triangles) soup.stored_normals.push_back(cross_of(t));
  soup.format = "stl-binary";
  return soup;
}

std::vector<Triangle> unit_box() { return box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}); }

MeshReport diagnose(const TriangleSoup& soup, const DiagnoseOptions& options = {}) {
  return diagnose_mesh(weld_vertices(soup), soup, options);
}

MeshReport diagnose(const std::vector<Triangle>& triangles, const DiagnoseOptions& options = {}) {
  return diagnose(soup_of(triangles), options);
}

TEST(DiagnoseMesh, ClosedBoxHasNoDefects) {
  const MeshReport r = diagnose(unit_box());
  EXPECT_EQ(r.num_facets, 12U);
  EXPECT_EQ(r.num_input_facets, 12U);
  EXPECT_EQ(r.num_vertices, 8U);
  EXPECT_EQ(r.boundary_edges.count, 0U);
  EXPECT_EQ(r.num_boundary_loops, 0U);
  EXPECT_EQ(r.non_manifold_edges.count, 0U);
  EXPECT_EQ(r.non_manifold_vertices.count, 0U);
  EXPECT_EQ(r.inconsistent_edges.count, 0U);
  EXPECT_EQ(r.unbalanced_edges.count, 0U);
  EXPECT_EQ(r.degenerate_facets.count, 0U);
  EXPECT_EQ(r.duplicate_facets.count, 0U);
  EXPECT_EQ(r.near_vertices.count, 0U);
  EXPECT_EQ(r.flipped_normals.count, 0U);
  EXPECT_EQ(r.zero_normals.count, 0U);
  EXPECT_EQ(r.self_intersections.count, 0U);
  EXPECT_FALSE(r.self_intersections_truncated);
  ASSERT_EQ(r.shells.size(), 1U);
  EXPECT_TRUE(r.shells[0].is_closed);
  EXPECT_TRUE(r.shells[0].is_balanced);
  EXPECT_FALSE(r.shells[0].is_inverted);
  EXPECT_EQ(r.verdict, Verdict::Printable);
}

TEST(DiagnoseMesh, BoxVolumeAndAreaAreExact) {
  const MeshReport r =
      diagnose(box_facets_lo_hi_diagonals({-1.5, 0.25, 2.0}, {2.5, 3.75, 10.0}));  // 4 x 3.5 x 8
  EXPECT_EQ(r.volume_mm3, 112.0);
  EXPECT_EQ(r.shells[0].signed_volume_mm3, 112.0);
  EXPECT_DOUBLE_EQ(r.surface_area_mm2, 2.0 * (4.0 * 3.5 + 3.5 * 8.0 + 8.0 * 4.0));
  EXPECT_EQ(r.bounds.min, (Vec3{-1.5, 0.25, 2.0}));
  EXPECT_EQ(r.bounds.max, (Vec3{2.5, 3.75, 10.0}));
}

TEST(DiagnoseMesh, VolumeFarFromOriginIsExact) {
  // Far from the origin the tetrahedra cancel to 1e-24 of their size: a double sum loses the
  // volume, the exact sum keeps it.
  const double far = 1e8;
  const MeshReport r =
      diagnose(box_facets_lo_hi_diagonals({far, far, far}, {far + 0.5, far + 0.25, far + 2.0}));
  EXPECT_EQ(r.volume_mm3, 0.25);
}

TEST(DiagnoseMesh, BoxWithoutOneFacetHasThreeBoundaryEdgesInOneLoop) {
  auto facets = unit_box();
  facets.erase(facets.begin() + 4);
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.boundary_edges.count, 3U);
  EXPECT_EQ(r.boundary_edges.locations.size(), 3U);
  EXPECT_EQ(r.num_boundary_loops, 1U);
  EXPECT_EQ(r.unbalanced_edges.count, 3U);
  ASSERT_EQ(r.shells.size(), 1U);
  EXPECT_FALSE(r.shells[0].is_closed);
  EXPECT_EQ(r.num_closed_shells, 0U);
  EXPECT_EQ(r.verdict, Verdict::NeedsRepair);
  EXPECT_NE(r.verdict_reason.find("3 open edges in 1 loop"), std::string::npos) << r.verdict_reason;
}

TEST(DiagnoseMesh, BoundaryEdgeLocationFollowsTheFacet) {
  const MeshReport r =
      diagnose(std::vector<Triangle>{{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}});
  ASSERT_EQ(r.boundary_edges.count, 3U);
  ASSERT_EQ(r.num_boundary_loops, 1U);
  // Every kept boundary edge runs in the facet's direction.
  for (const EdgeLocation& e : r.boundary_edges.locations) {
    const bool known = (e.from == Vec3{0, 0, 0} && e.to == Vec3{1, 0, 0}) ||
                       (e.from == Vec3{1, 0, 0} && e.to == Vec3{0, 1, 0}) ||
                       (e.from == Vec3{0, 1, 0} && e.to == Vec3{0, 0, 0});
    EXPECT_TRUE(known);
  }
}

TEST(DiagnoseMesh, TwoHolesMakeTwoLoops) {
  auto facets = unit_box();
  facets.erase(facets.begin() + 2);  // top
  facets.erase(facets.begin());      // bottom
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.boundary_edges.count, 6U);
  EXPECT_EQ(r.num_boundary_loops, 2U);
}

TEST(DiagnoseMesh, BoxesSharingAnEdgeHaveOneNonManifoldEdge) {
  const MeshReport r =
      diagnose(joined(unit_box(), box_facets_lo_hi_diagonals({1, 1, 0}, {2, 2, 1})));
  EXPECT_EQ(r.non_manifold_edges.count, 1U);
  ASSERT_EQ(r.non_manifold_edges.locations.size(), 1U);
  const EdgeLocation& e = r.non_manifold_edges.locations[0];
  EXPECT_EQ(e.from.x, 1.0);
  EXPECT_EQ(e.from.y, 1.0);
  EXPECT_EQ(e.to.x, 1.0);
  EXPECT_EQ(e.to.y, 1.0);
  EXPECT_EQ(r.boundary_edges.count, 0U);
  EXPECT_EQ(r.unbalanced_edges.count, 0U);
  EXPECT_EQ(r.self_intersections.count, 0U);
  EXPECT_EQ(r.shells.size(), 1U);  // joined through the shared edge
  EXPECT_EQ(r.verdict, Verdict::PrintableUnderRule);
}

TEST(DiagnoseMesh, BoxesSharingAVertexHaveOneNonManifoldVertex) {
  const MeshReport r =
      diagnose(joined(unit_box(), box_facets_lo_hi_diagonals({1, 1, 1}, {2, 2, 2})));
  EXPECT_EQ(r.non_manifold_edges.count, 0U);
  ASSERT_EQ(r.non_manifold_vertices.count, 1U);
  EXPECT_EQ(r.non_manifold_vertices.locations[0], (Vec3{1, 1, 1}));
  EXPECT_EQ(r.shells.size(), 2U);  // a vertex does not join shells
  EXPECT_EQ(r.self_intersections.count, 0U);
  EXPECT_EQ(r.verdict, Verdict::PrintableUnderRule);
}

/// A closed double pyramid, consistently oriented: `sides` corners about `centre` at radius 1,
/// apexes 1 above and below it.
std::vector<Triangle> double_pyramid(const Vec3& centre, int sides) {
  std::vector<Triangle> out;
  const Vec3 top{centre.x, centre.y, centre.z + 1};
  const Vec3 bottom{centre.x, centre.y, centre.z - 1};
  const auto corner = [&](int i) {
    const double angle = 6.283185307179586 * (i % sides) / sides;
    return Vec3{centre.x + std::cos(angle), centre.y + std::sin(angle), centre.z};
  };
  for (int i = 0; i < sides; ++i) {
    out.push_back({corner(i), corner(i + 1), top});
    out.push_back({corner(i + 1), corner(i), bottom});
  }
  return out;
}

TEST(DiagnoseMesh, AVertexsFansAreCountedWhateverItsFacetsNumberAndOrientation) {
  // Walking a vertex's facets in their orientation tells one fan at once; more than 16 facets,
  // two fans, or a facet turned the other way are counted in general. The counts agree.
  for (const int sides : {6, 12, 24}) {
    const std::vector<Triangle> one = double_pyramid({0, 0, 0}, sides);
    EXPECT_EQ(diagnose(one).non_manifold_vertices.count, 0U) << sides;
    std::vector<Triangle> turned = one;
    turned[3] = reversed(turned[3]);
    EXPECT_EQ(diagnose(turned).non_manifold_vertices.count, 0U) << sides;
    // A second one standing on the first's top apex: two fans about it, whichever way each turns.
    const std::vector<Triangle> above = double_pyramid({0, 0, 2}, sides);
    for (const auto& two : {joined(one, above), joined(one, reversed(above))}) {
      const MeshReport r = diagnose(two);
      ASSERT_EQ(r.non_manifold_vertices.count, 1U) << sides;
      EXPECT_EQ(r.non_manifold_vertices.locations[0], (Vec3{0, 0, 1})) << sides;
    }
  }
}

TEST(DiagnoseMesh, DuplicatedFacetIsCountedOnce) {
  auto facets = unit_box();
  facets.push_back(facets[3]);
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.duplicate_facets.count, 1U);
  ASSERT_EQ(r.duplicate_facets.locations.size(), 1U);
  EXPECT_EQ(r.duplicate_facets.locations[0], 12U);  // the extra copy
  EXPECT_EQ(r.non_manifold_edges.count, 3U);
  EXPECT_EQ(r.self_intersections.count, 0U);  // duplicates are not self-intersections
}

TEST(DiagnoseMesh, DuplicatedFacetInSameOrientationNeedsRepair) {
  // Its three edges are run twice one way and once the other: the winding number jumps by two
  // across the facet and the nonzero rule would fill outside the box.
  auto facets = unit_box();
  facets.push_back(facets[3]);
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.unbalanced_edges.count, 3U);
  EXPECT_EQ(r.verdict, Verdict::NeedsRepair);
}

TEST(DiagnoseMesh, DuplicatedFacetInReverseOrientationNeedsRepair) {
  // The reversed copy cancels the original: together they leave a hole in the box.
  auto facets = unit_box();
  facets.push_back(reversed(facets[3]));
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.duplicate_facets.count, 1U);
  EXPECT_EQ(r.unbalanced_edges.count, 3U);
  EXPECT_EQ(r.verdict, Verdict::NeedsRepair);
}

TEST(DiagnoseMesh, ExtraFacetTogetherWithItsReverseIsBalanced) {
  auto facets = unit_box();
  facets.push_back(facets[3]);
  facets.push_back(reversed(facets[3]));
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.duplicate_facets.count, 2U);
  EXPECT_EQ(r.unbalanced_edges.count, 0U);
  EXPECT_EQ(r.verdict, Verdict::PrintableUnderRule);
}

TEST(DiagnoseMesh, DuplicatedShellIsPrintableUnderRule) {
  const MeshReport r = diagnose(joined(unit_box(), unit_box()));
  EXPECT_EQ(r.duplicate_facets.count, 12U);
  EXPECT_EQ(r.non_manifold_edges.count, 18U);
  EXPECT_EQ(r.unbalanced_edges.count, 0U);
  EXPECT_EQ(r.volume_mm3, 2.0);
  EXPECT_EQ(r.verdict, Verdict::PrintableUnderRule);
  EXPECT_NE(r.verdict_reason.find("12 duplicate facets"), std::string::npos) << r.verdict_reason;
}

/// A unit box whose side facet (0,0,0)-(1,0,0)-(1,0,1) is split at m = (0.5, 0, 0), and the
/// T-junction at m closed by the zero-area facet ((0,0,0), (1,0,0), m), facet 13.
std::vector<Triangle> box_with_sealed_t_junction() {
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, m{0.5, 0, 0}, top{1, 0, 1};
  auto facets = unit_box();
  facets.erase(facets.begin() + 4);  // (o, x, top)
  facets.push_back({o, m, top});
  facets.push_back({m, x, top});
  facets.push_back({o, x, m});
  return facets;
}

TEST(DiagnoseMesh, CollinearFacetIsDegenerate) {
  const MeshReport r = diagnose(box_with_sealed_t_junction());
  EXPECT_EQ(r.degenerate_facets.count, 1U);
  ASSERT_EQ(r.degenerate_facets.locations.size(), 1U);
  EXPECT_EQ(r.degenerate_facets.locations[0], 13U);
  EXPECT_EQ(r.volume_mm3, 1.0);
  EXPECT_EQ(r.surface_area_mm2, 6.0);
}

TEST(DiagnoseMesh, EdgesOfZeroAreaFacetsAreNotPartOfTheTopology) {
  // Without the zero-area facet the split side leaves the crack o-m-x against the bottom's o-x.
  const MeshReport r = diagnose(box_with_sealed_t_junction());
  EXPECT_EQ(r.boundary_edges.count, 3U);
  EXPECT_EQ(r.num_boundary_loops, 1U);
  ASSERT_EQ(r.shells.size(), 1U);
  EXPECT_EQ(r.shells[0].num_facets, 13U);
  EXPECT_FALSE(r.shells[0].is_closed);
}

TEST(DiagnoseMesh, ZeroAreaFacetSealingACrackKeepsTheMeshBalanced) {
  const MeshReport r = diagnose(box_with_sealed_t_junction());
  EXPECT_EQ(r.unbalanced_edges.count, 0U);
  EXPECT_EQ(r.verdict, Verdict::PrintableUnderRule);
  EXPECT_NE(r.verdict_reason.find("sealed by zero-area facets"), std::string::npos)
      << r.verdict_reason;
}

TEST(DiagnoseMesh, CrackWithoutSealNeedsRepair) {
  auto facets = box_with_sealed_t_junction();
  facets.pop_back();
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.boundary_edges.count, 3U);
  EXPECT_EQ(r.unbalanced_edges.count, 3U);
  EXPECT_EQ(r.verdict, Verdict::NeedsRepair);
}

TEST(DiagnoseMesh, FacetWithTwoEqualVerticesIsDegenerate) {
  auto facets = unit_box();
  facets.push_back({Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{1, 0, 0}});
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.degenerate_facets.count, 1U);
  EXPECT_EQ(r.surface_area_mm2, 6.0);
}

TEST(DiagnoseMesh, NearlyCollinearFacetIsNotDegenerate) {
  auto facets = unit_box();
  facets.push_back({Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0.5, 1e-300, 0}});
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.degenerate_facets.count, 0U);
}

TEST(DiagnoseMesh, OneFlippedFacetGivesThreeInconsistentEdges) {
  auto facets = unit_box();
  facets[5] = reversed(facets[5]);
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.inconsistent_edges.count, 3U);
  EXPECT_EQ(r.boundary_edges.count, 0U);
  ASSERT_EQ(r.shells.size(), 1U);
  EXPECT_TRUE(r.shells[0].is_closed);
  EXPECT_FALSE(r.shells[0].is_balanced);
  EXPECT_EQ(r.verdict, Verdict::NeedsRepair);
  EXPECT_NE(r.verdict_reason.find("3 inconsistently oriented edges"), std::string::npos)
      << r.verdict_reason;
}

TEST(DiagnoseMesh, InvertedBoxIsAnInvertedShell) {
  const MeshReport r = diagnose(reversed(unit_box()));
  EXPECT_EQ(r.volume_mm3, -1.0);
  ASSERT_EQ(r.shells.size(), 1U);
  EXPECT_TRUE(r.shells[0].is_inverted);
  EXPECT_EQ(r.inverted_shells.count, 1U);
  EXPECT_EQ(r.inconsistent_edges.count, 0U);
  EXPECT_EQ(r.verdict, Verdict::PrintableUnderRule);
}

TEST(DiagnoseMesh, InnerWallOfHollowBoxIsACavityNotInverted) {
  const MeshReport r = diagnose(joined(box_facets_lo_hi_diagonals({0, 0, 0}, {4, 4, 4}),
                                       reversed(box_facets_lo_hi_diagonals({1, 1, 1}, {3, 3, 3}))));
  ASSERT_EQ(r.shells.size(), 2U);
  EXPECT_TRUE(r.shells[1].is_cavity);
  EXPECT_FALSE(r.shells[1].is_inverted);
  EXPECT_EQ(r.inverted_shells.count, 0U);
  EXPECT_EQ(r.volume_mm3, 64.0 - 8.0);
  EXPECT_EQ(r.verdict, Verdict::Printable);
}

TEST(DiagnoseMesh, OverlappingBoxesSelfIntersect) {
  const MeshReport r =
      diagnose(joined(unit_box(), box_facets_lo_hi_diagonals({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5})));
  EXPECT_GT(r.self_intersections.count, 0U);
  EXPECT_FALSE(r.self_intersections_truncated);
  for (const FacetPair& p : r.self_intersections.locations) {
    EXPECT_LT(p.first, 12U);  // every pair has one facet of each box
    EXPECT_GE(p.second, 12U);
  }
  EXPECT_EQ(r.shells.size(), 2U);
  EXPECT_EQ(r.num_closed_shells, 2U);
  EXPECT_EQ(r.verdict, Verdict::PrintableUnderRule);
}

TEST(DiagnoseMesh, SelfIntersectionSearchStopsAtItsLimit) {
  const MeshReport r =
      diagnose(joined(unit_box(), box_facets_lo_hi_diagonals({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5})),
               DiagnoseOptions{.max_self_intersection_pairs = 2});
  EXPECT_EQ(r.self_intersections.count, 2U);
  EXPECT_TRUE(r.self_intersections_truncated);
}

TEST(DiagnoseMesh, SelfIntersectionSearchCanBeSwitchedOff) {
  const MeshReport r =
      diagnose(joined(unit_box(), box_facets_lo_hi_diagonals({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5})),
               DiagnoseOptions{.check_self_intersections = false});
  EXPECT_FALSE(r.self_intersections_checked);
  EXPECT_EQ(r.self_intersections.count, 0U);
}

TEST(DiagnoseMesh, FacetsFoldedOntoEachOtherAcrossAnEdgeIntersect) {
  const Vec3 a{0, 0, 0}, b{2, 0, 0}, c{1, 1, 0}, d{1, 2, 0};
  const MeshReport r = diagnose(std::vector<Triangle>{{a, b, c}, {b, a, d}});
  EXPECT_EQ(r.self_intersections.count, 1U);
}

TEST(DiagnoseMesh, FacetsMeetingAlongAnEdgeDoNotIntersect) {
  const Vec3 a{0, 0, 0}, b{2, 0, 0}, c{1, 1, 0}, d{1, -1, 0};
  const MeshReport r = diagnose(std::vector<Triangle>{{a, b, c}, {b, a, d}});
  EXPECT_EQ(r.self_intersections.count, 0U);
}

TEST(DiagnoseMesh, FacetsSharingAVertexAndCrossingIntersect) {
  const Vec3 o{0, 0, 0};
  const MeshReport r = diagnose(std::vector<Triangle>{{o, Vec3{2, -1, 0}, Vec3{2, 1, 0}},
                                                      {o, Vec3{1, 0, -1}, Vec3{1, 0, 1}}});
  EXPECT_EQ(r.self_intersections.count, 1U);
}

TEST(DiagnoseMesh, FacetsTouchingOnlyAtASharedVertexDoNotIntersect) {
  const Vec3 o{0, 0, 0};
  const MeshReport r = diagnose(std::vector<Triangle>{{o, Vec3{2, -1, 0}, Vec3{2, 1, 0}},
                                                      {o, Vec3{-1, 0, -1}, Vec3{-1, 0, 1}}});
  EXPECT_EQ(r.self_intersections.count, 0U);
}

TEST(DiagnoseMesh, ReversedStoredNormalIsFlipped) {
  TriangleSoup soup = soup_of(unit_box());
  soup.stored_normals[7] = {-soup.stored_normals[7].x, -soup.stored_normals[7].y,
                            -soup.stored_normals[7].z};
  const MeshReport r = diagnose(soup);
  EXPECT_TRUE(r.normals_checked);
  EXPECT_EQ(r.flipped_normals.count, 1U);
  ASSERT_EQ(r.flipped_normals.locations.size(), 1U);
  EXPECT_EQ(r.flipped_normals.locations[0], 7U);
  EXPECT_EQ(r.verdict, Verdict::Printable);  // slicing never looks at stored normals
}

TEST(DiagnoseMesh, ZeroAndNonFiniteStoredNormalsAreCountedApart) {
  TriangleSoup soup = soup_of(unit_box());
  soup.stored_normals[2] = {0.0, -0.0, 0.0};
  soup.stored_normals[4] = {std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0};
  const MeshReport r = diagnose(soup);
  EXPECT_EQ(r.zero_normals.count, 1U);
  EXPECT_EQ(r.non_finite_normals.count, 1U);
  EXPECT_EQ(r.flipped_normals.count, 0U);
}

TEST(DiagnoseMesh, StoredNormalsOfManyFacetsAreListedInFacetOrder) {
  // 2,000 boxes apart (24,000 facets, several ranges for the threads), their stored normals zero,
  // not finite, reversed or right by a pattern that mixes the three findings.
  std::vector<Triangle> facets;
  for (int b = 0; b < 2000; ++b) {
    const Vec3 lo{3.0 * (b % 50), 3.0 * (b / 50), 0.0};
    for (const Triangle& t : box_facets_lo_hi_diagonals(lo, {lo.x + 1, lo.y + 1, 1})) {
      facets.push_back(t);
    }
  }
  TriangleSoup soup = soup_of(facets);
  std::vector<FacetIndex> zero, non_finite, flipped;
  for (FacetIndex f = 0; f < facets.size(); ++f) {
    Vec3& n = soup.stored_normals[f];
    if (f % 7 == 3) {
      n = {0.0, 0.0, -0.0};
      zero.push_back(f);
    } else if (f % 11 == 5) {
      n.y = std::numeric_limits<double>::infinity();
      non_finite.push_back(f);
    } else if (f % 5 == 1) {
      n = {-n.x, -n.y, -n.z};
      flipped.push_back(f);
    }
  }
  const auto expect_listed = [](const Occurrences<FacetIndex>& found,
                                const std::vector<FacetIndex>& all, std::size_t limit) {
    EXPECT_EQ(found.count, all.size());
    EXPECT_EQ(found.locations,
              std::vector<FacetIndex>(all.begin(), all.begin() + std::min(limit, all.size())));
  };
  for (const int threads : {1, 2, 4}) {
    SCOPED_TRACE(threads);
    const tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, threads);
    for (const std::size_t limit : {std::size_t{0}, std::size_t{3}, std::size_t{100'000}}) {
      SCOPED_TRACE(limit);
      // The normals alone are looked at: the searches for near vertices and crossings are not
      // run.
      const MeshReport r = diagnose(soup, DiagnoseOptions{.near_vertex_mm = 0.0,
                                                          .max_locations = limit,
                                                          .check_self_intersections = false});
      expect_listed(r.zero_normals, zero, limit);
      expect_listed(r.non_finite_normals, non_finite, limit);
      expect_listed(r.flipped_normals, flipped, limit);
    }
  }
}

TEST(DiagnoseMesh, SoupWithoutNormalsSkipsTheNormalCheck) {
  TriangleSoup soup = soup_of(unit_box());
  soup.stored_normals.clear();
  const MeshReport r = diagnose(soup);
  EXPECT_FALSE(r.normals_checked);
}

TEST(DiagnoseMesh, NearCoincidentVerticesAreReportedNotMerged) {
  auto facets = unit_box();
  facets[0][0] = {1e-9, 0, 0};  // instead of (0, 0, 0)
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.num_vertices, 9U);
  ASSERT_EQ(r.near_vertices.count, 1U);
  const PointPair& p = r.near_vertices.locations[0];
  EXPECT_TRUE((p.first == Vec3{0, 0, 0} && p.second == Vec3{1e-9, 0, 0}) ||
              (p.second == Vec3{0, 0, 0} && p.first == Vec3{1e-9, 0, 0}));
  EXPECT_GT(r.boundary_edges.count, 0U);
}

TEST(DiagnoseMesh, NearVertexToleranceIsAnOption) {
  auto facets = unit_box();
  facets[0][0] = {1e-3, 0, 0};
  EXPECT_EQ(diagnose(facets).near_vertices.count, 0U);
  EXPECT_EQ(diagnose(facets, DiagnoseOptions{.near_vertex_mm = 0.01}).near_vertices.count, 1U);
}

TEST(DiagnoseMesh, KeepsOnlyTheFirstLocations) {
  std::vector<Triangle> facets;
  for (int i = 0; i < 30; ++i) {
    const double x = 10.0 * i;
    facets.push_back({Vec3{x, 0, 0}, Vec3{x + 1, 0, 0}, Vec3{x, 1, 0}});
  }
  const MeshReport r = diagnose(facets);
  EXPECT_EQ(r.boundary_edges.count, 90U);
  EXPECT_EQ(r.num_boundary_loops, 30U);
  EXPECT_EQ(r.shells.size(), 30U);
  ASSERT_EQ(r.boundary_edges.locations.size(), kMaxLocations);
  EXPECT_EQ(r.boundary_edges.locations.front().from.x, 0.0);  // from facet 0
  EXPECT_LE(r.boundary_edges.locations.back().from.x, 70.0);  // from facets 0..6
}

TEST(DiagnoseMesh, EmptyMeshNeedsRepair) {
  const MeshReport r = diagnose(std::vector<Triangle>{});
  EXPECT_EQ(r.num_facets, 0U);
  EXPECT_TRUE(r.bounds.empty());
  EXPECT_EQ(r.verdict, Verdict::NeedsRepair);
}

TEST(DiagnoseMesh, RejectsOutOfRangeVertexIndex) {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}};
  mesh.triangles = {{0, 1, 2}};
  EXPECT_THROW((void)diagnose_mesh(mesh, TriangleSoup{}), InternalError);
}

TEST(DiagnoseMesh, ASelfIntersectionSearchCutShortBeforeAnyPairIsAReasonOfItsOwn) {
  // A closed box whose search may look at no candidate: nothing found, but not shown clean.
  const MeshReport r = diagnose(unit_box(), DiagnoseOptions{.max_self_intersection_candidates = 0});
  EXPECT_TRUE(r.self_intersections_truncated);
  EXPECT_EQ(r.self_intersections.count, 0U);
  EXPECT_EQ(r.verdict, Verdict::PrintableUnderRule);
  EXPECT_EQ(r.verdict_reason,
            "self-intersection search cut short; every edge is balanced, so the nonzero fill rule "
            "slices it as intended");
}

TEST(DiagnoseMesh, NearVertexSearchStopsAtItsLimit) {
  auto facets = unit_box();
  facets[0][0] = {1e-9, 0, 0};  // near (0, 0, 0), as in the test above
  const MeshReport r = diagnose(facets, DiagnoseOptions{.max_near_vertex_checks = 0});
  EXPECT_TRUE(r.near_vertices_truncated);
  EXPECT_EQ(r.near_vertices.count, 0U);
}

TEST(DiagnoseMesh, CountsEveryOccurrenceEvenWithoutKeepingALocation) {
  auto facets = unit_box();
  facets.pop_back();
  const MeshReport r = diagnose(facets, DiagnoseOptions{.max_locations = 0});
  EXPECT_EQ(r.boundary_edges.count, 3U);
  EXPECT_TRUE(r.boundary_edges.locations.empty());
}

/// Clusters of 12 points (a 3 x 2 x 2 grid, so three in a row along x) joined by random facets,
/// 14 a cluster: degenerate facets (repeated or collinear corners), duplicates in both
/// orientations, non-manifold edges and vertices, over enough vertices to be shared out among
/// threads.
std::vector<Triangle> random_cluster_facets(std::uint32_t seed, int clusters = 2000) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> corner(0, 11);
  std::vector<Triangle> facets;
  for (int cluster = 0; cluster < clusters; ++cluster) {
    const auto point = [&](int k) {
      return Vec3{10.0 * cluster + k % 3, static_cast<double>(k / 3 % 2),
                  static_cast<double>(k / 6)};
    };
    for (int f = 0; f < 12; ++f) {
      facets.push_back({point(corner(rng)), point(corner(rng)), point(corner(rng))});
    }
    facets.push_back(facets[facets.size() - 1 - static_cast<std::size_t>(corner(rng) % 4)]);
    facets.push_back(reversed(facets.back()));
  }
  return facets;
}

DiagnoseOptions keep_every_location() {
  return DiagnoseOptions{.max_locations = std::numeric_limits<std::size_t>::max(),
                         .check_self_intersections = false};
}

TEST(DiagnoseMesh, DuplicatesAndNonManifoldVerticesMatchABruteForceSearch) {
  for (const std::uint32_t seed : {1U, 2U, 3U}) {
    const TriangleSoup soup = soup_of(random_cluster_facets(seed));
    const IndexedMesh mesh = weld_vertices(soup);
    const MeshReport r = diagnose_mesh(mesh, soup, keep_every_location());
    const auto& degenerate = r.degenerate_facets.locations;
    const auto has_area = [&](FacetIndex f) {
      return !std::binary_search(degenerate.begin(), degenerate.end(), f);
    };

    std::vector<FacetIndex> duplicates;
    std::set<std::array<VertexIndex, 3>> seen;
    for (FacetIndex f = 0; f < mesh.triangles.size(); ++f) {
      if (!has_area(f)) continue;
      auto key = mesh.triangles[f];
      std::sort(key.begin(), key.end());
      if (!seen.insert(key).second) duplicates.push_back(f);
    }
    EXPECT_EQ(r.duplicate_facets.locations, duplicates) << "seed " << seed;
    EXPECT_EQ(r.duplicate_facets.count, duplicates.size()) << "seed " << seed;

    // A vertex's fans: its facets with area, joined when they share a second vertex.
    std::map<VertexIndex, std::vector<FacetIndex>> around;
    for (FacetIndex f = 0; f < mesh.triangles.size(); ++f) {
      if (has_area(f)) {
        for (VertexIndex v : mesh.triangles[f]) around[v].push_back(f);
      }
    }
    std::vector<Vec3> non_manifold;
    for (const auto& [v, facets] : around) {
      std::vector<int> fan(facets.size(), -1);
      int fans = 0;
      for (std::size_t start = 0; start < facets.size(); ++start) {
        if (fan[start] >= 0) continue;
        std::vector<std::size_t> stack{start};
        fan[start] = fans;
        while (!stack.empty()) {
          const auto& t = mesh.triangles[facets[stack.back()]];
          stack.pop_back();
          for (std::size_t k = 0; k < facets.size(); ++k) {
            if (fan[k] >= 0) continue;
            const auto& u = mesh.triangles[facets[k]];
            for (VertexIndex w : t) {
              if (w != v && std::find(u.begin(), u.end(), w) != u.end()) {
                fan[k] = fans;
                stack.push_back(k);
                break;
              }
            }
          }
        }
        ++fans;
      }
      if (fans > 1) non_manifold.push_back(mesh.vertices[v]);
    }
    ASSERT_EQ(r.non_manifold_vertices.locations.size(), non_manifold.size()) << "seed " << seed;
    EXPECT_TRUE(r.non_manifold_vertices.locations == non_manifold) << "seed " << seed;
    EXPECT_GT(duplicates.size(), 0U);
    EXPECT_GT(non_manifold.size(), 0U);
  }
}

TEST(DiagnoseMesh, OneThreadAndSeveralGiveTheSameReport) {
  // 84,000 facets: the counting sorts by vertex cut them into one range a thread.
  const TriangleSoup soup = soup_of(random_cluster_facets(4, 6000));
  const IndexedMesh mesh = weld_vertices(soup);
  const std::string several = mesh_report_json(diagnose_mesh(mesh, soup, keep_every_location()));
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(mesh_report_json(diagnose_mesh(mesh, soup, keep_every_location())), several);
}

TEST(DiagnoseMesh, ShellsOfManyBoxesInShuffledFacetOrderAreListedByTheirLowestFacet) {
  // 3,000 boxes apart, their facets shuffled, and a degenerate facet every so often (in no
  // shell): 36,000 facets, several blocks and ranges for the threads.
  constexpr std::size_t kBoxes = 3000;
  std::vector<std::pair<Triangle, std::size_t>> facets;  // a facet and its box, or kBoxes
  for (std::size_t b = 0; b < kBoxes; ++b) {
    const Vec3 lo{static_cast<double>(b % 60) * 3.0, static_cast<double>(b / 60) * 3.0, 0.0};
    for (const Triangle& t : box_facets_lo_hi_diagonals(lo, {lo.x + 1, lo.y + 1, 1})) {
      facets.emplace_back(t, b);
    }
    if (b % 7 == 0) facets.emplace_back(Triangle{lo, lo, {lo.x, lo.y, 2}}, kBoxes);
  }
  std::mt19937 random(11);
  std::shuffle(facets.begin(), facets.end(), random);
  std::vector<Triangle> triangles;
  std::vector<std::size_t> first_of_box(kBoxes, facets.size());
  for (std::size_t f = 0; f < facets.size(); ++f) {
    triangles.push_back(facets[f].first);
    const std::size_t b = facets[f].second;
    if (b < kBoxes) first_of_box[b] = std::min(first_of_box[b], f);
  }
  std::sort(first_of_box.begin(), first_of_box.end());
  for (const int threads : {1, 2, 4}) {
    SCOPED_TRACE(threads);
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    // The boxes do not meet: the self-intersection search, the dearest check, is spared.
    const MeshReport r = diagnose(triangles, DiagnoseOptions{.check_self_intersections = false});
    ASSERT_EQ(r.shells.size(), kBoxes);
    EXPECT_EQ(r.num_closed_shells, kBoxes);
    for (std::size_t s = 0; s < kBoxes; ++s) {
      EXPECT_EQ(r.shells[s].first_facet, first_of_box[s]) << s;
      EXPECT_EQ(r.shells[s].num_facets, 12U) << s;
      EXPECT_TRUE(r.shells[s].is_balanced) << s;
      EXPECT_DOUBLE_EQ(r.shells[s].signed_volume_mm3, 1.0) << s;
    }
    EXPECT_EQ(r.degenerate_facets.count, (kBoxes + 6) / 7);
  }
}

TEST(DiagnoseMesh, KeptLocationsAreTheFirstOfAllLocations) {
  const TriangleSoup soup = soup_of(random_cluster_facets(5));
  const IndexedMesh mesh = weld_vertices(soup);
  const MeshReport all = diagnose_mesh(mesh, soup, keep_every_location());
  DiagnoseOptions few = keep_every_location();
  few.max_locations = 5;
  const MeshReport first = diagnose_mesh(mesh, soup, few);
  const auto expect_first = [](const auto& kept, const auto& every, const char* what) {
    EXPECT_EQ(kept.count, every.count) << what;
    ASSERT_EQ(kept.locations.size(), std::min<std::size_t>(5, every.locations.size())) << what;
    for (std::size_t i = 0; i < kept.locations.size(); ++i) {
      EXPECT_EQ(std::memcmp(&kept.locations[i], &every.locations[i], sizeof(kept.locations[i])), 0)
          << what << " " << i;
    }
  };
  expect_first(first.degenerate_facets, all.degenerate_facets, "degenerate");
  expect_first(first.duplicate_facets, all.duplicate_facets, "duplicate");
  expect_first(first.non_manifold_vertices, all.non_manifold_vertices, "non-manifold vertex");
  expect_first(first.boundary_edges, all.boundary_edges, "boundary");
  expect_first(first.non_manifold_edges, all.non_manifold_edges, "non-manifold edge");
  expect_first(first.inconsistent_edges, all.inconsistent_edges, "inconsistent");
  expect_first(first.unbalanced_edges, all.unbalanced_edges, "unbalanced");
  expect_first(first.zero_normals, all.zero_normals, "zero normal");
}

TEST(DiagnoseMesh, NamesEveryVerdict) {
  EXPECT_STREQ(verdict_name(Verdict::Printable), "printable");
  EXPECT_STREQ(verdict_name(Verdict::PrintableUnderRule), "printable-under-rule");
  EXPECT_STREQ(verdict_name(Verdict::NeedsRepair), "needs-repair");
}

}  // namespace
}  // namespace strata::diagnose
