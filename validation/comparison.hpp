#pragma once

// What the runs found, all models together: the figures of the report's Totals table.

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "validation_records.hpp"

namespace strata::validation {

/// The runs' figures summed (counts, times) or maximised (distances) over every model read.
struct Totals {
  std::uint64_t models = 0, generated = 0, runs = 0, compared = 0, differing = 0,
                runs_differing = 0, refusals = 0, fast_failures = 0, unreadable = 0;
  std::array<std::uint64_t, kDifferenceReasonCount> by_reason{};
  double fast_s = 0.0, exact_s = 0.0, comparison_s = 0.0;
  std::uint64_t overlaid = 0, overlay_skipped = 0, area_only = 0;
  double max_hausdorff = 0.0;
  std::map<std::string, std::vector<std::string>> refusal_reasons;
  // The reference slicer.
  std::uint64_t ref_models = 0, ref_runs = 0, ref_layers = 0, ref_layers_at_vertex = 0,
                ref_differing = 0, ref_differing_at_vertex = 0, ref_open = 0, ref_outlined = 0;
  double ref_h_exact = 0.0, ref_h_fast = 0.0, ref_area = 0.0, ref_s = 0.0, ref_worst = 0.0;
  std::string ref_worst_model;
  std::map<std::string, std::uint64_t> ref_skipped_models;
};

/// The totals of `records`; an unreadable model counts in `unreadable` only.
Totals sum_runs(const std::vector<ModelRecord>& records);

}  // namespace strata::validation
