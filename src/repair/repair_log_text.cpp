#include "strata/repair/repair_log_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

namespace strata::repair {
namespace {

/// Changed facets named in the text (the JSON lists kMaxChangesListed).
constexpr std::size_t kChangesShown = 5;

std::string plural(std::size_t n, const char* one, const char* many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

}  // namespace

std::string repair_log_text(const RepairLog& log, std::string_view not_filled_reason) {
  std::string out = "repair\n";
  const auto line = [&out](const char* label, const std::string& value) {
    fmt::format_to(std::back_inserter(out), "  {:<28} {}\n", label, value);
  };
  line("input", fmt::format("{}, {}", plural(log.input_facets, "facet", "facets"),
                            plural(log.input_vertices, "vertex", "vertices")));
  line("corners merged (exact weld)", fmt::format("{}", log.points_merged));
  line("degenerate facets removed", fmt::format("{}", log.degenerate_facets_removed));
  std::string duplicates = fmt::format("{}", log.duplicate_facets_removed);
  if (log.cancelling_duplicates_removed > 0) {
    duplicates += fmt::format(", and the last copy of {} whose orientations cancel",
                              plural(log.cancelling_duplicates_removed, "set", "sets"));
  }
  line("duplicate facets removed", duplicates);
  std::string cracks = fmt::format("{}", log.t_junctions_closed);
  if (log.t_junctions_closed > 0) {
    cracks += fmt::format(" ({} added)", plural(log.t_junction_facets_added, "facet", "facets"));
  }
  line("T-junction cracks closed", cracks);
  line("non-manifold vertices split",
       fmt::format("{} ({} added; {} non-manifold edges)", log.non_manifold_vertices_split,
                   plural(log.vertex_copies_added, "copy", "copies"), log.non_manifold_edges));
  line("facets flipped (consistency)", fmt::format("{}", log.facets_flipped_for_consistency));
  if (!log.polygon_mesh) {
    line("stitching, holes", "skipped: the facets do not form a polygon mesh");
  } else {
    line("borders stitched", plural(log.borders_stitched, "edge pair", "edge pairs"));
    std::string holes =
        log.fill_holes_requested
            ? fmt::format("{} found, {} filled ({} added), {} left open", log.holes_found,
                          log.holes_filled, plural(log.hole_facets_added, "facet", "facets"),
                          log.holes_not_filled)
            : fmt::format("{} found, not filled ({})", log.holes_found, not_filled_reason);
    if (log.seams_at_shared_edges > 0) {
      holes += fmt::format("; {} along non-manifold edges left as they are",
                           plural(log.seams_at_shared_edges, "border", "borders"));
    }
    line("holes", holes);
  }
  std::string volume =
      log.volume_orientation_done
          ? fmt::format("{} of {} closed ({} flipped)", log.shells_reoriented, log.closed_shells,
                        plural(log.facets_flipped_with_shells, "facet", "facets"))
          : std::string();
  if (!log.volume_orientation_note.empty()) {
    volume += (volume.empty() ? "" : "; ") + log.volume_orientation_note;
  }
  line("shells reoriented (volume)", volume.empty() ? std::string("not run") : volume);
  line("output", fmt::format("{}, {} ({} input facets kept, {} flipped)",
                             plural(log.output_facets, "facet", "facets"),
                             plural(log.output_vertices, "vertex", "vertices"),
                             log.kept_input_facets, log.facets_flipped));
  if (!log.changes.empty()) {
    std::vector<std::string> items;
    for (std::size_t i = 0; i < std::min(log.changes.size(), kChangesShown); ++i) {
      items.push_back(
          fmt::format("facet {} {}", log.changes[i].facet, facet_change_name(log.changes[i].kind)));
    }
    line("changed input facets",
         fmt::format("{}  e.g. {}{}", log.changes.size(), fmt::join(items, ", "),
                     log.changes.size() > items.size() ? ", ..." : ""));
  }
  return out;
}

std::string repair_log_summary(const RepairLog& log) {
  std::vector<std::string> parts;
  const auto add = [&parts](std::size_t n, const char* one, const char* many) {
    if (n > 0) parts.push_back(plural(n, one, many));
  };
  add(log.degenerate_facets_removed, "degenerate facet removed", "degenerate facets removed");
  add(log.duplicate_facets_removed + log.cancelling_duplicates_removed, "duplicate facet removed",
      "duplicate facets removed");
  add(log.t_junctions_closed, "T-junction crack closed", "T-junction cracks closed");
  add(log.facets_flipped, "facet flipped", "facets flipped");
  add(log.shells_reoriented, "shell reoriented", "shells reoriented");
  add(log.holes_filled, "hole filled", "holes filled");
  add(log.holes_not_filled, "hole left open", "holes left open");
  if (!log.fill_holes_requested) {
    add(log.holes_found, "hole found (not filled)", "holes found (not filled)");
  }
  if (parts.empty()) parts.push_back("nothing to change");
  return fmt::format("repair: {} in, {} out; {}", plural(log.input_facets, "facet", "facets"),
                     log.output_facets, fmt::join(parts, ", "));
}

}  // namespace strata::repair
