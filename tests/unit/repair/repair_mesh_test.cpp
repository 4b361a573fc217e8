#include "strata/repair/repair_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <tuple>
#include <vector>

#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "support/mesh_builders.hpp"
#include "support/result_checks.hpp"

namespace strata::repair {
namespace {

using Triangle = test::Facet;
using test::box_facets_lo_hi_diagonals;
using test::joined;
using test::reversed;

TriangleSoup soup_of(const std::vector<Triangle>& triangles) {
  TriangleSoup soup;
  soup.triangles = triangles;
  soup.format = "generated";
  return soup;
}

std::vector<Triangle> without(std::vector<Triangle> ts, std::size_t index) {
  ts.erase(ts.begin() + static_cast<std::ptrdiff_t>(index));
  return ts;
}

diagnose::MeshReport diagnose_soup(const TriangleSoup& soup) {
  return diagnose::diagnose_mesh(weld_vertices(soup), soup);
}

RepairResult repaired(const TriangleSoup& soup, bool fill_holes = false) {
  return test::value_of(repair_mesh(soup, RepairOptions{.fill_holes = fill_holes}), "repair_mesh");
}

/// The counts of changes, which a second repair must find all zero.
std::vector<std::size_t> change_counts(const RepairLog& log) {
  return {log.degenerate_facets_removed,
          log.duplicate_facets_removed,
          log.cancelling_duplicates_removed,
          log.t_junctions_closed,
          log.t_junction_facets_added,
          log.facets_flipped_for_consistency,
          log.borders_stitched,
          log.holes_filled,
          log.hole_facets_added,
          log.holes_not_filled,
          log.shells_reoriented,
          log.facets_flipped_with_shells,
          log.facets_flipped,
          log.changes.size()};
}

TEST(RepairMesh, LeavesAClosedBoxAsItIs) {
  const TriangleSoup input = soup_of(box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}));
  const RepairResult r = repaired(input, true);
  EXPECT_EQ(r.soup.triangles, input.triangles);
  EXPECT_FALSE(r.log.changed_anything());
  EXPECT_EQ(r.log.input_facets, 12u);
  EXPECT_EQ(r.log.input_vertices, 8u);
  EXPECT_EQ(r.log.points_merged, 36u - 8u);
  EXPECT_EQ(r.log.closed_shells, 1u);
  EXPECT_TRUE(r.log.volume_orientation_done);
  EXPECT_EQ(r.log.output_facets, 12u);
  EXPECT_EQ(r.log.output_vertices, 8u);
  EXPECT_TRUE(r.log.changes.empty());
}

TEST(RepairMesh, RemovesADuplicatedFacet) {
  std::vector<Triangle> facets = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  facets.push_back(facets[4]);
  const RepairResult r = repaired(soup_of(facets));
  EXPECT_EQ(r.log.duplicate_facets_removed, 1u);
  EXPECT_EQ(r.log.cancelling_duplicates_removed, 0u);
  ASSERT_EQ(r.log.changes.size(), 1u);
  EXPECT_EQ(r.log.changes[0].facet, 12u);
  EXPECT_EQ(r.log.changes[0].kind, FacetChangeKind::RemovedDuplicate);
  EXPECT_EQ(r.soup.triangles, box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}));
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.duplicate_facets.count, 0u);
  EXPECT_EQ(after.verdict, diagnose::Verdict::Printable) << after.verdict_reason;
}

TEST(RepairMesh, KeepsTheOrientationMostCopiesHave) {
  // Facet 4 once as it should be and twice reversed: the reversed copy is kept, then turned back by
  // the orientation step because its neighbours disagree with it.
  std::vector<Triangle> facets = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  facets.push_back(reversed(facets[4]));
  facets.push_back(reversed(facets[4]));
  const RepairResult r = repaired(soup_of(facets));
  EXPECT_EQ(r.log.duplicate_facets_removed, 2u);
  EXPECT_EQ(r.log.facets_flipped_for_consistency, 1u);
  EXPECT_EQ(r.log.output_facets, 12u);
  EXPECT_EQ(diagnose_soup(r.soup).verdict, diagnose::Verdict::Printable);
}

