#include "strata/validate/validation_json.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "strata/voxel/cell_code.hpp"

namespace strata::validate {

namespace {

using nlohmann::json;

json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json box_json(const Bbox3& b) {
  if (b.empty()) return nullptr;
  return {{"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}};
}

json path_json(const PathFigures& p) {
  return {{"ran", p.ran},
          {"seconds", p.seconds},
          {"cells",
           {{"empty", p.class_counts[0]},
            {"interior", p.class_counts[1]},
            {"boundary", p.class_counts[2]}}},
          {"cell_volume_mm3", p.cell_volume_mm3},
          {"contour_volume_mm3", p.contour_volume_mm3},
          {"open_chains", p.open_chains},
          {"solid_bounds_mm", box_json(p.solid_bounds)}};
}

json counts_json(const ContourCounts& c) {
  return {{"outer_loops", c.outer_loops},
          {"holes", c.holes},
          {"open_chains", c.open_chains},
          {"points", c.points},
          {"area_mm2", c.area_mm2}};
}

json error_json(const std::optional<Error>& e) {
  if (!e) return nullptr;
  const char* code = e->code == ErrorCode::BadInput ? "bad-input"
                     : e->code == ErrorCode::Usage  ? "usage"
                                                    : "internal";
  return {{"code", code}, {"message", e->to_string()}};
}

double relative(double value, double reference) {
  return reference != 0.0 ? (value - reference) / std::fabs(reference)
                          : std::numeric_limits<double>::quiet_NaN();
}

json reference_json(const ReferenceSlicerFigures& f) {
  json layers = json::array();
  for (const ReferenceLayerComparison& l : f.layers) {
    layers.push_back({{"k", l.layer},
                      {"z_mm", l.z_mm},
                      {"closed_polylines", l.closed_polylines},
                      {"open_polylines", l.open_polylines},
                      {"isolated_points", l.isolated_points},
                      {"open_after_joining", l.open_after_joining},
                      {"vertices_on_plane", l.vertices_on_plane},
                      {"facet_on_plane", l.facet_on_plane},
                      {"hausdorff_exact_mm", number(l.hausdorff_exact_mm)},
                      {"hausdorff_fast_mm", number(l.hausdorff_fast_mm)},
                      {"symmetric_difference_exact_mm2", number(l.symmetric_difference_exact_mm2)},
                      {"symmetric_difference_fast_mm2", number(l.symmetric_difference_fast_mm2)},
                      {"area_method_exact", to_string(l.area_method_exact)},
                      {"area_method_fast", to_string(l.area_method_fast)},
                      {"differs_from_exact", l.differs_from_exact},
                      {"differs_from_fast", l.differs_from_fast}});
  }
  return {{"ran", f.ran},
          {"skipped", to_string(f.skipped)},
          {"reason", f.reason.empty() ? json(nullptr) : json(f.reason)},
          {"facets", f.facets},
          {"max_facets", f.max_facets},
          {"degenerate_facets_dropped", f.degenerate_facets_dropped},
          {"layers_compared", f.layers_compared},
          {"layers_vertex_on_plane", f.layers_vertex_on_plane},
          {"layers_facet_on_plane", f.layers_facet_on_plane},
          {"layers_differing_exact", f.layers_differing_exact},
          {"layers_differing_fast", f.layers_differing_fast},
          {"layers_differing_exact_at_vertex", f.layers_differing_exact_at_vertex},
          {"layers_differing_fast_at_vertex", f.layers_differing_fast_at_vertex},
          {"layers_region_differing_exact", f.layers_region_differing_exact},
          {"layers_region_differing_fast", f.layers_region_differing_fast},
          {"layers_outlined_exact", f.layers_outlined_exact},
          {"layers_outlined_fast", f.layers_outlined_fast},
          {"layers_overlay_skipped", f.layers_overlay_skipped},
          {"polylines", f.polylines},
          {"open_polylines", f.open_polylines},
          {"isolated_points", f.isolated_points},
          {"open_after_joining", f.open_after_joining},
          {"max_hausdorff_exact_mm", number(f.max_hausdorff_exact_mm)},
          {"max_hausdorff_fast_mm", number(f.max_hausdorff_fast_mm)},
          {"max_symmetric_difference_exact_mm2", number(f.max_symmetric_difference_exact_mm2)},
          {"max_symmetric_difference_fast_mm2", number(f.max_symmetric_difference_fast_mm2)},
          {"max_hausdorff_exact_all_layers_mm", number(f.max_hausdorff_exact_all_mm)},
          {"max_hausdorff_fast_all_layers_mm", number(f.max_hausdorff_fast_all_mm)},
          {"max_symmetric_difference_exact_all_layers_mm2",
           number(f.max_symmetric_difference_exact_all_mm2)},
          {"max_symmetric_difference_fast_all_layers_mm2",
           number(f.max_symmetric_difference_fast_all_mm2)},
          {"seconds", f.seconds()},
          {"build_seconds", f.build_seconds},
          {"slice_seconds", f.slice_seconds},
          {"compare_seconds", f.compare_seconds},
          {"layers", layers}};
}

}  // namespace

std::string validation_json(const ValidationReport& r) {
  const GridSpec& g = r.grid;
  json out;
  out["strata_version"] = "0.1.0";
  out["verdict"] = r.exact_error ? "exact-path-failed" : r.cells_agree() ? "agree" : "cells-differ";
  out["grid"] = {{"nx", g.nx},
                 {"ny", g.ny},
                 {"nz", g.nz},
                 {"origin_mm", {g.x0, g.y0, g.z0}},
                 {"cell_mm", {g.dx, g.dy, g.dz}},
                 {"cells", g.cell_count()}};
  out["options"] = {{"fill_rule", to_string(r.options.fill_rule)},
                    {"shell_mm", r.options.shell_mm},
                    {"shell_mode", to_string(r.options.shell_mode)},
                    {"scan_offset_mm", r.options.scan_offset_mm}};
  out["fast"] = path_json(r.fast);
  out["exact"] = path_json(r.exact);
  out["exact"]["error"] = error_json(r.exact_error);
  const ExactSliceReport& s = r.exact_soup;
  out["exact"]["soup"] = {{"input_points", s.input_points},
                          {"input_polygons", s.input_polygons},
                          {"points_merged", s.points_merged},
                          {"polygons_removed", s.polygons_removed},
                          {"points_duplicated", s.points_duplicated},
                          {"polygons_reversed", s.polygons_reversed},
                          {"non_manifold_edges", s.non_manifold_edges},
                          {"polygon_mesh", s.polygon_mesh},
                          {"halfedge_layers", s.halfedge_layers},
                          {"arrangement_layers", s.arrangement_layers},
                          {"empty_layers", s.empty_layers}};
  out["time_ratio_exact_over_fast"] = number(r.time_ratio());

  json reasons = json::object();
  for (std::size_t q = 0; q < kDifferenceReasonCount; ++q) {
    reasons[to_string(static_cast<DifferenceReason>(q))] = r.differing_by_reason[q];
  }
  json listed = json::array();
  for (const CellDifference& d : r.differences) {
    listed.push_back({{"i", d.i},
                      {"j", d.j},
                      {"k", d.k},
                      {"fast", cell_code(d.fast)},
                      {"exact", cell_code(d.exact)},
                      {"reason", to_string(d.reason)}});
  }
  out["cells"] = {{"layers_compared", r.layers_compared},
                  {"compared", r.cells_compared},
                  {"differing", r.cells_differing},
                  {"differing_by_reason", reasons},
                  {"differences", listed},
                  {"differences_listed", r.differences.size()}};

  json layers = json::array();
  for (const LayerComparison& l : r.layers) {
    layers.push_back({{"k", l.layer},
                      {"z_mm", l.z_mm},
                      {"fast", counts_json(l.fast)},
                      {"exact", counts_json(l.exact)},
                      {"symmetric_difference_mm2", number(l.symmetric_difference_mm2)},
                      {"area_method", to_string(l.area_method)},
                      {"hausdorff_mm", number(l.hausdorff_mm)},
                      {"cells_differing", l.cells_differing}});
  }
  out["contours"] = {{"max_symmetric_difference_mm2", number(r.max_symmetric_difference_mm2)},
                     {"total_symmetric_difference_mm2", number(r.total_symmetric_difference_mm2)},
                     {"max_hausdorff_mm", number(r.max_hausdorff_mm)},
                     {"max_hausdorff_all_layers_mm", number(r.max_hausdorff_all_mm)},
                     {"layers_with_open_chains", r.layers_with_open_chains},
                     {"layers_with_different_counts", r.layers_with_different_counts},
                     {"layers_arrangement", r.layers_arrangement},
                     {"layers_area_only", r.layers_area_only},
                     {"layers_overlay_skipped", r.layers_overlay_skipped},
                     {"layers", layers}};

  json offset_cells = json::array();
  for (const OffsetChange& c : r.scan_offset.cells) {
    offset_cells.push_back({{"i", c.i},
                            {"j", c.j},
                            {"k", c.k},
                            {"with_offset", cell_code(c.with_offset)},
                            {"without_offset", cell_code(c.without_offset)}});
  }
  out["scan_offset"] = {{"measured", r.scan_offset.measured},
                        {"offset_mm", r.scan_offset.offset_mm},
                        {"cells_changed", r.scan_offset.cells_changed},
                        {"cells", offset_cells}};

  const ModelFigures& m = r.model;
  out["model"] = {
      {"mesh_volume_mm3", m.mesh_volume_mm3},
      {"surface_area_mm2", m.surface_area_mm2},
      {"mesh_bounds_mm", box_json(m.mesh_bounds)},
      {"fast_cell_volume_error",
       number(relative(r.fast.cell_volume_mm3, std::fabs(m.mesh_volume_mm3)))},
      {"fast_contour_volume_error", number(relative(r.fast.contour_volume_mm3, m.mesh_volume_mm3))},
      {"exact_contour_volume_error",
       number(r.exact.ran ? relative(r.exact.contour_volume_mm3, m.mesh_volume_mm3)
                          : std::numeric_limits<double>::quiet_NaN())},
      {"surface_to_boundary_hausdorff_mm",
       m.surface_to_boundary_mm ? number(*m.surface_to_boundary_mm) : json(nullptr)},
      {"surface_samples", m.surface_samples},
      {"shell_thickness",
       {{"asked_mm", m.asked_shell_mm},
        {"cells", m.shell.cells},
        {"measured", m.shell.measured},
        {"min_mm", m.shell.measured ? number(m.shell.min_mm) : json(nullptr)},
        {"mean_mm", m.shell.measured ? number(m.shell.mean_mm) : json(nullptr)},
        {"max_mm", m.shell.measured ? number(m.shell.max_mm) : json(nullptr)}}}};
  out["reference_slicer"] = reference_json(r.reference);
  out["comparison_seconds"] = r.comparison_seconds;
  json diagnostics = json::array();
  for (const Diagnostic& d : r.diagnostics) {
    diagnostics.push_back({{"severity", d.severity == Severity::Warning ? "warning" : "info"},
                           {"code", d.code},
                           {"message", d.message}});
  }
  out["diagnostics"] = diagnostics;
  return out.dump(2) + "\n";
}

}  // namespace strata::validate
