#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "cli/command.hpp"
#include "strata/core/error.hpp"
#include "strata/core/quiet_cgal.hpp"

namespace {

constexpr const char* kDescription =
    "strata slices triangle meshes (STL, OBJ, OFF, PLY, also .gz) into layers of cells for\n"
    "binder-jetting and powder-bed printing: every cell of a regular grid is empty (00),\n"
    "interior (01) or boundary shell (11), decided by an exact inside rule.\n\n"
    "First run:  strata slice model.stl        (writes model-strata/: cells, PNGs, report, page)\n"
    "Read back:  strata info model-strata/model.cells\n"
    "Check mesh: strata check model.stl\n"
    "Prove it:   strata validate model.stl   (fast path vs exact path, cell for cell)\n"
    "See it:     strata view model.stl       (one HTML page: 3D model, layers, sections)\n"
    "Work in it: strata serve                (a local web app: open, slice, look, download)\n"
    "In parts:   strata plan model.stl --parts 4, then slice --layers A:B, then strata merge\n\n"
    "Exit codes: 0 success, 1 bad input, 2 bad usage, 3 internal error,\n"
    "            4 validate found cells on which the fast and exact paths differ.";

}  // namespace

int main(int argc, char** argv) {
  // CGAL reports through exceptions, which the library turns into errors; keep its default
  // handler from printing to stderr.
  strata::make_cgal_failures_throw();

  CLI::App app{kDescription, "strata"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "strata 0.1.0");
  // Usage errors read like strata's other messages: "strata: --layer: -1 is not a positive
  // length in mm", one line, then where the options are listed.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return fmt::format("strata: {}\nRun with --help for more information.\n", e.what());
  });
  strata::cli::CommandRunner runner;
  strata::cli::register_slice_command(app, runner);
  strata::cli::register_info_command(app, runner);
  strata::cli::register_check_command(app, runner);
  strata::cli::register_validate_command(app, runner);
  strata::cli::register_view_command(app, runner);
  strata::cli::register_serve_command(app, runner);
  strata::cli::register_merge_command(app, runner);
  strata::cli::register_plan_command(app, runner);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? strata::cli::kExitOk : strata::cli::kExitUsage;
  }
  if (!runner) return strata::cli::kExitUsage;
  try {
    return runner();
  } catch (const std::bad_alloc&) {
    std::fputs("strata: out of memory\n", stderr);
    return strata::cli::kExitInternal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "strata: internal error: %s\n", e.what());
    return strata::cli::kExitInternal;
  }
}
