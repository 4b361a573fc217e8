// The validation report as JSON: keys, verdicts, codes and the numbers that are written as null.
#include "strata/validate/validation_json.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace strata::validate {
namespace {

using nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ValidationReport agreeing_json_report() {
  ValidationReport r;
  r.grid = GridSpec{-1, 0, 0.5, 0.5, 0.5, 0.25, 4, 3, 2};
  r.fast.ran = true;
  r.exact.ran = true;
  r.fast.seconds = 0.5;
  r.exact.seconds = 1.0;
  r.layers_compared = 2;
  r.cells_compared = 24;
  r.model.mesh_volume_mm3 = 8.0;
  r.fast.cell_volume_mm3 = 10.0;
  r.fast.contour_volume_mm3 = 6.0;
  r.exact.contour_volume_mm3 = 8.0;
  return r;
}

json parsed(const ValidationReport& r) {
  const std::string text = validation_json(r);
  EXPECT_EQ(text.back(), '\n');
  return json::parse(text);
}

TEST(ValidationJson, GivesTheGridAndTheOptions) {
  ValidationReport r = agreeing_json_report();
  r.options.fill_rule = FillRule::EvenOdd;
  r.options.shell_mode = ShellMode::Layers;
  r.options.shell_mm = 0.75;
  r.options.scan_offset_mm = 0.125;
  const json j = parsed(r);
  EXPECT_EQ(j.at("grid"), json::parse(R"({"nx": 4, "ny": 3, "nz": 2, "origin_mm": [-1, 0, 0.5],
                                          "cell_mm": [0.5, 0.5, 0.25], "cells": 24})"));
  EXPECT_EQ(j.at("options"), json::parse(R"({"fill_rule": "evenodd", "shell_mm": 0.75,
                                             "shell_mode": "layers", "scan_offset_mm": 0.125})"));
}

TEST(ValidationJson, GivesTheVerdict) {
  ValidationReport r = agreeing_json_report();
  EXPECT_EQ(parsed(r).at("verdict"), "agree");
  r.cells_differing = 3;
  EXPECT_EQ(parsed(r).at("verdict"), "cells-differ");
  r.exact_error = Error{ErrorCode::BadInput, "refused", ""};
  EXPECT_EQ(parsed(r).at("verdict"), "exact-path-failed");
}

TEST(ValidationJson, NamesTheExactPathsErrorByItsCode) {
  ValidationReport r = agreeing_json_report();
  EXPECT_TRUE(parsed(r).at("exact").at("error").is_null());
  r.exact_error = Error{ErrorCode::BadInput, "non-finite coordinate", "box.stl: facet 3"};
  EXPECT_EQ(parsed(r).at("exact").at("error"), json::parse(R"({"code": "bad-input",
                            "message": "box.stl: facet 3: non-finite coordinate"})"));
  r.exact_error->code = ErrorCode::Usage;
  EXPECT_EQ(parsed(r).at("exact").at("error").at("code"), "usage");
  r.exact_error->code = ErrorCode::Internal;
  EXPECT_EQ(parsed(r).at("exact").at("error").at("code"), "internal");
}

TEST(ValidationJson, GivesBothPathsAndTheSoup) {
  ValidationReport r = agreeing_json_report();
  r.fast.class_counts = {10, 8, 6};
  r.fast.open_chains = 2;
  r.fast.solid_bounds.add({0, 0, 0});
  r.fast.solid_bounds.add({1, 2, 3});
  r.exact_soup.input_points = 8;
  r.exact_soup.input_polygons = 12;
  r.exact_soup.polygon_mesh = true;
  r.exact_soup.halfedge_layers = 2;
  const json j = parsed(r);
  EXPECT_EQ(j.at("fast"), json::parse(R"({"ran": true, "seconds": 0.5,
      "cells": {"empty": 10, "interior": 8, "boundary": 6}, "cell_volume_mm3": 10.0,
      "contour_volume_mm3": 6.0, "open_chains": 2,
      "solid_bounds_mm": {"min": [0, 0, 0], "max": [1, 2, 3]}})"));
  EXPECT_TRUE(j.at("exact").at("solid_bounds_mm").is_null()) << "no solid cell";
  EXPECT_EQ(j.at("exact").at("soup"), json::parse(R"({"input_points": 8, "input_polygons": 12,
      "points_merged": 0, "polygons_removed": 0, "points_duplicated": 0, "polygons_reversed": 0,
      "non_manifold_edges": 0, "polygon_mesh": true, "halfedge_layers": 2,
      "arrangement_layers": 0, "empty_layers": 0})"));
  EXPECT_EQ(j.at("time_ratio_exact_over_fast"), 2.0);
}

TEST(ValidationJson, WritesNoTimeRatioWhenAPathDidNotRun) {
  ValidationReport r = agreeing_json_report();
  r.exact.ran = false;
  const json j = parsed(r);
  EXPECT_EQ(j.at("time_ratio_exact_over_fast"), 0.0);
  EXPECT_TRUE(j.at("model").at("exact_contour_volume_error").is_null());
}

TEST(ValidationJson, ListsTheDifferingCellsWithTheirClassesAndReasons) {
  ValidationReport r = agreeing_json_report();
  r.cells_differing = 5;
  r.differing_by_reason = {1, 1, 1, 1, 1};
  r.differences = {{0, 1, 1, CellClass::Empty, CellClass::Interior, DifferenceReason::ScanOffset},
                   {2, 0, 0, CellClass::Boundary, CellClass::Interior, DifferenceReason::Shell},
                   {3, 2, 1, CellClass::Interior, CellClass::Empty, DifferenceReason::FillRule}};
  const json cells = parsed(r).at("cells");
  EXPECT_EQ(cells.at("layers_compared"), 2);
  EXPECT_EQ(cells.at("compared"), 24);
  EXPECT_EQ(cells.at("differing"), 5);
  EXPECT_EQ(cells.at("differing_by_reason"),
            json::parse(R"({"scan-offset": 1, "shell": 1, "near-degenerate": 1, "fill-rule": 1,
                            "unexplained": 1})"));
  EXPECT_EQ(cells.at("differences"), json::parse(R"([
      {"i": 0, "j": 1, "k": 1, "fast": "00", "exact": "01", "reason": "scan-offset"},
      {"i": 2, "j": 0, "k": 0, "fast": "11", "exact": "01", "reason": "shell"},
      {"i": 3, "j": 2, "k": 1, "fast": "01", "exact": "00", "reason": "fill-rule"}])"));
  EXPECT_EQ(cells.at("differences_listed"), 3);
}

TEST(ValidationJson, WritesTheContoursOfEveryLayerWithInfiniteDistancesAsNull) {
  ValidationReport r = agreeing_json_report();
  r.max_symmetric_difference_mm2 = 0.25;
  r.total_symmetric_difference_mm2 = 0.5;
  r.max_hausdorff_mm = 0.125;
  r.max_hausdorff_all_mm = kInf;
  r.layers_with_open_chains = 1;
  r.layers_with_different_counts = 1;
  r.layers_arrangement = 1;
  r.layers_area_only = 0;
  r.layers_overlay_skipped = 1;
  LayerComparison l;
  l.layer = 1;
  l.z_mm = 0.875;
  l.fast = {1, 2, 0, 12, 3.5};
  l.exact = {1, 1, 1, 10, 3.25};
  l.symmetric_difference_mm2 = 0.25;
  l.area_method = AreaMethod::NotCompared;
  l.hausdorff_mm = kInf;
  l.cells_differing = 7;
  r.layers.push_back(l);
  const json contours = parsed(r).at("contours");
  EXPECT_EQ(contours.at("max_symmetric_difference_mm2"), 0.25);
  EXPECT_EQ(contours.at("total_symmetric_difference_mm2"), 0.5);
  EXPECT_EQ(contours.at("max_hausdorff_mm"), 0.125);
  EXPECT_TRUE(contours.at("max_hausdorff_all_layers_mm").is_null());
  EXPECT_EQ(contours.at("layers_with_open_chains"), 1);
  EXPECT_EQ(contours.at("layers_overlay_skipped"), 1);
  EXPECT_EQ(contours.at("layers"), json::parse(R"([{"k": 1, "z_mm": 0.875,
      "fast": {"outer_loops": 1, "holes": 2, "open_chains": 0, "points": 12, "area_mm2": 3.5},
      "exact": {"outer_loops": 1, "holes": 1, "open_chains": 1, "points": 10, "area_mm2": 3.25},
      "symmetric_difference_mm2": 0.25, "area_method": "not-compared", "hausdorff_mm": null,
      "cells_differing": 7}])"));
}

