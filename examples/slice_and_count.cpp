// Reads a mesh, checks it, slices it into a cells file with strata's library and reads the file
// back, printing the counts of each step and checking that the file holds what the slice made.
//
// Usage: slice_and_count MODEL CELLS_FILE [CELL_MM]
// Exit code 0 when the counts agree, 1 on an error or a disagreement.

#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "strata/strata.hpp"

namespace {

using ClassCounts = std::array<std::uint64_t, 3>;  // empty, interior, boundary

int fail(const strata::Error& error) {
  std::fprintf(stderr, "slice_and_count: %s\n", error.to_string().c_str());
  return 1;
}

void print_counts(const char* what, const ClassCounts& counts) {
  std::printf("%s: %llu empty, %llu interior, %llu boundary\n", what,
              static_cast<unsigned long long>(counts[0]),
              static_cast<unsigned long long>(counts[1]),
              static_cast<unsigned long long>(counts[2]));
}

ClassCounts count_classes(const strata::io::CellsFile& file) {
  ClassCounts counts{};
  for (const strata::CellClass c : file.cells) {
    counts[c == strata::CellClass::Empty ? 0 : c == strata::CellClass::Interior ? 1 : 2] += 1;
  }
  return counts;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fputs("usage: slice_and_count MODEL CELLS_FILE [CELL_MM]\n", stderr);
    return 1;
  }
  const std::filesystem::path model = argv[1];
  const std::filesystem::path cells_file = argv[2];
  double cell_mm = strata::kDefaultCellSizeMm;
  if (argc == 4) {
    const std::string_view text = argv[3];
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), cell_mm);
    if (ec != std::errc{} || end != text.data() + text.size() || !(cell_mm > 0)) {
      std::fprintf(stderr, "slice_and_count: CELL_MM: '%s' is not a positive length\n", argv[3]);
      return 1;
    }
  }

  // Read and weld exactly, then check the mesh.
  auto soup = strata::io::read_mesh(model);
  if (!soup) return fail(soup.error());
  const strata::IndexedMesh mesh = strata::weld_vertices(*soup);
  const strata::diagnose::MeshReport report = strata::diagnose::diagnose_mesh(mesh, *soup);
  std::printf("mesh: %zu facets, %zu vertices, volume %.3f mm3, %s\n", report.num_facets,
              report.num_vertices, report.volume_mm3,
              strata::diagnose::verdict_name(report.verdict));

  // Slice: cubic cells, the default shell, into a binary cells file.
  strata::SliceOptions options;
  options.grid = strata::GridOptions{cell_mm, cell_mm, cell_mm, std::nullopt};
  auto grid = strata::make_grid(mesh.bounds(), options.grid);
  if (!grid) return fail(grid.error());
  const auto writer = strata::io::make_cells_writer(cells_file);
  strata::LayerSink* sinks[] = {writer.get()};
  auto summary = strata::slice_model(mesh, *grid, options, sinks);
  if (!summary) return fail(summary.error());
  std::printf("grid: %u x %u x %u cells of %g mm\n", grid->nx, grid->ny, grid->nz, cell_mm);
  print_counts("sliced", summary->class_counts);
  std::printf("solid volume: %.3f mm3\n", summary->solid_volume_mm3);

  // Read the file back: the same grid and, class by class, the same cells.
  auto cells = strata::io::read_cells(cells_file);
  if (!cells) return fail(cells.error());
  const ClassCounts read_back = count_classes(*cells);
  print_counts("read back", read_back);
  const strata::GridSpec& file_grid = cells->header.grid;
  if (file_grid.nx != grid->nx || file_grid.ny != grid->ny || file_grid.nz != grid->nz) {
    std::fputs("slice_and_count: the file's grid is not the slice's\n", stderr);
    return 1;
  }
  if (read_back != summary->class_counts) {
    std::fputs("slice_and_count: the file's counts are not the slice's\n", stderr);
    return 1;
  }
  if (read_back[1] + read_back[2] == 0) {
    std::fputs("slice_and_count: no solid cell\n", stderr);
    return 1;
  }
  std::puts("ok: the cells file holds the slice");
  return 0;
}
