#pragma once

#include <nlohmann/json.hpp>

#include "cli/load_model.hpp"
#include "strata/diagnose/mesh_report.hpp"
#include "strata/pipeline/run_slice.hpp"

namespace strata::cli {

/// The JSON report of a slice run (SPEC §3.2): inputs, parameters, mesh diagnostics, per-layer
/// and whole-model figures, timings.
nlohmann::json slice_report_json(const LoadedModel& model, const diagnose::MeshReport& mesh_report,
                                 const SliceOptions& options, const std::string& kernel,
                                 const SliceSummary& summary, double seconds_total);

}  // namespace strata::cli
