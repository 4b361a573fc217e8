#include "cli/slice_report.hpp"

#include <cmath>

namespace strata::cli {

namespace {

nlohmann::json vec(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json diagnostics_json(const Diagnostics& diagnostics) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& d : diagnostics) {
    out.push_back({{"severity", d.severity == Severity::Warning ? "warning" : "info"},
                   {"code", d.code},
                   {"message", d.message}});
  }
  return out;
}

}  // namespace

nlohmann::json slice_report_json(const LoadedModel& model, const diagnose::MeshReport& mesh_report,
                                 const SliceOptions& options, const std::string& kernel,
                                 const SliceSummary& s, double seconds_total) {
  const GridSpec& g = s.grid;
  const Bbox3 box = model.mesh.bounds();
  nlohmann::json report;
  report["strata_version"] = "0.1.0";
  report["model"] = {
      {"path", model.path.string()},
      {"format", model.soup.format},
      {"units", io::length_unit_name(model.scale.units)},
      {"scale", model.scale.scale},
      {"facets", model.mesh.triangles.size()},
      {"vertices", model.mesh.vertices.size()},
      {"bbox_min_mm", vec(box.min)},
      {"bbox_max_mm", vec(box.max)},
      {"read_diagnostics", diagnostics_json(model.soup.diagnostics)},
      {"defects",
       {{"open_edges", mesh_report.boundary_edges.count},
        {"non_manifold_edges", mesh_report.non_manifold_edges.count},
        {"degenerate_facets", mesh_report.degenerate_facets.count},
        {"duplicate_facets", mesh_report.duplicate_facets.count},
        {"inconsistent_edge_pairs", mesh_report.inconsistent_edges.count},
        {"shells", mesh_report.shells.size()},
        {"verdict", diagnose::verdict_name(mesh_report.verdict)}}},
  };
  report["parameters"] = {
      {"layer_mm", options.grid.dz_mm},
      {"dx_mm", options.grid.dx_mm},
      {"dy_mm", options.grid.dy_mm},
      {"shell_mm", options.shell_mm},
      {"shell_mode", to_string(options.shell_mode)},
      {"fill_rule", to_string(options.fill_rule)},
      {"scan_offset_mm", options.scan_offset_mm},
      {"kernel", kernel},
      {"threads", options.threads},
  };
  report["grid"] = {{"nx", g.nx},
                    {"ny", g.ny},
                    {"nz", g.nz},
                    {"origin_mm", {g.x0, g.y0, g.z0}},
                    {"spacing_mm", {g.dx, g.dy, g.dz}}};
  const double mesh_volume = mesh_report.volume_mm3;
  report["cells"] = {
      {"empty", s.class_counts[0]},
      {"interior", s.class_counts[1]},
      {"boundary", s.class_counts[2]},
      {"solid_volume_mm3", s.solid_volume_mm3},
  };
  report["metrics"] = {
      {"mesh_volume_mm3", mesh_volume},
      {"cell_volume_mm3", s.solid_volume_mm3},
      {"contour_volume_mm3", s.contour_volume_mm3},
      {"cell_volume_relative_error",
       mesh_volume != 0.0 ? (s.solid_volume_mm3 - mesh_volume) / std::fabs(mesh_volume) : 0.0},
      {"surface_area_mm2", mesh_report.surface_area_mm2},
      {"segments", s.segments},
      {"exact_fallbacks", s.exact_fallbacks},
      {"crossing_loop_layers", s.crossing_loop_layers},
      {"misnested_loop_layers", s.misnested_layers},
      {"outline_layers", s.outline_layers},
  };
  nlohmann::json chains = nlohmann::json::array();
  for (const auto& c : s.open_chain_reports) {
    chains.push_back({{"layer", c.layer},
                      {"z_mm", g.zk(c.layer)},
                      {"start_mm", {c.start.x, c.start.y}},
                      {"end_mm", {c.end.x, c.end.y}},
                      {"gap_mm", std::hypot(c.end.x - c.start.x, c.end.y - c.start.y)},
                      {"segments", c.segments}});
  }
  report["open_chains"] = {{"count", s.open_chains}, {"first", chains}};
  nlohmann::json layers = nlohmann::json::array();
  std::uint64_t empty_inside = 0;
  bool seen_solid = false;
  std::uint64_t gap = 0;
  for (const auto& l : s.layers) {
    layers.push_back({{"k", l.layer},
                      {"z_mm", l.z_mm},
                      {"segments", l.segments},
                      {"outer_loops", l.outer_loops},
                      {"holes", l.holes},
                      {"open_chains", l.open_chains},
                      {"loops_cross", l.loops_cross},
                      {"outline", l.outline},
                      {"contour_area_mm2", l.contour_area_mm2},
                      {"interior", l.interior},
                      {"boundary", l.boundary}});
    // Empty layers between solid ones: a warning sign the report should show.
    if (l.interior + l.boundary > 0) {
      if (seen_solid) empty_inside += gap;
      seen_solid = true;
      gap = 0;
    } else if (seen_solid) {
      ++gap;
    }
  }
  report["layers"] = layers;
  report["empty_layers_inside_model"] = empty_inside;
  report["diagnostics"] = diagnostics_json(s.diagnostics);
  report["timings_s"] = {{"read", model.seconds_read},
                         {"weld", model.seconds_weld},
                         {"slice", s.seconds},
                         {"total", seconds_total}};
  return report;
}

}  // namespace strata::cli
