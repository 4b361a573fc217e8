#include "strata/repair/repair_log_json.hpp"

#include <algorithm>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace strata::repair {

std::string repair_log_json(const RepairLog& log) {
  using json = nlohmann::ordered_json;
  json changes = json::array();
  for (std::size_t i = 0; i < std::min(log.changes.size(), kMaxChangesListed); ++i) {
    changes.push_back(
        {{"facet", log.changes[i].facet}, {"change", facet_change_name(log.changes[i].kind)}});
  }
  json out = {
      {"changed", log.changed_anything()},
      {"input", {{"facets", log.input_facets}, {"vertices", log.input_vertices}}},
      {"weld", {{"points_merged", log.points_merged}}},
      {"degenerate", {{"facets_removed", log.degenerate_facets_removed}}},
      {"duplicates",
       {{"facets_removed", log.duplicate_facets_removed},
        {"cancelling_removed", log.cancelling_duplicates_removed}}},
      {"t_junctions",
       {{"closed", log.t_junctions_closed}, {"facets_added", log.t_junction_facets_added}}},
      {"orientation",
       {{"non_manifold_vertices_split", log.non_manifold_vertices_split},
        {"vertex_copies_added", log.vertex_copies_added},
        {"non_manifold_edges", log.non_manifold_edges},
        {"facets_flipped", log.facets_flipped_for_consistency},
        {"polygon_mesh", log.polygon_mesh}}},
      {"stitching", {{"borders_stitched", log.borders_stitched}}},
      {"holes",
       {{"found", log.holes_found},
        {"seams_at_shared_edges", log.seams_at_shared_edges},
        {"fill_requested", log.fill_holes_requested},
        {"filled", log.holes_filled},
        {"facets_added", log.hole_facets_added},
        {"not_filled", log.holes_not_filled}}},
      {"volume_orientation",
       {{"done", log.volume_orientation_done},
        {"closed_shells", log.closed_shells},
        {"open_shells", log.open_shells},
        {"shells_reoriented", log.shells_reoriented},
        {"facets_flipped", log.facets_flipped_with_shells},
        {"note", log.volume_orientation_note}}},
      {"output",
       {{"facets", log.output_facets},
        {"vertices", log.output_vertices},
        {"kept_input_facets", log.kept_input_facets},
        {"facets_flipped", log.facets_flipped}}},
      {"changes", {{"count", log.changes.size()}, {"first", changes}}},
  };
  return out.dump();
}

}  // namespace strata::repair
