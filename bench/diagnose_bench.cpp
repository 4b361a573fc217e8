// Speed of the diagnosis that strata slice runs before slicing (edges, shells, vertices, stored
// normals, volumes; no self-intersection check), and of its exact volumes: by the floating-point
// filter (with its fall-back on integers) and on integers alone. Run:
//   cmake --preset release && cmake --build --preset release --target strata_bench
//   build/release/bench/strata_bench --benchmark_filter='Diagnose|Volumes'
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cstdint>
#include <string>
#include <vector>

#include "diagnose/exact_geometry.hpp"
#include "sample_models.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"

namespace {

using namespace strata;

void diagnose(benchmark::State& state, const std::string& name) {
  const bench::SampleModel& m = bench::sample_model(name);
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                    static_cast<std::size_t>(state.range(0)));
  diagnose::DiagnoseOptions options;  // as strata slice diagnoses
  options.check_self_intersections = false;
  options.near_vertex_mm = 0.0;
  for (auto _ : state) benchmark::DoNotOptimize(diagnose::diagnose_mesh(m.mesh, m.soup, options));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.mesh.triangles.size()));
}

void BM_DiagnoseSphere(benchmark::State& s) { diagnose(s, "sphere.stl"); }
void BM_DiagnoseRearCase(benchmark::State& s) { diagnose(s, "real/rear_case.stl"); }
BENCHMARK(BM_DiagnoseSphere)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DiagnoseRearCase)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Arg 0: exact_signed_volumes (the filter decides, or the integers); 1: the integers alone.
void BM_SignedVolumesRearCase(benchmark::State& state) {
  const IndexedMesh& mesh = bench::sample_model("real/rear_case.stl").mesh;
  const std::vector<std::uint32_t> group(mesh.triangles.size(), 0);
  const bool integers = state.range(0) == 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(integers ? diagnose::detail::integer_signed_volumes(mesh, group, 1)
                                      : diagnose::detail::exact_signed_volumes(mesh, group, 1));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangles.size()));
}
BENCHMARK(BM_SignedVolumesRearCase)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
