// The bytes as a small triangle soup sliced by both paths. The fast path's cells must be the
// exact path's, cell for cell (SPEC §2, section 5); their solid cells those of SPEC §2's inside
// rule as written, evaluated here on GMP rationals facet by facet and cell by cell; and the shell
// that of its definition with every facet asked (the exact point-triangle predicate for
// `distance`, the city-block distance to the nearest empty cell for `layers`).
//
// Encoding: byte 0 picks the options (bit 0 evenodd, bit 1 layers mode, bits 2-4 the shell's
// thickness from kShellInCells, bit 5 the published scan offset, bit 6 batches of four layers,
// bit 7 nudges), byte 1 the grid (bits 0-1 the cell sizes from kCells, bit 2 sizes of a tenth,
// bit 3 the origin at 0 rather than at the box's corner); then nine bytes a triangle, each a
// coordinate (byte & 31) / 4 - 1 in cells, moved one ulp up (top bits 110) or down (111) when
// nudges are on. The corners of this lattice of quarter cells fall on layer planes, scanlines,
// cell centres and faces, and at distances from the centres equal to the shell's thickness: the
// ties every filter and shortcut of the fast path must settle as the exact rule does.
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <vector>

#include "fuzz_support.hpp"
#include "strata/exact/slice_exact.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slicer/slice_model.hpp"
#include "strata/voxel/boundary_shell.hpp"
#include "support/collecting_sink.hpp"
#include "support/exact_crossing.hpp"
#include "voxel/point_triangle_distance_internal.hpp"

