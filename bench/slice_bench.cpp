// Speed of the fast path's stages on the sample models. Run:
//   cmake --preset release && cmake --build --preset release --target strata_bench
//   build/release/bench/strata_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>

#include "export/grey_png_internal.hpp"
#include "mesh/weld_vertices_internal.hpp"
#include "sample_models.hpp"
#include "strata/fill/scanline_fill.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/slice/slice_float.hpp"
#include "strata/slicer/slice_model.hpp"
#include "strata/voxel/boundary_shell.hpp"

namespace {

using namespace strata;

const IndexedMesh& model(const std::string& name) { return bench::sample_model(name).mesh; }

class NullSink final : public LayerSink {
 public:
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult& l) override {
    benchmark::DoNotOptimize(l.cells.data());
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override {}
};

void slice_whole_model(benchmark::State& state, const std::string& name, ShellMode mode) {
  const IndexedMesh& mesh = model(name);
  SliceOptions options;
  options.shell_mode = mode;
  options.threads = static_cast<int>(state.range(0));
  const GridSpec grid = *make_grid(mesh.bounds(), options.grid);
  NullSink sink;
  LayerSink* sinks[] = {&sink};
  for (auto _ : state) {
    auto summary = slice_model(mesh, grid, options, sinks);
    benchmark::DoNotOptimize(summary);
  }
  state.counters["cells/s"] = benchmark::Counter(static_cast<double>(grid.cell_count()),
                                                 benchmark::Counter::kIsIterationInvariantRate);
}

void BM_SliceRingDistanceShell(benchmark::State& s) {
  slice_whole_model(s, "ring.stl", ShellMode::Distance);
}
void BM_SliceRingLayersShell(benchmark::State& s) {
  slice_whole_model(s, "ring.stl", ShellMode::Layers);
}
void BM_SliceSphereDistanceShell(benchmark::State& s) {
  slice_whole_model(s, "sphere.stl", ShellMode::Distance);
}
void BM_SliceRearCaseDistanceShell(benchmark::State& s) {
  slice_whole_model(s, "real/rear_case.stl", ShellMode::Distance);
}
BENCHMARK(BM_SliceRingDistanceShell)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SliceRingLayersShell)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SliceSphereDistanceShell)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_SliceRearCaseDistanceShell)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SliceLayerSegments(benchmark::State& state) {
  const IndexedMesh& mesh = model("real/rear_case.stl");
  const GridSpec grid = *make_grid(mesh.bounds(), GridOptions{});
  const std::vector<FacetIndex> all = bench::all_facets(mesh);
  std::uint32_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(slice_layer(mesh, all, grid, k));
    k = (k + 1) % grid.nz;
  }
}
BENCHMARK(BM_SliceLayerSegments)->Unit(benchmark::kMicrosecond);

/// The distance shell on its own (about half of a `--format cells` run): building its marker
/// (the facets grouped into patches), and classifying one layer from the solid cells of it and
/// of the layers beside it, at the middle of the sphere (the default 0.1 mm grid, 0.5 mm shell).
void BM_ShellSetupSphere(benchmark::State& state) {
  const IndexedMesh& mesh = model("sphere.stl");
  const GridSpec grid = *make_grid(mesh.bounds(), GridOptions{});
  for (auto _ : state) {
    const BoundaryShell shell(mesh, grid, ShellMode::Distance, 0.5);
    benchmark::DoNotOptimize(&shell);
  }
}
BENCHMARK(BM_ShellSetupSphere)->Unit(benchmark::kMillisecond);

/// The solid layers k - reach .. k + reach of a model, and a lookup of them for the shell.
struct SolidLayers {
  std::int64_t first = 0;
  std::vector<SolidRows> layers;
  SolidLayerLookup lookup() const {
    return [this](std::int64_t q) -> const SolidRows* {
      const std::int64_t at = q - first;
      return at >= 0 && at < static_cast<std::int64_t>(layers.size())
                 ? &layers[static_cast<std::size_t>(at)]
                 : nullptr;
    };
  }
};
SolidLayers solid_layers(const IndexedMesh& mesh, const GridSpec& grid, std::uint32_t k,
                         std::uint32_t reach) {
  const std::vector<FacetIndex> all = bench::all_facets(mesh);
  SolidLayers out;
  out.first = static_cast<std::int64_t>(k) - reach;
  for (std::uint32_t q = k - reach; q <= k + reach; ++q) {
    out.layers.push_back(scanline_fill(mesh, slice_layer(mesh, all, grid, q), grid,
                                       FillRule::NonZero, 0.0,
                                       FillWanted{.cells = true, .hatches = false})
                             .solid);
  }
  return out;
}