TEST(RepairMesh, RemovesTheWallBetweenTwoBoxesThatTouch) {
  // The face x = 1 belongs to both boxes, once each way: both copies go and one closed solid is
  // left.
  const TriangleSoup input = soup_of(joined(box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}),
                                            box_facets_lo_hi_diagonals({1, 0, 0}, {2, 1, 1})));
  const auto before = diagnose_soup(input);
  EXPECT_EQ(before.duplicate_facets.count, 2u);
  const RepairResult r = repaired(input);
  EXPECT_EQ(r.log.duplicate_facets_removed, 2u);
  EXPECT_EQ(r.log.cancelling_duplicates_removed, 2u);
  EXPECT_EQ(r.log.output_facets, 20u);
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.boundary_edges.count, 0u);
  EXPECT_EQ(after.non_manifold_edges.count, 0u);
  EXPECT_EQ(after.shells.size(), 1u);
  EXPECT_EQ(after.volume_mm3, 2.0);
  EXPECT_EQ(after.verdict, diagnose::Verdict::Printable) << after.verdict_reason;
}

TEST(RepairMesh, KeepsOneCopyOfCancellingFacetsWhenRemovingBothWouldOpenAHole) {
  // An open box (no top) with one side facet doubled in reverse: taking both copies away would cut
  // a hole into the side, so one stays.
  std::vector<Triangle> facets =
      without(without(box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}), 3), 2);
  facets.push_back(reversed(facets[4]));
  const RepairResult r = repaired(soup_of(facets));
  EXPECT_EQ(r.log.duplicate_facets_removed, 1u);
  EXPECT_EQ(r.log.cancelling_duplicates_removed, 0u);
  EXPECT_EQ(r.log.output_facets, 10u);
  EXPECT_EQ(diagnose_soup(r.soup).boundary_edges.count, 4u);
}

TEST(RepairMesh, TurnsBackAFlippedFacetOfABox) {
  std::vector<Triangle> facets = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  facets[5] = reversed(facets[5]);
  const RepairResult r = repaired(soup_of(facets));
  EXPECT_EQ(r.log.facets_flipped_for_consistency, 1u);
  EXPECT_EQ(r.log.shells_reoriented, 0u);
  EXPECT_EQ(r.log.facets_flipped, 1u);
  ASSERT_EQ(r.log.changes.size(), 1u);
  EXPECT_EQ(r.log.changes[0].facet, 5u);
  EXPECT_EQ(r.log.changes[0].kind, FacetChangeKind::Flipped);
  EXPECT_EQ(r.soup.triangles, box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}));
  EXPECT_EQ(diagnose_soup(r.soup).volume_mm3, 1.0);
}

TEST(RepairMesh, TurnsBackAFlippedFirstFacetOfASphere) {
  // The first facet is where the orientation step starts a shell: the shell must still keep the
  // orientation of the majority.
  const TriangleSoup sphere = mesh::make_sphere(5.0, 2);
  TriangleSoup input = sphere;
  input.triangles[0] = reversed(input.triangles[0]);
  const RepairResult r = repaired(input);
  EXPECT_EQ(r.log.facets_flipped, 1u);
  EXPECT_EQ(r.log.facets_flipped_for_consistency, 1u);
  const double volume = diagnose_soup(r.soup).volume_mm3;
  EXPECT_GT(volume, 0.0);
  EXPECT_EQ(volume, diagnose_soup(sphere).volume_mm3);
  EXPECT_EQ(r.soup.triangles, sphere.triangles);
}

TEST(RepairMesh, TurnsAnInvertedSolidOutward) {
  const TriangleSoup sphere = mesh::make_sphere(5.0, 2);
  const RepairResult r = repaired(mesh::flip_orientation(sphere));
  EXPECT_EQ(r.log.shells_reoriented, 1u);
  EXPECT_EQ(r.log.facets_flipped_with_shells, sphere.triangles.size());
  EXPECT_EQ(r.log.facets_flipped, sphere.triangles.size());
  EXPECT_EQ(r.log.facets_flipped_for_consistency, 0u);
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.volume_mm3, diagnose_soup(sphere).volume_mm3);
  EXPECT_EQ(after.verdict, diagnose::Verdict::Printable) << after.verdict_reason;
}

