// Speed of the exact path's stages on a sample model: a layer cut on rationals, and its fill with
// hatches (every crossing rounded from its exact value) and without (cell counts from double
// intervals, the exact crossing only where a cell centre lies inside one). Run:
//   build/release/bench/strata_bench --benchmark_filter=Exact
#include <benchmark/benchmark.h>

#include <vector>

#include "exact/exact_cut_internal.hpp"
#include "exact/exact_fill_internal.hpp"
#include "sample_models.hpp"

namespace {

using namespace strata;

struct MiddleLayer {
  const IndexedMesh& mesh = bench::sample_model("sphere.stl").mesh;
  GridSpec grid = *make_grid(mesh.bounds(), GridOptions{});
  std::vector<FacetIndex> facets = bench::all_facets(mesh);
  std::vector<std::int8_t> signs = exact::detail::facet_normal_x_signs(mesh);
  std::uint32_t k = grid.nz / 2;
};

void BM_ExactCutLayer(benchmark::State& state) {
  const MiddleLayer m;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        exact::detail::cut_layer(m.mesh, m.facets, m.signs, m.k, m.grid.zk(m.k)));
  }
}
BENCHMARK(BM_ExactCutLayer)->Unit(benchmark::kMicrosecond);

/// Arg 1: with hatches; 0: cells only.
void BM_ExactFillLayer(benchmark::State& state) {
  const MiddleLayer m;
  const exact::detail::ExactLayer layer =
      exact::detail::cut_layer(m.mesh, m.facets, m.signs, m.k, m.grid.zk(m.k));
  const bool hatches = state.range(0) != 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        exact::detail::fill_layer(m.mesh, layer, m.grid, FillRule::NonZero, 0.0, hatches));
  }
}
BENCHMARK(BM_ExactFillLayer)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

}  // namespace
