#include "cli/slice_cli_options.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "cli/option_checks.hpp"

namespace strata::cli {

void add_slice_options(CLI::App& command, SliceCliOptions& o) {
  command.add_option("--layer", o.layer_mm, "Layer thickness dz in mm")
      ->default_val(kDefaultLayerHeightMm)
      ->check(positive_real("length in mm"));
  auto* cell = command.add_option("--cell", o.cell_mm, "Cell size in x and y, mm (default 0.1)")
                   ->check(positive_real("length in mm"));
  command.add_option("--dx", o.dx_mm, "Cell size in x, mm")
      ->check(positive_real("length in mm"))
      ->excludes(cell);
  command.add_option("--dy", o.dy_mm, "Cell size in y, mm")
      ->check(positive_real("length in mm"))
      ->excludes(cell);
  command.add_option("--shell", o.shell_mm, "Boundary shell thickness t in mm")
      ->default_val(kDefaultShellThicknessMm)
      ->check(non_negative_real("length in mm"));
  command
      .add_option("--shell-mode", o.shell_mode,
                  "distance: cells whose centre is closer than t to the surface;\n"
                  "layers: int(t/d) rings of cells (the published rule)")
      ->default_val("distance")
      ->check(CLI::IsMember({"distance", "layers"}));
  command
      .add_option("--fill-rule", o.fill_rule,
                  "nonzero: union of all shells; evenodd: parity (the published rule);\n"
                  "winding: generalized winding number (open meshes)")
      ->default_val("nonzero")
      ->check(CLI::IsMember({"nonzero", "evenodd", "winding"}));
  command
      .add_option("--scan-offset", o.scan_offset_mm,
                  "Shift every scanline by this many mm in +y (0.0001 = the published 0.1 um "
                  "mode; default 0, the exact symbolic rule)")
      ->default_val(0.0)
      ->check(finite_real());
  command
      .add_option("--origin", o.origin,
                  "Grid origin X,Y,Z in mm (default: the model's minimum corner)")
      ->delimiter(',')
      ->expected(3)
      ->check(finite_real());
  command.add_option("--threads", o.threads, "Worker threads (default: all cores)")
      ->default_val(0)
      ->check(whole_number(0, std::numeric_limits<int>::max(), "number of threads"));
  add_units_options(command, o.units);
}

Result<SliceOptions> to_slice_options(const SliceCliOptions& o) {
  SliceOptions options;
  const double cell = o.cell_mm.value_or(kDefaultCellSizeMm);
  options.grid.dx_mm = o.dx_mm.value_or(cell);
  options.grid.dy_mm = o.dy_mm.value_or(cell);
  options.grid.dz_mm = o.layer_mm;
  if (!o.origin.empty()) {
    if (o.origin.size() != 3 || !std::isfinite(o.origin[0]) || !std::isfinite(o.origin[1]) ||
        !std::isfinite(o.origin[2])) {
      return Error{ErrorCode::Usage, "--origin takes three finite numbers X,Y,Z", {}};
    }
    options.grid.origin = Vec3{o.origin[0], o.origin[1], o.origin[2]};
  }
  for (const double d : {options.grid.dx_mm, options.grid.dy_mm, options.grid.dz_mm}) {
    if (!(d > 0.0) || !std::isfinite(d)) {
      return Error{ErrorCode::Usage, fmt::format("cell sizes must be positive, got {}", d), {}};
    }
  }
  if (!(o.shell_mm >= 0.0) || !std::isfinite(o.shell_mm)) {
    return Error{ErrorCode::Usage, "--shell must be a finite number >= 0", {}};
  }
  if (!std::isfinite(o.scan_offset_mm)) {
    return Error{ErrorCode::Usage, "--scan-offset must be finite", {}};
  }
  options.shell_mm = o.shell_mm;
  options.shell_mode = o.shell_mode == "layers" ? ShellMode::Layers : ShellMode::Distance;
  options.fill_rule = o.fill_rule == "evenodd"   ? FillRule::EvenOdd
                      : o.fill_rule == "winding" ? FillRule::Winding
                                                 : FillRule::NonZero;
  options.scan_offset_mm = o.scan_offset_mm;
  options.threads = o.threads;
  return options;
}

}  // namespace strata::cli
