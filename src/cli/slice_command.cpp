#include "cli/slice_command.hpp"

#include <fmt/format.h>
#include <malloc.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "cli/command.hpp"
#include "cli/exit_code.hpp"
#include "cli/flag_names.hpp"
#include "cli/job_plan.hpp"
#include "cli/load_model.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "cli/slice_cli_options.hpp"
#include "cli/slice_report.hpp"
#include "strata/core/thousands.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/exact/slice_exact.hpp"
#include "strata/export/cells_writer.hpp"
#include "strata/export/cli_writer.hpp"
#include "strata/export/png_stack_writer.hpp"
#include "strata/export/svg_writer.hpp"
#include "strata/io/output_file.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/pipeline/cancel_sink.hpp"
#include "strata/repair/repair_log_json.hpp"
#include "strata/repair/repair_log_text.hpp"
#include "strata/repair/repair_mesh.hpp"
#include "strata/slice/layer_range.hpp"
#include "strata/slice/slice_fingerprint.hpp"
#include "strata/slicer/slice_model.hpp"
#include "strata/view/view_page.hpp"
#include "strata/view/view_stack.hpp"

namespace strata::cli {

namespace {

namespace fs = std::filesystem;

const std::set<std::string> kFormats = {"cells", "cells-ascii", "png",  "svg",
                                        "cli",   "cli-binary",  "json", "html"};

Result<std::set<std::string>> parse_formats(const std::string& list) {
  std::set<std::string> formats;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty()) continue;
    if (!kFormats.count(item)) {
      return Error{ErrorCode::Usage,
                   fmt::format("--format: unknown format '{}' (known: cells, cells-ascii, png, "
                               "svg, cli, cli-binary, json, html)",
                               item),
                   {}};
    }
    formats.insert(item);
  }
  if (formats.empty()) return Error{ErrorCode::Usage, "--format: no format given", {}};
  return formats;
}

/// The fingerprint of SPEC §3.1b: the model's bytes and every option that decides a cell, here
/// also how the model is read (units, scale, repair) and the kernel (which makes the contours).
Result<std::string> run_fingerprint(const SliceCommandOptions& o, const LoadedModel& m,
                                    const SliceOptions& options) {
  const std::string text = fmt::format(
      "{};units={};scale={:a};repair={};fill_holes={};kernel={}", cell_options_text(options),
      io::length_unit_name(m.scale.units), m.scale.scale, o.repair, o.fill_holes, o.kernel);
  return slice_fingerprint(m.path, text);
}

std::string file_url(const fs::path& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) absolute = path;
  std::string url = "file://";
  for (const unsigned char c : absolute.lexically_normal().string()) {
    if (std::isalnum(c) || std::strchr("/-._~", c) != nullptr) {
      url.push_back(static_cast<char>(c));
    } else {
      url += fmt::format("%{:02X}", c);
    }
  }
  return url;
}

}  // namespace

