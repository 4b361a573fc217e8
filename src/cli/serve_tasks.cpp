#include "cli/serve_tasks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "cli/load_model.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/diagnose/mesh_report_json.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/validate/validate_model.hpp"
#include "strata/validate/validation_json.hpp"
#include "strata/view/view_page.hpp"

namespace strata::cli {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

Error usage(const std::string& message) { return Error{ErrorCode::Usage, message, {}}; }

/// The reader's message names the uploaded file by its name, not by its place on the server.
Error as_seen_by_the_page(Error e, const fs::path& model) {
  const std::string where = model.string();
  if (e.location.compare(0, where.size(), where) == 0) {
    e.location = model.filename().string() + e.location.substr(where.size());
  }
  if (e.message.find(where) != std::string::npos) {
    e.message.replace(e.message.find(where), where.size(), model.filename().string());
  }
  return e;
}

/// The view page's data for a model checked but not sliced yet: the display mesh and the
/// check's defects, no layer (web/DATA.md), so that the page shows the defects in 3D at once.
Result<void> write_model_view(const serve::TaskRequest& request, const LoadedModel& model,
                              const diagnose::MeshReport& report) {
  view::ViewPage page;
  page.title = model.stem;
  page.source_kind = "model";
  page.source_path = request.model.filename().string();
  const PageOptions defaults;
  view::NotedDisplayMesh display = view::make_noted_display_mesh(
      model.mesh, defaults.max_facets, view::SliceStage::NotSlicedYet, view::CountDigits::Plain);
  page.mesh = std::move(display.mesh);
  if (display.note) page.notes.push_back(std::move(*display.note));
  page.notes.push_back(
      "not sliced yet: the layers, the section and the report appear once the model is sliced");
  page.check = report;
  page.model_mesh = &model.mesh;
  // No layer: the grid is the model's box, one cell, only for the page's frame and dimensions.
  const Bbox3 box = model.mesh.bounds();
  GridSpec& g = page.stack.grid;
  g.x0 = box.min.x;
  g.y0 = box.min.y;
  g.z0 = box.min.z;
  g.dx = std::max(box.max.x - box.min.x, 1e-9);
  g.dy = std::max(box.max.y - box.min.y, 1e-9);
  g.dz = std::max(box.max.z - box.min.z, 1e-9);
  return view::write_view_page_data(serve::model_view_path(request), page);
}

Result<std::string> run_check(const serve::TaskRequest& request, const io::CoordinateScale& scale) {
  auto model = load_model(request.model, scale);
  if (!model) return as_seen_by_the_page(model.error(), request.model);
  diagnose::DiagnoseOptions diagnose_options;
  diagnose_options.max_locations = PageOptions{}.max_defects;
  const diagnose::MeshReport report =
      diagnose::diagnose_mesh(model->mesh, model->soup, diagnose_options);
  if (auto written = write_model_view(request, *model, report); !written) return written.error();
  json out = json::parse(diagnose::mesh_report_json(report));
  const auto bounds = model->mesh.bounds();
  json warnings = json::array();
  for (const auto& d : model->soup.diagnostics) warnings.push_back(d.message);
  out["model"] = {{"name", request.model.filename().string()},
                  {"format", model->soup.format},
                  {"facets", model->mesh.triangles.size()},
                  {"vertices", model->mesh.vertices.size()},
                  {"min_mm", {bounds.min.x, bounds.min.y, bounds.min.z}},
                  {"max_mm", {bounds.max.x, bounds.max.y, bounds.max.z}},
                  {"warnings", warnings}};
  return out.dump();
}

Result<std::string> run_slice_task(const serve::TaskRequest& request,
                                   const serve::TaskControl& control,
                                   const io::CoordinateScale& scale) {
  auto options = slice_options_of_json(request.options_json);
  if (!options) return options.error();
  options->slice.units.units = io::length_unit_name(scale.units);
  options->slice.units.scale = scale.scale;
  options->model = request.model.string();
  options->output_dir = request.output_dir.string();
  options->formats = "cells,png,svg,cli,json,html";
  options->quiet = true;
  options->page.full_check = true;
  options->page.data_path = request.output_dir / "view.json";
  SliceRunControl run;
  run.cancel = control.cancel;
  run.progress = control.progress;
  auto outcome = slice_to_folder(*options, run);
  if (!outcome) return as_seen_by_the_page(outcome.error(), request.model);
  const SliceSummary& s = outcome->summary;
  json notes = json::array();
  for (const auto& d : s.diagnostics) notes.push_back(d.message);
  return json{{"grid", {{"nx", s.grid.nx}, {"ny", s.grid.ny}, {"nz", s.grid.nz}}},
              {"cells",
               {{"empty", s.class_counts[0]},
                {"interior", s.class_counts[1]},
                {"boundary", s.class_counts[2]}}},
              {"solid_volume_mm3", s.solid_volume_mm3},
              {"open_chains", s.open_chains},
              {"seconds_slice", s.seconds},
              {"seconds_total", outcome->seconds_total},
              {"notes", notes}}
      .dump();
}

Result<std::string> run_validate_task(const serve::TaskRequest& request,
                                      const serve::TaskControl& control,
                                      const io::CoordinateScale& scale) {
  auto command = slice_options_of_json(request.options_json);
  if (!command) return command.error();
  auto options = to_slice_options(command->slice);
  if (!options) return options.error();
  if (options->fill_rule == FillRule::Winding) {
    return usage(
        "fill rule winding cannot be validated: the exact path does not implement it; use "
        "nonzero or evenodd");
  }
  auto model = load_model(request.model, scale);
  if (!model) return as_seen_by_the_page(model.error(), request.model);
  auto grid = make_grid(model->mesh.bounds(), options->grid);
  if (!grid) return as_seen_by_the_page(about_model(grid.error(), request.model), request.model);
  validate::ValidateOptions vopts;
  vopts.progress = control.progress;
  auto report = validate::validate_model(model->mesh, *grid, *options, vopts);
  if (!report) return as_seen_by_the_page(report.error(), request.model);
  return validate::validation_json(*report);
}

}  // namespace