namespace {

using namespace strata;

constexpr std::size_t kHeaderBytes = 2;
constexpr std::size_t kTriangleBytes = 9;
constexpr std::size_t kMaxTriangles = 12;
constexpr std::uint32_t kMaxCellsXY = 32;
constexpr std::uint32_t kMaxCellsZ = 16;

/// Fails naming the cell, the fast path's class and the one it is held to.
[[noreturn]] void fail_at(const char* what, std::uint32_t i, std::uint32_t j, std::uint32_t k,
                          int fast, int other) {
  std::fprintf(stderr, "at cell (%u, %u, %u): %d against %d\n", i, j, k, fast, other);
  fuzz::fail(what);
}

/// A coordinate on the lattice of quarter cells from -1 to 6.75 cells, nudged by one ulp either
/// way when the byte's top bits ask it and nudges are on.
double coordinate(std::uint8_t byte, double cell, bool nudges) {
  const double v = (static_cast<double>(byte & 31) * 0.25 - 1.0) * cell;
  if (!nudges) return v;
  switch (byte >> 5) {
    case 6:
      return std::nextafter(v, HUGE_VAL);
    case 7:
      return std::nextafter(v, -HUGE_VAL);
    default:
      return v;
  }
}

std::vector<std::vector<CellClass>> slice_with(bool exact, const IndexedMesh& mesh,
                                               const GridSpec& grid, const SliceOptions& options) {
  testing::CollectingSink sink;
  sink.reads_hatches = false;
  LayerSink* sinks[] = {&sink};
  const Result<SliceSummary> summary = exact ? slice_model_exact(mesh, grid, options, sinks)
                                             : slice_model(mesh, grid, options, sinks);
  if (!summary) {
    std::fprintf(stderr, "%s path: %s\n", exact ? "exact" : "fast",
                 summary.error().to_string().c_str());
    fuzz::fail("a path fails on a mesh of finite coordinates under nonzero or evenodd");
  }
  fuzz::check(sink.layers.size() == grid.nz, "a path sends every layer");
  return sink.layers;
}

/// A crossing of a facet with a layer's plane, exactly.
struct RationalPoint {
  mpq_class x, y;
};

/// The solid cells of SPEC §2's inside rule, word for word: a segment from each facet that
/// crosses the plane (a vertex on it counts as above), a crossing where exactly one of its ends is
/// below the scanline (one on it counts as above), counted for the cells whose centre lies
/// strictly left of it, with the sign of the facet normal's x; nonzero or odd.
std::vector<std::vector<bool>> inside_rule(const IndexedMesh& mesh, const GridSpec& grid,
                                           const SliceOptions& options) {
  std::vector<std::vector<bool>> solid(grid.nz, std::vector<bool>(grid.cells_per_layer()));
  for (std::uint32_t k = 0; k < grid.nz; ++k) {
    const double zk = grid.zk(k);
    std::vector<std::pair<RationalPoint, RationalPoint>> segments;
    std::vector<int> signs;
    for (const auto& f : mesh.triangles) {
      const Vec3* v[3] = {&mesh.vertices[f[0]], &mesh.vertices[f[1]], &mesh.vertices[f[2]]};
      std::vector<RationalPoint> ends;
      for (int e = 0; e < 3; ++e) {
        const Vec3& p = *v[e];
        const Vec3& q = *v[(e + 1) % 3];
        if ((p.z < zk) == (q.z < zk)) continue;
        ends.push_back(
            {test::crossing_as_written(p, q, zk, 0), test::crossing_as_written(p, q, zk, 1)});
      }
      if (ends.empty()) continue;
      fuzz::check(ends.size() == 2, "a facet crosses a plane in two edges or none");
      const auto d = [](double a, double b) -> mpq_class { return mpq_class(a) - mpq_class(b); };
      const mpq_class nx =
          d(v[1]->y, v[0]->y) * d(v[2]->z, v[0]->z) - d(v[1]->z, v[0]->z) * d(v[2]->y, v[0]->y);
      segments.emplace_back(ends[0], ends[1]);
      signs.push_back(sgn(nx));
    }
    std::vector<mpq_class> centres_x;
    for (std::uint32_t i = 0; i < grid.nx; ++i) centres_x.emplace_back(grid.xc(i));
    for (std::uint32_t j = 0; j < grid.ny; ++j) {
      const mpq_class y(grid.yc(j) + options.scan_offset_mm);
      std::vector<int> winding(grid.nx, 0), crossings(grid.nx, 0);
      for (std::size_t s = 0; s < segments.size(); ++s) {
        const auto& [a, b] = segments[s];
        if ((a.y < y) == (b.y < y)) continue;
        const mpq_class x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
        for (std::uint32_t i = 0; i < grid.nx; ++i) {
          if (!(x > centres_x[i])) continue;
          winding[i] += signs[s];
          ++crossings[i];
        }
      }
      for (std::uint32_t i = 0; i < grid.nx; ++i) {
        solid[k][std::size_t{j} * grid.nx + i] =
            options.fill_rule == FillRule::EvenOdd ? crossings[i] % 2 == 1 : winding[i] != 0;
      }
    }
  }
  return solid;
}

/// The shell as SPEC §2 defines it, from the cells' solid bits: each solid cell asks every facet.
void check_shell(const std::vector<std::vector<CellClass>>& layers, const IndexedMesh& mesh,
                 const GridSpec& grid, const SliceOptions& options) {
  const auto solid = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    if (i < 0 || j < 0 || k < 0 || i >= grid.nx || j >= grid.ny || k >= grid.nz) return false;
    return layers[static_cast<std::size_t>(k)][static_cast<std::size_t>(j) * grid.nx +
                                               static_cast<std::size_t>(i)] != CellClass::Empty;
  };
  const double t = options.shell_mm;
  // The layers mode's ring count; 1 in the distance mode, which looks for an empty 6-neighbour.
  const std::int64_t rings = BoundaryShell::reach_layers(grid, options.shell_mode, t);
  for (std::uint32_t k = 0; k < grid.nz; ++k) {
    for (std::uint32_t j = 0; j < grid.ny; ++j) {
      for (std::uint32_t i = 0; i < grid.nx; ++i) {
        if (!solid(i, j, k)) continue;
        // The nearest empty cell in city-block steps, up to `rings` (further counts as far).
        std::int64_t nearest_empty = rings + 1;
        for (std::int64_t dk = -rings; dk <= rings; ++dk) {
          for (std::int64_t dj = -rings; dj <= rings; ++dj) {
            for (std::int64_t di = -rings; di <= rings; ++di) {
              const std::int64_t steps = std::abs(di) + std::abs(dj) + std::abs(dk);
              if (steps == 0 || steps > rings) continue;
              if (!solid(i + di, j + dj, k + dk)) nearest_empty = std::min(nearest_empty, steps);
            }
          }
        }
        bool boundary = nearest_empty == 1;
        if (!boundary && options.shell_mode == ShellMode::Layers) boundary = nearest_empty <= rings;
        if (!boundary && options.shell_mode == ShellMode::Distance && t > 0.0) {
          const Vec3 centre{grid.xc(i), grid.yc(j), grid.zk(k)};
          for (const auto& f : mesh.triangles) {
            if (detail::triangle_closer_than(centre, mesh.vertices[f[0]], mesh.vertices[f[1]],
                                             mesh.vertices[f[2]], t)) {
              boundary = true;
              break;
            }
          }
        }
        const CellClass want = boundary ? CellClass::Boundary : CellClass::Interior;
        const CellClass got = layers[k][std::size_t{j} * grid.nx + i];
        if (got != want) {
          fail_at("the shell differs from its definition", i, j, k, static_cast<int>(got),
                  static_cast<int>(want));
        }
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < kHeaderBytes + kTriangleBytes) return 0;
  const std::uint8_t how = data[0];
  const std::uint8_t sizes = data[1];
  // Cell sizes: equal; thinner layers; or three different sizes. Scaled by 1 or by 0.1, the
  // second giving the decimal coordinates of real models (not exact in binary).
  constexpr std::array<std::array<double, 3>, 4> kCells{
      {{1.0, 1.0, 1.0}, {1.0, 1.0, 0.5}, {1.0, 0.5, 0.75}, {0.5, 1.0, 1.0}}};
  const double scale = (sizes & 4) != 0 ? 0.1 : 1.0;
  const std::array<double, 3> d{kCells[sizes & 3][0] * scale, kCells[sizes & 3][1] * scale,
                                kCells[sizes & 3][2] * scale};
  const bool nudges = (how & 0x80) != 0;
  TriangleSoup soup;
  const std::size_t count = std::min(kMaxTriangles, (size - kHeaderBytes) / kTriangleBytes);
  for (std::size_t f = 0; f < count; ++f) {
    const std::uint8_t* b = data + kHeaderBytes + f * kTriangleBytes;
    std::array<Vec3, 3> t{};
    for (int c = 0; c < 3; ++c) {
      t[c] = {coordinate(b[3 * c], d[0], nudges), coordinate(b[3 * c + 1], d[1], nudges),
              coordinate(b[3 * c + 2], d[2], nudges)};
    }
    soup.triangles.push_back(t);
  }
  const IndexedMesh mesh = weld_vertices(soup);

  SliceOptions options;
  options.fill_rule = (how & 1) != 0 ? FillRule::EvenOdd : FillRule::NonZero;
  options.shell_mode = (how & 2) != 0 ? ShellMode::Layers : ShellMode::Distance;
  // In units of the smallest cell: none, within a cell, and thicknesses that equal distances
  // between lattice points and centres (1, 1.25 = |(1, 0.75)|, 1.5, 2.5).
  constexpr std::array<double, 8> kShellInCells{0.0, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5};
  options.shell_mm = kShellInCells[(how >> 2) & 7] * std::min({d[0], d[1], d[2]});
  options.scan_offset_mm = (how & 0x20) != 0 ? 1e-4 * scale : 0.0;
  options.batch_layers = 1 + ((how >> 6) & 1) * 3;
  options.threads = 1;
  // The grid's origin: the box's lowest corner (the default), or the lattice's origin, which
  // leaves the corners below it outside the grid.
  options.grid = GridOptions{d[0], d[1], d[2], std::nullopt};
  if ((sizes & 8) != 0) options.grid.origin = Vec3{0.0, 0.0, 0.0};
  const Result<GridSpec> grid = make_grid(mesh.bounds(), options.grid);
  if (!grid || grid->nx > kMaxCellsXY || grid->ny > kMaxCellsXY || grid->nz > kMaxCellsZ) return 0;

  const auto fast = slice_with(false, mesh, *grid, options);
  const auto exact = slice_with(true, mesh, *grid, options);
  const auto rule = inside_rule(mesh, *grid, options);
  for (std::uint32_t k = 0; k < grid->nz; ++k) {
    for (std::size_t c = 0; c < fast[k].size(); ++c) {
      const auto i = static_cast<std::uint32_t>(c % grid->nx);
      const auto j = static_cast<std::uint32_t>(c / grid->nx);
      const int got = static_cast<int>(fast[k][c]);
      if (fast[k][c] != exact[k][c]) {
        fail_at("the fast path's cell differs from the exact path's", i, j, k, got,
                static_cast<int>(exact[k][c]));
      }
      if ((fast[k][c] != CellClass::Empty) != rule[k][c]) {
        fail_at("a solid cell differs from SPEC's inside rule", i, j, k, got, rule[k][c] ? 1 : 0);
      }
    }
  }
  check_shell(fast, mesh, *grid, options);
  return 0;
}
