#include "strata/validate/validate_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "strata/validate/validation_json.hpp"
#include "strata/validate/validation_text.hpp"
#include "support/mesh_builders.hpp"
#include "support/validated_model.hpp"

namespace strata::validate {
namespace {

using test::validated_model;
using test::welded_box;

SliceOptions unit_cells(FillRule rule = FillRule::NonZero) {
  SliceOptions options;
  options.grid.dx_mm = options.grid.dy_mm = options.grid.dz_mm = 1.0;
  options.grid.origin = Vec3{0, 0, 0};
  options.fill_rule = rule;
  options.shell_mm = 1.0;
  options.threads = 1;
  return options;
}

TEST(ValidateModel, FindsNoDifferenceOnABox) {
  // Faces on a cell-centre plane (x = 6.5), a scanline (y = 4.5) and a layer plane (z = 3.5).
  const ValidationReport r = validated_model(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), unit_cells());
  EXPECT_FALSE(r.exact_error.has_value()) << r.exact_error->to_string();
  EXPECT_TRUE(r.cells_agree());
  EXPECT_EQ(r.cells_differing, 0u);
  EXPECT_EQ(r.cells_compared, r.grid.cell_count());
  EXPECT_EQ(r.layers_compared, r.grid.nz);
  EXPECT_EQ(r.fast.class_counts, r.exact.class_counts);
  EXPECT_EQ(r.max_symmetric_difference_mm2, 0.0);
  EXPECT_EQ(r.max_hausdorff_mm, 0.0);
}

TEST(ValidateModel, MeasuresTheBox) {
  const ValidationReport r = validated_model(welded_box({0, 0, 0}, {6, 4, 3}), unit_cells());
  EXPECT_DOUBLE_EQ(r.model.mesh_volume_mm3, 72.0);
  EXPECT_DOUBLE_EQ(r.fast.cell_volume_mm3, 72.0);
  EXPECT_DOUBLE_EQ(r.exact.cell_volume_mm3, 72.0);
  EXPECT_DOUBLE_EQ(r.fast.contour_volume_mm3, 72.0);
  EXPECT_DOUBLE_EQ(r.exact.contour_volume_mm3, 72.0);
  EXPECT_DOUBLE_EQ(r.model.shell.min_mm, 1.5);
  EXPECT_GE(r.model.shell.min_mm, r.model.asked_shell_mm);
  EXPECT_TRUE(r.fast.ran);
  EXPECT_TRUE(r.exact.ran);
  EXPECT_GT(r.fast.seconds, 0.0);
  EXPECT_GT(r.exact.seconds, 0.0);
}

TEST(ValidateModel, AgreesOnOverlappingShellsUnderBothRules) {
  IndexedMesh m = welded_box({0, 0, 0}, {4, 4, 4});
  const IndexedMesh b = welded_box({2.5, 1.5, 0.5}, {6.5, 5.5, 3.5});
  const auto offset = static_cast<VertexIndex>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    const ValidationReport r = validated_model(m, unit_cells(rule));
    EXPECT_TRUE(r.cells_agree()) << to_string(rule) << ": " << validation_text(r);
    EXPECT_EQ(r.max_symmetric_difference_mm2, 0.0) << to_string(rule);
  }
}

TEST(ValidateModel, ListsTheCellsTheScanOffsetChanges) {
  // The face y = 4.5 lies on the scanline of row 4: with offset 0 the row is solid (a point on
  // the line counts as above it); shifted 0.1 um up, the scanline misses the box. That empties
  // row 4 (6 x 3 cells) and turns the 4 interior cells of row 3 into shell cells.
  SliceOptions options = unit_cells();
  options.scan_offset_mm = 0.0001;
  const ValidationReport r = validated_model(welded_box({0, 0, 0}, {6, 4.5, 3}), options);
  ASSERT_TRUE(r.scan_offset.measured);
  EXPECT_EQ(r.scan_offset.cells_changed, 22u);
  ASSERT_EQ(r.scan_offset.cells.size(), 22u);
  std::size_t emptied = 0;
  std::size_t to_shell = 0;
  for (const OffsetChange& c : r.scan_offset.cells) {
    if (c.j == 4 && c.with_offset == CellClass::Empty) ++emptied;
    if (c.j == 3 && c.with_offset == CellClass::Boundary &&
        c.without_offset == CellClass::Interior) {
      ++to_shell;
    }
  }
  EXPECT_EQ(emptied, 18u);
  EXPECT_EQ(to_shell, 4u);
  EXPECT_TRUE(r.cells_agree());
}

TEST(ValidateModel, RefusesTheWindingRule) {
  const IndexedMesh m = welded_box({0, 0, 0}, {2, 2, 2});
  const GridSpec grid = make_grid(m.bounds(), unit_cells().grid).value();
  SliceOptions options = unit_cells();
  options.fill_rule = FillRule::Winding;
  const auto r = validate_model(m, grid, options);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::Usage);
}

TEST(ValidateModel, StopsWithAnInternalErrorWhenTheComparisonFails) {
  // The progress callback runs inside the comparison of each layer pair; its failure stops both
  // paths, and the report is replaced by the error.
  const IndexedMesh mesh = welded_box({0, 0, 0}, {6, 4, 3});
  const GridSpec grid = make_grid(mesh.bounds(), unit_cells().grid).value();
  ValidateOptions validate_options;
  validate_options.window_layers = 1;
  std::uint32_t calls = 0;
  validate_options.progress = [&](std::uint32_t, std::uint32_t) {
    ++calls;
    throw std::runtime_error("progress display closed");
  };
  const auto report = validate_model(mesh, grid, unit_cells(), validate_options);
  ASSERT_FALSE(report.has_value());
  EXPECT_EQ(report.error().code, ErrorCode::Internal);
  EXPECT_EQ(report.error().message, "comparing layers: progress display closed");
  EXPECT_EQ(calls, 1u);
}

TEST(ValidationJson, SaysTheCellsAgree) {
  const ValidationReport r = validated_model(welded_box({0, 0, 0}, {3, 2, 2}), unit_cells());
  const nlohmann::json j = nlohmann::json::parse(validation_json(r));
  EXPECT_EQ(j.at("verdict"), "agree");
  EXPECT_EQ(j.at("cells").at("differing"), 0);
  EXPECT_EQ(j.at("cells").at("compared"), r.grid.cell_count());
  EXPECT_EQ(j.at("contours").at("layers").size(), r.grid.nz);
  EXPECT_DOUBLE_EQ(j.at("model").at("mesh_volume_mm3").get<double>(), 12.0);
}

TEST(ValidationText, SaysTheCellsAgree) {
  const ValidationReport r = validated_model(welded_box({0, 0, 0}, {3, 2, 2}), unit_cells());
  const std::string text = validation_text(r);
  EXPECT_NE(text.find("AGREE"), std::string::npos) << text;
  EXPECT_NE(text.find("exact/fast"), std::string::npos) << text;
}

}  // namespace
}  // namespace strata::validate
