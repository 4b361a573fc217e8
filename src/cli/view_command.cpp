#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/load_model.hpp"
#include "cli/slice_command.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/io/read_cells.hpp"
#include "strata/slicer/slice_model.hpp"
#include "strata/view/view_page.hpp"
#include "strata/view/view_stack.hpp"

namespace strata::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct ViewCommandOptions {
  std::string input;  ///< a model, or an output folder of `strata slice`
  SliceCommandOptions slice;
};

std::optional<std::string> read_text(const fs::path& path) {
  std::FILE* f = std::fopen(path.string().c_str(), "rb");
  if (f == nullptr) return std::nullopt;
  std::string text;
  char buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) return std::nullopt;
  return text;
}

/// The files of an output folder the page is made from.
struct FolderContents {
  fs::path cells;  ///< <stem>.cells, else <stem>.cells.txt
  std::string stem;
  std::optional<fs::path> report;      ///< <stem>.json with a "grid"
  std::optional<fs::path> validation;  ///< a `strata validate --json` report
};

Result<FolderContents> find_outputs(const fs::path& dir) {
  FolderContents found;
  std::vector<fs::path> binary, ascii, jsons;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    const std::string name = entry.path().filename().string();
    const auto ends_with = [&](std::string_view tail) {
      return name.size() > tail.size() &&
             name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    if (ends_with(".cells")) binary.push_back(entry.path());
    if (ends_with(".cells.txt")) ascii.push_back(entry.path());
    if (ends_with(".json")) jsons.push_back(entry.path());
  }
  if (ec) return Error{ErrorCode::BadInput, ec.message(), dir.string()};
  std::sort(binary.begin(), binary.end());
  std::sort(ascii.begin(), ascii.end());
  std::sort(jsons.begin(), jsons.end());
  if (binary.size() + ascii.size() == 0) {
    return Error{ErrorCode::BadInput,
                 "no cells file (.cells or .cells.txt) here: slice with --format cells first",
                 dir.string()};
  }
  if (binary.size() > 1 || (binary.empty() && ascii.size() > 1)) {
    return Error{ErrorCode::BadInput,
                 "more than one cells file here: make the page from each model's own folder",
                 dir.string()};
  }
  if (!binary.empty()) {
    found.cells = binary.front();
    found.stem = found.cells.stem().string();
  } else {
    found.cells = ascii.front();
    found.stem = found.cells.stem().stem().string();
  }
  for (const fs::path& path : jsons) {
    auto text = read_text(path);
    if (!text) continue;
    const json j = json::parse(*text, nullptr, false);
    if (!j.is_object()) continue;
    if (path.filename() == found.stem + ".json" && j.contains("grid") && j.contains("parameters")) {
      found.report = path;
    } else if (j.contains("cells") && j["cells"].is_object() &&
               j["cells"].contains("differences") && j.contains("exact")) {
      if (!found.validation) found.validation = path;
    }
  }
  return found;
}