TEST(RepairMesh, KeepsACavityFacingIn) {
  const TriangleSoup input =
      soup_of(joined(box_facets_lo_hi_diagonals({0, 0, 0}, {4, 4, 4}),
                     reversed(box_facets_lo_hi_diagonals({1, 1, 1}, {2, 2, 2}))));
  const RepairResult r = repaired(input);
  EXPECT_EQ(r.log.closed_shells, 2u);
  EXPECT_EQ(r.log.shells_reoriented, 0u);
  EXPECT_EQ(r.soup.triangles, input.triangles);
}

TEST(RepairMesh, TurnsAnInnerWallThatFacesOutIntoACavity) {
  const TriangleSoup input = soup_of(joined(box_facets_lo_hi_diagonals({0, 0, 0}, {4, 4, 4}),
                                            box_facets_lo_hi_diagonals({1, 1, 1}, {2, 2, 2})));
  const RepairResult r = repaired(input);
  EXPECT_EQ(r.log.shells_reoriented, 1u);
  EXPECT_EQ(r.log.facets_flipped_with_shells, 12u);
  EXPECT_EQ(diagnose_soup(r.soup).volume_mm3, 64.0 - 1.0);
}

TEST(RepairMesh, TreatsOverlappingSolidsAsSolidsNotCavities) {
  // The second box's highest corners lie inside the first box, but the boxes intersect: it is a
  // second solid, to face out, not a cavity.
  const std::vector<Triangle> a = box_facets_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
  const std::vector<Triangle> b = box_facets_lo_hi_diagonals({1, 1, 0.5}, {3, 3, 1.5});
  const RepairResult kept = repaired(soup_of(joined(a, b)));
  EXPECT_EQ(kept.log.shells_reoriented, 0u);
  const RepairResult turned = repaired(soup_of(joined(a, reversed(b))));
  EXPECT_EQ(turned.log.shells_reoriented, 1u);
  EXPECT_EQ(turned.soup.triangles, joined(a, b));
}

TEST(RepairMesh, FillsTheHoleOfARemovedFacet) {
  const std::vector<Triangle> cube = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  const RepairResult r = repaired(soup_of(without(cube, 7)), true);
  EXPECT_EQ(r.log.holes_found, 1u);
  EXPECT_EQ(r.log.holes_filled, 1u);
  EXPECT_EQ(r.log.hole_facets_added, 1u);
  EXPECT_EQ(r.log.holes_not_filled, 0u);
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.boundary_edges.count, 0u);
  EXPECT_EQ(after.volume_mm3, 1.0);
  EXPECT_EQ(after.verdict, diagnose::Verdict::Printable) << after.verdict_reason;
}

TEST(RepairMesh, FillsTheSquareHoleOfARemovedFace) {
  // Both triangles of the face y = 1 removed: a planar square hole; any triangulation of it gives
  // the cube's volume exactly.
  const std::vector<Triangle> cube = box_facets_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
  const RepairResult r = repaired(soup_of(without(without(cube, 7), 6)), true);
  EXPECT_EQ(r.log.holes_filled, 1u);
  EXPECT_EQ(r.log.hole_facets_added, 2u);
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.boundary_edges.count, 0u);
  EXPECT_EQ(after.volume_mm3, 8.0);
  EXPECT_EQ(after.verdict, diagnose::Verdict::Printable) << after.verdict_reason;
}

TEST(RepairMesh, FillsTheHoleOfASphereAndOrientsItOutward) {
  const TriangleSoup sphere = mesh::make_sphere(5.0, 2);
  TriangleSoup input = mesh::flip_orientation(sphere);
  input.triangles.erase(input.triangles.begin() + 17);
  const RepairResult r = repaired(input, true);
  EXPECT_EQ(r.log.holes_filled, 1u);
  EXPECT_EQ(r.log.shells_reoriented, 1u);
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.boundary_edges.count, 0u);
  EXPECT_EQ(after.volume_mm3, diagnose_soup(sphere).volume_mm3);
}

