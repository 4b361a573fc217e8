#pragma once

#include <string>
#include <vector>

namespace strata {

/// How much a Diagnostic matters: a note, or a warning about the input or the result.
enum class Severity { Info, Warning };

/// Usable-but-odd input, or something a stage did that the user should know about. Diagnostics
/// travel with results through every later stage and end up in the report.
struct Diagnostic {
  Severity severity = Severity::Warning;
  std::string code;     ///< stable machine-readable key, e.g. "stl.trailing_bytes"
  std::string message;  ///< what a person reads, naming the file and the line or facet
};

/// The diagnostics of a result, in the order they arose.
using Diagnostics = std::vector<Diagnostic>;

}  // namespace strata