/// One layer of the sphere's shell, the argument its thickness in tenths of a millimetre: 0.5 mm
/// (5 cells, the default) and 3 mm (30 cells; in the distance mode the boxes are then taken a
/// tile of 64 x 64 cells at a time, in the layers mode as many rings as cells).
void shell_classify_layer_sphere(benchmark::State& state, ShellMode mode) {
  const IndexedMesh& mesh = model("sphere.stl");
  const GridSpec grid = *make_grid(mesh.bounds(), GridOptions{});
  const std::uint32_t k = grid.nz / 2;
  const double thickness = static_cast<double>(state.range(0)) / 10.0;
  const SolidLayers solid =
      solid_layers(mesh, grid, k, BoundaryShell::reach_layers(grid, mode, thickness));
  const SolidLayerLookup lookup = solid.lookup();
  const BoundaryShell shell(mesh, grid, mode, thickness);
  std::vector<CellClass> cells(grid.cells_per_layer());
  for (auto _ : state) {
    shell.classify(k, lookup, cells);
    benchmark::DoNotOptimize(cells.data());
  }
  state.counters["cells"] = static_cast<double>(cells.size());
  state.counters["boundary"] =
      static_cast<double>(std::count(cells.begin(), cells.end(), CellClass::Boundary));
}
void BM_ShellClassifyLayerSphere(benchmark::State& state) {
  shell_classify_layer_sphere(state, ShellMode::Distance);
}
BENCHMARK(BM_ShellClassifyLayerSphere)->Arg(5)->Arg(30)->Unit(benchmark::kMicrosecond);
void BM_ShellRingsLayerSphere(benchmark::State& state) {
  shell_classify_layer_sphere(state, ShellMode::Layers);
}
BENCHMARK(BM_ShellRingsLayerSphere)->Arg(5)->Arg(30)->Unit(benchmark::kMicrosecond);

/// The layers each facet crosses: two exact plane counts a facet from a first guess (count_prefix).
void BM_FacetLayerRanges(benchmark::State& state) {
  const IndexedMesh& mesh = model("real/rear_case.stl");
  const GridSpec grid = *make_grid(mesh.bounds(), GridOptions{});
  for (auto _ : state) benchmark::DoNotOptimize(facet_layer_ranges(mesh, grid));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangles.size()));
}
BENCHMARK(BM_FacetLayerRanges)->Unit(benchmark::kMicrosecond);

/// The weld of a sphere of 327,680 facets in Arg blocks side by side (weld_vertices takes one a
/// thread above 131,072 facets): the same mesh either way.
void BM_WeldSphereInBlocks(benchmark::State& state) {
  static const TriangleSoup soup = mesh::make_sphere(50.0, 7);
  const auto blocks = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(detail::weld_vertices_in_blocks(soup, blocks));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(soup.triangles.size()));
}
BENCHMARK(BM_WeldSphereInBlocks)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReadStlBinary(benchmark::State& state) {
  const std::string path = std::string(STRATA_DATA_DIR) + "/real/rear_case.stl";
  for (auto _ : state) benchmark::DoNotOptimize(io::read_mesh(path));
}
BENCHMARK(BM_ReadStlBinary)->Unit(benchmark::kMillisecond);

/// A layer as the PNG stack sees it: a ring 800 pixels across on 1100 x 1100, interior grey
/// with a boundary rim five pixels wide, each row behind its filter byte.
std::vector<std::uint8_t> ring_layer_rows() {
  constexpr int kSide = 1100;
  std::vector<std::uint8_t> rows(std::size_t{kSide} * (kSide + 1), 0);
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      const double from_rim = std::fabs(std::hypot(i - 550.0, j - 550.0) - 400.0);
      rows[std::size_t(j) * (kSide + 1) + 1 + i] =
          from_rim < 150 ? (from_rim > 145 ? 255 : 128) : 0;
    }
  }
  return rows;
}

void BM_DeflatePngLayer(benchmark::State& state) {
  const std::vector<std::uint8_t> rows = ring_layer_rows();
  for (auto _ : state) {
    std::string out;
    io::detail::RowDeflater deflater(1101, out);
    for (std::size_t r = 0; r < 1100; ++r) deflater.add_row(rows.data() + r * 1101);
    deflater.finish();
    benchmark::DoNotOptimize(out.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * rows.size()));
}
BENCHMARK(BM_DeflatePngLayer)->Unit(benchmark::kMicrosecond);

/// The same rows through zlib at level 3, what the PNG stack used before its own deflater.
void BM_ZlibLevel3PngLayer(benchmark::State& state) {
  const std::vector<std::uint8_t> rows = ring_layer_rows();
  std::vector<Bytef> out(compressBound(static_cast<uLong>(rows.size())));
  for (auto _ : state) {
    uLongf size = out.size();
    compress2(out.data(), &size, rows.data(), static_cast<uLong>(rows.size()), 3);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * rows.size()));
}
BENCHMARK(BM_ZlibLevel3PngLayer)->Unit(benchmark::kMicrosecond);

}  // namespace