TEST(RepairMesh, CountsAHoleButLeavesItOpenUnlessAsked) {
  const RepairResult r =
      repaired(soup_of(without(box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}), 7)));
  EXPECT_EQ(r.log.holes_found, 1u);
  EXPECT_FALSE(r.log.fill_holes_requested);
  EXPECT_EQ(r.log.holes_filled, 0u);
  EXPECT_EQ(r.log.output_facets, 11u);
  EXPECT_EQ(r.log.open_shells, 1u);
  EXPECT_FALSE(r.log.volume_orientation_done);
  EXPECT_NE(r.log.volume_orientation_note.find("no closed shell"), std::string::npos)
      << r.log.volume_orientation_note;
}

TEST(RepairMesh, LeavesAHoleLargerThanTheLimitOpen) {
  auto result =
      repair_mesh(soup_of(without(without(box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}), 7), 6)),
                  RepairOptions{.fill_holes = true, .max_hole_edges = 3});
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->log.holes_found, 1u);
  EXPECT_EQ(result->log.holes_filled, 0u);
  EXPECT_EQ(result->log.holes_not_filled, 1u);
  EXPECT_EQ(result->log.output_facets, 10u);
}

TEST(RepairMesh, DoesNotFillTheBorderOfAFinOnANonManifoldEdge) {
  // A fin: one more triangle on an edge of the box. Its border runs along that edge, which the
  // box's facets use: it is no hole, and filling it would close the fin against the box.
  std::vector<Triangle> facets = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  facets.push_back({Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0.5, -1, 0.5}});
  const RepairResult r = repaired(soup_of(facets), true);
  EXPECT_EQ(r.log.non_manifold_edges, 1u);
  EXPECT_EQ(r.log.holes_found, 0u);
  EXPECT_EQ(r.log.seams_at_shared_edges, 1u);
  EXPECT_EQ(r.log.hole_facets_added, 0u);
  EXPECT_EQ(r.soup.triangles, facets);
}

TEST(RepairMesh, RemovesZeroAreaFacets) {
  const std::vector<Triangle> cube = box_facets_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
  std::vector<Triangle> facets = cube;
  facets.insert(facets.begin() + 3, Triangle{Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{2, 2, 2}});
  facets.push_back({Vec3{0, 0, 0}, Vec3{1, 1, 1}, Vec3{2, 2, 2}});  // three collinear corners
  const RepairResult r = repaired(soup_of(facets));
  EXPECT_EQ(r.log.degenerate_facets_removed, 2u);
  ASSERT_EQ(r.log.changes.size(), 2u);
  EXPECT_EQ(r.log.changes[0].facet, 3u);
  EXPECT_EQ(r.log.changes[0].kind, FacetChangeKind::RemovedDegenerate);
  EXPECT_EQ(r.log.changes[1].facet, 13u);
  EXPECT_EQ(r.soup.triangles, cube);
  EXPECT_EQ(diagnose_soup(r.soup).degenerate_facets.count, 0u);
}

/// A box [0, 2]^3 whose top face is cut at M = (1, 0, 2), the middle of its front edge, while the
/// front face is not: a T-junction, the front face's edge running past M.
std::vector<Triangle> box_with_t_junction() {
  std::vector<Triangle> facets = box_facets_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
  const Vec3 m{1, 0, 2};
  const Vec3 v4{0, 0, 2}, v5{2, 0, 2}, v6{0, 2, 2}, v7{2, 2, 2};
  facets[2] = {v4, m, v6};
  facets[3] = {m, v5, v7};
  facets.push_back({m, v7, v6});
  return facets;
}

TEST(RepairMesh, ClosesATJunctionCrack) {
  const TriangleSoup input = soup_of(box_with_t_junction());
  EXPECT_EQ(diagnose_soup(input).boundary_edges.count, 3u);
  const RepairResult r = repaired(input);
  EXPECT_EQ(r.log.t_junctions_closed, 1u);
  EXPECT_EQ(r.log.t_junction_facets_added, 1u);
  EXPECT_EQ(r.log.output_facets, 14u);
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.boundary_edges.count, 0u);
  EXPECT_EQ(after.volume_mm3, 8.0);
  EXPECT_EQ(after.verdict, diagnose::Verdict::Printable) << after.verdict_reason;
}

