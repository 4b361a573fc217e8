#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace strata::cli {

/// Checks of numeric options whose refusals read as one plain line, which CLI11 prefixes with
/// the option's name: "--layer: -1 is not a positive length in mm". A token that is no number
/// gets the readers' message ("bad number 'abc': not a number"), so the command line accepts
/// the number grammar of the text formats (README, "Numbers in text formats").

/// A real number > 0; `what` completes "… is not a positive …", e.g. "length in mm".
CLI::Validator positive_real(const std::string& what);

/// A real number >= 0; `what` is the phrase the refusal uses, e.g. "length in mm".
CLI::Validator non_negative_real(const std::string& what);

/// Any finite real number (the grammar refuses inf, nan and overflow).
CLI::Validator finite_real();

/// A whole number from `lowest` to `highest`; `what` names it in the refusal, e.g.
/// "port number" gives "70000 is not a port number from 0 to 65535" (or "… of 0 or more" when
/// `highest` is the largest int64).
CLI::Validator whole_number(std::int64_t lowest, std::int64_t highest, const std::string& what);

}  // namespace strata::cli