TEST(ValidationJson, ListsTheCellsTheScanOffsetChanges) {
  ValidationReport r = agreeing_json_report();
  r.scan_offset.measured = true;
  r.scan_offset.offset_mm = 0.001;
  r.scan_offset.cells_changed = 4;
  r.scan_offset.cells = {{1, 2, 0, CellClass::Interior, CellClass::Boundary}};
  EXPECT_EQ(parsed(r).at("scan_offset"), json::parse(R"({"measured": true, "offset_mm": 0.001,
      "cells_changed": 4,
      "cells": [{"i": 1, "j": 2, "k": 0, "with_offset": "01", "without_offset": "11"}]})"));
}

TEST(ValidationJson, GivesTheModelsFiguresAndVolumeErrors) {
  ValidationReport r = agreeing_json_report();
  r.model.surface_area_mm2 = 24.0;
  r.model.mesh_bounds.add({0, 0, 0});
  r.model.mesh_bounds.add({2, 2, 2});
  r.model.surface_to_boundary_mm = 0.5;
  r.model.surface_samples = 100;
  r.model.asked_shell_mm = 0.5;
  r.model.shell = {6, 3, 0.5, 0.625, 0.75};
  EXPECT_EQ(parsed(r).at("model"), json::parse(R"({"mesh_volume_mm3": 8.0,
      "surface_area_mm2": 24.0, "mesh_bounds_mm": {"min": [0, 0, 0], "max": [2, 2, 2]},
      "fast_cell_volume_error": 0.25, "fast_contour_volume_error": -0.25,
      "exact_contour_volume_error": 0.0, "surface_to_boundary_hausdorff_mm": 0.5,
      "surface_samples": 100,
      "shell_thickness": {"asked_mm": 0.5, "cells": 6, "measured": 3, "min_mm": 0.5,
                          "mean_mm": 0.625, "max_mm": 0.75}})"));
}

