#include "strata/voxel/boundary_shell.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <random>
#include <vector>

#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slicer/slice_model.hpp"
#include "support/collecting_sink.hpp"
#include "voxel/point_triangle_distance_internal.hpp"

// The distance shell against its definition, cell by cell: a solid cell is boundary exactly when
// it touches the outside or its centre is closer than t to some facet (the exact predicate, every
// facet whose box may reach it). The meshes have wide facets, whose rows the shell decides as
// runs between two exact tests, and small ones, decided cell by cell.

namespace strata {
namespace {

/// Rotates every corner by the same rotation (in double): a closed mesh stays closed and welded.
TriangleSoup rotated(const TriangleSoup& soup, double ax, double ay, double az) {
  const auto turn = [&](Vec3 p) {
    const auto about = [](double& u, double& v, double angle) {
      const double c = std::cos(angle);
      const double s = std::sin(angle);
      const double nu = c * u - s * v;
      v = s * u + c * v;
      u = nu;
    };
    about(p.y, p.z, ax);
    about(p.z, p.x, ay);
    about(p.x, p.y, az);
    return p;
  };
  TriangleSoup out = soup;
  for (auto& t : out.triangles) {
    for (Vec3& p : t) p = turn(p);
  }
  return out;
}

bool may_reach(const IndexedMesh& mesh, const std::array<VertexIndex, 3>& t, const Vec3& p,
               double reach) {
  for (int axis = 0; axis < 3; ++axis) {
    const auto coord = [axis](const Vec3& v) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; };
    const double a = coord(mesh.vertices[t[0]]);
    const double b = coord(mesh.vertices[t[1]]);
    const double c = coord(mesh.vertices[t[2]]);
    if (coord(p) < std::min({a, b, c}) - reach || coord(p) > std::max({a, b, c}) + reach) {
      return false;
    }
  }
  return true;
}

/// Slices `mesh` with the distance shell t and checks every cell against the definition (of
/// every `layer_step`-th layer); returns how many cells the distance (not the outside) made
/// boundary.
std::size_t expect_shell_by_definition(const IndexedMesh& mesh, double cell, double t,
                                       std::uint32_t layer_step = 1) {
  SliceOptions options;
  options.grid = GridOptions{cell, cell, cell, std::nullopt};
  options.shell_mode = ShellMode::Distance;
  options.shell_mm = t;
  options.batch_layers = 3;
  auto grid = make_grid(mesh.bounds(), options.grid);
  EXPECT_TRUE(grid.has_value());
  if (!grid) return 0;
  testing::CollectingSink sink;
  LayerSink* sinks[] = {&sink};
  auto summary = slice_model(mesh, *grid, options, sinks);
  EXPECT_TRUE(summary.has_value());
  if (!summary) return 0;
  // The counts the shell reports are its cells'.
  EXPECT_EQ(summary->class_counts[1], sink.count(CellClass::Interior));
  EXPECT_EQ(summary->class_counts[2], sink.count(CellClass::Boundary));
  const GridSpec& g = *grid;
  const auto solid = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    if (i < 0 || j < 0 || k < 0 || i >= g.nx || j >= g.ny || k >= g.nz) return false;
    return sink.at(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j),
                   static_cast<std::uint32_t>(k)) != CellClass::Empty;
  };
  std::size_t by_distance = 0;
  std::size_t wrong = 0;
  for (std::uint32_t k = 0; k < g.nz; k += layer_step) {
    for (std::uint32_t j = 0; j < g.ny; ++j) {
      for (std::uint32_t i = 0; i < g.nx; ++i) {
        if (!solid(i, j, k)) continue;
        const bool outside = !solid(i - 1, j, k) || !solid(i + 1, j, k) || !solid(i, j - 1, k) ||
                             !solid(i, j + 1, k) || !solid(i, j, k - 1) || !solid(i, j, k + 1);
        bool near = false;
        const Vec3 p{g.xc(i), g.yc(j), g.zk(k)};
        for (const auto& tri : mesh.triangles) {
          if (!may_reach(mesh, tri, p, t * 1.001)) continue;
          if (detail::triangle_closer_than(p, mesh.vertices[tri[0]], mesh.vertices[tri[1]],
                                           mesh.vertices[tri[2]], t)) {
            near = true;
            break;
          }
        }
        by_distance += (near && !outside) ? 1 : 0;
        const CellClass expected = outside || near ? CellClass::Boundary : CellClass::Interior;
        if (sink.at(i, j, k) != expected && ++wrong <= 5) {
          ADD_FAILURE() << "cell (" << i << ", " << j << ", " << k << ") t=" << t << ": is "
                        << static_cast<int>(sink.at(i, j, k)) << ", the definition gives "
                        << static_cast<int>(expected);
        }
      }
    }
  }
  EXPECT_EQ(wrong, 0u);
  return by_distance;
}

