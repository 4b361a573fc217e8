#pragma once

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli/job_plan.hpp"
#include "cli/load_model.hpp"
#include "cli/slice_cli_options.hpp"
#include "strata/core/result.hpp"
#include "strata/diagnose/mesh_report.hpp"
#include "strata/pipeline/run_slice.hpp"
#include "strata/repair/repair_log.hpp"

namespace strata::cli {

inline constexpr const char* kDefaultFormats = "cells,png,json,html";
/// The default outputs of a layer range: the view page shows a whole run, so it is left out.
inline constexpr const char* kDefaultRangeFormats = "cells,png,json";

/// How the view page is made, for `slice --format html` and `view`.
struct PageOptions {
  std::string path;                  ///< where the page goes; empty: <output folder>/<stem>.html
  double budget_mb = 200.0;          ///< --page-budget
  std::size_t max_facets = 300'000;  ///< --page-facets
  std::size_t max_defects = 10'000;  ///< locations of each kind of defect drawn
  bool hatches = true;               ///< --no-hatches clears it
  bool full_check = false;           ///< also look for self-intersections (as `strata check`)
  std::filesystem::path data_path;   ///< also write the page's data (web/DATA.md) there
};

struct SliceCommandOptions {
  std::string model;
  std::string output_dir;
  std::string formats = kDefaultFormats;
  bool formats_given = false;  ///< --format was on the command line
  std::string layers;          ///< --layers A:B, A: or K; empty: every layer
  std::string kernel = "fast";
  SliceCliOptions slice;
  PageOptions page;
  bool quiet = false;
  bool repair = false;      ///< --repair: slice the repaired mesh (in memory)
  bool fill_holes = false;  ///< --fill-holes, with --repair
};

/// How a slice run reports progress and learns that it must stop.
struct SliceRunControl {
  ProgressCallback progress;
  const std::atomic<bool>* cancel = nullptr;  ///< raised: stop, leaving no output (may be null)
  /// Told the reader's warnings as soon as the model is read, so that they are seen even when a
  /// later step fails (may be empty).
  std::function<void(const Diagnostics&)> read_warnings;
  /// Told the job's plan, and a warning when the model's size suggests another unit, once the
  /// grid is known and before anything is written (may be empty).
  std::function<void(const JobPlan&, const std::optional<std::string>&)> planned;
};

/// What a slice run did, for the summary the CLI prints or the server shows.
struct SliceOutcome {
  LoadedModel model;  ///< as sliced (repaired when asked)
  diagnose::MeshReport mesh_report;
  SliceOptions options;
  SliceSummary summary;
  std::optional<repair::RepairLog> repair_log;
  double seconds_repair = 0.0;
  std::filesystem::path dir;
  std::vector<std::string> written;  ///< the outputs, as listed to the user
  std::optional<std::filesystem::path> page_path;
  double seconds_total = 0.0;
  JobPlan plan;                             ///< what the job was to make, before it started
  std::optional<std::string> size_warning;  ///< the model's size suggests another unit
};

/// Reads, (repairs,) checks and slices the model and writes the chosen outputs; prints nothing.
/// A failed or cancelled run (Error with kCancelledMessage) leaves no output behind.
Result<SliceOutcome> slice_to_folder(const SliceCommandOptions& options,
                                     const SliceRunControl& control = {});

/// `strata slice`; `strata view MODEL` runs it with the html format alone. Returns the exit code.
int run_slice(const SliceCommandOptions& options);

/// Adds --page-budget, --page-facets and --no-hatches.
void add_page_options(CLI::App& command, PageOptions& page);

}  // namespace strata::cli
