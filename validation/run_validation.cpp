// strata-validation: cross-validates the fast path against the exact path on the generated
// degenerate models and on the shared mesh corpus, and writes a Markdown report.
//
//   strata-validation [--quick] [--only TEXT] [--corpus DIR] [--max-bytes N] [--max-cells N]
//                     [--max-layers N] [--out FILE] [--write-models DIR] [--strict]
//
// Every model is validated under the nonzero and evenodd fill rules on two grids: one aligned
// with the model's features and one that is not. Exit codes: 0 every cell agrees, 4 some cell
// differs, 3 (with --strict) a path failed or refused a model, 2 bad usage, 1 the report could
// not be written. Closed 2-manifolds are also sliced by CGAL's Polygon_mesh_slicer (exact
// kernel), whose contours are compared with both paths'.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "degenerate_models.hpp"
#include "strata/core/quiet_cgal.hpp"
#include "strata/io/output_file.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/io/write_stl.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/validate/validate_model.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using strata::FillRule;
using strata::GridSpec;
using strata::SliceOptions;
using strata::validate::DifferenceReason;
using strata::validate::kDifferenceReasonCount;
using strata::validate::ReferenceSkip;
using strata::validate::ValidationReport;

constexpr const char* kUsage =
    "usage: strata-validation [--quick] [--only TEXT] [--corpus DIR] [--max-bytes N]\n"
    "                         [--max-cells N] [--max-layers N] [--out FILE]\n"
    "                         [--write-models DIR] [--strict]\n"
    "\n"
    "Validates the fast slicing path against the exact (CGAL) path on the generated degenerate\n"
    "models and on every STL/OBJ/OFF/PLY mesh (also .gz) of the corpus, each under the nonzero\n"
    "and evenodd fill rules on an aligned and a shifted grid, and writes a Markdown report.\n"
    "Closed 2-manifolds (up to 200000 facets) are also sliced by CGAL's Polygon_mesh_slicer\n"
    "with the exact kernel, and its contours compared with both paths'.\n"
    "\n"
    "  --quick            generated models and about 10 small corpus files only\n"
    "  --only TEXT        only the models whose name contains TEXT (repeatable)\n"
    "  --corpus DIR       corpus folder with MANIFEST.tsv (default: ../shared/corpus)\n"
    "  --max-bytes N      skip corpus files larger than N bytes (default 5000000)\n"
    "  --max-cells N      cells per run at most, about (default 1000000)\n"
    "  --max-layers N     layers per run at most (default 64)\n"
    "  --out FILE         the report (default: validation/REPORT.md of the source tree)\n"
    "  --write-models DIR also write the generated models there as binary STL\n"
    "  --strict           exit 3 when a path failed or refused a model\n"
    "\n"
    "Exit codes: 0 every cell agrees, 4 some cell differs, 3 a path failed (--strict),\n"
    "2 bad usage, 1 the report could not be written.\n";

struct RunnerOptions {
  bool quick = false;
  fs::path corpus = fs::path(STRATA_SHARED_DIR) / "corpus";
  std::uint64_t max_bytes = 5'000'000;
  double max_cells = 1.0e6;
  std::uint32_t max_layers = 64;
  fs::path out = fs::path(STRATA_VALIDATION_DIR) / "REPORT.md";
  fs::path write_models;
  bool strict = false;
  std::vector<std::string> only;
};

constexpr std::size_t kQuickCorpusFiles = 10;
// The aligned grid of a corpus model divides its largest extent into whole cells; the other
// grid uses an odd cell size and an origin shifted by odd fractions of a cell.
constexpr double kOddCellFactor = 1.0731;
constexpr double kGeneratedOddCellFactor = 0.2713;
constexpr double kShiftX = 0.377, kShiftY = 0.291, kShiftZ = 0.413;
// Layers a run overlays exactly when the two paths' contours differ at rounding level only
// (layers with larger differences are always overlaid).
constexpr std::uint32_t kOverlayLayers = 16;
// The shell thickness asked in every run, in cells.
constexpr double kShellCells = 2.0;