Result<SliceOutcome> slice_to_folder(const SliceCommandOptions& o, const SliceRunControl& control) {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  auto options = to_slice_options(o.slice);
  if (!options) return options.error();
  // --threads holds for the whole run: reading, diagnosing and the page's model too, not only
  // the slicing (which sets the same limit).
  std::optional<tbb::global_control> thread_limit;
  if (options->threads > 0) {
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism,
                         static_cast<std::size_t>(options->threads));
  }
  if (!o.layers.empty()) {
    auto range = parse_layer_range(o.layers);
    if (!range) return Error{ErrorCode::Usage, "--layers: " + range.error().message, {}};
    options->layers = *range;
  }
  const bool ranged = !o.layers.empty();
  auto formats = parse_formats(ranged && !o.formats_given ? kDefaultRangeFormats : o.formats);
  if (!formats) return formats.error();
  if (ranged && formats->count("html")) {
    return Error{ErrorCode::Usage,
                 "--format html: the view page shows a whole run; merge the ranges with `strata "
                 "merge` and run `strata view` on the merged folder",
                 {}};
  }
  // The report counts the cells; contour outputs alone (cli, cli-binary, svg) do not need them.
  options->always_classify = formats->count("json") > 0;
  const auto cancelled = [&] {
    return control.cancel != nullptr && control.cancel->load(std::memory_order_relaxed);
  };
  const Error cancel_error{ErrorCode::Internal, kCancelledMessage, {}};

  SliceOutcome out;
  auto model = load_model(o.model, to_coordinate_scale(o.slice.units));
  if (!model) return model.error();
  out.model = std::move(model).value();
  LoadedModel& m = out.model;
  if (control.read_warnings) control.read_warnings(m.soup.diagnostics);
  if (o.repair) {
    // The repaired mesh replaces the one read, in memory only; the model file is not touched.
    const auto repair_started = Clock::now();
    auto repaired = repair::repair_mesh(m.soup, repair::RepairOptions{.fill_holes = o.fill_holes});
    if (!repaired) return repaired.error();
    repaired->soup.format = m.soup.format;
    m.soup = std::move(repaired->soup);
    m.mesh = weld_vertices(m.soup);
    out.repair_log = std::move(repaired->log);
    out.seconds_repair = std::chrono::duration<double>(Clock::now() - repair_started).count();
  }
  const Bbox3 bounds = m.mesh.bounds();
  auto grid = make_grid(bounds, options->grid);
  if (!grid) return about_model(grid.error(), m.path);
  auto span = resolve_layer_range(options->layers, grid->nz);
  if (!span) {
    return about_model(Error{ErrorCode::Usage, "--layers: " + span.error().message, {}}, m.path);
  }
  GridSpec range_grid = *grid;
  range_grid.nz = span->count();
  out.plan = plan_job(range_grid, *formats, options->threads);
  out.size_warning = size_warning(bounds, Vec3{grid->dx, grid->dy, grid->dz});
  if (control.planned) control.planned(out.plan, out.size_warning);
  if (cancelled()) return cancel_error;

  out.dir = o.output_dir.empty() ? fs::path(m.stem + "-strata") : fs::path(o.output_dir);
  const fs::path& dir = out.dir;
  const std::string& stem = m.stem;
  std::error_code ec;
  const bool dir_existed = fs::exists(dir, ec);
  if (dir_existed && !fs::is_directory(dir, ec)) {
    return Error{ErrorCode::Usage, "the output path exists and is not a folder", dir.string()};
  }
  // Before any output: a job whose files cannot fit fails now, not after hours of slicing.
  if (auto full = check_free_space(out.plan, dir)) return *full;

  std::vector<std::unique_ptr<LayerSink>> owned;
  std::vector<std::string>& written = out.written;
  if (control.cancel != nullptr) owned.push_back(std::make_unique<CancelSink>(*control.cancel));
  if (formats->count("cells")) {
    owned.push_back(io::make_cells_writer(dir / (stem + ".cells"), io::CellsEncoding::Binary));
    written.push_back(stem + ".cells");
  }
  if (formats->count("cells-ascii")) {
    owned.push_back(io::make_cells_writer(dir / (stem + ".cells.txt"), io::CellsEncoding::Ascii));
    written.push_back(stem + ".cells.txt");
  }
  if (formats->count("png")) {
    owned.push_back(io::make_png_stack_writer(dir, stem));
    written.push_back(fmt::format("png/ ({} layers)", span->count()));
  }
  if (formats->count("svg")) {
    owned.push_back(io::make_svg_writer(dir, stem));
    written.push_back(fmt::format("svg/ ({} layers)", span->count()));
  }
  if (formats->count("cli")) {
    owned.push_back(io::make_cli_writer(dir / (stem + ".cli"), io::CliEncoding::Ascii));
    written.push_back(stem + ".cli");
  }
  if (formats->count("cli-binary")) {
    owned.push_back(io::make_cli_writer(dir / (stem + ".bin.cli"), io::CliEncoding::Binary));
    written.push_back(stem + ".bin.cli");
  }
  view::ViewStackCollector* view_collector = nullptr;
  if (formats->count("html")) {
    auto collector = std::make_unique<view::ViewStackCollector>(
        view::ViewStackOptions{.hatches = o.page.hatches});
    view_collector = collector.get();
    owned.push_back(std::move(collector));
  }
  std::vector<LayerSink*> sinks;
  for (auto& s : owned) sinks.push_back(s.get());

  // The page's drawing of the model needs the mesh alone: with more than one thread it is
  // simplified on a thread of its own while the mesh is checked and sliced.
  const auto make_display = [&] {
    return view::make_noted_display_mesh(m.mesh, o.page.max_facets, view::SliceStage::Sliced,
                                         view::CountDigits::GroupedByThousands);
  };
  std::future<view::NotedDisplayMesh> display_ahead;
  if (view_collector != nullptr && options->threads != 1) {
    display_ahead = std::async(std::launch::async, make_display);
  }
  // The report's fingerprint hashes the model file (50 MB for a million facets): with more than
  // one thread, beside the slicing too.
  std::future<Result<std::string>> fingerprint_ahead;
  if (formats->count("json") && options->threads != 1) {
    fingerprint_ahead =
        std::async(std::launch::async, [&] { return run_fingerprint(o, m, *options); });
  }

  diagnose::DiagnoseOptions diagnose_options;
  diagnose_options.check_self_intersections = view_collector != nullptr && o.page.full_check;
  diagnose_options.near_vertex_mm = 0.0;
  // The page draws the defects, so it asks for more of their locations than a report lists.
  if (view_collector != nullptr) diagnose_options.max_locations = o.page.max_defects;
  // The diagnosis reads the soup's stored normals and facet count only: its corners, as large
  // again as the welded mesh (96 MB for a million facets), are released first. (Diagnosed beside
  // the slicing, its own memory would come on top of the slicing's.)
  const std::size_t input_facets = m.soup.triangles.size();
  m.soup.triangles.clear();
  m.soup.triangles.shrink_to_fit();
  out.mesh_report = diagnose::diagnose_mesh(m.mesh, m.soup, diagnose_options);
  out.mesh_report.num_input_facets = input_facets;
  m.soup.stored_normals.clear();
  m.soup.stored_normals.shrink_to_fit();
  // What reading and diagnosing freed goes back to the system before the slicing allocates: a
  // block freed on a worker thread stays in that thread's heap otherwise, and the run's peak
  // would depend on which thread happened to free what (up to 17 MB more on a 200k-facet model).
  malloc_trim(0);
  if (cancelled()) return cancel_error;

  Result<SliceSummary> summary = Error{ErrorCode::Internal, "not run", {}};
  if (o.kernel == "exact" && options->fill_rule == FillRule::Winding) {
    // The exact path refuses the winding rule too; the command line says it with its flags.
    summary = Error{ErrorCode::Usage,
                    "--fill-rule winding is evaluated by the fast path only (solid angles are not "
                    "exact): use --kernel fast, or nonzero or evenodd",
                    {}};
  } else {
    summary = o.kernel == "exact"
                  ? slice_model_exact(m.mesh, *grid, *options, sinks, control.progress)
                  : slice_model(m.mesh, *grid, *options, sinks, control.progress);
  }
  const auto remove_dir_if_we_made_it = [&] {
    if (!dir_existed && fs::is_empty(dir, ec)) fs::remove(dir, ec);
  };
  // Every file written past this point is removed again if a later step fails or the run is
  // cancelled, so that a failed run leaves no partial output.
  std::vector<fs::path> committed;
  const auto fail = [&](Error e) -> Result<SliceOutcome> {
    for (const fs::path& p : committed) fs::remove(p, ec);
    remove_dir_if_we_made_it();
    return e;
  };
  if (!summary) {
    remove_dir_if_we_made_it();
    return summary.error();
  }
  const diagnose::MeshReport& mesh_report = out.mesh_report;
  name_flags(summary->diagnostics);
  out.summary = std::move(summary).value();
  out.options = *options;
  const double seconds_total = std::chrono::duration<double>(Clock::now() - started).count();
  // The report is written as JSON and shown on the page; contour outputs alone make neither.
  const bool report_wanted = formats->count("json") != 0 || view_collector != nullptr;
  nlohmann::json report;
  if (report_wanted) {
    report = slice_report_json(m, mesh_report, *options, o.kernel, out.summary, seconds_total);
    report["plan"] = nlohmann::json::parse(plan_json(out.plan));
  }
  if (formats->count("json")) {
    // What `strata merge` needs to join ranges: which layers, of which run, in which outputs.
    auto fingerprint =
        fingerprint_ahead.valid() ? fingerprint_ahead.get() : run_fingerprint(o, m, *options);
    if (!fingerprint) return fail(fingerprint.error());
    report["range"] = {{"first", span->first}, {"end", span->end}, {"nz_total", grid->nz}};
    report["fingerprint"] = *fingerprint;
    report["formats"] = *formats;
  }
  if (report_wanted && out.repair_log) {
    report["repair"] = nlohmann::json::parse(repair::repair_log_json(*out.repair_log));
    report["repair"]["seconds"] = out.seconds_repair;
  }
  if (formats->count("json")) {
    fs::create_directories(dir, ec);
    if (auto ok = io::write_text_file(dir / (stem + ".json"), report.dump(2) + "\n"); !ok) {
      return fail(ok.error());
    }
    committed.push_back(dir / (stem + ".json"));
    written.push_back(stem + ".json");
  }
  if (view_collector != nullptr) {
    if (cancelled()) return fail(cancel_error);
    out.page_path = o.page.path.empty() ? dir / (stem + ".html") : fs::path(o.page.path);
    view::ViewPage page;
    page.title = stem;
    page.source_kind = "model";
    page.source_path = m.path.string();
    page.report_json = report.dump();
    view::NotedDisplayMesh display = display_ahead.valid() ? display_ahead.get() : make_display();
    page.mesh = std::move(display.mesh);
    if (display.note) page.notes.push_back(std::move(*display.note));
    if (!mesh_report.self_intersections_checked) {
      page.notes.push_back(
          fmt::format("self-intersections not checked: `strata check {}` or "
                      "`strata view {}` checks them",
                      m.path.filename().string(), m.path.filename().string()));
    }
    page.check = mesh_report;
    page.model_mesh = &m.mesh;
    page.stack = view_collector->take();
    view::fit_to_budget(page.stack, static_cast<std::uint64_t>(o.page.budget_mb * 1e6));
    if (out.page_path->has_parent_path()) fs::create_directories(out.page_path->parent_path(), ec);
    if (auto ok = view::write_view_page(*out.page_path, page); !ok) return fail(ok.error());
    committed.push_back(*out.page_path);
    if (!o.page.data_path.empty()) {
      if (auto ok = view::write_view_page_data(o.page.data_path, page); !ok) {
        return fail(ok.error());
      }
      committed.push_back(o.page.data_path);
    }
    if (o.page.path.empty()) written.push_back(stem + ".html");
  }
  if (cancelled()) return fail(cancel_error);
  out.seconds_total = std::chrono::duration<double>(Clock::now() - started).count();
  return out;
}

