#include "strata/contour/assemble_contours.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slice/slice_float.hpp"
#include "support/mesh_builders.hpp"

namespace strata {
namespace {

/// Every facet of `mesh` cut by the plane z (z - 0.5 + 0.5 == z for the values used here).
LayerSegments cut(const IndexedMesh& mesh, double z) {
  GridSpec grid;
  grid.z0 = z - 0.5;
  grid.dz = 1.0;
  grid.nz = 1;
  return slice_layer(mesh, test::all_facets(mesh), grid, 0);
}

IndexedMesh two_boxes(Vec3 lo_a, Vec3 hi_a, Vec3 lo_b, Vec3 hi_b) {
  IndexedMesh m = test::indexed_box_lo_hi_diagonals(lo_a, hi_a);
  test::append_mesh(m, test::indexed_box_lo_hi_diagonals(lo_b, hi_b));
  return m;
}

/// Adds the tetrahedron of four of `m`'s vertices, each facet facing away from the fourth corner.
void add_tetrahedron(IndexedMesh& m, VertexIndex a, VertexIndex b, VertexIndex c, VertexIndex d) {
  const auto orient = [&](VertexIndex p, VertexIndex q, VertexIndex r, VertexIndex s) {
    const Vec3 &P = m.vertices[p], &Q = m.vertices[q], &R = m.vertices[r], &S = m.vertices[s];
    const double ux = Q.x - P.x, uy = Q.y - P.y, uz = Q.z - P.z;
    const double vx = R.x - P.x, vy = R.y - P.y, vz = R.z - P.z;
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const double side = nx * (S.x - P.x) + ny * (S.y - P.y) + nz * (S.z - P.z);
    if (side > 0) {
      m.triangles.push_back({p, r, q});
    } else {
      m.triangles.push_back({p, q, r});
    }
  };
  orient(a, b, c, d);
  orient(a, b, d, c);
  orient(a, c, d, b);
  orient(b, c, d, a);
}

TEST(AssembleContoursChecked, SeparateBoxesAreSimple) {
  const IndexedMesh m = two_boxes({0, 0, 0}, {10, 10, 10}, {12, 0, 0}, {20, 10, 10});
  const LayerContours c = assemble_contours(m, cut(m, 5));
  EXPECT_FALSE(c.loops_cross);
  EXPECT_FALSE(c.misnested);
  EXPECT_TRUE(c.loops_are_simple());
  ASSERT_EQ(c.loops.size(), 2u);
  EXPECT_EQ(c.loops[0].kind, LoopKind::Outer);
  EXPECT_EQ(c.loops[1].kind, LoopKind::Outer);
}

TEST(AssembleContoursChecked, OverlappingBoxesCross) {
  const IndexedMesh m = two_boxes({0, 0, 0}, {10, 10, 10}, {5, 5, 0}, {15, 15, 10});
  const LayerContours c = assemble_contours(m, cut(m, 5));
  EXPECT_TRUE(c.loops_cross);
  EXPECT_FALSE(c.loops_are_simple());
  EXPECT_EQ(c.loops.size(), 2u);  // the chained loops; the outline is the kernels' business
}

TEST(AssembleContoursChecked, BoxesSharingAVerticalEdgeTouch) {
  // Not welded: the two crossing points on the shared edge are equal exactly, under two keys.
  const IndexedMesh m = two_boxes({0, 0, 0}, {10, 10, 10}, {10, 10, 0}, {20, 20, 10});
  EXPECT_TRUE(assemble_contours(m, cut(m, 5)).loops_cross);
}

TEST(AssembleContoursChecked, WeldedBoxesSharingAVerticalEdgeTouch) {
  IndexedMesh m = two_boxes({0, 0, 0}, {10, 10, 10}, {10, 10, 0}, {20, 20, 10});
  TriangleSoup soup;
  for (const auto& t : m.triangles) {
    soup.triangles.push_back({m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]});
  }
  m = weld_vertices(soup);
  EXPECT_TRUE(assemble_contours(m, cut(m, 5)).loops_cross);
}

TEST(AssembleContoursChecked, BoxesSharingAFaceTouch) {
  const IndexedMesh m = two_boxes({0, 0, 0}, {10, 10, 10}, {10, 2, 0}, {20, 8, 10});
  EXPECT_TRUE(assemble_contours(m, cut(m, 5)).loops_cross);
}

TEST(AssembleContoursChecked, BoxesApartByOneUlpDoNotTouch) {
  const double x = std::nextafter(10.0, 11.0);
  const IndexedMesh m = two_boxes({0, 0, 0}, {10, 10, 10}, {x, 0, 0}, {20, 10, 10});
  const LayerContours c = assemble_contours(m, cut(m, 5));
  EXPECT_FALSE(c.loops_cross);
  EXPECT_TRUE(c.loops_are_simple());
}

TEST(AssembleContoursChecked, SlantedFacetsMeetingAtAnUnrepresentablePointTouch) {
  // Two tetrahedra whose edges (0, 0, 0)-(1, 3, 3) and (0, 1, 0)-(1, 1, 3) meet at (1/3, 1, 1):
  // at z = 1 the first's section lies in x <= 1/3 and the second's in x >= 1/3, and they share
  // only that point, which no double represents. At z = 1.25 their extreme corners are
  // (5/12, 1.25) and (5/12, 1): an exact tie in x, apart in y.
  IndexedMesh m;
  m.vertices = {{0, 0, 0}, {1, 3, 3}, {-6, 1, 0}, {-6, 1, 3},  // first
                {0, 1, 0}, {1, 1, 3}, {6, 0, 0},  {6, 2, 3}};  // second
  add_tetrahedron(m, 0, 1, 2, 3);
  add_tetrahedron(m, 4, 5, 6, 7);
  EXPECT_TRUE(assemble_contours(m, cut(m, 1.0)).loops_cross);
  EXPECT_FALSE(assemble_contours(m, cut(m, 1.25)).loops_cross);
}

TEST(AssembleContoursChecked, CollinearSidesApartByLessThanTheMarginAtUnrepresentablePoints) {
  // Two tetrahedra with a face each in the plane y = 0: at z = 1 their sections have sides on
  // the line y = 0, the first's from x = -11/3 to 1/3, the second's from 1/3 + 2d/3 to 13/3.
  // No double is any of these ends, and 2d/3 is far below the doubles' margin: only the exact
  // order along the line tells a gap (d > 0) from a shared end (d = 0).
  for (const double d : {0x1p-50, 0.0}) {
    IndexedMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 3}, {-6, 0, 0}, {-3, -2, 0},  // first
                  {d, 0, 0}, {1, 0, 3}, {6, 0, 0},  {3, -2, 0}};  // second
    add_tetrahedron(m, 0, 1, 2, 3);
    add_tetrahedron(m, 4, 5, 6, 7);
    const LayerContours c = assemble_contours(m, cut(m, 1.0));
    ASSERT_EQ(c.loops.size(), 2u) << d;
    EXPECT_EQ(c.loops_cross, d == 0.0) << d;
  }
}

