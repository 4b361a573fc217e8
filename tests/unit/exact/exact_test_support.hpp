#pragma once

// Models and helpers shared by the exact path's tests: hand-built indexed meshes on the SPEC's tie
// cases and defects, a sink that keeps every layer, and runners for the fast and exact paths.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exact/exact_kernel_internal.hpp"
#include "strata/exact/slice_exact.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/slicer/slice_model.hpp"
#include "support/mesh_builders.hpp"

namespace strata::exact_test {

/// Keeps every layer: classes, contours, hatches.
class LayerCollector final : public LayerSink {
 public:
  Result<void> begin(const SliceRunInfo& run) override {
    grid = run.grid;
    return {};
  }
  Result<void> add_layer(const LayerResult& layer) override {
    cells.emplace_back(layer.cells.begin(), layer.cells.end());
    contours.push_back(layer.contours);
    hatches.push_back(layer.hatches);
    return {};
  }
  Result<void> finish() override {
    finished = true;
    return {};
  }
  void abort() noexcept override { aborted = true; }

  bool solid(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    return cells[k][std::size_t{j} * grid.nx + i] != CellClass::Empty;
  }

  GridSpec grid;
  std::vector<std::vector<CellClass>> cells;
  std::vector<LayerContours> contours;
  std::vector<std::vector<HatchSegment>> hatches;
  bool finished = false;
  bool aborted = false;
};

struct Run {
  LayerCollector sink;
  SliceSummary summary;
  ExactSliceReport report;
  bool ok = false;
};

inline Run run_fast(const IndexedMesh& mesh, const GridSpec& grid, const SliceOptions& options) {
  Run r;
  LayerSink* sinks[] = {&r.sink};
  auto s = slice_model(mesh, grid, options, sinks);
  EXPECT_TRUE(s.has_value()) << (s ? "" : s.error().to_string());
  if (s) {
    r.summary = *s;
    r.ok = true;
  }
  return r;
}

inline Run run_exact(const IndexedMesh& mesh, const GridSpec& grid, const SliceOptions& options) {
  Run r;
  LayerSink* sinks[] = {&r.sink};
  auto s = slice_model_exact(mesh, grid, options, sinks, {}, &r.report);
  EXPECT_TRUE(s.has_value()) << (s ? "" : s.error().to_string());
  if (s) {
    r.summary = *s;
    r.ok = true;
  }
  return r;
}

/// The exact kernel with a chosen contour method, through run_slice.
inline Run run_exact_with(const IndexedMesh& mesh, const GridSpec& grid,
                          const SliceOptions& options, exact::detail::ContourMethod method) {
  Run r;
  LayerSink* sinks[] = {&r.sink};
  exact::detail::ExactKernel kernel(mesh, grid, options, method);
  auto s = run_slice(mesh, grid, options, kernel, sinks);
  EXPECT_TRUE(s.has_value()) << (s ? "" : s.error().to_string());
  if (s) {
    r.summary = *s;
    r.report = kernel.report();
    r.ok = true;
  }
  return r;
}

// --- models ------------------------------------------------------------------------------------

inline void add_quad(IndexedMesh& m, VertexIndex a, VertexIndex b, VertexIndex c, VertexIndex d) {
  // (a, b, c, d) counter-clockwise seen from outside.
  m.triangles.push_back({a, b, c});
  m.triangles.push_back({a, c, d});
}

/// Welds exactly equal positions (through the project's weld_vertices).
inline IndexedMesh welded(const IndexedMesh& m) {
  TriangleSoup soup;
  for (const auto& t : m.triangles) {
    soup.triangles.push_back({m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]});
  }
  return weld_vertices(soup);
}

/// A square frame: the box [outer_lo, outer_hi] x [z0, z1] with the hole [inner_lo, inner_hi]
/// through it, one closed outward-oriented surface.
inline IndexedMesh frame(std::array<double, 2> outer_lo, std::array<double, 2> outer_hi,
                         std::array<double, 2> inner_lo, std::array<double, 2> inner_hi, double z0,
                         double z1) {
  IndexedMesh m;
  const auto square = [](std::array<double, 2> lo, std::array<double, 2> hi) {
    return std::array<std::array<double, 2>, 4>{
        {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}}};
  };
  const auto o = square(outer_lo, outer_hi);
  const auto in = square(inner_lo, inner_hi);
  // Vertex index: outer bottom 0-3, outer top 4-7, inner bottom 8-11, inner top 12-15.
  for (const auto& p : o) m.vertices.push_back({p[0], p[1], z0});
  for (const auto& p : o) m.vertices.push_back({p[0], p[1], z1});
  for (const auto& p : in) m.vertices.push_back({p[0], p[1], z0});
  for (const auto& p : in) m.vertices.push_back({p[0], p[1], z1});
  for (VertexIndex k = 0; k < 4; ++k) {
    const VertexIndex n = (k + 1) % 4;
    add_quad(m, k, n, 4 + n, 4 + k);            // outer wall, facing out
    add_quad(m, 8 + n, 8 + k, 12 + k, 12 + n);  // inner wall, facing the hole
    add_quad(m, k, 8 + k, 8 + n, n);            // bottom ring, -z
    add_quad(m, 4 + k, 4 + n, 12 + n, 12 + k);  // top ring, +z
  }
  return m;
}

/// A double pyramid: square equator at z = zm with corners (cx +- r, cy) and (cx, cy +- r), apexes
/// at z0 and z1.
inline IndexedMesh octahedron(double cx, double cy, double r, double z0, double zm, double z1) {
  IndexedMesh m;
  m.vertices = {{cx + r, cy, zm}, {cx, cy + r, zm}, {cx - r, cy, zm},
                {cx, cy - r, zm}, {cx, cy, z1},     {cx, cy, z0}};
  for (VertexIndex k = 0; k < 4; ++k) {
    const VertexIndex n = (k + 1) % 4;
    m.triangles.push_back({k, n, 4});
    m.triangles.push_back({n, k, 5});
  }
  return m;
}

/// A closed sphere-like mesh: an icosphere whose vertices are moved by up to `jitter` on every
/// axis (std::mt19937_64 with `seed`), so facets are in general position.
inline IndexedMesh perturbed_sphere(double radius, int subdivisions, double jitter,
                                    std::uint64_t seed, Vec3 centre) {
  IndexedMesh m = weld_vertices(mesh::make_sphere(radius, subdivisions));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(-jitter, jitter);
  for (Vec3& v : m.vertices) {
    v.x += centre.x + d(rng);
    v.y += centre.y + d(rng);
    v.z += centre.z + d(rng);
  }
  return m;
}

/// Nonzero winding of the point (x, y) with respect to closed loops (double arithmetic, for
/// points that are not on a loop).
inline int winding_of_loops(const LayerContours& contours, double x, double y) {
  int w = 0;
  for (const Contour& c : contours.loops) {
    if (!c.is_closed) continue;
    for (std::size_t i = 0, n = c.points.size(); i < n; ++i) {
      const Point2& a = c.points[i];
      const Point2& b = c.points[(i + 1) % n];
      const double cross = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
      if (a.y <= y && b.y > y && cross > 0) ++w;
      if (a.y > y && b.y <= y && cross < 0) --w;
    }
  }
  return w;
}

}  // namespace strata::exact_test
