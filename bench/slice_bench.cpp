// Speed of the fast path's stages on the sample models. Run:
//   cmake --preset release && cmake --build --preset release --target strata_bench
//   build/release/bench/strata_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <map>
#include <numeric>
#include <stdexcept>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slice/slice_float.hpp"
#include "strata/slicer/slice_model.hpp"
#include "strata/voxel/boundary_shell.hpp"

namespace {

using namespace strata;

const IndexedMesh& model(const std::string& name) {
  static std::map<std::string, IndexedMesh> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    auto soup = io::read_mesh(std::string(STRATA_DATA_DIR) + "/" + name);
    if (!soup) throw std::runtime_error(soup.error().to_string());
    it = cache.emplace(name, weld_vertices(*soup)).first;
  }
  return it->second;
}

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
  std::vector<FacetIndex> all(mesh.triangles.size());
  std::iota(all.begin(), all.end(), FacetIndex{0});
  std::uint32_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(slice_layer(mesh, all, grid, k));
    k = (k + 1) % grid.nz;
  }
}
BENCHMARK(BM_SliceLayerSegments)->Unit(benchmark::kMicrosecond);

/// The layers each facet crosses: two exact plane counts a facet from a first guess (count_prefix).
void BM_FacetLayerRanges(benchmark::State& state) {
  const IndexedMesh& mesh = model("real/rear_case.stl");
  const GridSpec grid = *make_grid(mesh.bounds(), GridOptions{});
  for (auto _ : state) benchmark::DoNotOptimize(facet_layer_ranges(mesh, grid));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangles.size()));
}
BENCHMARK(BM_FacetLayerRanges)->Unit(benchmark::kMicrosecond);

void BM_ReadStlBinary(benchmark::State& state) {
  const std::string path = std::string(STRATA_DATA_DIR) + "/real/rear_case.stl";
  for (auto _ : state) benchmark::DoNotOptimize(io::read_mesh(path));
}
BENCHMARK(BM_ReadStlBinary)->Unit(benchmark::kMillisecond);

}  // namespace