TEST(AssembleContoursChecked, NestedBoxesOfOneOrientationAreMisnested) {
  const IndexedMesh m = two_boxes({0, 0, 0}, {10, 10, 10}, {2, 2, 2}, {4, 4, 4});
  const LayerContours c = assemble_contours(m, cut(m, 3));
  EXPECT_FALSE(c.loops_cross);
  EXPECT_TRUE(c.misnested);
  EXPECT_FALSE(c.loops_are_simple());
  ASSERT_EQ(c.loops.size(), 2u);
  EXPECT_EQ(c.loops[1].depth, 1);
}

TEST(AssembleContoursChecked, RingLayersAreSimpleAndUnchanged) {
  auto soup = io::read_mesh(STRATA_DATA_DIR "/ring.stl");
  ASSERT_TRUE(soup.has_value());
  const IndexedMesh m = weld_vertices(*soup);
  const Bbox3 box = m.bounds();
  for (const double f : {0.1, 0.5, 0.9}) {
    const LayerSegments segments = cut(m, box.min.z + f * (box.max.z - box.min.z));
    const LayerContours checked = assemble_contours(m, segments);
    const LayerContours plain = assemble_contours(segments);
    EXPECT_TRUE(checked.loops_are_simple());
    ASSERT_EQ(checked.loops.size(), 2u);
    ASSERT_EQ(plain.loops.size(), 2u);
    for (std::size_t l = 0; l < 2; ++l) {
      EXPECT_EQ(checked.loops[l].points, plain.loops[l].points);
      EXPECT_EQ(checked.loops[l].kind, plain.loops[l].kind);
      EXPECT_EQ(checked.loops[l].depth, plain.loops[l].depth);
    }
    EXPECT_EQ(checked.loops[0].depth + checked.loops[1].depth, 1);
  }
}

}  // namespace
}  // namespace strata