TEST(RepairMesh, ClosesATJunctionCrackSealedByAZeroAreaFacet) {
  // The zero-area facet (v4, v5, M) balances the crack's edges: the input is printable under the
  // fill rule, but has a zero-area facet and three open edges among the facets with area.
  std::vector<Triangle> facets = box_with_t_junction();
  facets.push_back({Vec3{0, 0, 2}, Vec3{2, 0, 2}, Vec3{1, 0, 2}});
  const RepairResult r = repaired(soup_of(facets));
  EXPECT_EQ(r.log.degenerate_facets_removed, 1u);
  EXPECT_EQ(r.log.t_junctions_closed, 1u);
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.boundary_edges.count, 0u);
  EXPECT_EQ(after.degenerate_facets.count, 0u);
  EXPECT_EQ(after.volume_mm3, 8.0);
  EXPECT_EQ(after.verdict, diagnose::Verdict::Printable) << after.verdict_reason;
}

TEST(RepairMesh, SplitsTheVertexWhereTwoSolidsTouch) {
  const TriangleSoup input = soup_of(joined(box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}),
                                            box_facets_lo_hi_diagonals({1, 1, 1}, {2, 2, 2})));
  EXPECT_EQ(diagnose_soup(input).non_manifold_vertices.count, 1u);
  const RepairResult r = repaired(input);
  EXPECT_EQ(r.log.non_manifold_vertices_split, 1u);
  EXPECT_EQ(r.log.vertex_copies_added, 1u);
  EXPECT_EQ(r.log.closed_shells, 2u);
  EXPECT_FALSE(r.log.changed_anything());
  EXPECT_EQ(r.soup.triangles, input.triangles);
}

TEST(RepairMesh, AccountsForEveryInputFacet) {
  std::vector<Triangle> facets = box_with_t_junction();
  facets.push_back(facets[0]);
  facets.push_back({Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{1, 0, 0}});
  facets[8] = reversed(facets[8]);
  facets.erase(facets.begin() + 10);
  const RepairResult r = repaired(soup_of(facets), true);
  const RepairLog& log = r.log;
  EXPECT_EQ(log.input_facets, log.kept_input_facets + log.degenerate_facets_removed +
                                  log.duplicate_facets_removed + log.cancelling_duplicates_removed);
  EXPECT_EQ(log.output_facets,
            log.kept_input_facets + log.t_junction_facets_added + log.hole_facets_added);
  EXPECT_EQ(r.soup.triangles.size(), log.output_facets);
  EXPECT_TRUE(std::is_sorted(log.changes.begin(), log.changes.end(),
                             [](const FacetChange& a, const FacetChange& b) {
                               return std::tie(a.facet, a.kind) < std::tie(b.facet, b.kind);
                             }));
}

TEST(RepairMesh, UsesOnlyTheInputsCoordinates) {
  TriangleSoup input = mesh::make_sphere(3.0, 3);
  input.triangles.erase(input.triangles.begin() + 100);
  input.triangles.erase(input.triangles.begin() + 40);
  for (std::size_t i = 0; i < input.triangles.size(); i += 7) {
    input.triangles[i] = reversed(input.triangles[i]);
  }
  const RepairResult r = repaired(input, true);
  EXPECT_EQ(r.log.holes_filled, 2u);
  std::set<std::tuple<double, double, double>> points;
  for (const auto& t : input.triangles) {
    for (const Vec3& p : t) points.emplace(p.x, p.y, p.z);
  }
  for (const auto& t : r.soup.triangles) {
    for (const Vec3& p : t) EXPECT_TRUE(points.count({p.x, p.y, p.z})) << p.x << " " << p.y;
  }
  EXPECT_EQ(diagnose_soup(r.soup).verdict, diagnose::Verdict::Printable);
}

