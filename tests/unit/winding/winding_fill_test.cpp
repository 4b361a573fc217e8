// The `winding` fill rule through slice_model: what issue-level promises it keeps on damaged
// closed meshes (facets removed, facets flipped, shells overlapping or inverted).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slicer/slice_model.hpp"
#include "support/collecting_sink.hpp"

namespace strata {
namespace {

constexpr double kCell = 0.25;

struct Cells {
  std::vector<std::vector<CellClass>> layers;
  std::uint64_t solid = 0;
  SliceSummary summary;
};

/// Slices on a fixed grid (the closed sphere's), so runs compare cell for cell.
Cells slice(const IndexedMesh& mesh, FillRule rule) {
  SliceOptions o;
  o.grid.dx_mm = o.grid.dy_mm = o.grid.dz_mm = kCell;
  o.grid.origin = Vec3{-10.5, -10.5, -10.5};
  o.fill_rule = rule;
  Bbox3 box;
  box.add({-10.5, -10.5, -10.5});
  box.add({10.5, 10.5, 10.5});
  auto grid = make_grid(box, o.grid);
  EXPECT_TRUE(grid.has_value());
  testing::CollectingSink sink;
  LayerSink* sinks[] = {&sink};
  auto summary = slice_model(mesh, *grid, o, sinks);
  EXPECT_TRUE(summary.has_value()) << (summary ? "" : summary.error().to_string());
  Cells out;
  out.layers = std::move(sink.layers);
  if (summary) {
    out.summary = *summary;
    out.solid = summary->class_counts[1] + summary->class_counts[2];
  }
  return out;
}

std::uint64_t differing(const Cells& a, const Cells& b) {
  std::uint64_t n = 0;
  for (std::size_t k = 0; k < a.layers.size(); ++k) {
    for (std::size_t c = 0; c < a.layers[k].size(); ++c) {
      n += (a.layers[k][c] == CellClass::Empty) != (b.layers[k][c] == CellClass::Empty) ? 1 : 0;
    }
  }
  return n;
}

IndexedMesh sphere() { return weld_vertices(mesh::make_sphere(10.0, 4)); }

/// `count` facets chosen at random (fixed seed), removed or flipped.
IndexedMesh damaged(IndexedMesh m, std::size_t count, bool flip, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::size_t> order(m.triangles.size());
  for (std::size_t f = 0; f < order.size(); ++f) order[f] = f;
  std::shuffle(order.begin(), order.end(), rng);
  order.resize(count);
  std::sort(order.begin(), order.end());
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    if (flip) {
      std::swap(m.triangles[*it][1], m.triangles[*it][2]);
    } else {
      m.triangles.erase(m.triangles.begin() + static_cast<std::ptrdiff_t>(*it));
    }
  }
  return m;
}

double relative_error(const Cells& got, const Cells& expected) {
  return std::abs(static_cast<double>(got.solid) - static_cast<double>(expected.solid)) /
         static_cast<double>(expected.solid);
}

TEST(WindingFill, ClosedMeshGivesTheNonzeroCellsExactly) {
  const IndexedMesh s = sphere();
  const Cells nonzero = slice(s, FillRule::NonZero);
  const Cells winding = slice(s, FillRule::Winding);
  EXPECT_EQ(winding.layers, nonzero.layers);
  ASSERT_FALSE(winding.summary.diagnostics.empty());
  EXPECT_EQ(winding.summary.diagnostics.back().code, "winding.closed");
}

class FacetsRemoved : public ::testing::TestWithParam<std::size_t> {};

TEST_P(FacetsRemoved, WindingStaysWithinHalfAPercentWhereCrossingRulesGoWrong) {
  const IndexedMesh closed = sphere();  // 5120 facets
  const Cells expected = slice(closed, FillRule::NonZero);
  const IndexedMesh open = damaged(closed, GetParam(), false, 2026);
  const Cells winding = slice(open, FillRule::Winding);
  const Cells nonzero = slice(open, FillRule::NonZero);
  const Cells evenodd = slice(open, FillRule::EvenOdd);
  EXPECT_LT(relative_error(winding, expected), 0.005);
  const std::uint64_t winding_wrong = differing(winding, expected);
  std::printf(
      "%zu facets removed: solid cells off by %.3f %% (winding), %.3f %% (nonzero), "
      "%.3f %% (evenodd); cells differing %llu / %llu / %llu of %llu solid\n",
      GetParam(), 100.0 * relative_error(winding, expected),
      100.0 * relative_error(nonzero, expected), 100.0 * relative_error(evenodd, expected),
      static_cast<unsigned long long>(winding_wrong),
      static_cast<unsigned long long>(differing(nonzero, expected)),
      static_cast<unsigned long long>(differing(evenodd, expected)),
      static_cast<unsigned long long>(expected.solid));
  EXPECT_LT(winding_wrong, differing(nonzero, expected));
  EXPECT_LT(winding_wrong, differing(evenodd, expected));
  EXPECT_GT(winding.summary.open_chains, 0u);  // reported, not hidden
}

// 1 facet, 10 facets and 1 % of the facets.
INSTANTIATE_TEST_SUITE_P(Sphere, FacetsRemoved, ::testing::Values(1, 10, 51));

TEST(WindingFill, FlippedFacetsStayWithinHalfAPercent) {
  const IndexedMesh closed = sphere();
  const Cells expected = slice(closed, FillRule::NonZero);
  const IndexedMesh flipped = damaged(closed, 51, true, 7);
  const Cells winding = slice(flipped, FillRule::Winding);
  EXPECT_LT(relative_error(winding, expected), 0.005);
  EXPECT_LT(differing(winding, expected), differing(slice(flipped, FillRule::NonZero), expected));
}

TEST(WindingFill, OverlappingShellsFillTheirUnion) {
  TriangleSoup two = mesh::make_sphere(6.0, 3);
  const TriangleSoup other = mesh::translate_soup(mesh::make_sphere(6.0, 3), {4.0, 0.0, 0.0});
  two.triangles.insert(two.triangles.end(), other.triangles.begin(), other.triangles.end());
  const IndexedMesh m = weld_vertices(two);
  const Cells nonzero = slice(m, FillRule::NonZero);
  const Cells winding = slice(m, FillRule::Winding);
  EXPECT_EQ(winding.layers, nonzero.layers);
  // Evenodd empties the lens where the two overlap; winding, like nonzero, keeps it.
  EXPECT_GT(winding.solid, slice(m, FillRule::EvenOdd).solid);
}

TEST(WindingFill, AnInvertedClosedShellIsEmptyAsTheDefinitionSays) {
  // w = -1 inside: below 1/2. `strata check` reports the inversion and `--repair` turns it.
  const IndexedMesh inverted = weld_vertices(mesh::flip_orientation(mesh::make_sphere(10.0, 4)));
  EXPECT_EQ(slice(inverted, FillRule::Winding).solid, 0u);
}

}  // namespace
}  // namespace strata