/// A model to validate: generated or from the corpus.
struct ModelCase {
  std::string name;
  std::string source;  ///< "generated" or "corpus"
  std::string defects;
  std::uint64_t bytes = 0;
  std::function<strata::Result<strata::TriangleSoup>()> load;
  std::optional<double> aligned_cell_mm;  ///< generated models: the cell they were built for
};

/// What the report keeps of one run.
struct RunRecord {
  std::string grid_name;  ///< "aligned" or "shifted"
  FillRule rule = FillRule::NonZero;
  GridSpec grid;
  std::optional<std::string> fast_error;
  std::optional<std::string> exact_error;
  std::uint64_t cells_compared = 0;
  std::uint64_t cells_differing = 0;
  std::array<std::uint64_t, kDifferenceReasonCount> by_reason{};
  std::vector<strata::validate::CellDifference> first_differences;
  double max_hausdorff_mm = 0.0;
  double max_symmetric_difference_mm2 = 0.0;
  std::uint32_t layers_with_open_chains = 0;
  std::uint32_t layers_area_only = 0;
  std::uint32_t layers_overlaid = 0;
  std::uint32_t layers_overlay_skipped = 0;
  double mesh_volume_mm3 = 0.0;
  double fast_cell_volume_mm3 = 0.0;
  double exact_contour_volume_mm3 = 0.0;
  bool exact_ran = false;
  double fast_seconds = 0.0;
  double exact_seconds = 0.0;
  double comparison_seconds = 0.0;
  std::optional<double> surface_to_boundary_mm;
  double shell_min_mm = 0.0;
  double asked_shell_mm = 0.0;
  // The reference slicer (CGAL Polygon_mesh_slicer), over the layers whose plane holds no
  // vertex unless said otherwise.
  bool ref_ran = false;
  ReferenceSkip ref_skipped = ReferenceSkip::Off;
  std::string ref_reason;
  std::uint32_t ref_layers = 0;
  std::uint32_t ref_layers_at_vertex = 0;
  /// Layers whose regions differ from a path's (symmetric difference above the tolerance).
  std::uint32_t ref_differing = 0;
  /// Layers without a vertex on the plane that a path outlined (compared by region only).
  std::uint32_t ref_outlined = 0;
  /// Layers whose plane holds a vertex and whose contours differ from either path's.
  std::uint32_t ref_differing_at_vertex = 0;
  double ref_hausdorff_exact_mm = 0.0;
  double ref_hausdorff_fast_mm = 0.0;
  double ref_symmetric_difference_mm2 = 0.0;  ///< the larger of vs exact and vs fast
  std::uint64_t ref_open_polylines = 0;
  double ref_seconds = 0.0;
};

struct ModelRecord {
  ModelCase model;
  std::optional<std::string> read_error;
  std::size_t facets = 0;
  std::vector<RunRecord> runs;
  double seconds = 0.0;
};

// ---- corpus manifest

struct ManifestRow {
  std::string path;
  std::string format;
  std::string defects;
  std::string tags;
  std::string family;
  std::uint64_t bytes = 0;
};

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(line);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

std::optional<std::vector<ManifestRow>> read_manifest(const fs::path& dir, std::string& error) {
  std::ifstream in(dir / "MANIFEST.tsv");
  if (!in) {
    error = fmt::format("{}: cannot open", (dir / "MANIFEST.tsv").string());
    return std::nullopt;
  }
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line, '\t');
  const auto column = [&](const char* name) -> std::optional<std::size_t> {
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == name) return c;
    }
    return std::nullopt;
  };
  const auto path = column("path"), format = column("format"), defects = column("defects_summary"),
             bytes = column("bytes"), tags = column("tags"), family = column("family");
  if (!path || !format || !defects || !bytes || !tags || !family) {
    error = fmt::format("{}: missing columns (path, format, defects_summary, bytes, tags, family)",
                        (dir / "MANIFEST.tsv").string());
    return std::nullopt;
  }
  std::vector<ManifestRow> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line, '\t');
    const auto at = [&](std::size_t c) { return c < cells.size() ? cells[c] : std::string(); };
    ManifestRow row;
    row.path = at(*path);
    row.format = at(*format);
    row.defects = at(*defects);
    row.tags = at(*tags);
    row.family = at(*family);
    row.bytes = std::strtoull(at(*bytes).c_str(), nullptr, 10);
    rows.push_back(std::move(row));
  }
  return rows;
}

