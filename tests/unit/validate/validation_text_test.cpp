// The validation report for people: every section on hand-made reports with known figures.
#include "strata/validate/validation_text.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace strata::validate {
namespace {

constexpr double kInfiniteDistance = std::numeric_limits<double>::infinity();

/// A 4 x 3 x 2 grid of 1 mm cells from the origin, both paths run, cells agreeing.
ValidationReport agreeing_text_report() {
  ValidationReport r;
  r.grid = GridSpec{0, 0, 0, 1, 1, 1, 4, 3, 2};
  r.options.shell_mm = 0.5;
  r.fast.ran = true;
  r.exact.ran = true;
  r.fast.seconds = 0.5;
  r.exact.seconds = 1.5;
  r.layers_compared = 2;
  r.cells_compared = 24;
  r.reference.skipped = ReferenceSkip::Off;
  return r;
}

/// True when `text` holds `line` as a whole line.
bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

TEST(ValidationText, StartsWithTheGridAndTheRule) {
  ValidationReport r = agreeing_text_report();
  r.options.fill_rule = FillRule::EvenOdd;
  r.options.shell_mode = ShellMode::Layers;
  r.options.scan_offset_mm = 0.25;
  const std::string text = validation_text(r);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "grid      4 x 3 x 2 cells of 1 x 1 x 1 mm, origin (0, 0, 0)");
  EXPECT_TRUE(has_line(text, "rule      fill evenodd, shell 0.5 mm (layers), scan offset 0.25 mm"))
      << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(ValidationText, SaysTheCellsAgreeWithTheRatioOfTheTimes) {
  const std::string text = validation_text(agreeing_text_report());
  EXPECT_TRUE(has_line(text, "cells     AGREE: 24 cells compared in 2 layers, none differs"))
      << text;
  EXPECT_TRUE(has_line(text,
                       "time      fast 0.500 s, exact 1.500 s (exact/fast 3.0), comparison "
                       "0.000 s"))
      << text;
}

TEST(ValidationText, SaysTheCellsWereNotValidatedWhenTheExactPathStopped) {
  ValidationReport r = agreeing_text_report();
  r.exact.ran = false;
  r.exact_error = Error{ErrorCode::BadInput, "non-finite coordinate", "box.stl: facet 3"};
  r.cells_differing = 1234;
  r.cells_compared = 1234567;
  const std::string text = validation_text(r);
  EXPECT_TRUE(has_line(text,
                       "cells     NOT VALIDATED: the exact path stopped: box.stl: facet 3: "
                       "non-finite coordinate"))
      << text;
  EXPECT_TRUE(
      has_line(text, "          before that, 1,234 of 1,234,567 cells differed in 2 layers"))
      << text;
  // Without the exact path, no exact figures, no soup line and no ratio of the times.
  EXPECT_TRUE(has_line(text, "          cells    fast 0 mm3 (n/a)")) << text;
  EXPECT_EQ(text.find("exact     soup"), std::string::npos) << text;
  EXPECT_TRUE(has_line(text, "time      fast 0.500 s, exact 1.500 s, comparison 0.000 s")) << text;
}

TEST(ValidationText, SaysNothingOfEarlierLayersWhenTheExactPathStoppedAtOnce) {
  ValidationReport r = agreeing_text_report();
  r.exact_error = Error{ErrorCode::Internal, "exact path: out of memory", ""};
  r.layers_compared = 0;
  const std::string text = validation_text(r);
  EXPECT_TRUE(
      has_line(text, "cells     NOT VALIDATED: the exact path stopped: exact path: out of memory"))
      << text;
  EXPECT_EQ(text.find("before that"), std::string::npos) << text;
  EXPECT_EQ(text.find("contours  "), std::string::npos) << "no layer compared: " << text;
}

TEST(ValidationText, ListsTwentyDifferingCellsByReasonAndCountsTheRest) {
  ValidationReport r = agreeing_text_report();
  r.cells_differing = 1001;
  r.differing_by_reason[static_cast<std::size_t>(DifferenceReason::Shell)] = 1;
  r.differing_by_reason[static_cast<std::size_t>(DifferenceReason::NearDegenerate)] = 1000;
  r.differences.push_back(
      {1, 2, 0, CellClass::Interior, CellClass::Boundary, DifferenceReason::Shell});
  for (int n = 0; n < 24; ++n) {
    r.differences.push_back(
        {3, 0, 1, CellClass::Empty, CellClass::Boundary, DifferenceReason::NearDegenerate});
  }
  const std::string text = validation_text(r);
  EXPECT_TRUE(
      has_line(text, "cells     DIFFER: 1,001 of 24 cells (shell 1, near-degenerate 1,000)"))
      << text;
  EXPECT_TRUE(
      has_line(text, "          cell (1, 2, 0) at (1.5, 2.5, 0.5) mm: fast 01, exact 11: shell"))
      << text;
  const std::string near =
      "          cell (3, 0, 1) at (3.5, 0.5, 1.5) mm: fast 00, exact 11: near-degenerate\n";
  std::size_t listed = 0;
  for (std::size_t at = text.find(near); at != std::string::npos; at = text.find(near, at + 1)) {
    ++listed;
  }
  EXPECT_EQ(listed, 19u) << "20 cells in all";
  EXPECT_TRUE(has_line(text, "          ... 981 more (the JSON report lists 25)")) << text;
}

TEST(ValidationText, ListsEveryDifferingCellWhenThereAreFewOfThem) {
  ValidationReport r = agreeing_text_report();
  r.cells_differing = 1;
  r.differing_by_reason[static_cast<std::size_t>(DifferenceReason::Unexplained)] = 1;
  r.differences.push_back(
      {0, 0, 0, CellClass::Boundary, CellClass::Empty, DifferenceReason::Unexplained});
  const std::string text = validation_text(r);
  EXPECT_TRUE(has_line(text, "cells     DIFFER: 1 of 24 cells (unexplained 1)")) << text;
  EXPECT_TRUE(has_line(
      text, "          cell (0, 0, 0) at (0.5, 0.5, 0.5) mm: fast 11, exact 00: unexplained"))
      << text;
  EXPECT_EQ(text.find("more (the JSON report"), std::string::npos) << text;
}

TEST(ValidationText, GivesTheContourFiguresAndTheWorstFiveLayersInOrder) {
  ValidationReport r = agreeing_text_report();
  r.layers_compared = 7;
  r.layers_with_different_counts = 1;
  r.max_symmetric_difference_mm2 = 0.25;
  r.total_symmetric_difference_mm2 = 0.5;
  r.max_hausdorff_mm = 0.125;
  for (std::uint32_t k = 0; k < 7; ++k) {
    LayerComparison l;
    l.layer = k;
    l.z_mm = k + 0.5;
    l.fast.outer_loops = l.exact.outer_loops = 1;
    l.area_method = AreaMethod::Arrangement;
    // Layer 0 agrees; then the worst are those with most differing cells, then the farthest.
    if (k > 0) l.hausdorff_mm = 0.001 * k;
    if (k == 3) {
      l.cells_differing = 4;
      l.fast.open_chains = 2;
      l.exact.holes = 1;
      l.symmetric_difference_mm2 = 0.25;
      l.hausdorff_mm = 0.125;
    }
    if (k == 5) {
      l.exact.open_chains = 1;
      l.area_method = AreaMethod::AreaOnly;
      l.hausdorff_mm = kInfiniteDistance;
    }
    r.layers.push_back(l);
  }
  const std::string text = validation_text(r);
  EXPECT_TRUE(has_line(text,
                       "contours  7 layers; loop counts differ in 1; symmetric difference max "
                       "0.25 mm2, total 0.5 mm2; Hausdorff max 0.125 mm"))
      << text;
  const std::string worst[] = {
      "          layer 3 (z 3.5): loops fast 1+0h+2open, exact 1+1h; symmetric difference 0.25 "
      "mm2 (arrangement), Hausdorff 0.125 mm, 4 cells differ\n",
      "          layer 5 (z 5.5): loops fast 1+0h, exact 1+0h+1open; symmetric difference 0 mm2 "
      "(area-only), Hausdorff inf mm, 0 cells differ\n",
      "          layer 6 (z 6.5): loops fast 1+0h, exact 1+0h; symmetric difference 0 mm2 "
      "(arrangement), Hausdorff 0.006 mm, 0 cells differ\n",
      "          layer 4 (z 4.5)",
      "          layer 2 (z 2.5)",
  };
  std::size_t at = 0;
  for (const std::string& line : worst) {
    const std::size_t found = text.find(line, at);
    ASSERT_NE(found, std::string::npos) << line << "\nin\n" << text;
    at = found + line.size();
  }
  EXPECT_EQ(text.find("          layer 1 (z 1.5)"), std::string::npos) << "only five: " << text;
  EXPECT_EQ(text.find("          layer 0 (z"), std::string::npos) << "an agreeing layer: " << text;
  EXPECT_EQ(text.find("open chains (left open"), std::string::npos) << text;
  EXPECT_EQ(text.find("exact overlay"), std::string::npos) << text;
}

TEST(ValidationText, SaysWhichLayersHaveOpenChainsAndHowTheLoopsWereOverlaid) {
  ValidationReport r = agreeing_text_report();
  r.layers_with_open_chains = 2;
  r.max_hausdorff_all_mm = kInfiniteDistance;
  r.layers_arrangement = 1;
  r.layers_area_only = 1;
  r.layers_overlay_skipped = 3;
  const std::string text = validation_text(r);
  EXPECT_TRUE(has_line(text,
                       "          2 layers have open chains (left open by the fast path, closed "
                       "towards -x by the exact path): not in the figures above; Hausdorff with "
                       "them inf mm"))
      << text;
  EXPECT_TRUE(has_line(text,
                       "          loops differ in 1 layers (exact overlay), 1 compared by "
                       "area only (overlay failed), 3 more differ only at rounding level and "
                       "were not overlaid"))
      << text;
}

TEST(ValidationText, NamesTheOverlaysAloneWhenNoneFailedOrWasSkipped) {
  ValidationReport r = agreeing_text_report();
  r.layers_arrangement = 2;
  EXPECT_TRUE(has_line(validation_text(r), "          loops differ in 2 layers (exact overlay)"));
  r.layers_arrangement = 0;
  r.layers_overlay_skipped = 1;
  EXPECT_TRUE(has_line(validation_text(r),
                       "          loops differ in 0 layers (exact overlay), 1 more differ only at "
                       "rounding level and were not overlaid"));
}

TEST(ValidationText, SaysTheReferenceSlicerWasOffOrWhyItDidNotRun) {
  ValidationReport r = agreeing_text_report();
  EXPECT_TRUE(has_line(validation_text(r),
                       "reference slicer (CGAL Polygon_mesh_slicer, exact kernel): off"));
  r.reference.skipped = ReferenceSkip::NotClosed;
  r.reference.reason = "not closed: 4 border edges";
  EXPECT_TRUE(has_line(validation_text(r),
                       "reference slicer (CGAL Polygon_mesh_slicer, exact kernel): not run: not "
                       "closed: 4 border edges"));
}

ReferenceSlicerFigures reference_run() {
  ReferenceSlicerFigures f;
  f.ran = true;
  f.skipped = ReferenceSkip::None;
  f.layers_compared = 10;
  f.max_hausdorff_exact_mm = 0.0;
  f.max_symmetric_difference_exact_mm2 = 0.0;
  f.max_hausdorff_fast_mm = 1.5e-7;
  f.max_symmetric_difference_fast_mm2 = 2e-9;
  f.layers_differing_fast = 1;
  f.polylines = 12345;
  f.open_polylines = 4;
  f.open_after_joining = 1;
  f.isolated_points = 2;
  f.build_seconds = 0.25;
  f.slice_seconds = 0.5;
  f.compare_seconds = 0.125;
  return f;
}

TEST(ValidationText, GivesTheReferenceSlicersFiguresWhereNoVertexIsOnAPlane) {
  ValidationReport r = agreeing_text_report();
  r.reference = reference_run();
  const std::string text = validation_text(r);
  EXPECT_TRUE(
      has_line(text,
               "reference slicer (CGAL Polygon_mesh_slicer, exact kernel): 10 layers; where "
               "the plane contains no vertex (10 layers): vs exact Hausdorff max 0 mm, "
               "symmetric difference max 0 mm2; vs fast Hausdorff max 1.5e-07 mm, "
               "symmetric difference max 2e-09 mm2; contours differ in 0 layers from the "
               "exact path (regions in 0), 1 from the fast path (regions in 0)"))
      << text;
  EXPECT_TRUE(has_line(text, "          the plane contains no mesh vertex in any layer")) << text;
  EXPECT_TRUE(has_line(text,
                       "          12,345 polylines: 4 open (1 still open after joining them "
                       "at shared points), 2 single points"))
      << text;
  EXPECT_TRUE(has_line(text,
                       "          time 0.875 s: building 0.250 s, slicing 0.500 s, comparing "
                       "0.125 s"))
      << text;
  EXPECT_EQ(text.find("outlined layers"), std::string::npos) << text;
  EXPECT_EQ(text.find("stopped:"), std::string::npos) << text;
}

TEST(ValidationText, GivesTheReferenceSlicersLayersAtVerticesOutlinesAndDroppedFacets) {
  ValidationReport r = agreeing_text_report();
  r.reference = reference_run();
  r.reference.layers_outlined_exact = 2;
  r.reference.layers_outlined_fast = 3;
  r.reference.layers_vertex_on_plane = 4;
  r.reference.layers_facet_on_plane = 1;
  r.reference.layers_differing_exact_at_vertex = 1;
  r.reference.layers_differing_fast_at_vertex = 2;
  r.reference.max_hausdorff_exact_all_mm = 0.5;
  r.reference.max_symmetric_difference_exact_all_mm2 = 0.25;
  r.reference.max_hausdorff_fast_all_mm = 0.75;
  r.reference.max_symmetric_difference_fast_all_mm2 = 0.125;
  r.reference.degenerate_facets_dropped = 3;
  const std::string text = validation_text(r);
  EXPECT_NE(text.find("where the plane contains no vertex (6 layers)"), std::string::npos) << text;
  EXPECT_TRUE(has_line(
      text,
      "          outlined layers, compared by region only (their loops are open, cross, touch or "
      "are misnested, so a path gives the outline of the filled region instead of the loops the "
      "slicer gives): 2 by the exact path, 3 by the fast path; Hausdorff above is over the other "
      "layers"))
      << text;
  EXPECT_TRUE(has_line(
      text,
      "          the plane contains a mesh vertex in 4 layers (a facet lies in it in 1) (CGAL "
      "keeps such a vertex on the plane, strata counts it above): contours differ there in 1 "
      "layers from the exact path, 2 from the fast path; over every layer: vs exact Hausdorff max "
      "0.5 mm, symmetric difference max 0.25 mm2; vs fast 0.75 mm, 0.125 mm2"))
      << text;
  EXPECT_NE(text.find(", 2 single points; 3 facets with a repeated corner left out\n"),
            std::string::npos)
      << text;
  r.reference.layers_facet_on_plane = 0;
  EXPECT_NE(validation_text(r).find("a mesh vertex in 4 layers (CGAL keeps"), std::string::npos);
}

TEST(ValidationText, SaysWhereTheReferenceSlicerStopped) {
  ValidationReport r = agreeing_text_report();
  r.reference = reference_run();
  r.reference.ran = false;
  r.reference.skipped = ReferenceSkip::Failed;
  r.reference.reason = "CGAL failed slicing layer 3 (z 3.5): boom";
  const std::string text = validation_text(r);
  EXPECT_NE(text.find("exact kernel): 10 layers;"), std::string::npos) << text;
  EXPECT_TRUE(has_line(text, "          stopped: CGAL failed slicing layer 3 (z 3.5): boom"))
      << text;
}

TEST(ValidationText, ComparesTheVolumesWithTheMeshVolumesMagnitude) {
  ValidationReport r = agreeing_text_report();
  // An inverted shell: its signed volume is negative, its cells are not.
  r.model.mesh_volume_mm3 = -8.0;
  r.fast.cell_volume_mm3 = 10.0;
  r.exact.cell_volume_mm3 = 6.0;
  r.fast.contour_volume_mm3 = -8.0;
  r.exact.contour_volume_mm3 = -6.0;
  r.model.surface_area_mm2 = 24.0;
  const std::string text = validation_text(r);
  EXPECT_TRUE(has_line(text, "volume    mesh -8 mm3 (exact, from the facets)")) << text;
  EXPECT_TRUE(has_line(text, "          cells    fast 10 mm3 (+25.000 %), exact 6 mm3 (-25.000 %)"))
      << text;
  EXPECT_TRUE(has_line(text,
                       "          contours fast -8 mm3 (+0.000 %), exact -6 mm3 (+25.000 %)  "
                       "(sum of layer area x dz)"))
      << text;
  EXPECT_TRUE(has_line(text, "surface   24 mm2")) << text;
}

TEST(ValidationText, GivesTheBoundsOrNone) {
  ValidationReport r = agreeing_text_report();
  r.model.mesh_bounds.add({0, 0, 0});
  r.model.mesh_bounds.add({2, 1.5, 1});
  const std::string text = validation_text(r);
  EXPECT_TRUE(has_line(text, "bounds    mesh  (0, 0, 0) .. (2, 1.5, 1)")) << text;
  EXPECT_TRUE(has_line(text, "          cells none")) << "no solid cell: " << text;
}

TEST(ValidationText, GivesTheSurfaceToShellDistanceWhenMeasured) {
  ValidationReport r = agreeing_text_report();
  EXPECT_EQ(validation_text(r).find("surface-to-shell"), std::string::npos);
  r.model.surface_to_boundary_mm = 0.75;
  r.model.surface_samples = 4321;
  r.grid.dx = r.grid.dy = 2.0;
  EXPECT_TRUE(has_line(validation_text(r),
                       "surface-to-shell  0.75 mm: the farthest of 4,321 surface points from the "
                       "nearest boundary cell centre (a cell diagonal is 3 mm)"));
}

TEST(ValidationText, GivesTheShellThicknessAndHowManyCellsWereMeasured) {
  ValidationReport r = agreeing_text_report();
  r.model.asked_shell_mm = 0.5;
  EXPECT_TRUE(has_line(validation_text(r),
                       "shell     asked t = 0.5 mm; no interior cell touches the shell"));
  r.model.shell.cells = 2000;
  r.model.shell.measured = 2000;
  r.model.shell.min_mm = 0.5;
  r.model.shell.mean_mm = 0.75;
  r.model.shell.max_mm = 1.25;
  EXPECT_TRUE(has_line(validation_text(r),
                       "shell     asked t = 0.5 mm (distance); interior cells next to the shell: "
                       "2,000; their distance to the surface: min 0.5 mm, mean 0.75 mm, max 1.25 "
                       "mm"));
  r.model.shell.measured = 1000;
  EXPECT_NE(validation_text(r).find("next to the shell: 2,000 (1,000 measured); their"),
            std::string::npos);
}

TEST(ValidationText, ListsTheCellsTheScanOffsetChanges) {
  ValidationReport r = agreeing_text_report();
  EXPECT_EQ(validation_text(r).find("offset    "), std::string::npos) << "not measured";
  r.scan_offset.measured = true;
  r.scan_offset.offset_mm = 0.001;
  r.scan_offset.cells_changed = 2;
  r.scan_offset.cells = {{1, 2, 0, CellClass::Interior, CellClass::Empty},
                         {2, 2, 1, CellClass::Boundary, CellClass::Interior}};
  std::string text = validation_text(r);
  EXPECT_TRUE(has_line(text, "offset    the scan offset of 0.001 mm changes 2 cells")) << text;
  EXPECT_TRUE(has_line(text, "          cell (1, 2, 0): 01 with the offset, 00 without")) << text;
  EXPECT_TRUE(has_line(text, "          cell (2, 2, 1): 11 with the offset, 01 without")) << text;
  EXPECT_EQ(text.find("more\n"), std::string::npos) << text;
  r.scan_offset.cells_changed = 25;
  r.scan_offset.cells.resize(21, r.scan_offset.cells.back());
  text = validation_text(r);
  EXPECT_TRUE(has_line(text, "          ... 5 more")) << text;
}

TEST(ValidationText, GivesTheExactPathsSoupAndTheNotes) {
  ValidationReport r = agreeing_text_report();
  r.exact_soup.points_merged = 1;
  r.exact_soup.polygons_removed = 2;
  r.exact_soup.points_duplicated = 3;
  r.exact_soup.non_manifold_edges = 4;
  r.exact_soup.halfedge_layers = 5;
  r.exact_soup.arrangement_layers = 6;
  r.exact_soup.empty_layers = 7;
  r.diagnostics.push_back({Severity::Info, "validate.boundary_cells", "first note"});
  r.diagnostics.push_back({Severity::Warning, "stl.trailing_bytes", "second note"});
  const std::string text = validation_text(r);
  EXPECT_TRUE(has_line(text,
                       "exact     soup: 1 points merged, 2 polygons removed, 3 points "
                       "duplicated, 4 non-manifold edges; layers by halfedges 5, by "
                       "arrangement 6, empty 7"))
      << text;
  EXPECT_NE(text.find("note      first note\nnote      second note\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace strata::validate
