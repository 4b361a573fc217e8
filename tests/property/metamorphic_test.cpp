// Transformations whose effect on the cells is known exactly, for every kernel (CGAL tests each
// kernel the same way); and the kernels agreeing with each other cell for cell.
#include <gtest/gtest.h>

#include "slice_support_for_tests.hpp"
#include "strata/mesh/primitive_models.hpp"

namespace strata {
namespace {

using testing::cells_of;
using testing::Kernel;
using testing::KernelTestName;
using testing::slice_in_memory;
using testing::SlicedCells;

// Dyadic cell sizes and offsets keep every grid quantity exact, so the effect is exact too.
constexpr double kCell = 0.25;

TriangleSoup test_part() {
  // A ring and a sphere overlapping it: outer and inner walls, curved and flat faces.
  TriangleSoup part = mesh::make_ring(6.0, 3.5, 4.0, 48);
  const TriangleSoup ball = mesh::translate_soup(mesh::make_sphere(2.5, 3), {5.0, 0.5, 3.0});
  part.triangles.insert(part.triangles.end(), ball.triangles.begin(), ball.triangles.end());
  return part;
}

void expect_same_cells(const SlicedCells& a, const SlicedCells& b) {
  ASSERT_EQ(a.grid.nx, b.grid.nx);
  ASSERT_EQ(a.grid.ny, b.grid.ny);
  ASSERT_EQ(a.grid.nz, b.grid.nz);
  ASSERT_EQ(a.layers.size(), b.layers.size());
  for (std::size_t k = 0; k < a.layers.size(); ++k) {
    ASSERT_EQ(a.layers[k], b.layers[k]) << "layer " << k;
  }
}

class Metamorphic : public ::testing::TestWithParam<Kernel> {};

TEST_P(Metamorphic, TranslatingByWholeCellsKeepsTheCells) {
  const Kernel kernel = GetParam();
  const TriangleSoup part = test_part();
  for (const ShellMode mode : {ShellMode::Distance, ShellMode::Layers}) {
    const SlicedCells before = slice_in_memory(part, cells_of(kCell, mode, 0.6), kernel);
    const SlicedCells after =
        slice_in_memory(mesh::translate_soup(part, {7 * kCell, -3 * kCell, 5 * kCell}),
                        cells_of(kCell, mode, 0.6), kernel);
    expect_same_cells(before, after);
    EXPECT_GT(before.solid(), 1000u);
  }
}

TEST_P(Metamorphic, TranslatingAgainstAFixedOriginShiftsTheCells) {
  const TriangleSoup part = test_part();
  SliceOptions o = cells_of(kCell);
  o.grid.origin = Vec3{-8.0, -8.0, -1.0};
  const SlicedCells before = slice_in_memory(part, o, GetParam());
  const SlicedCells after =
      slice_in_memory(mesh::translate_soup(part, {3 * kCell, 2 * kCell, 4 * kCell}), o, GetParam());
  ASSERT_EQ(after.layers.size(), before.layers.size() + 4);
  for (std::uint32_t k = 0; k < before.grid.nz; ++k) {
    for (std::uint32_t j = 0; j < before.grid.ny; ++j) {
      for (std::uint32_t i = 0; i < before.grid.nx; ++i) {
        ASSERT_EQ(before.at(i, j, k), after.at(i + 3, j + 2, k + 4)) << i << "," << j << "," << k;
      }
    }
  }
}

TEST_P(Metamorphic, RotatingNinetyDegreesAboutZTransposesTheCells) {
  const TriangleSoup part = test_part();
  // Origin (-12, -12): a rotated centre (x', y') is the original centre (y', -x'), and with
  // x0 = y0 = -12 and d = 1/4 that is cell (j', 95 - i') of the original grid.
  SliceOptions o = cells_of(kCell);
  o.grid.origin = Vec3{-12.0, -12.0, -1.0};
  const SlicedCells before = slice_in_memory(part, o, GetParam());
  const SlicedCells after = slice_in_memory(mesh::rotate_soup_z90(part), o, GetParam());
  ASSERT_EQ(before.solid(), after.solid());
  ASSERT_EQ(before.grid.nz, after.grid.nz);
  std::uint64_t matched = 0;
  for (std::uint32_t k = 0; k < after.grid.nz; ++k) {
    for (std::uint32_t j = 0; j < after.grid.ny; ++j) {
      for (std::uint32_t i = 0; i < after.grid.nx; ++i) {
        const CellClass c = after.at(i, j, k);
        if (c == CellClass::Empty) continue;
        const std::uint32_t oi = j;
        const std::uint32_t oj = 95 - i;
        ASSERT_LT(oi, before.grid.nx);
        ASSERT_LT(oj, before.grid.ny);
        ASSERT_NE(before.at(oi, oj, k), CellClass::Empty) << i << "," << j << "," << k;
        ++matched;
      }
    }
  }
  EXPECT_EQ(matched, after.solid());
}

TEST_P(Metamorphic, FacetOrderAndCornerRotationDoNotMatter) {
  const Kernel kernel = GetParam();
  const TriangleSoup part = test_part();
  const SliceOptions o = cells_of(kCell, ShellMode::Layers, 0.5);
  const SlicedCells base = slice_in_memory(part, o, kernel);
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    expect_same_cells(base, slice_in_memory(mesh::shuffle_facets(part, seed), o, kernel));
  }
  expect_same_cells(base, slice_in_memory(mesh::rotate_corners(part), o, kernel));
}

TEST_P(Metamorphic, ScalingByTwoScalesTheGridWithIt) {
  const TriangleSoup part = test_part();
  const SlicedCells base = slice_in_memory(part, cells_of(kCell), GetParam());
  const SlicedCells doubled = slice_in_memory(
      mesh::scale_soup(part, 2.0), cells_of(2 * kCell, ShellMode::Distance, 1.0), GetParam());
  expect_same_cells(base, doubled);
}

INSTANTIATE_TEST_SUITE_P(Kernels, Metamorphic,
                         ::testing::Values(Kernel::Fast, Kernel::Exact, Kernel::Winding),
                         KernelTestName{});

/// The kernels of the exact crossing rules (nonzero, evenodd).
class MetamorphicCrossingRule : public ::testing::TestWithParam<Kernel> {};

TEST_P(MetamorphicCrossingRule, FlippingEveryFacetKeepsNonZeroAndEvenOddCells) {
  // An inside-out model has winding -1 inside: nonzero and evenodd still call it solid.
  const TriangleSoup part = mesh::make_sphere(3.0, 3);
  for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    SliceOptions o = cells_of(kCell);
    o.fill_rule = rule;
    expect_same_cells(slice_in_memory(part, o, GetParam()),
                      slice_in_memory(mesh::flip_orientation(part), o, GetParam()));
  }
}

