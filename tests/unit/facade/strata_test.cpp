#include "strata/strata.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>

#include "strata/io/write_stl.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "support/temp_dir.hpp"

namespace strata {
namespace {

// The example at the top of strata/strata.hpp, word for word.
Result<std::uint64_t> solid_cells(const std::filesystem::path& model,
                                  const std::filesystem::path& cells_file) {
  // Read (STL, OBJ, OFF, PLY, any of them gzip-compressed) and weld exactly.
  auto soup = strata::io::read_mesh(model);
  if (!soup) return soup.error();
  const strata::IndexedMesh mesh = strata::weld_vertices(*soup);

  // Check: open edges, orientation, self-intersections; the verdict says whether it slices.
  const strata::diagnose::MeshReport report = strata::diagnose::diagnose_mesh(mesh, *soup);
  if (report.verdict == strata::diagnose::Verdict::NeedsRepair) {
    // report.verdict_reason says why; strata::repair::repair_mesh() can fix many meshes.
  }

  // Slice: 0.1 mm cells and layers, a 0.5 mm boundary shell, the nonzero fill rule.
  strata::SliceOptions options;
  options.grid = strata::GridOptions{0.1, 0.1, 0.1, std::nullopt};
  options.shell_mm = 0.5;
  auto grid = strata::make_grid(mesh.bounds(), options.grid);
  if (!grid) return grid.error();
  const auto writer = strata::io::make_cells_writer(cells_file);
  strata::LayerSink* sinks[] = {writer.get()};
  auto summary = strata::slice_model(mesh, *grid, options, sinks);
  if (!summary) return summary.error();  // every sink was aborted: no partial file

  // Read back: every cell is Empty, Interior or Boundary.
  auto cells = strata::io::read_cells(cells_file);
  if (!cells) return cells.error();
  std::uint64_t solid = 0;
  for (const strata::CellClass c : cells->cells) solid += c != strata::CellClass::Empty;
  return solid;  // == summary->class_counts[1] + summary->class_counts[2]
}

TEST(Facade, TheExampleSlicesABoxAndReadsItsCellsBack) {
  test::TempDir dir("facade");
  const auto written = io::write_stl(dir / "box.stl", mesh::make_box({0, 0, 0}, {1, 1, 1}));
  ASSERT_TRUE(written.has_value()) << written.error().to_string();
  const auto solid = solid_cells(dir / "box.stl", dir / "box.cells");
  ASSERT_TRUE(solid.has_value()) << solid.error().to_string();
  EXPECT_EQ(*solid, 10u * 10u * 10u);
}

TEST(Facade, TheExampleSaysWhatIsWrongWithAMissingModel) {
  test::TempDir dir("facade");
  const auto solid = solid_cells(dir / "missing.stl", dir / "missing.cells");
  ASSERT_FALSE(solid.has_value());
  EXPECT_EQ(solid.error().code, ErrorCode::BadInput);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing.cells"));
}

}  // namespace
}  // namespace strata
