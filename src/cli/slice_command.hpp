#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

#include "cli/slice_cli_options.hpp"

namespace strata::cli {

inline constexpr const char* kDefaultFormats = "cells,png,json,html";

/// How the view page is made, for `slice --format html` and `view`.
struct PageOptions {
  std::string path;                  ///< where the page goes; empty: <output folder>/<stem>.html
  double budget_mb = 200.0;          ///< --page-budget
  std::size_t max_facets = 300'000;  ///< --page-facets
  std::size_t max_defects = 10'000;  ///< locations of each kind of defect drawn
  bool hatches = true;               ///< --no-hatches clears it
  bool full_check = false;           ///< also look for self-intersections (as `strata check`)
};

struct SliceCommandOptions {
  std::string model;
  std::string output_dir;
  std::string formats = kDefaultFormats;
  std::string kernel = "fast";
  SliceCliOptions slice;
  PageOptions page;
  bool quiet = false;
  bool repair = false;      ///< --repair: slice the repaired mesh (in memory)
  bool fill_holes = false;  ///< --fill-holes, with --repair
};

/// `strata slice`; `strata view MODEL` runs it with the html format alone. Returns the exit code.
int run_slice(const SliceCommandOptions& options);

/// Adds --page-budget, --page-facets and --no-hatches.
void add_page_options(CLI::App& command, PageOptions& page);

}  // namespace strata::cli
