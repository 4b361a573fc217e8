// The numbers' text: a CLI or SVG file is mostly shortest round-trip numbers, and writing them is
// the largest single cost of a contour run. Contour points (16 to 17 significant digits), hatch
// rows on the grid (a few digits) and fmt's own "{}" as the reference the text must equal.
#include <benchmark/benchmark.h>
#include <fmt/compile.h>
#include <fmt/format.h>

#include <random>
#include <vector>

#include "export/shortest_number_internal.hpp"

namespace {

constexpr std::size_t kNumbers = 4096;

/// Coordinates of crossing points on a part 50 mm across: nearly every one needs 16 or 17
/// digits to read back.
std::vector<double> contour_coordinates() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> mm(-25.0, 25.0);
  std::vector<double> out(kNumbers);
  for (double& v : out) v = mm(rng);
  return out;
}

/// Scanline heights of a 0.1 mm grid from -25 mm: short texts, "-24.95" and the like.
std::vector<double> grid_rows() {
  std::vector<double> out(kNumbers);
  for (std::size_t k = 0; k < kNumbers; ++k)
    out[k] = -25.0 + (static_cast<double>(k % 500) + 0.5) * 0.1;
  return out;
}

template <class Write>
void write_all(benchmark::State& state, const std::vector<double>& numbers, const Write& write) {
  std::vector<char> text(numbers.size() * strata::io::detail::kShortestNumberChars);
  std::size_t bytes = 0;
  for (auto _ : state) {
    char* out = text.data();
    for (const double v : numbers) out = write(out, v);
    bytes = static_cast<std::size_t>(out - text.data());
    benchmark::DoNotOptimize(text.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * numbers.size()));
  state.counters["chars_per_number"] =
      static_cast<double>(bytes) / static_cast<double>(numbers.size());
}

char* write_strata(char* out, double v) { return strata::io::detail::write_shortest(out, v); }
char* write_fmt(char* out, double v) { return fmt::format_to(out, FMT_COMPILE("{}"), v); }

void BM_ShortestContourCoordinates(benchmark::State& state) {
  write_all(state, contour_coordinates(), write_strata);
}
void BM_FmtContourCoordinates(benchmark::State& state) {
  write_all(state, contour_coordinates(), write_fmt);
}
void BM_ShortestGridRows(benchmark::State& state) { write_all(state, grid_rows(), write_strata); }
void BM_FmtGridRows(benchmark::State& state) { write_all(state, grid_rows(), write_fmt); }

}  // namespace

BENCHMARK(BM_ShortestContourCoordinates)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FmtContourCoordinates)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ShortestGridRows)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FmtGridRows)->Unit(benchmark::kMicrosecond);