TEST(RepairMesh, IsIdempotent) {
  // Every kind of defect at once: a duplicate, a zero-area facet, a T-junction, a flipped facet, an
  // inverted second solid touching the first at a corner, a hole.
  std::vector<Triangle> facets = box_with_t_junction();
  facets.push_back(facets[1]);
  facets.push_back({Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{2, 0, 0}});
  facets[9] = reversed(facets[9]);
  facets = joined(facets, reversed(without(box_facets_lo_hi_diagonals({2, 2, 2}, {3, 3, 3}), 4)));
  for (const bool fill : {false, true}) {
    const RepairResult first = repaired(soup_of(facets), fill);
    EXPECT_TRUE(first.log.changed_anything());
    const RepairResult second = repaired(first.soup, fill);
    EXPECT_EQ(second.soup.triangles, first.soup.triangles) << "fill " << fill;
    EXPECT_FALSE(second.log.changed_anything()) << "fill " << fill;
    const std::vector<std::size_t> zeros(change_counts(second.log).size(), 0);
    EXPECT_EQ(change_counts(second.log), zeros) << "fill " << fill;
    EXPECT_EQ(second.log.holes_found, fill ? 0u : 1u);
    EXPECT_EQ(second.log.non_manifold_vertices_split, first.log.non_manifold_vertices_split);
  }
}

TEST(RepairMesh, RefusesANonFiniteCoordinate) {
  std::vector<Triangle> facets = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  facets[3][1].y = std::numeric_limits<double>::quiet_NaN();
  const auto result = repair_mesh(soup_of(facets));
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().code, ErrorCode::BadInput);
  EXPECT_EQ(result.error().location, "facet 3");
}

TEST(RepairMesh, RepairsAnEmptySoupToAnEmptySoup) {
  const RepairResult r = repaired(TriangleSoup{});
  EXPECT_TRUE(r.soup.triangles.empty());
  EXPECT_FALSE(r.log.changed_anything());
  EXPECT_FALSE(r.log.volume_orientation_done);
}

TEST(RepairMesh, RefusesANonFiniteCoordinateOnEveryAxis) {
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Triangle> facets = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
    double& c = axis == 0 ? facets[5][2].x : axis == 1 ? facets[5][2].y : facets[5][2].z;
    c = axis == 2 ? -std::numeric_limits<double>::infinity()
                  : std::numeric_limits<double>::infinity();
    const auto result = repair_mesh(soup_of(facets));
    ASSERT_FALSE(result.has_value()) << axis;
    EXPECT_EQ(result.error().to_string(), "facet 5: a corner has a coordinate that is not finite");
  }
}

TEST(RepairMesh, NamesEveryKindOfChange) {
  EXPECT_STREQ(facet_change_name(FacetChangeKind::RemovedDegenerate), "removed-degenerate");
  EXPECT_STREQ(facet_change_name(FacetChangeKind::RemovedDuplicate), "removed-duplicate");
  EXPECT_STREQ(facet_change_name(FacetChangeKind::RemovedCancellingDuplicate),
               "removed-cancelling-duplicate");
  EXPECT_STREQ(facet_change_name(FacetChangeKind::SplitAtTJunction), "split-at-t-junction");
  EXPECT_STREQ(facet_change_name(FacetChangeKind::Flipped), "flipped");
}

TEST(RepairMesh, OrientsNoVolumeWithoutAClosedShell) {
  const RepairResult r =
      repaired(soup_of(joined(without(box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1}), 0),
                              without(box_facets_lo_hi_diagonals({3, 0, 0}, {4, 1, 1}), 0))));
  EXPECT_EQ(r.log.open_shells, 2u);
  EXPECT_EQ(r.log.closed_shells, 0u);
  EXPECT_FALSE(r.log.volume_orientation_done);
  EXPECT_EQ(r.log.volume_orientation_note,
            "skipped: no closed shell (2 open shells, which bound no volume)");
}

TEST(RepairMesh, OrientsTheClosedShellsAndLeavesTheOpenOnesAsTheyAre) {
  const RepairResult r =
      repaired(soup_of(joined(joined(reversed(box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1})),
                                     without(box_facets_lo_hi_diagonals({3, 0, 0}, {4, 1, 1}), 0)),
                              without(box_facets_lo_hi_diagonals({6, 0, 0}, {7, 1, 1}), 0))));
  EXPECT_EQ(r.log.closed_shells, 1u);
  EXPECT_EQ(r.log.open_shells, 2u);
  EXPECT_TRUE(r.log.volume_orientation_done);
  EXPECT_EQ(r.log.shells_reoriented, 1u);
  EXPECT_EQ(r.log.facets_flipped_with_shells, 12u);
  EXPECT_EQ(r.log.volume_orientation_note,
            "2 open shells left as oriented (an open shell bounds no volume)");
}

