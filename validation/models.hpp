#pragma once

// The models strata-validation validates: its generated degenerate models and the corpus meshes
// MANIFEST.tsv lists.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "validation_records.hpp"

namespace strata::validation {

/// The models to validate, and the corpus files left out for their size.
struct ModelCases {
  std::vector<ModelCase> cases;
  std::vector<std::pair<std::string, std::uint64_t>> too_large;  ///< path and bytes
};

/// The generated models (also written to `o.write_models` when it is set), then the corpus
/// meshes the options choose, in path order; only those named by `o.only` when it is set.
/// @return std::nullopt, or the exit code after printing why to stderr: 1 when a generated model
///         cannot be written, 2 when the corpus manifest cannot be read
std::optional<int> collect_model_cases(const RunnerOptions& o, ModelCases& out);

}  // namespace strata::validation
