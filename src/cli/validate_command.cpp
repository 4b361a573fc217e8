#include <fmt/format.h>

#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/flag_names.hpp"
#include "cli/load_model.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "cli/slice_cli_options.hpp"
#include "strata/io/output_file.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/validate/validate_model.hpp"
#include "strata/validate/validation_json.hpp"
#include "strata/validate/validation_text.hpp"

namespace strata::cli {

namespace {

constexpr const char* kValidateDescription =
    "Slice a model twice on the same grid, with the fast path (double arithmetic with exact\n"
    "predicates, what `strata slice` uses) and with the exact path (CGAL, exact rational\n"
    "arithmetic), and compare them cell by cell and contour by contour.\n\n"
    "Prints whether every cell agrees and, for cells that differ, where they are and why\n"
    "(scan-offset, shell, near-degenerate, fill-rule or unexplained); per layer the loop counts,\n"
    "the area between the two sets of contours and their Hausdorff distance; and the accuracy\n"
    "of the result: mesh volume vs cell volume vs contour volume, bounding boxes, distance from\n"
    "the surface to the boundary cells, and the shell thickness actually obtained vs --shell.\n"
    "With --scan-offset, it also lists every cell that the offset changes.\n\n"
    "When the mesh is a closed, consistently oriented 2-manifold (at most\n"
    "--reference-max-facets facets), a third opinion: CGAL's Polygon_mesh_slicer with the\n"
    "exact kernel cuts every layer's plane, and its contours are compared with both paths'\n"
    "(Hausdorff distance, symmetric difference). It keeps a vertex lying on the plane on the\n"
    "plane where strata counts it above, so layers whose plane contains a vertex are counted\n"
    "apart. --reference-slicer off skips it.\n\n"
    "The exact path is several times slower than the fast one: use a coarser --cell/--layer\n"
    "for a quick check.\n"
    "Exit codes: 0 every cell agrees, 4 some cells differ, 1 bad input, 2 bad usage,\n"
    "3 internal error. When the exact path refuses the model or fails, the summary is printed\n"
    "and the exit code is that of its error.\n\n"
    "Example: strata validate part.stl --cell 0.5 --layer 0.5 --json part-validation.json";

struct ValidateCommandOptions {
  std::string model;
  std::string json_file;
  SliceCliOptions slice;
  std::size_t max_listed = 1000;
  bool no_contours = false;
  std::string reference_slicer = "on";
  std::size_t reference_max_facets = 200'000;
  bool quiet = false;
};

int run_validate(const ValidateCommandOptions& o) {
  auto options = to_slice_options(o.slice);
  if (!options) return report_error(options.error());
  if (options->fill_rule == FillRule::Winding) {
    return report_error(Error{ErrorCode::Usage,
                              "--fill-rule winding cannot be validated: the exact path does not "
                              "implement it (solid angles are not exact); use nonzero or evenodd",
                              {}});
  }
  auto model = load_model(o.model, to_coordinate_scale(o.slice.units));
  if (!model) return report_error(model.error());
  for (const auto& d : model->soup.diagnostics) {
    std::fprintf(stderr, "strata: %s: %s\n", d.severity == Severity::Warning ? "warning" : "note",
                 d.message.c_str());
  }
  auto grid = make_grid(model->mesh.bounds(), options->grid);
  if (!grid) return report_error(about_model(grid.error(), model->path));

  validate::ValidateOptions vopts;
  vopts.max_listed_cells = o.max_listed;
  vopts.compare_contours = !o.no_contours;
  vopts.reference_slicer = o.reference_slicer == "on" && !o.no_contours;
  vopts.reference_max_facets = o.reference_max_facets;
  Result<validate::ValidationReport> report = Error{ErrorCode::Internal, "not run", {}};
  {
    ProgressLine progress("validating " + model->path.filename().string());
    vopts.progress = [&](std::uint32_t done, std::uint32_t total) { progress.update(done, total); };
    report = validate::validate_model(model->mesh, *grid, *options, vopts);
  }
  if (!report) return report_error(report.error());
  name_flags(report->diagnostics);

  if (!o.json_file.empty()) {
    if (auto ok = io::write_text_file(o.json_file, validate::validation_json(*report)); !ok) {
      return report_error(ok.error());
    }
  }
  if (!o.quiet) {
    std::string out =
        fmt::format("model     {} ({}, {} facets, {} vertices)\n", model->path.string(),
                    model->soup.format, model->mesh.triangles.size(), model->mesh.vertices.size());
    out += validate::validation_text(*report);
    if (!o.json_file.empty()) out += fmt::format("report    {}\n", o.json_file);
    std::fputs(out.c_str(), stdout);
  }
  if (report->exact_error) {
    Error e = *report->exact_error;
    e.message = "the exact path stopped: " + e.message;
    if (e.location.empty()) e.location = model->path.string();
    return report_error(e);
  }
  return report->cells_differing == 0 ? kExitOk : kExitCellsDiffer;
}

}  // namespace

void register_validate_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<ValidateCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "validate", "Compare the fast and the exact slicing paths cell by cell; accuracy metrics");
  cmd->footer(kValidateDescription);
  cmd->add_option("MODEL", options->model,
                  "Mesh file: STL (ASCII or binary), OBJ, OFF, PLY, or .gz of one")
      ->required();
  add_slice_options(*cmd, options->slice);
  cmd->add_option("--json", options->json_file,
                  "Also write the full report (every layer, the listed cells) as JSON to FILE")
      ->type_name("FILE");
  cmd->add_option("--max-listed", options->max_listed,
                  "Differing cells (and cells changed by the scan offset) listed in the JSON "
                  "report; all are counted")
      ->default_val(1000)
      ->check(whole_number(0, std::numeric_limits<std::int64_t>::max(), "number of cells"));
  cmd->add_flag("--no-contours", options->no_contours,
                "Compare cells and loop counts only (skip the exact contour overlay and the "
                "Hausdorff distances)");
  cmd->add_option("--reference-slicer", options->reference_slicer,
                  "Also slice with CGAL's Polygon_mesh_slicer (exact kernel) and compare its "
                  "contours with both paths; runs only on closed, consistently oriented "
                  "2-manifolds")
      ->default_val("on")
      ->check(CLI::IsMember({"on", "off"}))
      ->type_name("on|off");
  cmd->add_option("--reference-max-facets", options->reference_max_facets,
                  "Skip the reference slicer on meshes with more facets than this")
      ->default_val(200'000)
      ->check(whole_number(0, std::numeric_limits<std::int64_t>::max(), "number of facets"));
  cmd->add_flag("-q,--quiet", options->quiet, "Print nothing; the exit code tells the verdict");
  cmd->callback([options, &runner] { runner = [options] { return run_validate(*options); }; });
}

}  // namespace strata::cli