/// The unit box with its corner (1, 1, 1) moved to `corner`.
std::vector<Triangle> box_with_corner(const Vec3& corner) {
  std::vector<Triangle> facets = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  for (Triangle& t : facets) {
    for (Vec3& p : t) {
      if (p == Vec3{1, 1, 1}) p = corner;
    }
  }
  return facets;
}

TEST(RepairMesh, JudgesAShellThatCrossesItselfByTheSignOfItsVolume) {
  // The corner pushed through the bottom face: the shell intersects itself, its volume is 1/6.
  const std::vector<Triangle> folded = box_with_corner({0.5, 0.5, -0.5});
  const RepairResult kept = repaired(soup_of(folded));
  EXPECT_EQ(kept.log.shells_reoriented, 0u);
  EXPECT_EQ(kept.soup.triangles, folded);
  const RepairResult turned = repaired(soup_of(reversed(folded)));
  EXPECT_EQ(turned.log.shells_reoriented, 1u);
  EXPECT_EQ(turned.log.facets_flipped_with_shells, 12u);
  EXPECT_EQ(turned.soup.triangles, folded);
}

TEST(RepairMesh, LeavesAShellThatCrossesItselfWithoutVolumeAsItIs) {
  // Pushed further, to z = -1, the two parts of the shell have opposite volumes that cancel.
  const std::vector<Triangle> folded = reversed(box_with_corner({0.5, 0.5, -1}));
  const RepairResult r = repaired(soup_of(folded));
  EXPECT_TRUE(r.log.volume_orientation_done);
  EXPECT_EQ(r.log.shells_reoriented, 0u);
  EXPECT_EQ(r.soup.triangles, folded);
}

TEST(RepairMesh, ListsTheChangesOfOneFacetInTheOrderTheStepsRan) {
  // The front facet that runs past M, turned over: it is split at M, then its pieces flipped.
  std::vector<Triangle> facets = box_with_t_junction();
  facets[5] = reversed(facets[5]);
  const RepairResult r = repaired(soup_of(facets));
  EXPECT_EQ(r.log.t_junctions_closed, 1u);
  EXPECT_EQ(r.log.facets_flipped, 1u);
  std::vector<FacetChangeKind> of_facet_5;
  for (const FacetChange& c : r.log.changes) {
    if (c.facet == 5) of_facet_5.push_back(c.kind);
  }
  EXPECT_EQ(of_facet_5, (std::vector<FacetChangeKind>{FacetChangeKind::SplitAtTJunction,
                                                      FacetChangeKind::Flipped}));
  const auto after = diagnose_soup(r.soup);
  EXPECT_EQ(after.volume_mm3, 8.0);
  EXPECT_EQ(after.verdict, diagnose::Verdict::Printable) << after.verdict_reason;
}

TEST(RepairMesh, RemovesFacetsThatRepeatACornerWhereverItIsRepeated) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  const std::vector<Triangle> box_facets = box_facets_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  const std::vector<Triangle> needles = {{a, a, b}, {a, b, b}, {c, b, c}};
  const RepairResult r = repaired(soup_of(joined(box_facets, needles)));
  EXPECT_EQ(r.log.degenerate_facets_removed, 3u);
  EXPECT_EQ(r.soup.triangles, box_facets);
  EXPECT_EQ(r.log.changes.size(), 3u);
  for (const FacetChange& change : r.log.changes) {
    EXPECT_GE(change.facet, 12u);
    EXPECT_EQ(change.kind, FacetChangeKind::RemovedDegenerate);
  }
}

TEST(RepairMesh, LeavesATJunctionCrackOpenWhenAsked) {
  const TriangleSoup input = soup_of(box_with_t_junction());
  const auto result = repair_mesh(input, RepairOptions{.close_t_junctions = false});
  ASSERT_TRUE(result.has_value()) << result.error().to_string();
  EXPECT_EQ(result->log.t_junctions_closed, 0u);
  EXPECT_EQ(result->log.output_facets, 13u);
  EXPECT_EQ(diagnose_soup(result->soup).boundary_edges.count, 3u);
}

}  // namespace
}  // namespace strata::repair
