#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "strata/core/result.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata {

/// Every option of `options` that decides a cell (SPEC §3.1b) as one line of text: cell sizes,
/// origin, shell thickness and mode, fill rule, scan offset, each double in hexadecimal so that
/// no two values share a text. The layer range, threads and batching are left out: they change
/// which layers are made and how fast, not what a cell is.
std::string cell_options_text(const SliceOptions& options);

/// The fingerprint of a run (SPEC §3.1b): SHA-256, as 64 hex digits, of the model file's bytes
/// as stored (compressed or not), then `options_text` (cell_options_text() and whatever else the
/// caller lets decide a cell). Two ranges can be merged only when their fingerprints are equal.
/// @return Error{BadInput} naming the file when it cannot be read.
Result<std::string> slice_fingerprint(const std::filesystem::path& model,
                                      std::string_view options_text);

}  // namespace strata
