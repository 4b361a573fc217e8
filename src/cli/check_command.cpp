#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/job_plan.hpp"
#include "cli/load_model.hpp"
#include "cli/units_options.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/diagnose/mesh_report_json.hpp"
#include "strata/diagnose/mesh_report_text.hpp"
#include "strata/io/output_file.hpp"
#include "strata/io/write_stl.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/repair/repair_log_json.hpp"
#include "strata/repair/repair_log_text.hpp"
#include "strata/repair/repair_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata::cli {

namespace {

namespace fs = std::filesystem;

struct CheckOptions {
  std::string model;
  std::string json_file;
  bool json_stdout = false;
  std::string repair_output;  ///< --repair OUT; empty: no repair
  bool fill_holes = false;
  UnitsCliOptions units;
};

/// True when `out` names the same file as `in` (also through another spelling or a link).
bool same_file(const fs::path& in, const fs::path& out) {
  std::error_code ec;
  if (fs::exists(out, ec) && fs::equivalent(in, out, ec)) return true;
  return fs::weakly_canonical(in, ec) == fs::weakly_canonical(out, ec);
}

/// The repaired mesh, its log and its diagnostics, for the reports.
struct RepairOutcome {
  repair::RepairResult result;
  diagnose::MeshReport after;
  double seconds = 0.0;
};

std::string report_json(const diagnose::MeshReport& before, const RepairOutcome* repaired,
                        const std::string& output) {
  if (repaired == nullptr) return diagnose::mesh_report_json(before) + "\n";
  nlohmann::ordered_json out = nlohmann::ordered_json::parse(diagnose::mesh_report_json(before));
  nlohmann::ordered_json log =
      nlohmann::ordered_json::parse(repair::repair_log_json(repaired->result.log));
  log["file"] = output;
  log["seconds"] = repaired->seconds;
  log["verdict_before"] = diagnose::verdict_name(before.verdict);
  log["verdict_after"] = diagnose::verdict_name(repaired->after.verdict);
  log["after"] = nlohmann::ordered_json::parse(diagnose::mesh_report_json(repaired->after));
  out["repair"] = std::move(log);
  return out.dump() + "\n";
}

int run_check(const CheckOptions& o) {
  const bool repair_asked = !o.repair_output.empty();
  if (repair_asked && same_file(o.model, o.repair_output)) {
    return report_error(Error{ErrorCode::Usage,
                              "--repair would overwrite the model it reads; name another file",
                              o.repair_output});
  }
  auto model = load_model(o.model, to_coordinate_scale(o.units));
  if (!model) return report_error(model.error());
  const diagnose::MeshReport report = diagnose::diagnose_mesh(model->mesh, model->soup);

  std::unique_ptr<RepairOutcome> repaired;
  if (repair_asked) {
    const auto started = std::chrono::steady_clock::now();
    auto result =
        repair::repair_mesh(model->soup, repair::RepairOptions{.fill_holes = o.fill_holes});
    if (!result) return report_error(result.error());
    repaired = std::make_unique<RepairOutcome>();
    repaired->result = std::move(result).value();
    repaired->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (auto ok = io::write_stl(o.repair_output, repaired->result.soup, io::StlEncoding::Binary);
        !ok) {
      return report_error(ok.error());
    }
    repaired->after =
        diagnose::diagnose_mesh(weld_vertices(repaired->result.soup), repaired->result.soup);
  }

  if (!o.json_file.empty()) {
    if (auto ok =
            io::write_text_file(o.json_file, report_json(report, repaired.get(), o.repair_output));
        !ok) {
      return report_error(ok.error());
    }
  }
  if (o.json_stdout) {
    std::fputs(report_json(report, repaired.get(), o.repair_output).c_str(), stdout);
    return kExitOk;
  }
  std::fprintf(stdout, "model    %s (%s)\n", model->path.string().c_str(),
               model->soup.format.c_str());
  for (const auto& d : model->soup.diagnostics) {
    std::fprintf(stdout, "%s  %s\n", d.severity == Severity::Warning ? "warning" : "note   ",
                 d.message.c_str());
  }
  const Bbox3 box = model->mesh.bounds();
  std::fprintf(stdout, "size     %s\n", size_text(box).c_str());
  if (const auto warning =
          size_warning(box, Vec3{kDefaultCellSizeMm, kDefaultCellSizeMm, kDefaultLayerHeightMm})) {
    std::fprintf(stdout, "warning  %s\n", warning->c_str());
  }
  // What `strata slice` would make of it with the default settings.
  if (const auto grid = make_grid(box, GridOptions{}); grid) {
    const JobPlan plan = plan_job(*grid, {"cells", "png", "json", "html"}, 0);
    std::fprintf(stdout, "slice    at the defaults: %s\n", plan_text(plan).c_str());
  } else {
    std::fprintf(stdout, "slice    at the defaults: %s\n", grid.error().message.c_str());
  }
  std::fputs(diagnose::mesh_report_text(report).c_str(), stdout);
  if (repaired) {
    std::fputs("\n", stdout);
    std::fputs(repair::repair_log_text(repaired->result.log, "--fill-holes not given").c_str(),
               stdout);
    std::fprintf(stdout, "\nrepaired %s (binary STL, %zu facets, %.3f s)\n",
                 o.repair_output.c_str(), repaired->result.soup.triangles.size(),
                 repaired->seconds);
    std::fputs(diagnose::mesh_report_text(repaired->after).c_str(), stdout);
    std::fprintf(stdout, "\nverdict before repair: %s\nverdict after repair:  %s\n",
                 diagnose::verdict_name(report.verdict),
                 diagnose::verdict_name(repaired->after.verdict));
  }
  return kExitOk;
}

}  // namespace

void register_check_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* cmd =
      app.add_subcommand("check", "Report a mesh's defects and whether it can be printed as is");
  cmd->add_option("MODEL", options->model, "Mesh file: STL, OBJ, OFF, PLY, or .gz of one")
      ->required();
  auto* json_file = cmd->add_option("--json-file", options->json_file,
                                    "Also write the report as JSON to this file");
  cmd->add_flag("--json", options->json_stdout, "Print the report as JSON instead of text")
      ->excludes(json_file);
  auto* repair = cmd->add_option(
      "--repair", options->repair_output,
      "Repair the mesh and write it to this binary STL file (never the model itself): exact "
      "weld, zero-area and duplicate facets removed, T-junction cracks closed, orientation made "
      "consistent, closed shells oriented to bound a volume; then check the repaired mesh too");
  cmd->add_flag("--fill-holes", options->fill_holes,
                "With --repair: fill holes with triangles between their own border vertices")
      ->needs(repair);
  add_units_options(*cmd, options->units);
  cmd->callback([options, &runner] { runner = [options] { return run_check(*options); }; });
}

}  // namespace strata::cli