int run_slice(const SliceCommandOptions& o) {
  std::optional<ProgressLine> progress;
  SliceRunControl control;
  control.progress = [&](std::uint32_t done, std::uint32_t total) {
    if (progress) progress->update(done, total);
  };
  control.read_warnings = [&](const Diagnostics& diagnostics) {
    for (const auto& d : diagnostics) {
      std::fprintf(stderr, "strata: %s: %s\n", d.severity == Severity::Warning ? "warning" : "note",
                   d.message.c_str());
    }
  };
  control.planned = [&](const JobPlan& plan, const std::optional<std::string>& warning) {
    if (warning) std::fprintf(stderr, "strata: warning: %s\n", warning->c_str());
    // The job's size before it starts, for the person watching; logs get it in the report.
    if (isatty(STDERR_FILENO) == 1) {
      std::fprintf(stderr, "strata: job: %s\n", plan_text(plan).c_str());
    }
  };
  progress.emplace("slicing " + fs::path(o.model).filename().string());
  auto outcome = slice_to_folder(o, control);
  progress.reset();
  if (!outcome) return report_error(outcome.error());
  const LoadedModel& m = outcome->model;
  if (outcome->repair_log) {
    std::fprintf(stderr, "strata: %s\n", repair::repair_log_summary(*outcome->repair_log).c_str());
  }
  const SliceSummary& s = outcome->summary;
  for (const auto& d : s.diagnostics) {
    std::fprintf(stderr, "strata: %s: %s\n", d.severity == Severity::Warning ? "warning" : "note",
                 d.message.c_str());
  }
  if (o.quiet) return kExitOk;

  const diagnose::MeshReport& mesh_report = outcome->mesh_report;
  const SliceOptions& options = outcome->options;
  const GridSpec& g = s.grid;
  std::string out;
  out +=
      fmt::format("model   {} ({}, {} facets, {} vertices)\n", m.path.string(), m.soup.format,
                  with_thousands(m.mesh.triangles.size()), with_thousands(m.mesh.vertices.size()));
  out += fmt::format(
      "mesh    {} (open edges {}, non-manifold edges {}, degenerate facets {}, duplicate facets "
      "{})\n",
      diagnose::verdict_name(mesh_report.verdict), mesh_report.boundary_edges.count,
      mesh_report.non_manifold_edges.count, mesh_report.degenerate_facets.count,
      mesh_report.duplicate_facets.count);
  out += fmt::format("grid    {} x {} x {} cells of {} x {} x {} mm, origin ({}, {}, {})\n", g.nx,
                     g.ny, g.nz, g.dx, g.dy, g.dz, g.x0, g.y0, g.z0);
  if (s.range.count() != g.nz) {
    out += fmt::format("range   layers {}..{} of {} (--layers {}:{})\n", s.range.first,
                       s.range.end - 1, g.nz, s.range.first, s.range.end);
  }
  out += fmt::format("rule    fill {}, shell {} mm ({}), scan offset {} mm\n",
                     to_string(options.fill_rule), options.shell_mm, to_string(options.shell_mode),
                     options.scan_offset_mm);
  const double mesh_volume = mesh_report.volume_mm3;
  if (s.cells_classified) {
    out += fmt::format("cells   {} empty, {} interior, {} boundary\n",
                       with_thousands(s.class_counts[0]), with_thousands(s.class_counts[1]),
                       with_thousands(s.class_counts[2]));
    out += fmt::format(
        "volume  cells {:.6g} mm3, mesh {:.6g} mm3 ({:+.3f} %), contours {:.6g} mm3\n",
        s.solid_volume_mm3, mesh_volume,
        mesh_volume != 0.0 ? 100.0 * (s.solid_volume_mm3 - mesh_volume) / std::fabs(mesh_volume)
                           : 0.0,
        s.contour_volume_mm3);
  } else {
    out += "cells   not classified: the formats asked hold contours and hatches only\n";
    out += fmt::format("volume  mesh {:.6g} mm3, contours {:.6g} mm3\n", mesh_volume,
                       s.contour_volume_mm3);
  }
  out += fmt::format("chains  {} open chains in {} layers{}\n", s.open_chains,
                     std::count_if(s.layers.begin(), s.layers.end(),
                                   [](const LayerStats& l) { return l.open_chains > 0; }),
                     s.open_chains ? " (see the report: nothing was closed by a guess)" : "");
  if (!outcome->written.empty()) {
    out +=
        fmt::format("output  {}/: {}\n", outcome->dir.string(), fmt::join(outcome->written, ", "));
  }
  if (outcome->page_path) {
    out += fmt::format("page    {} (open {} in a browser; it works offline)\n",
                       outcome->page_path->string(), file_url(*outcome->page_path));
  }
  out += fmt::format("time    read {:.3f} s, slice {:.3f} s, total {:.3f} s\n", m.seconds_read,
                     s.seconds, outcome->seconds_total);
  std::fputs(out.c_str(), stdout);
  return kExitOk;
}