/// STL, OBJ, OFF or PLY, possibly gzip-compressed, by the file name.
bool is_mesh_file(const std::string& path) {
  std::string name = fs::path(path).filename().string();
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (name.size() > 3 && name.ends_with(".gz")) name.resize(name.size() - 3);
  return name.ends_with(".stl") || name.ends_with(".obj") || name.ends_with(".off") ||
         name.ends_with(".ply");
}

// ---- grids

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

// ---- running

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

// ---- report

std::string thousands(std::uint64_t n) {
  const std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out.push_back(',');
    out.push_back(digits[i]);
  }
  return out;
}

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

std::string class_code(strata::CellClass c) {
  switch (c) {
    case strata::CellClass::Empty:
      return "00";
    case strata::CellClass::Interior:
      return "01";
    case strata::CellClass::Boundary:
      return "11";
  }
  return "10";
}

std::string make_report(const std::vector<ModelRecord>& records,
                        const std::vector<std::pair<std::string, std::uint64_t>>& too_large,
                        const RunnerOptions& o, double wall_seconds) {
  std::uint64_t models = 0, generated = 0, runs = 0, compared = 0, differing = 0,
                runs_differing = 0, refusals = 0, fast_failures = 0, unreadable = 0;
  std::array<std::uint64_t, kDifferenceReasonCount> by_reason{};
  double fast_s = 0.0, exact_s = 0.0, comparison_s = 0.0;
  std::uint64_t overlaid = 0, overlay_skipped = 0, area_only = 0;
  double max_hausdorff = 0.0;
  std::map<std::string, std::vector<std::string>> refusal_reasons;
  // The reference slicer.
  std::uint64_t ref_models = 0, ref_runs = 0, ref_layers = 0, ref_layers_at_vertex = 0,
                ref_differing = 0, ref_differing_at_vertex = 0, ref_open = 0, ref_outlined = 0;
  double ref_h_exact = 0.0, ref_h_fast = 0.0, ref_area = 0.0, ref_s = 0.0, ref_worst = 0.0;
  std::string ref_worst_model;
  std::map<std::string, std::uint64_t> ref_skipped_models;
  for (const ModelRecord& m : records) {
    if (m.read_error) {
      ++unreadable;
      continue;
    }
    ++models;
    if (m.model.source == "generated") ++generated;
    bool ref_any = false;
    for (const RunRecord& r : m.runs) {
      ref_s += r.ref_seconds;
      if (!r.ref_ran && r.ref_layers == 0) continue;
      ref_any = true;
      ++ref_runs;
      ref_layers += r.ref_layers;
      ref_layers_at_vertex += r.ref_layers_at_vertex;
      ref_differing += r.ref_differing;
      ref_outlined += r.ref_outlined;
      ref_differing_at_vertex += r.ref_differing_at_vertex;
      ref_open += r.ref_open_polylines;
      const double h = std::max(r.ref_hausdorff_exact_mm, r.ref_hausdorff_fast_mm);
      if (h > ref_worst) {
        ref_worst = h;
        ref_worst_model = m.model.name;
      }
      ref_h_exact = std::max(ref_h_exact, r.ref_hausdorff_exact_mm);
      ref_h_fast = std::max(ref_h_fast, r.ref_hausdorff_fast_mm);
      ref_area = std::max(ref_area, r.ref_symmetric_difference_mm2);
    }
    if (ref_any) {
      ++ref_models;
    } else if (!m.runs.empty()) {
      ++ref_skipped_models[strata::validate::to_string(m.runs.front().ref_skipped)];
    }
    for (const RunRecord& r : m.runs) {
      ++runs;
      compared += r.cells_compared;
      differing += r.cells_differing;
      if (r.cells_differing > 0) ++runs_differing;
      for (std::size_t q = 0; q < kDifferenceReasonCount; ++q) by_reason[q] += r.by_reason[q];
      if (r.fast_error) ++fast_failures;
      if (r.exact_error) {
        ++refusals;
        refusal_reasons[r.exact_error->substr(0, 160)].push_back(
            fmt::format("{} ({}, {})", m.model.name, r.grid_name, rule_name(r.rule)));
      }
      if (r.exact_ran && !r.fast_error) {
        fast_s += r.fast_seconds;
        exact_s += r.exact_seconds;
      }
      comparison_s += r.comparison_seconds;
      overlaid += r.layers_overlaid;
      overlay_skipped += r.layers_overlay_skipped;
      area_only += r.layers_area_only;
      max_hausdorff = std::max(max_hausdorff, r.max_hausdorff_mm);
    }
  }

  std::string invocation = o.quick ? " --quick" : "";
  for (const std::string& text : o.only) invocation += " --only " + text;
  std::string out;
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
      thousands(static_cast<std::uint64_t>(o.max_cells)), o.max_layers, kShellCells,
      thousands(o.max_bytes));

  out += "## Totals\n\n";
  out += "| | |\n|---|---|\n";
  out += fmt::format("| models validated | {} ({} generated, {} from the corpus) |\n", models,
                     generated, models - generated);
  out += fmt::format("| runs (model x fill rule x grid) | {} |\n", runs);
  out += fmt::format("| cells compared | {} |\n", thousands(compared));
  std::vector<std::string> reason_parts;
  for (std::size_t q = 0; q < kDifferenceReasonCount; ++q) {
    reason_parts.push_back(
        fmt::format("{} {}", strata::validate::to_string(static_cast<DifferenceReason>(q)),
                    thousands(by_reason[q])));
  }
  out += fmt::format("| cells differing | **{}** in {} runs ({}) |\n", thousands(differing),
                     runs_differing, fmt::join(reason_parts, ", "));
  out += fmt::format(
      "| contours | largest Hausdorff distance {} mm; {} layers overlaid exactly, {} more "
      "differing at rounding level only not overlaid (at most {} overlays a run), {} compared "
      "by area only |\n",
      mm(max_hausdorff), thousands(overlaid), thousands(overlay_skipped), kOverlayLayers,
      area_only);
  out += fmt::format("| runs the exact path refused or failed | {} |\n", refusals);
  out += fmt::format("| runs the fast path refused | {} |\n", fast_failures);
  out += fmt::format("| time, fast path | {:.1f} s |\n", fast_s);
  out += fmt::format("| time, exact path | {:.1f} s |\n", exact_s);
  out += fmt::format("| exact / fast time ratio | {} |\n",
                     fast_s > 0 ? fmt::format("{:.1f}", exact_s / fast_s) : std::string("n/a"));
  out += fmt::format("| time comparing and measuring | {:.1f} s |\n", comparison_s);
  {
    std::vector<std::string> skipped;
    for (const auto& [why, n] : ref_skipped_models) skipped.push_back(fmt::format("{} {}", why, n));
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
        ref_models, models, ref_runs, thousands(ref_layers), mm(ref_h_exact), mm(ref_h_fast),
        ref_worst_model.empty() ? std::string()
                                : fmt::format(" (`{}`)", cell_text(ref_worst_model, 60)),
        mm(ref_area), ref_differing, thousands(ref_outlined), thousands(ref_layers_at_vertex),
        ref_differing_at_vertex, ref_open,
        skipped.empty() ? std::string("none") : fmt::format("{}", fmt::join(skipped, ", ")), ref_s);
  }
  out += fmt::format("| corpus files skipped (over {} bytes) | {} |\n", thousands(o.max_bytes),
                     too_large.size());
  out += fmt::format("| files that could not be read | {} |\n\n", unreadable);

  if (!refusal_reasons.empty()) {
    out += "### Refusals and failures of the exact path\n\n";
    for (const auto& [reason, where] : refusal_reasons) {
      out += fmt::format("- {} run(s): `{}` — {}\n", where.size(), cell_text(reason, 160),
                         cell_text(fmt::format("{}", fmt::join(where, "; ")), 400));
    }
    out += "\n";
  }

  out += "## Differing cells\n\n";
  if (differing == 0) {
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
          cells.push_back(fmt::format("({}, {}, {}: {}/{}, {})", d.i, d.j, d.k, class_code(d.fast),
                                      class_code(d.exact), strata::validate::to_string(d.reason)));
        }
        out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", cell_text(m.model.name, 60),
                           r.grid_name, rule_name(r.rule), thousands(r.cells_differing),
                           fmt::join(reasons, ", "), fmt::join(cells, " "));
      }
    }
    out += "\n";
  }

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
        cell_text(m.model.name, 70), cell_text(m.model.defects, 110), thousands(m.facets),
        thousands(c), d > 0 ? fmt::format("**{}**", d) : "0", mm(h), mm(area), ref_text, cells_vol,
        contour_vol, fs_, es, cell_text(note_text, 160));
  }
  out += "\n";

  if (unreadable > 0 || !too_large.empty()) {
    out += "## Skipped\n\n";
    for (const ModelRecord& m : records) {
      if (m.read_error) {
        out += fmt::format("- {}: could not be read: {}\n", m.model.name,
                           cell_text(*m.read_error, 200));
      }
    }
    for (const auto& [path, bytes] : too_large) {
      out += fmt::format("- {}: {} bytes, over the limit\n", path, thousands(bytes));
    }
    out += "\n";
  }
  return out;
}