TEST(ValidationJson, WritesWhatWasNotMeasuredAsNull) {
  ValidationReport r = agreeing_json_report();
  r.model.mesh_volume_mm3 = 0.0;  // no volume to compare with
  r.model.shell.cells = 4;        // none measured
  const json model = parsed(r).at("model");
  EXPECT_TRUE(model.at("mesh_bounds_mm").is_null());
  EXPECT_TRUE(model.at("fast_cell_volume_error").is_null());
  EXPECT_TRUE(model.at("fast_contour_volume_error").is_null());
  EXPECT_TRUE(model.at("exact_contour_volume_error").is_null());
  EXPECT_TRUE(model.at("surface_to_boundary_hausdorff_mm").is_null());
  EXPECT_EQ(model.at("shell_thickness").at("cells"), 4);
  EXPECT_TRUE(model.at("shell_thickness").at("min_mm").is_null());
  EXPECT_TRUE(model.at("shell_thickness").at("mean_mm").is_null());
  EXPECT_TRUE(model.at("shell_thickness").at("max_mm").is_null());
}

TEST(ValidationJson, GivesTheReferenceSlicerWithItsLayers) {
  ValidationReport r = agreeing_json_report();
  ReferenceSlicerFigures& f = r.reference;
  f.ran = true;
  f.skipped = ReferenceSkip::None;
  f.facets = 12;
  f.max_facets = 200;
  f.layers_compared = 1;
  f.max_hausdorff_fast_mm = kNaN;
  f.build_seconds = 0.25;
  f.slice_seconds = 0.5;
  ReferenceLayerComparison l;
  l.layer = 1;
  l.z_mm = 0.875;
  l.closed_polylines = 1;
  l.open_polylines = 2;
  l.isolated_points = 3;
  l.open_after_joining = 1;
  l.vertices_on_plane = 4;
  l.facet_on_plane = true;
  l.hausdorff_exact_mm = 0.0;
  l.hausdorff_fast_mm = kNaN;  // the fast path did not deliver the layer
  l.symmetric_difference_exact_mm2 = 0.0;
  l.symmetric_difference_fast_mm2 = kNaN;
  l.area_method_exact = AreaMethod::Identical;
  l.area_method_fast = AreaMethod::NotCompared;
  l.differs_from_exact = true;
  f.layers.push_back(l);
  const json j = parsed(r).at("reference_slicer");
  EXPECT_TRUE(j.at("ran").get<bool>());
  EXPECT_EQ(j.at("skipped"), "none");
  EXPECT_TRUE(j.at("reason").is_null());
  EXPECT_EQ(j.at("facets"), 12);
  EXPECT_EQ(j.at("max_facets"), 200);
  EXPECT_TRUE(j.at("max_hausdorff_fast_mm").is_null());
  EXPECT_EQ(j.at("max_hausdorff_exact_mm"), 0.0);
  EXPECT_EQ(j.at("seconds"), 0.75);
  EXPECT_EQ(j.at("layers"), json::parse(R"([{"k": 1, "z_mm": 0.875, "closed_polylines": 1,
      "open_polylines": 2, "isolated_points": 3, "open_after_joining": 1,
      "vertices_on_plane": 4, "facet_on_plane": true, "hausdorff_exact_mm": 0.0,
      "hausdorff_fast_mm": null, "symmetric_difference_exact_mm2": 0.0,
      "symmetric_difference_fast_mm2": null, "area_method_exact": "identical",
      "area_method_fast": "not-compared", "differs_from_exact": true,
      "differs_from_fast": false}])"));
}