void add_page_options(CLI::App& cmd, PageOptions& page) {
  cmd.add_option("--page-budget", page.budget_mb,
                 "MB of layers the HTML page may hold; above it the scanline segments are left "
                 "out, then every n-th layer only")
      ->default_val(page.budget_mb)
      ->check(positive_real("size in MB"));
  cmd.add_option("--page-facets", page.max_facets,
                 "Facets the page's 3D model may have; a larger mesh is simplified for display")
      ->default_val(page.max_facets)
      ->check(whole_number(1000, 50'000'000, "number of facets"));
  cmd.add_flag("!--no-hatches", page.hatches, "Leave the scanline segments out of the page");
}

void register_slice_command(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<SliceCommandOptions>();
  CLI::App* cmd = app.add_subcommand("slice", "Slice a model into layers of classified cells");
  cmd->add_option("MODEL", options->model,
                  "Mesh file: STL (ASCII or binary), OBJ, OFF, PLY, or .gz of one")
      ->required();
  cmd->add_option("-o,--output", options->output_dir, "Output folder (default: <stem>-strata/)");
  add_slice_options(*cmd, options->slice);
  cmd->add_option("--kernel", options->kernel, "fast: double with exact predicates; exact: CGAL")
      ->default_val("fast")
      ->check(CLI::IsMember({"fast", "exact"}));
  CLI::Option* format =
      cmd->add_option("--format", options->formats,
                      "Comma list of outputs: cells, cells-ascii, png, svg, cli, cli-binary, json, "
                      "html (the view page, <stem>.html); with --layers the default is "
                      "cells,png,json")
          ->default_val(kDefaultFormats);
  cmd->add_option("--layers", options->layers,
                  "Slice only layers A..B-1 of the whole model's grid (A:B, A: to the last, or K "
                  "alone), for `strata merge`; see `strata plan`");
  cmd->add_flag("-q,--quiet", options->quiet, "Print nothing on success");
  auto* repair = cmd->add_flag("--repair", options->repair,
                               "Repair the mesh in memory before slicing (as `strata check "
                               "--repair`; the model file is not changed) and log it in the "
                               "report");
  cmd->add_flag("--fill-holes", options->fill_holes, "With --repair: fill holes too")
      ->needs(repair);
  add_page_options(*cmd, options->page);
  cmd->callback([options, format, &runner] {
    options->formats_given = format->count() > 0;
    runner = [options] { return run_slice(*options); };
  });
}

}  // namespace strata::cli