TEST(BoundaryShell, ATiltedBoxIsItsDefinitionCellForCell) {
  const IndexedMesh box =
      weld_vertices(rotated(mesh::make_box({-5, -4, -3}, {5, 4, 3}), 0.3, 0.5, 0.7));
  for (const double t : {0.6, 1.3}) {
    EXPECT_GT(expect_shell_by_definition(box, 0.25, t), 100u) << "t=" << t;
  }
}

TEST(BoundaryShell, ATetrahedronAndASphereAreTheirDefinitionCellForCell) {
  // The shell groups facets into patches by box: by counting when the boxes they span are no
  // more than the facets (these two, 4 and 208 boxes), by sorting otherwise (the tilted box's 12
  // facets span 90).
  const IndexedMesh tetra = weld_vertices(mesh::make_tetrahedron());
  EXPECT_GT(expect_shell_by_definition(tetra, 0.25, 0.9), 100u);
  // 320 facets about 1.6 mm wide: rows of six to eight cells, decided cell by cell or as runs.
  const IndexedMesh ball = weld_vertices(rotated(mesh::make_sphere(5.0, 2), 0.1, 0.2, 0.3));
  EXPECT_GT(expect_shell_by_definition(ball, 0.2, 0.7), 100u);
}

TEST(BoundaryShell, SmallFacetsReachingFarAreTheirDefinitionCellForCell) {
  // Small facets are tested together, a patch of neighbours at a time, over the patch's box.
  // A shell of 36 cells makes that box wider than the 64 cells the shell keeps as bits.
  const IndexedMesh ball = weld_vertices(rotated(mesh::make_sphere(1.0, 3), 0.3, 0.1, 0.2));
  EXPECT_GT(expect_shell_by_definition(ball, 0.025, 0.9, 13), 1000u);
  // A cylinder lying along y: its sides are strips a few cells across and 90 rows long, so a
  // patch's box is narrow but taller than the 64 rows kept as bits.
  const IndexedMesh rod =
      weld_vertices(rotated(mesh::make_cylinder(1.5, 9.0, 40), 1.5707963267948966, 0.0, 0.05));
  EXPECT_GT(expect_shell_by_definition(rod, 0.1, 0.45), 1000u);
}

TEST(BoundaryShell, FacetsInsideTheSolidMakeAShellAroundThemToo) {
  // Two overlapping boxes: under nonzero their union is solid, and the facets of each inside the
  // other are surface all the same, with a shell around them.
  TriangleSoup both = rotated(mesh::make_box({0, 0, 0}, {8, 6, 5}), 0.0, 0.0, 0.4);
  const TriangleSoup other = rotated(mesh::make_box({3, 2, 1}, {11, 9, 7}), 0.2, 0.0, 0.0);
  both.triangles.insert(both.triangles.end(), other.triangles.begin(), other.triangles.end());
  EXPECT_GT(expect_shell_by_definition(weld_vertices(both), 0.25, 0.8), 100u);
}

TEST(BoundaryShell, ALoneFacetInsideTheSolidHasTheShellItsEdgesAndCornersReach) {
  // No other facet comes near the lone facet's edges and corners: the cells around them are
  // boundary by its distance alone, up to the true reach past each edge and corner.
  TriangleSoup soup = mesh::make_box({0, 0, 0}, {12, 12, 8});
  soup.triangles.push_back({Vec3{3, 3, 4}, Vec3{9.5, 4, 3}, Vec3{5, 9.25, 5}});
  soup.triangles.push_back({Vec3{3, 3, 4}, Vec3{5, 9.25, 5}, Vec3{9.5, 4, 3}});
  EXPECT_GT(expect_shell_by_definition(weld_vertices(soup), 0.25, 0.9), 100u);
}

