#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "strata/io/length_unit.hpp"

namespace strata::cli {

/// `--units` and `--scale` as typed: the unit of the model file's coordinates and a factor.
struct UnitsCliOptions {
  std::string units = "mm";
  double scale = 1.0;
};

/// Adds --units mm|cm|m|in|um and --scale F to a command that reads a model.
void add_units_options(CLI::App& command, UnitsCliOptions& options);

/// The reading option the command line asked for (both checked by add_units_options).
io::CoordinateScale to_coordinate_scale(const UnitsCliOptions& options);

}  // namespace strata::cli
