#include "comparison.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace strata::validation {

Totals sum_runs(const std::vector<ModelRecord>& records) {
  Totals t;
  for (const ModelRecord& m : records) {
    if (m.read_error) {
      ++t.unreadable;
      continue;
    }
    ++t.models;
    if (m.model.source == "generated") ++t.generated;
    bool ref_any = false;
    for (const RunRecord& r : m.runs) {
      t.ref_s += r.ref_seconds;
      if (!r.ref_ran && r.ref_layers == 0) continue;
      ref_any = true;
      ++t.ref_runs;
      t.ref_layers += r.ref_layers;
      t.ref_layers_at_vertex += r.ref_layers_at_vertex;
      t.ref_differing += r.ref_differing;
      t.ref_outlined += r.ref_outlined;
      t.ref_differing_at_vertex += r.ref_differing_at_vertex;
      t.ref_open += r.ref_open_polylines;
      const double h = std::max(r.ref_hausdorff_exact_mm, r.ref_hausdorff_fast_mm);
      if (h > t.ref_worst) {
        t.ref_worst = h;
        t.ref_worst_model = m.model.name;
      }
      t.ref_h_exact = std::max(t.ref_h_exact, r.ref_hausdorff_exact_mm);
      t.ref_h_fast = std::max(t.ref_h_fast, r.ref_hausdorff_fast_mm);
      t.ref_area = std::max(t.ref_area, r.ref_symmetric_difference_mm2);
    }
    if (ref_any) {
      ++t.ref_models;
    } else if (!m.runs.empty()) {
      ++t.ref_skipped_models[strata::validate::to_string(m.runs.front().ref_skipped)];
    }
    for (const RunRecord& r : m.runs) {
      ++t.runs;
      t.compared += r.cells_compared;
      t.differing += r.cells_differing;
      if (r.cells_differing > 0) ++t.runs_differing;
      for (std::size_t q = 0; q < kDifferenceReasonCount; ++q) t.by_reason[q] += r.by_reason[q];
      if (r.fast_error) ++t.fast_failures;
      if (r.exact_error) {
        ++t.refusals;
        t.refusal_reasons[r.exact_error->substr(0, 160)].push_back(
            fmt::format("{} ({}, {})", m.model.name, r.grid_name, strata::to_string(r.rule)));
      }
      if (r.exact_ran && !r.fast_error) {
        t.fast_s += r.fast_seconds;
        t.exact_s += r.exact_seconds;
      }
      t.comparison_s += r.comparison_seconds;
      t.overlaid += r.layers_overlaid;
      t.overlay_skipped += r.layers_overlay_skipped;
      t.area_only += r.layers_area_only;
      t.max_hausdorff = std::max(t.max_hausdorff, r.max_hausdorff_mm);
    }
  }
  return t;
}

}  // namespace strata::validation