TEST(BoundaryShell, AShellManyCellsThickIsItsDefinitionAcrossTheTilesOfItsReach) {
  // A shell of 30 cells about a small ball of small facets inside the solid: the boxes that a
  // patch's vertices and facets reach (about 75 cells a side) are taken in tiles of 64 columns by
  // 64 rows, and the cells of the far tiles are boundary by the ball's facets alone (the side
  // walls' shells lie farther away).
  TriangleSoup soup = mesh::make_box({0, 0, 0}, {16, 16, 10});
  TriangleSoup ball = rotated(mesh::make_sphere(0.7, 2), 0.3, 0.1, 0.2);
  for (auto& t : ball.triangles) {
    for (Vec3& p : t) p = {p.x + 8.0, p.y + 8.0, p.z + 5.0};
  }
  soup.triangles.insert(soup.triangles.end(), ball.triangles.begin(), ball.triangles.end());
  EXPECT_GT(expect_shell_by_definition(weld_vertices(soup), 0.1, 3.0, 13), 10000u);
}

TEST(BoundaryShell, ACellExactlyTFromAVertexIsNotInTheShell) {
  // Cells near a vertex are marked by its distance before any facet tests them, with a bound on
  // the rounding: a centre exactly t from the vertex must stay interior, at either end of the
  // vertex's run of cells along the row. A small lone facet (both orientations, so the fill is
  // the box's) has its corner v = p - side (0.375, 0.5, 0), so |p - v| = 0.625 = t exactly, and
  // the facet runs away from p: v is its closest point.
  const double cell = 0.125;
  const double t = 0.625;
  const Vec3 p{0.0625 + 40 * cell, 0.0625 + 40 * cell, 0.0625 + 32 * cell};
  for (const double side : {1.0, -1.0}) {
    SCOPED_TRACE(side > 0 ? "p at the high end of the vertex's run" : "p at its low end");
    const Vec3 v{p.x - side * 0.375, p.y - side * 0.5, p.z};
    const Vec3 b{v.x - side * 0.25, v.y - side * 0.75, v.z + 0.1};
    const Vec3 c{v.x - side * 0.75, v.y - side * 0.25, v.z - 0.1};
    EXPECT_FALSE(detail::triangle_closer_than(p, v, b, c, t));
    EXPECT_TRUE(detail::triangle_closer_than(p, v, b, c, std::nextafter(t, 1.0)));
    TriangleSoup soup = mesh::make_box({0, 0, 0}, {8, 8, 8});
    soup.triangles.push_back({v, b, c});
    soup.triangles.push_back({v, c, b});
    EXPECT_GT(expect_shell_by_definition(weld_vertices(soup), cell, t), 100u);
  }
}

/// Solid layers for the rings' tests: a few balls of cells in an nx x ny x nz grid, so that the
/// solid has a deep inside, thin parts and cells on the grid's sides.
std::vector<std::vector<std::uint8_t>> random_balls(std::uint32_t nx, std::uint32_t ny,
                                                    std::uint32_t nz, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::vector<std::uint8_t>> layers(nz, std::vector<std::uint8_t>(nx * ny, 0));
  for (int ball = 0; ball < 6; ++ball) {
    const double cx = unit(rng) * nx, cy = unit(rng) * ny, cz = unit(rng) * nz;
    const double r = 1.5 + unit(rng) * 7.0;
    for (std::uint32_t k = 0; k < nz; ++k) {
      for (std::uint32_t j = 0; j < ny; ++j) {
        for (std::uint32_t i = 0; i < nx; ++i) {
          const double dx = i + 0.5 - cx, dy = j + 0.5 - cy, dz = k + 0.5 - cz;
          if (dx * dx + dy * dy + dz * dz < r * r) layers[k][j * nx + i] = 1;
        }
      }
    }
  }
  return layers;
}

