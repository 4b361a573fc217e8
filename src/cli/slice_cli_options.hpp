#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

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
};

/// Adds --layer, --cell, --dx, --dy, --shell, --shell-mode, --fill-rule, --scan-offset,
/// --origin and --threads to a subcommand.
void add_slice_options(CLI::App& command, SliceCliOptions& options);

/// Checks and converts; Error{Usage} says which option is wrong.
Result<SliceOptions> to_slice_options(const SliceCliOptions& options);

}  // namespace strata::cli