/// Where the report says the model was, as given then or from the folder's side.
std::optional<fs::path> locate_model(const json& report, const fs::path& dir) {
  if (!report.contains("model") || !report["model"].contains("path")) return std::nullopt;
  const fs::path recorded = report["model"]["path"].get<std::string>();
  std::error_code ec;
  for (const fs::path& candidate :
       {recorded, dir.parent_path() / recorded, dir / recorded.filename(),
        dir.parent_path() / recorded.filename()}) {
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

bool same_grid(const GridSpec& a, const GridSpec& b) {
  return a.nx == b.nx && a.ny == b.ny && a.nz == b.nz && a.x0 == b.x0 && a.y0 == b.y0 &&
         a.z0 == b.z0 && a.dx == b.dx && a.dy == b.dy && a.dz == b.dz;
}

/// The slice options a report records, so that a fresh slice of the model lands on its grid.
Result<SliceOptions> options_of_report(const json& report) {
  try {
    const json& p = report.at("parameters");
    SliceCliOptions cli;
    cli.layer_mm = p.at("layer_mm").get<double>();
    cli.dx_mm = p.at("dx_mm").get<double>();
    cli.dy_mm = p.at("dy_mm").get<double>();
    cli.shell_mm = p.at("shell_mm").get<double>();
    cli.shell_mode = p.at("shell_mode").get<std::string>();
    cli.fill_rule = p.at("fill_rule").get<std::string>();
    cli.scan_offset_mm = p.at("scan_offset_mm").get<double>();
    cli.origin = report.at("grid").at("origin_mm").get<std::vector<double>>();
    return to_slice_options(cli);
  } catch (const json::exception& e) {
    return Error{
        ErrorCode::BadInput, fmt::format("the report lacks a parameter: {}", e.what()), {}};
  }
}

int run_view_folder(const ViewCommandOptions& o) {
  const fs::path dir = o.input;
  const PageOptions& page_options = o.slice.page;
  auto found = find_outputs(dir);
  if (!found) return report_error(found.error());

  view::ViewPage page;
  page.title = found->stem;
  page.source_kind = "folder";
  page.source_path = dir.string();

  // The cells file is what the page shows; a fresh slice of the model adds its contours.
  view::ViewStackCollector from_file(view::ViewStackOptions{.hatches = false, .contours = false});
  const auto header = io::read_cells_layers(
      found->cells,
      [&](const io::CellsHeader& h, std::uint32_t k,
          std::span<const CellClass> cells) -> Result<void> {
        if (k == 0) {
          SliceRunInfo run;
          run.grid = h.grid;
          run.options.shell_mm = h.shell_mm;
          run.model_name = found->stem;
          if (auto ok = from_file.begin(run); !ok) return ok;
        }
        const std::vector<CellClass> layer(cells.begin(), cells.end());
        const LayerContours no_contours;
        const std::vector<HatchSegment> no_hatches;
        return from_file.add_layer(LayerResult{k, h.grid.zk(k), layer, no_contours, no_hatches});
      });
  if (!header) return report_error(header.error());
  if (auto ok = from_file.finish(); !ok) return report_error(ok.error());
  page.stack = from_file.take();

  json report;
  if (found->report) {
    auto text = read_text(*found->report);
    report = text ? json::parse(*text, nullptr, false) : json();
    if (report.is_discarded() || !report.is_object()) {
      return report_error(Error{ErrorCode::BadInput, "not a JSON report", found->report->string()});
    }
    page.report_json = report.dump();
  } else {
    page.notes.push_back(
        fmt::format("no report ({}.json) in the folder: counts by layer and the "
                    "model are not shown",
                    found->stem));
  }
  if (found->validation) {
    auto text = read_text(*found->validation);
    if (text) page.validation_json = *text;
  }

  std::optional<LoadedModel> model;
  if (found->report) {
    if (const auto path = locate_model(report, dir)) {
      // Read as the slice read it: the report records the unit and scale asked then.
      io::CoordinateScale scale;
      scale.units =
          io::parse_length_unit(report.value(json::json_pointer("/model/units"), std::string("mm")))
              .value_or(io::LengthUnit::Millimetre);
      scale.scale = report.value(json::json_pointer("/model/scale"), 1.0);
      auto loaded = load_model(*path, scale);
      if (!loaded) return report_error(loaded.error());
      model = std::move(loaded).value();
    } else {
      page.notes.push_back(fmt::format(
          "model not found ({}): the page shows the cells file without the 3D model, contours "
          "and defects",
          report.value(json::json_pointer("/model/path"), std::string("no path in the report"))));
    }
  }
  if (model) {
    diagnose::DiagnoseOptions diagnose_options;
    diagnose_options.max_locations = page_options.max_defects;
    page.check = diagnose::diagnose_mesh(model->mesh, model->soup, diagnose_options);
    page.model_mesh = &model->mesh;
    view::NotedDisplayMesh display = view::make_noted_display_mesh(
        model->mesh, page_options.max_facets, view::SliceStage::Sliced, view::CountDigits::Plain);
    page.mesh = std::move(display.mesh);
    if (display.note) page.notes.push_back(std::move(*display.note));
    // Contours and scanlines come from slicing the model again on the report's grid; the cells
    // shown stay the file's, and any layer where the two differ is named.
    auto options = options_of_report(report);
    Result<GridSpec> grid = options ? make_grid(model->mesh.bounds(), options->grid)
                                    : Result<GridSpec>(options.error());
    if (!grid || !same_grid(*grid, page.stack.grid)) {
      page.notes.push_back(
          "the report's parameters do not give the cells file's grid: contours "
          "are not shown");
    } else {
      view::ViewStackCollector fresh(view::ViewStackOptions{.hatches = page_options.hatches});
      LayerSink* sinks[] = {&fresh};
      auto summary = slice_model(model->mesh, *grid, *options, sinks);
      if (!summary) return report_error(summary.error());
      view::ViewStack sliced = fresh.take();
      std::uint32_t differing = 0;
      for (std::size_t n = 0; n < sliced.stored.size(); ++n) {
        if (sliced.cells_zlib[n] != page.stack.cells_zlib[n]) ++differing;
      }
      if (differing > 0) {
        page.notes.push_back(fmt::format(
            "{} layers of the cells file differ from a fresh slice of the model with the "
            "report's parameters: the page shows the file's cells",
            differing));
      }
      page.stack.contours = std::move(sliced.contours);
      page.stack.hatches = std::move(sliced.hatches);
      page.stack.has_hatches = sliced.has_hatches;
    }
  }
  view::fit_to_budget(page.stack, static_cast<std::uint64_t>(page_options.budget_mb * 1e6));

  const fs::path out =
      page_options.path.empty() ? dir / (found->stem + ".html") : fs::path(page_options.path);
  std::error_code ec;
  if (out.has_parent_path()) fs::create_directories(out.parent_path(), ec);
  if (auto ok = view::write_view_page(out, page); !ok) return report_error(ok.error());
  if (!o.slice.quiet) {
    std::printf("page    %s (open %s in a browser; it works offline)\n", out.string().c_str(),
                fs::absolute(out, ec).string().c_str());
  }
  return kExitOk;
}

int run_view(ViewCommandOptions o) {
  std::error_code ec;
  if (fs::is_directory(o.input, ec)) return run_view_folder(o);
  o.slice.model = o.input;
  o.slice.formats = "html";
  o.slice.page.full_check = true;
  if (o.slice.page.path.empty()) o.slice.page.path = model_stem(o.input) + ".html";
  return run_slice(o.slice);
}

constexpr const char* kViewHelp =
    "Writes one self-contained HTML page (it opens from disk, offline, in any current browser)\n"
    "that shows the model in 3D with its defects, every layer's cells with contours and\n"
    "scanlines, vertical sections, the sliced entity in 3D, and the report.\n\n"
    "From a model it slices first (the slice options above, with the defaults of `strata\n"
    "slice`) and checks the mesh as `strata check` does. From an output folder of `strata\n"
    "slice` it shows the cells file there as it is, with the report, a `strata validate\n"
    "--json` report if one is there, and the model the report names (read again for the 3D\n"
    "view, its defects and the contours); the slice options do not apply then.\n\n"
    "Example: strata view part.stl --cell 0.5 --layer 0.5 -o part.html";

}  // namespace

void register_view_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<ViewCommandOptions>();
  CLI::App* cmd = app.add_subcommand("view", "Write an interactive HTML page of a slice");
  cmd->footer(kViewHelp);
  cmd->add_option("INPUT", options->input,
                  "A model (STL, OBJ, OFF, PLY, .gz of one) or an output folder of `strata slice`")
      ->required();
  cmd->add_option("-o,--output", options->slice.page.path,
                  "The page to write (default: <stem>.html here for a model, <folder>/<stem>.html "
                  "for a folder)");
  add_slice_options(*cmd, options->slice.slice);
  cmd->add_option("--kernel", options->slice.kernel,
                  "fast: double with exact predicates; exact: CGAL (a model only)")
      ->default_val("fast")
      ->check(CLI::IsMember({"fast", "exact"}));
  auto* repair = cmd->add_flag("--repair", options->slice.repair,
                               "Repair the mesh in memory before slicing (a model only)");
  cmd->add_flag("--fill-holes", options->slice.fill_holes, "With --repair: fill holes too")
      ->needs(repair);
  add_page_options(*cmd, options->slice.page);
  cmd->add_flag("-q,--quiet", options->slice.quiet, "Print nothing on success");
  cmd->callback([options, &runner] { runner = [options] { return run_view(*options); }; });
}

}  // namespace strata::cli
