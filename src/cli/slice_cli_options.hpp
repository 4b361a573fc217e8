#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/units_options.hpp"
#include "strata/core/result.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata::cli {

/// The slicing options shared by `slice` and `validate`, as typed on the command line.
struct SliceCliOptions {
  double layer_mm = kDefaultLayerHeightMm;
  std::optional<double> cell_mm;
  std::optional<double> dx_mm;
  std::optional<double> dy_mm;
  double shell_mm = kDefaultShellThicknessMm;
  std::string shell_mode = "distance";
  std::string fill_rule = "nonzero";
  double scan_offset_mm = 0.0;
  std::vector<double> origin;
  int threads = 0;
  UnitsCliOptions units;  ///< how the model is read: --units, --scale
};

/// Adds --layer, --cell, --dx, --dy, --shell, --shell-mode, --fill-rule, --scan-offset,
/// --origin, --threads, --units and --scale to a subcommand.
void add_slice_options(CLI::App& command, SliceCliOptions& options);

/// Checks and converts; Error{Usage} says which option is wrong.
Result<SliceOptions> to_slice_options(const SliceCliOptions& options);

}  // namespace strata::cli
