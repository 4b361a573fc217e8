#include "runs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "strata/mesh/weld_vertices.hpp"

namespace strata::validation {
namespace {

using Clock = std::chrono::steady_clock;
using strata::validate::ValidationReport;

double extent(double lo, double hi) { return std::isfinite(hi - lo) ? hi - lo : 0.0; }

/// The cell size whose grid over the box has at most `max_cells` cells (layers capped at
/// max_layers), dividing the largest extent into a whole number of cells.
std::pair<double, double> budget_cell(const strata::Bbox3& box, const RunnerOptions& o) {
  const double ex = extent(box.min.x, box.max.x);
  const double ey = extent(box.min.y, box.max.y);
  const double ez = extent(box.min.z, box.max.z);
  const double longest = std::max({ex, ey, ez});
  if (!(longest > 0.0)) return {1.0, 1.0};
  for (int n = 1000; n >= 1; --n) {
    const double d = longest / n;
    const double nz = std::min<double>(o.max_layers, std::max(1.0, std::ceil(ez / d)));
    const double cells = std::max(1.0, std::ceil(ex / d)) * std::max(1.0, std::ceil(ey / d)) * nz;
    if (cells <= o.max_cells) {
      const double dz = std::ceil(ez / d) > o.max_layers ? ez / o.max_layers : d;
      return {d, dz};
    }
  }
  return {longest, longest};
}

struct GridChoice {
  std::string name;
  SliceOptions options;
};

std::vector<GridChoice> grid_choices(const ModelCase& m, const strata::Bbox3& box,
                                     const RunnerOptions& o) {
  const auto [budget_d, budget_dz] = budget_cell(box, o);
  double d = budget_d, dz = budget_dz;
  double odd_d = budget_d * kOddCellFactor, odd_dz = budget_dz * kOddCellFactor;
  if (m.aligned_cell_mm) {
    d = dz = *m.aligned_cell_mm;
    odd_d = odd_dz =
        std::max(*m.aligned_cell_mm * kGeneratedOddCellFactor, budget_d * kOddCellFactor);
  }
  std::vector<GridChoice> out;
  SliceOptions aligned;
  aligned.grid.dx_mm = aligned.grid.dy_mm = d;
  aligned.grid.dz_mm = dz;
  aligned.shell_mm = kShellCells * std::max(d, dz);
  out.push_back({"aligned", aligned});
  SliceOptions shifted;
  shifted.grid.dx_mm = shifted.grid.dy_mm = odd_d;
  shifted.grid.dz_mm = odd_dz;
  shifted.grid.origin = strata::Vec3{box.min.x - kShiftX * odd_d, box.min.y - kShiftY * odd_d,
                                     box.min.z - kShiftZ * odd_dz};
  shifted.shell_mm = kShellCells * std::max(odd_d, odd_dz);
  out.push_back({"shifted", shifted});
  return out;
}

RunRecord run_one(const strata::IndexedMesh& mesh, const std::string& grid_name,
                  SliceOptions options, FillRule rule) {
  RunRecord r;
  r.grid_name = grid_name;
  r.rule = rule;
  options.fill_rule = rule;
  auto grid = strata::make_grid(mesh.bounds(), options.grid);
  if (!grid) {
    r.fast_error = grid.error().to_string();
    return r;
  }
  r.grid = *grid;
  strata::validate::ValidateOptions vopts;
  vopts.max_listed_cells = 20;
  vopts.max_surface_samples = 50'000;
  vopts.max_shell_samples = 20'000;
  vopts.max_overlay_layers = kOverlayLayers;
  auto report = strata::validate::validate_model(mesh, *grid, options, vopts);
  if (!report) {
    r.fast_error = report.error().to_string();
    return r;
  }
  const ValidationReport& v = *report;
  if (v.exact_error) r.exact_error = v.exact_error->to_string();
  r.cells_compared = v.cells_compared;
  r.cells_differing = v.cells_differing;
  r.by_reason = v.differing_by_reason;
  r.first_differences = v.differences;
  r.max_hausdorff_mm = v.max_hausdorff_mm;
  r.max_symmetric_difference_mm2 = v.max_symmetric_difference_mm2;
  r.layers_with_open_chains = v.layers_with_open_chains;
  r.layers_area_only = v.layers_area_only;
  r.layers_overlaid = v.layers_arrangement;
  r.layers_overlay_skipped = v.layers_overlay_skipped;
  r.mesh_volume_mm3 = v.model.mesh_volume_mm3;
  r.fast_cell_volume_mm3 = v.fast.cell_volume_mm3;
  r.exact_contour_volume_mm3 = v.exact.contour_volume_mm3;
  r.exact_ran = v.exact.ran;
  r.fast_seconds = v.fast.seconds;
  r.exact_seconds = v.exact.seconds;
  r.comparison_seconds = v.comparison_seconds;
  r.surface_to_boundary_mm = v.model.surface_to_boundary_mm;
  r.shell_min_mm = v.model.shell.min_mm;
  r.asked_shell_mm = v.model.asked_shell_mm;
  const strata::validate::ReferenceSlicerFigures& ref = v.reference;
  r.ref_ran = ref.ran;
  r.ref_skipped = ref.skipped;
  r.ref_reason = ref.reason;
  r.ref_layers = ref.layers_compared;
  r.ref_layers_at_vertex = ref.layers_vertex_on_plane;
  for (const strata::validate::ReferenceLayerComparison& l : ref.layers) {
    if (l.vertex_on_plane() && (l.differs_from_exact || l.differs_from_fast)) {
      ++r.ref_differing_at_vertex;
    }
  }
  r.ref_differing = std::max(ref.layers_region_differing_exact, ref.layers_region_differing_fast);
  r.ref_outlined = std::max(ref.layers_outlined_exact, ref.layers_outlined_fast);
  r.ref_hausdorff_exact_mm = ref.max_hausdorff_exact_mm;
  r.ref_hausdorff_fast_mm = ref.max_hausdorff_fast_mm;
  r.ref_symmetric_difference_mm2 =
      std::max(ref.max_symmetric_difference_exact_mm2, ref.max_symmetric_difference_fast_mm2);
  r.ref_open_polylines = ref.open_polylines;
  r.ref_seconds = ref.seconds();
  return r;
}

}  // namespace

ModelRecord validate_case(const ModelCase& m, const RunnerOptions& o) {
  const auto started = Clock::now();
  ModelRecord record;
  record.model = m;
  auto soup = m.load();
  if (!soup) {
    // Name the file as the manifest does, not by the machine's absolute path.
    std::string message = soup.error().to_string();
    const std::string prefix = (o.corpus / "").string();
    for (std::size_t at = message.find(prefix); at != std::string::npos;
         at = message.find(prefix)) {
      message.replace(at, prefix.size(), "");
    }
    record.read_error = message;
    return record;
  }
  const strata::IndexedMesh mesh = strata::weld_vertices(*soup);
  record.facets = mesh.triangles.size();
  for (const GridChoice& g : grid_choices(m, mesh.bounds(), o)) {
    for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
      record.runs.push_back(run_one(mesh, g.name, g.options, rule));
    }
  }
  record.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  return record;
}

}  // namespace strata::validation