INSTANTIATE_TEST_SUITE_P(Kernels, MetamorphicCrossingRule,
                         ::testing::Values(Kernel::Fast, Kernel::Exact), KernelTestName{});

TEST(MetamorphicWinding, FlippingEveryFacetEmptiesAClosedShell) {
  // Under `winding` an inside-out closed shell has winding number -1 < 1/2 everywhere: empty.
  const TriangleSoup part = mesh::make_sphere(3.0, 3);
  const SlicedCells outward = slice_in_memory(part, cells_of(kCell), Kernel::Winding);
  const SlicedCells flipped =
      slice_in_memory(mesh::flip_orientation(part), cells_of(kCell), Kernel::Winding);
  EXPECT_GT(outward.solid(), 1000u);
  EXPECT_EQ(flipped.solid(), 0u);
}

/// The exact kernel, and the winding kernel on closed outward meshes, give the fast kernel's
/// cells bit for bit.
class KernelAgreement : public ::testing::TestWithParam<Kernel> {};

TEST_P(KernelAgreement, GivesTheFastKernelsCellsInBothShellModes) {
  const TriangleSoup part = test_part();
  for (const ShellMode mode : {ShellMode::Distance, ShellMode::Layers}) {
    const SlicedCells fast = slice_in_memory(part, cells_of(kCell, mode, 0.6), Kernel::Fast);
    const SlicedCells other = slice_in_memory(part, cells_of(kCell, mode, 0.6), GetParam());
    expect_same_cells(fast, other);
    EXPECT_EQ(fast.summary.class_counts, other.summary.class_counts);
    EXPECT_GT(fast.solid(), 1000u);
  }
}

TEST_P(KernelAgreement, GivesTheFastKernelsCellsOnAnOffsetGridWithScanOffset) {
  // A grid whose planes and scanlines do not fall on the part's vertices, shifted scanlines.
  const TriangleSoup part = test_part();
  SliceOptions o = cells_of(0.3, ShellMode::Distance, 0.45);
  o.grid.origin = Vec3{-6.7, -6.55, -0.13};
  o.scan_offset_mm = 0.0001;
  expect_same_cells(slice_in_memory(part, o, Kernel::Fast), slice_in_memory(part, o, GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Kernels, KernelAgreement,
                         ::testing::Values(Kernel::Exact, Kernel::Winding), KernelTestName{});

TEST(KernelAgreementEvenOdd, ExactGivesTheFastKernelsCellsWhereShellsOverlap) {
  // The ring and the ball overlap: evenodd empties the overlap, in both kernels alike.
  const TriangleSoup part = test_part();
  SliceOptions o = cells_of(kCell);
  o.fill_rule = FillRule::EvenOdd;
  const SlicedCells fast = slice_in_memory(part, o, Kernel::Fast);
  expect_same_cells(fast, slice_in_memory(part, o, Kernel::Exact));
  const SlicedCells nonzero = slice_in_memory(part, cells_of(kCell), Kernel::Fast);
  EXPECT_LT(fast.solid(), nonzero.solid());
}

}  // namespace
}  // namespace strata