TEST(BoundaryShell, RingsAreTheirDefinitionCellForCell) {
  // SPEC: n rings, the first being the solid cells with an empty 6-neighbour (outside the grid
  // counts as empty), each further ring the solid 6-neighbours of the one before. Here by
  // breadth-first search over the whole grid, against the shell's classes of every layer.
  const std::uint32_t nx = 23, ny = 19, nz = 14;
  const TriangleSoup box = mesh::make_box({0, 0, 0}, {nx, ny, nz});
  const IndexedMesh mesh = weld_vertices(box);
  GridSpec grid;
  grid.nx = nx;
  grid.ny = ny;
  grid.nz = nz;
  for (const unsigned seed : {1u, 2u, 3u}) {
    const auto layers = random_balls(nx, ny, nz, seed);
    const auto at = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
      return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz && layers[k][j * nx + i] != 0;
    };
    // ring[c]: 0 for an empty cell, else the ring the cell is in.
    std::vector<std::uint32_t> ring(std::size_t{nx} * ny * nz, 0);
    std::deque<std::array<std::int64_t, 3>> frontier;
    const std::array<std::array<int, 3>, 6> steps = {
        {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
    const auto index = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
      return (static_cast<std::size_t>(k) * ny + j) * nx + i;
    };
    for (std::int64_t k = 0; k < nz; ++k) {
      for (std::int64_t j = 0; j < ny; ++j) {
        for (std::int64_t i = 0; i < nx; ++i) {
          if (!at(i, j, k)) continue;
          for (const auto& s : steps) {
            if (!at(i + s[0], j + s[1], k + s[2])) {
              ring[index(i, j, k)] = 1;
              frontier.push_back({i, j, k});
              break;
            }
          }
        }
      }
    }
    while (!frontier.empty()) {
      const auto [i, j, k] = frontier.front();
      frontier.pop_front();
      for (const auto& s : steps) {
        const std::int64_t a = i + s[0], b = j + s[1], c = k + s[2];
        if (at(a, b, c) && ring[index(a, b, c)] == 0) {
          ring[index(a, b, c)] = ring[index(i, j, k)] + 1;
          frontier.push_back({a, b, c});
        }
      }
    }
    const std::uint32_t deepest = *std::max_element(ring.begin(), ring.end());
    ASSERT_GE(deepest, 5u) << "seed " << seed << ": the balls must leave a deep inside";
    std::vector<SolidRows> rows;
    for (const auto& layer : layers) rows.push_back(SolidRows::from_cells(layer, nx, ny));
    const SolidLayerLookup solid = [&](std::int64_t k) -> const SolidRows* {
      return k >= 0 && k < nz ? &rows[static_cast<std::size_t>(k)] : nullptr;
    };
    for (const std::uint32_t n : {1u, 2u, 3u, 4u, 7u, 255u}) {
      // t = n + 0.5 cells gives n rings (int(t / d)); 255 is the most there are.
      const BoundaryShell shell(mesh, grid, ShellMode::Layers, n == 255 ? 1000.0 : n + 0.5);
      ASSERT_EQ(shell.rings(), n);
      std::size_t wrong = 0, beyond_first = 0;
      std::vector<CellClass> out(std::size_t{nx} * ny);
      for (std::uint32_t k = 0; k < nz; ++k) {
        // The reserved code in every cell: classify writes each one.
        std::fill(out.begin(), out.end(), static_cast<CellClass>(0b10));
        const BoundaryShell::ClassCounts counts = shell.classify(k, solid, out);
        EXPECT_EQ(counts.interior, static_cast<std::uint64_t>(
                                       std::count(out.begin(), out.end(), CellClass::Interior)));
        EXPECT_EQ(counts.boundary, static_cast<std::uint64_t>(
                                       std::count(out.begin(), out.end(), CellClass::Boundary)));
        for (std::uint32_t j = 0; j < ny; ++j) {
          for (std::uint32_t i = 0; i < nx; ++i) {
            const std::uint32_t r = ring[index(i, j, k)];
            const CellClass expected =
                r == 0 ? CellClass::Empty : (r <= n ? CellClass::Boundary : CellClass::Interior);
            beyond_first += r > 1 && r <= n ? 1 : 0;
            if (out[j * nx + i] != expected && ++wrong <= 5) {
              ADD_FAILURE() << "seed " << seed << ", n " << n << ": cell (" << i << ", " << j
                            << ", " << k << ") in ring " << r << " is "
                            << static_cast<int>(out[j * nx + i]);
            }
          }
        }
      }
      EXPECT_EQ(wrong, 0u) << "seed " << seed << ", n " << n;
      if (n > 1) {
        EXPECT_GT(beyond_first, 0u) << "seed " << seed << ", n " << n;
      }
    }
  }
}

}  // namespace
}  // namespace strata
