#include "report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <set>

#include "comparison.hpp"
#include "strata/core/thousands.hpp"
#include "strata/voxel/cell_code.hpp"

namespace strata::validation {
namespace {

using strata::validate::DifferenceReason;

/// Text safe in a Markdown table cell, cut to `limit` characters.
std::string cell_text(std::string s, std::size_t limit = 90) {
  for (char& c : s) {
    if (c == '|') c = '/';
    if (c == '\n' || c == '\t') c = ' ';
  }
  if (s.size() > limit) s = s.substr(0, limit - 3) + "...";
  return s;
}

std::string percent(double value, double reference) {
  if (reference == 0.0 || !std::isfinite(value) || !std::isfinite(reference)) return "n/a";
  return fmt::format("{:+.2f}%", 100.0 * (value - reference) / std::fabs(reference));
}

std::string mm(double v) { return std::isfinite(v) ? fmt::format("{:.3g}", v) : "inf"; }

const char* rule_name(FillRule rule) { return strata::to_string(rule); }

/// The title, how the runs were made and the Totals table.
std::string summary_section(const Totals& t,
                            const std::vector<std::pair<std::string, std::uint64_t>>& too_large,
                            const RunnerOptions& o, double wall_seconds) {
  std::string out;
  std::string invocation = o.quick ? " --quick" : "";
  for (const std::string& text : o.only) invocation += " --only " + text;
  out += "# strata cross-validation: fast path vs exact path\n\n";
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  out += fmt::format(
      "Written by `strata-validation{}` on {} in {:.0f} s. Every model is sliced by both paths "
      "under the `nonzero` and `evenodd` fill rules on two grids: *aligned* (origin at the "
      "bounding box minimum; for a corpus model, cells that divide its largest extent; for a "
      "generated model, the cell it was built for, which puts its features on cell centres, "
      "scanlines and layer planes) and *shifted* (an odd cell size, {} times the aligned one "
      "for corpus models, and an origin moved by odd fractions of a cell). At most about {} "
      "cells and {} layers a run; shell thickness {} cells (distance mode); scan offset 0. "
      "Corpus files over {} bytes are skipped. How to run it: `validation/README.md`.\n\n",
      invocation, date, wall_seconds, kOddCellFactor,
      with_thousands(static_cast<std::uint64_t>(o.max_cells)), o.max_layers, kShellCells,
      with_thousands(o.max_bytes));

  out += "## Totals\n\n";
  out += "| | |\n|---|---|\n";
  out += fmt::format("| models validated | {} ({} generated, {} from the corpus) |\n", t.models,
                     t.generated, t.models - t.generated);
  out += fmt::format("| runs (model x fill rule x grid) | {} |\n", t.runs);
  out += fmt::format("| cells compared | {} |\n", with_thousands(t.compared));
  std::vector<std::string> reason_parts;
  for (std::size_t q = 0; q < kDifferenceReasonCount; ++q) {
    reason_parts.push_back(
        fmt::format("{} {}", strata::validate::to_string(static_cast<DifferenceReason>(q)),
                    with_thousands(t.by_reason[q])));
  }
  out += fmt::format("| cells differing | **{}** in {} runs ({}) |\n", with_thousands(t.differing),
                     t.runs_differing, fmt::join(reason_parts, ", "));
  out += fmt::format(
      "| contours | largest Hausdorff distance {} mm; {} layers overlaid exactly, {} more "
      "differing at rounding level only not overlaid (at most {} overlays a run), {} compared "
      "by area only |\n",
      mm(t.max_hausdorff), with_thousands(t.overlaid), with_thousands(t.overlay_skipped),
      kOverlayLayers, t.area_only);
  out += fmt::format("| runs the exact path refused or failed | {} |\n", t.refusals);
  out += fmt::format("| runs the fast path refused | {} |\n", t.fast_failures);
  out += fmt::format("| time, fast path | {:.1f} s |\n", t.fast_s);
  out += fmt::format("| time, exact path | {:.1f} s |\n", t.exact_s);
  out +=
      fmt::format("| exact / fast time ratio | {} |\n",
                  t.fast_s > 0 ? fmt::format("{:.1f}", t.exact_s / t.fast_s) : std::string("n/a"));
  out += fmt::format("| time comparing and measuring | {:.1f} s |\n", t.comparison_s);
  {
    std::vector<std::string> skipped;
    for (const auto& [why, n] : t.ref_skipped_models)
      skipped.push_back(fmt::format("{} {}", why, n));
    out += fmt::format(
        "| reference slicer (CGAL Polygon_mesh_slicer, exact kernel) | {} of {} models compared "
        "({} runs, {} layers); where the plane holds no mesh vertex: worst Hausdorff distance "
        "vs exact {} mm, vs fast {} mm{} over the layers neither path outlined, worst symmetric "
        "difference {} mm2 over all of them, {} layers whose regions differ, {} outlined "
        "layers compared by region only; {} layers whose plane holds a vertex, {} of them "
        "differing (CGAL "
        "keeps "
        "such a vertex on the plane, strata counts it above); {} open polylines; not run: {}; "
        "{:.1f} s |\n",
        t.ref_models, t.models, t.ref_runs, with_thousands(t.ref_layers), mm(t.ref_h_exact),
        mm(t.ref_h_fast),
        t.ref_worst_model.empty() ? std::string()
                                  : fmt::format(" (`{}`)", cell_text(t.ref_worst_model, 60)),
        mm(t.ref_area), t.ref_differing, with_thousands(t.ref_outlined),
        with_thousands(t.ref_layers_at_vertex), t.ref_differing_at_vertex, t.ref_open,
        skipped.empty() ? std::string("none") : fmt::format("{}", fmt::join(skipped, ", ")),
        t.ref_s);
  }
  out += fmt::format("| corpus files skipped (over {} bytes) | {} |\n", with_thousands(o.max_bytes),
                     too_large.size());
  out += fmt::format("| files that could not be read | {} |\n\n", t.unreadable);
  return out;
}

std::string refusals_section(const Totals& t) {
  std::string out;
  if (!t.refusal_reasons.empty()) {
    out += "### Refusals and failures of the exact path\n\n";
    for (const auto& [reason, where] : t.refusal_reasons) {
      out += fmt::format("- {} run(s): `{}` — {}\n", where.size(), cell_text(reason, 160),
                         cell_text(fmt::format("{}", fmt::join(where, "; ")), 400));
    }
    out += "\n";
  }
  return out;
}

std::string differing_cells_section(const std::vector<ModelRecord>& records, const Totals& t) {
  std::string out;
  out += "## Differing cells\n\n";
  if (t.differing == 0) {
    out += "None: on every run the two paths classify every cell identically.\n\n";
  } else {
    out +=
        "| model | grid | rule | differing | by reason | first cells (i, j, k: fast/exact, reason) "
        "|\n";
    out += "|---|---|---|---|---|---|\n";
    for (const ModelRecord& m : records) {
      for (const RunRecord& r : m.runs) {
        if (r.cells_differing == 0) continue;
        std::vector<std::string> reasons, cells;
        for (std::size_t q = 0; q < kDifferenceReasonCount; ++q) {
          if (r.by_reason[q] > 0) {
            reasons.push_back(
                fmt::format("{} {}", strata::validate::to_string(static_cast<DifferenceReason>(q)),
                            r.by_reason[q]));
          }
        }
        for (std::size_t q = 0; q < std::min<std::size_t>(5, r.first_differences.size()); ++q) {
          const auto& d = r.first_differences[q];
          cells.push_back(fmt::format("({}, {}, {}: {}/{}, {})", d.i, d.j, d.k, cell_code(d.fast),
                                      cell_code(d.exact), strata::validate::to_string(d.reason)));
        }
        out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", cell_text(m.model.name, 60),
                           r.grid_name, rule_name(r.rule), with_thousands(r.cells_differing),
                           fmt::join(reasons, ", "), fmt::join(cells, " "));
      }
    }
    out += "\n";
  }
  return out;
}

std::string models_section(const std::vector<ModelRecord>& records) {
  std::string out;
  out += "## Models\n\n";
  out +=
      "Cells: summed over the model's runs. Hausdorff: the largest distance between the two "
      "paths' contours over the layers without open chains (mm); sym. diff.: the largest area "
      "of the symmetric difference of the regions they bound under the fill rule, over the same "
      "layers (exact overlay, mm2). Where a layer's loops are open, cross, touch or are "
      "misnested, both paths give the outline of the region the fill rule fills, so their "
      "contours are compared like any other. Volume errors, from the aligned `nonzero` run, "
      "relative to the magnitude of the mesh's exact signed volume: the fast path's cells, and "
      "the exact path's contours (sum of the layers' net signed areas x dz; an outlined layer "
      "counts its filled region, so an inside-out shell counts positive, and a mesh whose "
      "shells cancel in the signed volume shows a large error). These are discretisation "
      "errors of coarse grids and defects of the meshes, not disagreements between the paths. "
      "Times: summed over the runs. ref Hausdorff: CGAL's Polygon_mesh_slicer (exact kernel) "
      "on closed, consistently oriented 2-manifolds, the largest Hausdorff distance of its "
      "contours to the exact path's / the fast path's over the layers whose plane holds no mesh "
      "vertex and which the path did not outline (an outline drops the walls between touching "
      "loops that the slicer keeps; those layers are compared by region) (mm), with "
      "the number of layers whose plane holds a vertex and differ there (legitimately: CGAL "
      "keeps a vertex on the plane, strata counts it above); otherwise why it did not run.\n\n";
  out +=
      "| model | defects | facets | cells compared | differing | Hausdorff mm | sym. diff. mm2 | "
      "ref Hausdorff mm | cells vol. | contours vol. (exact) | fast s | exact s | notes |\n";
  out += "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const ModelRecord& m : records) {
    if (m.read_error) continue;
    std::uint64_t c = 0, d = 0;
    double h = 0.0, area = 0.0, fs_ = 0.0, es = 0.0;
    std::uint32_t open_layers = 0, area_only = 0;
    std::set<std::string> notes;
    bool ref_ran = false;
    double ref_he = 0.0, ref_hf = 0.0;
    std::uint32_t ref_vertex_differ = 0, ref_generic_differ = 0;
    for (const RunRecord& r : m.runs) {
      if (r.ref_ran || r.ref_layers > 0) {
        ref_ran = true;
        ref_he = std::max(ref_he, r.ref_hausdorff_exact_mm);
        ref_hf = std::max(ref_hf, r.ref_hausdorff_fast_mm);
        ref_vertex_differ += r.ref_differing_at_vertex;
        ref_generic_differ += r.ref_differing;
      }
      if (r.ref_skipped == ReferenceSkip::Failed) notes.insert("reference: " + r.ref_reason);
      c += r.cells_compared;
      d += r.cells_differing;
      h = std::max(h, r.max_hausdorff_mm);
      area = std::max(area, r.max_symmetric_difference_mm2);
      fs_ += r.fast_seconds;
      es += r.exact_seconds;
      open_layers += r.layers_with_open_chains;
      area_only += r.layers_area_only;
      if (r.fast_error) notes.insert("fast path: " + *r.fast_error);
      if (r.exact_error) notes.insert("exact path: " + *r.exact_error);
    }
    if (open_layers > 0) notes.insert(fmt::format("open chains in {} layers", open_layers));
    if (area_only > 0) notes.insert(fmt::format("{} layers compared by area only", area_only));
    std::string cells_vol = "n/a", contour_vol = "n/a";
    if (!m.runs.empty()) {
      const RunRecord& a = m.runs.front();
      // Cells have no sign, and an inside-out shell's layers are outlined (their filled region
      // counts positive): both are compared with the volume's magnitude.
      cells_vol = percent(a.fast_cell_volume_mm3, std::fabs(a.mesh_volume_mm3));
      if (a.exact_ran) {
        contour_vol = percent(a.exact_contour_volume_mm3, std::fabs(a.mesh_volume_mm3));
      }
    }
    std::string ref_text;
    if (ref_ran) {
      ref_text = fmt::format("{} / {}", mm(ref_he), mm(ref_hf));
      if (ref_generic_differ > 0)
        ref_text += fmt::format(", **regions differ in {} layers**", ref_generic_differ);
      if (ref_vertex_differ > 0) ref_text += fmt::format(", {} at a vertex", ref_vertex_differ);
    } else if (!m.runs.empty()) {
      ref_text =
          fmt::format("not run: {}", strata::validate::to_string(m.runs.front().ref_skipped));
    }
    std::string note_text;
    for (const std::string& n : notes) note_text += (note_text.empty() ? "" : "; ") + n;
    out += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.2f} | {:.2f} | {} |\n",
        cell_text(m.model.name, 70), cell_text(m.model.defects, 110), with_thousands(m.facets),
        with_thousands(c), d > 0 ? fmt::format("**{}**", d) : "0", mm(h), mm(area), ref_text,
        cells_vol, contour_vol, fs_, es, cell_text(note_text, 160));
  }
  out += "\n";
  return out;
}

std::string skipped_section(const std::vector<ModelRecord>& records,
                            const std::vector<std::pair<std::string, std::uint64_t>>& too_large,
                            const Totals& t) {
  std::string out;
  if (t.unreadable > 0 || !too_large.empty()) {
    out += "## Skipped\n\n";
    for (const ModelRecord& m : records) {
      if (m.read_error) {
        out += fmt::format("- {}: could not be read: {}\n", m.model.name,
                           cell_text(*m.read_error, 200));
      }
    }
    for (const auto& [path, bytes] : too_large) {
      out += fmt::format("- {}: {} bytes, over the limit\n", path, with_thousands(bytes));
    }
    out += "\n";
  }
  return out;
}

}  // namespace

std::string make_report(const std::vector<ModelRecord>& records,
                        const std::vector<std::pair<std::string, std::uint64_t>>& too_large,
                        const RunnerOptions& o, double wall_seconds) {
  const Totals t = sum_runs(records);
  return summary_section(t, too_large, o, wall_seconds) + refusals_section(t) +
         differing_cells_section(records, t) + models_section(records) +
         skipped_section(records, too_large, t);
}

}  // namespace strata::validation