Result<SliceCommandOptions> slice_options_of_json(const std::string& json_text) {
  const json j = json::parse(json_text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return usage("the options must be a JSON object");
  static const std::set<std::string> kKeys = {"layer",  "cell",       "dx",        "dy",
                                              "shell",  "shell_mode", "fill_rule", "scan_offset",
                                              "kernel", "origin",     "repair",    "fill_holes"};
  for (const auto& [key, value] : j.items()) {
    if (!kKeys.count(key)) return usage(fmt::format("unknown option '{}'", key));
  }
  SliceCommandOptions o;
  SliceCliOptions& s = o.slice;
  const auto number = [&](const char* key, bool positive) -> Result<std::optional<double>> {
    if (!j.contains(key) || j[key].is_null()) return std::optional<double>();
    if (!j[key].is_number()) return usage(fmt::format("--{}: a number is expected", key));
    const double v = j[key].get<double>();
    if (!std::isfinite(v) || (positive && !(v > 0.0))) {
      return usage(fmt::format("--{}: {} is not a {}number", key, v, positive ? "positive " : ""));
    }
    return std::optional<double>(v);
  };
  const auto word = [&](const char* key, std::string& out,
                        std::initializer_list<const char*> allowed) -> Result<void> {
    if (!j.contains(key) || j[key].is_null()) return {};
    if (!j[key].is_string()) return usage(fmt::format("{}: a word is expected", key));
    const std::string v = j[key].get<std::string>();
    for (const char* a : allowed) {
      if (v == a) {
        out = v;
        return {};
      }
    }
    return usage(fmt::format("{}: '{}' is not one of the choices", key, v));
  };
  const auto flag = [&](const char* key, bool& out) -> Result<void> {
    if (!j.contains(key) || j[key].is_null()) return {};
    if (!j[key].is_boolean()) return usage(fmt::format("--{}: true or false is expected", key));
    out = j[key].get<bool>();
    return {};
  };
  for (const auto& [key, target] :
       {std::pair<const char*, std::optional<double>*>{"cell", &s.cell_mm},
        {"dx", &s.dx_mm},
        {"dy", &s.dy_mm}}) {
    auto v = number(key, true);
    if (!v) return v.error();
    *target = *v;
  }
  if (s.cell_mm && (s.dx_mm || s.dy_mm)) return usage("--cell excludes --dx and --dy");
  if (auto v = number("layer", true); !v) {
    return v.error();
  } else if (*v) {
    s.layer_mm = **v;
  }
  if (auto v = number("shell", false); !v) {
    return v.error();
  } else if (*v) {
    if (**v < 0.0) return usage("--shell must be >= 0");
    s.shell_mm = **v;
  }
  if (auto v = number("scan_offset", false); !v) {
    return v.error();
  } else if (*v) {
    s.scan_offset_mm = **v;
  }
  if (auto ok = word("shell_mode", s.shell_mode, {"distance", "layers"}); !ok) return ok.error();
  if (auto ok = word("fill_rule", s.fill_rule, {"nonzero", "evenodd", "winding"}); !ok) {
    return ok.error();
  }
  if (auto ok = word("kernel", o.kernel, {"fast", "exact"}); !ok) return ok.error();
  if (auto ok = flag("repair", o.repair); !ok) return ok.error();
  if (auto ok = flag("fill_holes", o.fill_holes); !ok) return ok.error();
  if (o.fill_holes && !o.repair) return usage("--fill-holes needs --repair");
  if (j.contains("origin") && !j["origin"].is_null()) {
    const json& origin = j["origin"];
    if (!origin.is_array() || origin.size() != 3 ||
        !std::all_of(origin.begin(), origin.end(), [](const json& v) { return v.is_number(); })) {
      return usage("--origin takes three numbers X,Y,Z");
    }
    s.origin = origin.get<std::vector<double>>();
  }
  if (auto checked = to_slice_options(s); !checked) return checked.error();
  return o;
}

serve::TaskRunner make_serve_task_runner(const io::CoordinateScale& scale) {
  return [scale](const serve::TaskRequest& request,
                 const serve::TaskControl& control) -> Result<std::string> {
    switch (request.kind) {
      case serve::TaskKind::Check:
        return run_check(request, scale);
      case serve::TaskKind::Slice:
        return run_slice_task(request, control, scale);
      case serve::TaskKind::Validate:
        return run_validate_task(request, control, scale);
    }
    return Error{ErrorCode::Internal, "unknown task", {}};
  };
}

}  // namespace strata::cli
