#pragma once

#include <string>
#include <vector>

namespace strata {

enum class Severity { Info, Warning };

/// Usable-but-odd input, or something a stage did that the user should know about. Diagnostics
/// travel with results through every later stage and end up in the report.
struct Diagnostic {
  Severity severity = Severity::Warning;
  std::string code;     ///< stable machine-readable key, e.g. "stl.trailing_bytes"
  std::string message;  ///< what a person reads, naming the file and the line or facet
};

using Diagnostics = std::vector<Diagnostic>;

}  // namespace strata
