#include "strata/validate/validation_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "strata/core/thousands.hpp"
#include "strata/voxel/cell_code.hpp"

namespace strata::validate {

namespace {

constexpr std::size_t kListedInText = 20;
constexpr std::size_t kWorstLayers = 5;

std::string mm(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "inf"; }

std::string percent_of(double value, double reference) {
  if (reference == 0.0) return "n/a";
  return fmt::format("{:+.3f} %", 100.0 * (value - reference) / std::fabs(reference));
}

std::string box_text(const Bbox3& b) {
  if (b.empty()) return "none";
  return fmt::format("({}, {}, {}) .. ({}, {}, {})", mm(b.min.x), mm(b.min.y), mm(b.min.z),
                     mm(b.max.x), mm(b.max.y), mm(b.max.z));
}

std::string reference_text(const ReferenceSlicerFigures& f) {
  constexpr const char* kTitle = "slicer (CGAL Polygon_mesh_slicer, exact kernel)";
  if (!f.ran && f.layers_compared == 0) {
    if (f.skipped == ReferenceSkip::Off) return fmt::format("reference {}: off\n", kTitle);
    return fmt::format("reference {}: not run: {}\n", kTitle, f.reason);
  }
  std::string out;
  const std::uint32_t generic = f.layers_compared - f.layers_vertex_on_plane;
  out += fmt::format(
      "reference {}: {} layers; where the plane contains no vertex ({} layers): vs exact "
      "Hausdorff max {} mm, symmetric difference max {} mm2; vs fast Hausdorff max {} mm, "
      "symmetric difference max {} mm2; contours differ in {} layers from the exact path "
      "(regions in {}), {} from the fast path (regions in {})\n",
      kTitle, f.layers_compared, generic, mm(f.max_hausdorff_exact_mm),
      mm(f.max_symmetric_difference_exact_mm2), mm(f.max_hausdorff_fast_mm),
      mm(f.max_symmetric_difference_fast_mm2), f.layers_differing_exact,
      f.layers_region_differing_exact, f.layers_differing_fast, f.layers_region_differing_fast);
  if (f.layers_outlined_exact + f.layers_outlined_fast > 0) {
    out += fmt::format(
        "          outlined layers, compared by region only (their loops are open, cross, touch "
        "or are misnested, so a path gives the outline of the filled region instead of the loops "
        "the slicer gives): {} by the exact path, {} by the fast path; Hausdorff above is over "
        "the other layers\n",
        f.layers_outlined_exact, f.layers_outlined_fast);
  }
  if (f.layers_vertex_on_plane > 0) {
    out += fmt::format(
        "          the plane contains a mesh vertex in {} layers{} (CGAL keeps such a vertex on "
        "the plane, strata counts it above): contours differ there in {} layers from the exact "
        "path, {} from the fast path; over every layer: vs exact Hausdorff max {} mm, "
        "symmetric difference max {} mm2; vs fast {} mm, {} mm2\n",
        f.layers_vertex_on_plane,
        f.layers_facet_on_plane > 0
            ? fmt::format(" (a facet lies in it in {})", f.layers_facet_on_plane)
            : std::string(),
        f.layers_differing_exact_at_vertex, f.layers_differing_fast_at_vertex,
        mm(f.max_hausdorff_exact_all_mm), mm(f.max_symmetric_difference_exact_all_mm2),
        mm(f.max_hausdorff_fast_all_mm), mm(f.max_symmetric_difference_fast_all_mm2));
  } else {
    out += "          the plane contains no mesh vertex in any layer\n";
  }
  out += fmt::format(
      "          {} polylines: {} open ({} still open after joining them at shared points), {} "
      "single points{}\n",
      with_thousands(f.polylines), with_thousands(f.open_polylines),
      with_thousands(f.open_after_joining), with_thousands(f.isolated_points),
      f.degenerate_facets_dropped > 0
          ? fmt::format("; {} facets with a repeated corner left out", f.degenerate_facets_dropped)
          : std::string());
  if (f.skipped == ReferenceSkip::Failed) out += fmt::format("          stopped: {}\n", f.reason);
  out += fmt::format(
      "          time {:.3f} s: building {:.3f} s, slicing {:.3f} s, comparing {:.3f} s\n",
      f.seconds(), f.build_seconds, f.slice_seconds, f.compare_seconds);
  return out;
}

}  // namespace

std::string validation_text(const ValidationReport& r) {
  const GridSpec& g = r.grid;
  std::string out;
  out += fmt::format("grid      {} x {} x {} cells of {} x {} x {} mm, origin ({}, {}, {})\n", g.nx,
                     g.ny, g.nz, g.dx, g.dy, g.dz, g.x0, g.y0, g.z0);
  out += fmt::format("rule      fill {}, shell {} mm ({}), scan offset {} mm\n",
                     to_string(r.options.fill_rule), r.options.shell_mm,
                     to_string(r.options.shell_mode), r.options.scan_offset_mm);

  // Cells.
  if (r.exact_error) {
    out += fmt::format("cells     NOT VALIDATED: the exact path stopped: {}\n",
                       r.exact_error->to_string());
    if (r.layers_compared > 0) {
      out += fmt::format("          before that, {} of {} cells differed in {} layers\n",
                         with_thousands(r.cells_differing), with_thousands(r.cells_compared),
                         r.layers_compared);
    }
  } else if (r.cells_differing == 0) {
    out += fmt::format("cells     AGREE: {} cells compared in {} layers, none differs\n",
                       with_thousands(r.cells_compared), r.layers_compared);
  } else {
    std::vector<std::string> parts;
    for (std::size_t q = 0; q < kDifferenceReasonCount; ++q) {
      if (r.differing_by_reason[q] == 0) continue;
      parts.push_back(fmt::format("{} {}", to_string(static_cast<DifferenceReason>(q)),
                                  with_thousands(r.differing_by_reason[q])));
    }
    out += fmt::format("cells     DIFFER: {} of {} cells ({})\n", with_thousands(r.cells_differing),
                       with_thousands(r.cells_compared), fmt::join(parts, ", "));
    const std::size_t shown = std::min(kListedInText, r.differences.size());
    for (std::size_t q = 0; q < shown; ++q) {
      const CellDifference& d = r.differences[q];
      out += fmt::format("          cell ({}, {}, {}) at ({}, {}, {}) mm: fast {}, exact {}: {}\n",
                         d.i, d.j, d.k, mm(g.xc(d.i)), mm(g.yc(d.j)), mm(g.zk(d.k)),
                         cell_code(d.fast), cell_code(d.exact), to_string(d.reason));
    }
    if (r.cells_differing > shown) {
      out += fmt::format("          ... {} more (the JSON report lists {})\n",
                         with_thousands(r.cells_differing - shown), r.differences.size());
    }
  }

  // Contours.
  if (r.layers_compared > 0) {
    out += fmt::format(
        "contours  {} layers; loop counts differ in {}; symmetric difference max {} mm2, total "
        "{} mm2; Hausdorff max {} mm\n",
        r.layers_compared, r.layers_with_different_counts, mm(r.max_symmetric_difference_mm2),
        mm(r.total_symmetric_difference_mm2), mm(r.max_hausdorff_mm));
    if (r.layers_with_open_chains > 0) {
      out += fmt::format(
          "          {} layers have open chains (left open by the fast path, closed towards -x "
          "by the exact path): not in the figures above; Hausdorff with them {} mm\n",
          r.layers_with_open_chains, mm(r.max_hausdorff_all_mm));
    }
    if (r.layers_arrangement > 0 || r.layers_area_only > 0 || r.layers_overlay_skipped > 0) {
      std::string extra;
      if (r.layers_area_only > 0) {
        extra += fmt::format(", {} compared by area only (overlay failed)", r.layers_area_only);
      }
      if (r.layers_overlay_skipped > 0) {
        extra += fmt::format(", {} more differ only at rounding level and were not overlaid",
                             r.layers_overlay_skipped);
      }
      out += fmt::format("          loops differ in {} layers (exact overlay){}\n",
                         r.layers_arrangement, extra);
    }
    std::vector<const LayerComparison*> worst;
    for (const LayerComparison& l : r.layers) {
      if (l.symmetric_difference_mm2 > 0.0 || l.hausdorff_mm > 0.0 || l.cells_differing > 0) {
        worst.push_back(&l);
      }
    }
    std::sort(worst.begin(), worst.end(), [](const auto* a, const auto* b) {
      return std::tie(a->cells_differing, a->hausdorff_mm, a->symmetric_difference_mm2) >
             std::tie(b->cells_differing, b->hausdorff_mm, b->symmetric_difference_mm2);
    });
    for (std::size_t q = 0; q < std::min(kWorstLayers, worst.size()); ++q) {
      const LayerComparison& l = *worst[q];
      out += fmt::format(
          "          layer {} (z {}): loops fast {}+{}h{}, exact {}+{}h{}; symmetric difference {} "
          "mm2 ({}), Hausdorff {} mm, {} cells differ\n",
          l.layer, mm(l.z_mm), l.fast.outer_loops, l.fast.holes,
          l.fast.open_chains ? fmt::format("+{}open", l.fast.open_chains) : std::string(),
          l.exact.outer_loops, l.exact.holes,
          l.exact.open_chains ? fmt::format("+{}open", l.exact.open_chains) : std::string(),
          mm(l.symmetric_difference_mm2), to_string(l.area_method), mm(l.hausdorff_mm),
          l.cells_differing);
    }
  }

  out += reference_text(r.reference);

  // Model.
  const ModelFigures& m = r.model;
  out += fmt::format("volume    mesh {} mm3 (exact, from the facets)\n", mm(m.mesh_volume_mm3));
  // Cells have no sign: they are compared with the volume's magnitude (an inverted shell has a
  // negative signed volume); contour areas carry the facets' orientation like the mesh volume.
  const double magnitude = std::fabs(m.mesh_volume_mm3);
  out += fmt::format("          cells    fast {} mm3 ({}){}\n", mm(r.fast.cell_volume_mm3),
                     percent_of(r.fast.cell_volume_mm3, magnitude),
                     r.exact.ran ? fmt::format(", exact {} mm3 ({})", mm(r.exact.cell_volume_mm3),
                                               percent_of(r.exact.cell_volume_mm3, magnitude))
                                 : std::string());
  out += fmt::format(
      "          contours fast {} mm3 ({}){}  (sum of layer area x dz)\n",
      mm(r.fast.contour_volume_mm3), percent_of(r.fast.contour_volume_mm3, m.mesh_volume_mm3),
      r.exact.ran ? fmt::format(", exact {} mm3 ({})", mm(r.exact.contour_volume_mm3),
                                percent_of(r.exact.contour_volume_mm3, m.mesh_volume_mm3))
                  : std::string());
  out += fmt::format("surface   {} mm2\n", mm(m.surface_area_mm2));
  out += fmt::format("bounds    mesh  {}\n          cells {}\n", box_text(m.mesh_bounds),
                     box_text(r.fast.solid_bounds));
  if (m.surface_to_boundary_mm) {
    out += fmt::format(
        "surface-to-shell  {} mm: the farthest of {} surface points from the nearest boundary "
        "cell centre (a cell diagonal is {} mm)\n",
        mm(*m.surface_to_boundary_mm), with_thousands(m.surface_samples),
        mm(std::sqrt(g.dx * g.dx + g.dy * g.dy + g.dz * g.dz)));
  }
  if (m.shell.measured > 0) {
    out += fmt::format(
        "shell     asked t = {} mm ({}); interior cells next to the shell: {}{}; their distance "
        "to the surface: min {} mm, mean {} mm, max {} mm\n",
        m.asked_shell_mm, to_string(r.options.shell_mode), with_thousands(m.shell.cells),
        m.shell.measured < m.shell.cells
            ? fmt::format(" ({} measured)", with_thousands(m.shell.measured))
            : std::string(),
        mm(m.shell.min_mm), mm(m.shell.mean_mm), mm(m.shell.max_mm));
  } else {
    out += fmt::format("shell     asked t = {} mm; no interior cell touches the shell\n",
                       m.asked_shell_mm);
  }

  // Scan offset.
  if (r.scan_offset.measured) {
    out += fmt::format("offset    the scan offset of {} mm changes {} cells\n",
                       r.scan_offset.offset_mm, with_thousands(r.scan_offset.cells_changed));
    const std::size_t shown = std::min(kListedInText, r.scan_offset.cells.size());
    for (std::size_t q = 0; q < shown; ++q) {
      const OffsetChange& c = r.scan_offset.cells[q];
      out += fmt::format("          cell ({}, {}, {}): {} with the offset, {} without\n", c.i, c.j,
                         c.k, cell_code(c.with_offset), cell_code(c.without_offset));
    }
    if (r.scan_offset.cells_changed > shown) {
      out += fmt::format("          ... {} more\n",
                         with_thousands(r.scan_offset.cells_changed - shown));
    }
  }

  // Exact path's reading of the soup, and times.
  const ExactSliceReport& s = r.exact_soup;
  if (r.exact.ran) {
    out += fmt::format(
        "exact     soup: {} points merged, {} polygons removed, {} points duplicated, {} "
        "non-manifold edges; layers by halfedges {}, by arrangement {}, empty {}\n",
        s.points_merged, s.polygons_removed, s.points_duplicated, s.non_manifold_edges,
        s.halfedge_layers, s.arrangement_layers, s.empty_layers);
  }
  out += fmt::format(
      "time      fast {:.3f} s, exact {:.3f} s{}, comparison {:.3f} s\n", r.fast.seconds,
      r.exact.seconds,
      r.time_ratio() > 0 ? fmt::format(" (exact/fast {:.1f})", r.time_ratio()) : std::string(),
      r.comparison_seconds);
  for (const Diagnostic& d : r.diagnostics) {
    out += fmt::format("note      {}\n", d.message);
  }
  return out;
}

}  // namespace strata::validate