bool parse_number(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(out) && out > 0;
}

}  // namespace

int main(int argc, char** argv) {
  strata::make_cgal_failures_throw();
  RunnerOptions o;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    const auto value = [&]() -> const char* {
      if (a + 1 >= argc) {
        std::fprintf(stderr, "strata-validation: %s needs a value\n%s", arg.c_str(), kUsage);
        return nullptr;
      }
      return argv[++a];
    };
    double number = 0;
    if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (arg == "--quick") {
      o.quick = true;
    } else if (arg == "--strict") {
      o.strict = true;
    } else if (arg == "--only") {
      const char* v = value();
      if (!v) return 2;
      o.only.emplace_back(v);
    } else if (arg == "--corpus") {
      const char* v = value();
      if (!v) return 2;
      o.corpus = v;
    } else if (arg == "--out") {
      const char* v = value();
      if (!v) return 2;
      o.out = v;
    } else if (arg == "--write-models") {
      const char* v = value();
      if (!v) return 2;
      o.write_models = v;
    } else if (arg == "--max-bytes" || arg == "--max-cells" || arg == "--max-layers") {
      const char* v = value();
      if (!v) return 2;
      if (!parse_number(v, number)) {
        std::fprintf(stderr, "strata-validation: %s takes a positive number\n%s", arg.c_str(),
                     kUsage);
        return 2;
      }
      if (arg == "--max-bytes") o.max_bytes = static_cast<std::uint64_t>(number);
      if (arg == "--max-cells") o.max_cells = number;
      if (arg == "--max-layers") o.max_layers = static_cast<std::uint32_t>(std::max(1.0, number));
    } else {
      std::fprintf(stderr, "strata-validation: unknown argument '%s'\n%s", arg.c_str(), kUsage);
      return 2;
    }
  }

  const auto started = Clock::now();
  std::vector<ModelCase> cases;
  for (strata::validation::GeneratedModel& g : strata::validation::degenerate_models()) {
    if (!o.write_models.empty()) {
      std::error_code ec;
      fs::create_directories(o.write_models, ec);
      if (auto ok = strata::io::write_stl(o.write_models / (g.name + ".stl"), g.soup); !ok) {
        std::fprintf(stderr, "strata-validation: %s\n", ok.error().to_string().c_str());
        return 1;
      }
    }
    auto soup = std::make_shared<strata::TriangleSoup>(std::move(g.soup));
    cases.push_back({g.name, "generated", g.defects, 0,
                     [soup]() -> strata::Result<strata::TriangleSoup> { return *soup; },
                     g.cell_mm});
  }

  std::vector<std::pair<std::string, std::uint64_t>> too_large;
  std::string manifest_error;
  const auto rows = read_manifest(o.corpus, manifest_error);
  if (!rows) {
    std::fprintf(stderr, "strata-validation: %s\n", manifest_error.c_str());
    return 2;
  }
  std::vector<ManifestRow> chosen;
  for (const ManifestRow& row : *rows) {
    if (!is_mesh_file(row.path)) continue;
    if (row.bytes > o.max_bytes) {
      too_large.emplace_back(row.path, row.bytes);
      continue;
    }
    chosen.push_back(row);
  }
  if (o.quick) {
    // Small, readable files of distinct families, smallest first.
    std::sort(chosen.begin(), chosen.end(),
              [](const ManifestRow& a, const ManifestRow& b) { return a.bytes < b.bytes; });
    std::vector<ManifestRow> quick;
    std::set<std::string> families;
    for (const ManifestRow& row : chosen) {
      if (quick.size() >= kQuickCorpusFiles) break;
      if (row.bytes < 1000 || row.tags.find("empty-or-malformed") != std::string::npos) continue;
      if (!families.insert(row.family).second) continue;
      quick.push_back(row);
    }
    chosen = std::move(quick);
    too_large.clear();
  }
  std::sort(chosen.begin(), chosen.end(),
            [](const ManifestRow& a, const ManifestRow& b) { return a.path < b.path; });
  for (const ManifestRow& row : chosen) {
    const fs::path full = o.corpus / row.path;
    cases.push_back({row.path, "corpus", row.defects, row.bytes,
                     [full]() { return strata::io::read_mesh(full); }, std::nullopt});
  }

  if (!o.only.empty()) {
    std::erase_if(cases, [&](const ModelCase& c) {
      return std::none_of(o.only.begin(), o.only.end(), [&](const std::string& text) {
        return c.name.find(text) != std::string::npos;
      });
    });
  }

  std::vector<ModelRecord> records;
  bool any_differ = false, any_failure = false;
  for (std::size_t q = 0; q < cases.size(); ++q) {
    ModelRecord record = validate_case(cases[q], o);
    std::uint64_t differing = 0;
    double fast_s = 0, exact_s = 0;
    for (const RunRecord& r : record.runs) {
      differing += r.cells_differing;
      fast_s += r.fast_seconds;
      exact_s += r.exact_seconds;
      if (r.fast_error || r.exact_error) any_failure = true;
    }
    any_differ = any_differ || differing > 0;
    if (record.read_error) {
      std::fprintf(stderr, "[%zu/%zu] %s: unreadable: %s\n", q + 1, cases.size(),
                   record.model.name.c_str(), record.read_error->c_str());
    } else {
      std::fprintf(stderr,
                   "[%zu/%zu] %s: %zu runs, %llu cells differ, fast %.2f s, exact %.2f s%s\n",
                   q + 1, cases.size(), record.model.name.c_str(), record.runs.size(),
                   static_cast<unsigned long long>(differing), fast_s, exact_s,
                   std::any_of(record.runs.begin(), record.runs.end(),
                               [](const RunRecord& r) { return r.exact_error.has_value(); })
                       ? " (exact path refused or failed)"
                       : "");
    }
    records.push_back(std::move(record));
  }
  const double wall = std::chrono::duration<double>(Clock::now() - started).count();
  const std::string report = make_report(records, too_large, o, wall);
  if (o.out.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(o.out.parent_path(), ec);
  }
  if (auto ok = strata::io::write_text_file(o.out, report); !ok) {
    std::fprintf(stderr, "strata-validation: %s\n", ok.error().to_string().c_str());
    return 1;
  }
  std::fprintf(stderr, "strata-validation: report written to %s\n", o.out.string().c_str());
  if (any_differ) return 4;
  if (o.strict && any_failure) return 3;
  return 0;
}
