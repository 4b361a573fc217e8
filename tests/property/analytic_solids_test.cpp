// Solids with known volumes and distances.
#include <gtest/gtest.h>

#include <cmath>

#include "slice_support_for_tests.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/mesh/primitive_models.hpp"

namespace strata {
namespace {

using testing::cells_of;
using testing::Kernel;
using testing::KernelTestName;
using testing::slice_in_memory;

/// The tests every kernel runs in milliseconds; the fine grids below stay on the fast kernel
/// (tests/property/metamorphic_test.cpp checks the kernels agree).
class AnalyticSolidsKernel : public ::testing::TestWithParam<Kernel> {};

double exact_volume(const TriangleSoup& soup) {
  diagnose::DiagnoseOptions o;
  o.check_self_intersections = false;
  o.near_vertex_mm = 0.0;
  return diagnose::diagnose_mesh(weld_vertices(soup), soup, o).volume_mm3;
}

double relative_volume_error(const TriangleSoup& soup, double cell, double shift = 0.0) {
  SliceOptions o = cells_of(cell, ShellMode::Layers, cell);
  const Bbox3 box = weld_vertices(soup).bounds();
  o.grid.origin = Vec3{box.min.x - shift * cell, box.min.y - shift * 0.7 * cell,
                       box.min.z - shift * 0.3 * cell};
  const auto sliced = slice_in_memory(soup, o);
  const double cells = static_cast<double>(sliced.solid()) * cell * cell * cell;
  return (cells - exact_volume(soup)) / exact_volume(soup);
}

TEST_P(AnalyticSolidsKernel, BoxOnAnAlignedGridHasExactCountsInBothShellModes) {
  const Kernel kernel = GetParam();
  const TriangleSoup box = mesh::make_box({0, 0, 0}, {3.0, 2.5, 2.0});
  // 0.25 mm cells: 12 x 10 x 8 solid cells.
  auto layers = slice_in_memory(box, cells_of(0.25, ShellMode::Layers, 0.5), kernel);  // 2 rings
  EXPECT_EQ(layers.summary.class_counts[0], 0u);
  EXPECT_EQ(layers.summary.class_counts[1], 8u * 6 * 4);
  EXPECT_EQ(layers.summary.class_counts[2], 12u * 10 * 8 - 8 * 6 * 4);
  // Distance 0.5: centres at 0.125, 0.375 from a face are closer, 0.625 is not.
  auto distance = slice_in_memory(box, cells_of(0.25, ShellMode::Distance, 0.5), kernel);
  EXPECT_EQ(distance.summary.class_counts[1], 8u * 6 * 4);
  // Distance 0.625 exactly: the third ring's centres lie at exactly t and stay interior.
  auto tie = slice_in_memory(box, cells_of(0.25, ShellMode::Distance, 0.625), kernel);
  EXPECT_EQ(tie.summary.class_counts[1], 8u * 6 * 4);
  auto past = slice_in_memory(box, cells_of(0.25, ShellMode::Distance, 0.626), kernel);
  EXPECT_EQ(past.summary.class_counts[1], 6u * 4 * 2);
}

TEST(AnalyticSolids, SphereVolumeWithinOnePercentAndConverging) {
  const TriangleSoup sphere = mesh::make_sphere(10.0, 4);
  // One grid's error can cancel by chance; the mean over grid offsets shrinks with the cells.
  const auto mean_error = [&](double cell) {
    double sum = 0.0;
    for (const double shift : {0.0, 0.25, 0.5, 0.75}) {
      sum += std::fabs(relative_volume_error(sphere, cell, shift));
    }
    return sum / 4.0;
  };
  const double coarse = mean_error(1.6);
  const double medium = mean_error(0.8);
  const double fine = mean_error(0.4);
  EXPECT_LT(medium, coarse);
  EXPECT_LT(fine, medium);
  EXPECT_LT(std::fabs(relative_volume_error(sphere, 0.1)), 0.01);
}

TEST(AnalyticSolids, RingVolumeWithinOnePercentAndConverging) {
  const TriangleSoup ring = mesh::make_ring(20.0, 12.0, 10.0, 128);
  const double coarse = std::fabs(relative_volume_error(ring, 0.4));
  const double fine = std::fabs(relative_volume_error(ring, 0.1));
  EXPECT_LT(fine, 0.01);
  EXPECT_LT(fine, coarse);
}

TEST(AnalyticSolids, SphereShellHasTheAskedThickness) {
  // Icosphere of radius R: the surface lies between the inscribed radius r_in and R, so a centre
  // at radius rho is between r_in - rho and R - rho from it.
  const double radius = 10.0;
  const double t = 0.5;
  const TriangleSoup sphere = mesh::make_sphere(radius, 4);
  double r_in = radius;
  for (const auto& tri : sphere.triangles) {
    const Vec3 c{(tri[0].x + tri[1].x + tri[2].x) / 3, (tri[0].y + tri[1].y + tri[2].y) / 3,
                 (tri[0].z + tri[1].z + tri[2].z) / 3};
    r_in = std::min(r_in, std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z));
  }
  const auto sliced = slice_in_memory(sphere, cells_of(0.2, ShellMode::Distance, t));
  const GridSpec& g = sliced.grid;
  std::uint64_t boundary = 0, interior = 0;
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    for (std::uint32_t j = 0; j < g.ny; ++j) {
      for (std::uint32_t i = 0; i < g.nx; ++i) {
        const CellClass c = sliced.at(i, j, k);
        const double x = g.xc(i), y = g.yc(j), z = g.zk(k);
        const double rho = std::sqrt(x * x + y * y + z * z);
        if (c == CellClass::Boundary) {
          ++boundary;
          EXPECT_LT(r_in - rho, t + 1e-9) << i << "," << j << "," << k;
        } else if (c == CellClass::Interior) {
          ++interior;
          EXPECT_GE(radius - rho, t - 1e-9) << i << "," << j << "," << k;
        }
      }
    }
  }
  EXPECT_GT(boundary, 10000u);
  EXPECT_GT(interior, 100000u);
}

TEST_P(AnalyticSolidsKernel, ContourAreaMatchesTheRingSection) {
  const double outer = 20.0, inner = 12.0;
  const int n = 128;
  const TriangleSoup ring = mesh::make_ring(outer, inner, 10.0, n);
  const auto sliced = slice_in_memory(ring, cells_of(0.5), GetParam());
  ASSERT_EQ(sliced.summary.layers.size(), 20u);
  // Every layer's contours are the two 128-gons: area (n/2) sin(2 pi / n) (R^2 - r^2).
  const double polygon_area = 0.5 * n * std::sin(2 * M_PI / n) * (outer * outer - inner * inner);
  for (const auto& layer : sliced.summary.layers) {
    EXPECT_NEAR(layer.contour_area_mm2, polygon_area, 1e-6 * polygon_area);
    EXPECT_EQ(layer.outer_loops, 1u);
    EXPECT_EQ(layer.holes, 1u);
  }
}

INSTANTIATE_TEST_SUITE_P(Kernels, AnalyticSolidsKernel,
                         ::testing::Values(Kernel::Fast, Kernel::Exact, Kernel::Winding),
                         KernelTestName{});

}  // namespace
}  // namespace strata