TEST(ValidationJson, SaysWhyTheReferenceSlicerDidNotRun) {
  ValidationReport r = agreeing_json_report();
  r.reference.skipped = ReferenceSkip::TooManyFacets;
  r.reference.reason = "300 facets, over the cap of 200";
  const json j = parsed(r).at("reference_slicer");
  EXPECT_FALSE(j.at("ran").get<bool>());
  EXPECT_EQ(j.at("skipped"), "too-many-facets");
  EXPECT_EQ(j.at("reason"), "300 facets, over the cap of 200");
  EXPECT_TRUE(j.at("layers").empty());
}

TEST(ValidationJson, GivesTheDiagnosticsWithTheirSeverity) {
  ValidationReport r = agreeing_json_report();
  r.diagnostics.push_back({Severity::Warning, "stl.trailing_bytes", "box.stl: 3 trailing bytes"});
  r.diagnostics.push_back({Severity::Info, "validate.boundary_cells", "not measured"});
  EXPECT_EQ(parsed(r).at("diagnostics"), json::parse(R"([
      {"severity": "warning", "code": "stl.trailing_bytes",
       "message": "box.stl: 3 trailing bytes"},
      {"severity": "info", "code": "validate.boundary_cells", "message": "not measured"}])"));
}

}  // namespace
}  // namespace strata::validate
