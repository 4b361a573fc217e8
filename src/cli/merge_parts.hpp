#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "strata/core/result.hpp"

namespace strata::cli {

/// What a merge wrote.
struct MergeOutcome {
  std::string stem;
  std::uint32_t nz_total = 0;
  std::size_t parts = 0;
  std::vector<std::string> written;  ///< the outputs, as listed to the user
};

/// Joins the output folders of layer ranges (`strata slice --layers`) into the outputs of the
/// whole run, in `out_dir` (SPEC §3.1b). Every part must hold its JSON report (which carries
/// its range and fingerprint) and the same outputs. The parts must share one fingerprint and
/// tile the layers 0 .. nz_total-1 without overlap or gap.
/// - `.cells`: the first part's header with nz = nz_total, then every part's layers: the bytes
///   of the whole run's file.
/// - `.cells.txt`: likewise, each `layer` line renumbered from the part's first layer.
/// - PNG and SVG stacks: the files, whose names already carry the whole run's layer index.
/// - `.cli`, `.bin.cli`: the first part's header with the last part's top z and the layer
///   count of all, then every part's layers.
/// - `<stem>.json`: the first part's report, with counts and metrics recomputed over all parts:
///   range, cells, metrics (cell volume and its error, contour volume, segments, exact
///   fallbacks, loop layer counts), layers, open chains, empty layers inside the model. The
///   diagnostics are the parts' (each once); timings are summed; the job plan, which describes
///   one run, is dropped; `merged_from` lists the parts.
/// Everything is checked before anything is written; a failure while writing removes what the
/// merge wrote. Files are written under temporary names and renamed into place.
/// @return Error{BadInput} naming the offending part (or, for gaps, the missing layers).
Result<MergeOutcome> merge_parts(const std::vector<std::filesystem::path>& part_dirs,
                                 const std::filesystem::path& out_dir);

}  // namespace strata::cli
