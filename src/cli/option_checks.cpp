#include "cli/option_checks.hpp"

#include <fmt/format.h>

#include <limits>
#include <string_view>

#include "strata/io/scan_number.hpp"

namespace strata::cli {
namespace {

/// The refusal of a token that is no real number, or "" and the value.
std::string scan_real_option(std::string_view token, double& value) {
  const io::ScannedNumber<double> scanned = io::scan_real(token);
  if (!scanned.ok()) return io::bad_number_message(token, scanned.fault, scanned.type);
  value = scanned.value;
  return {};
}

}  // namespace

CLI::Validator positive_real(const std::string& what) {
  return CLI::Validator(
      [what](std::string& token) {
        double value = 0.0;
        if (std::string refusal = scan_real_option(token, value); !refusal.empty()) {
          return refusal;
        }
        return value > 0.0 ? std::string() : fmt::format("{} is not a positive {}", token, what);
      },
      "> 0");
}

CLI::Validator non_negative_real(const std::string& what) {
  return CLI::Validator(
      [what](std::string& token) {
        double value = 0.0;
        if (std::string refusal = scan_real_option(token, value); !refusal.empty()) {
          return refusal;
        }
        // -0 is 0: a thickness of -0 is no thickness.
        return value >= 0.0 ? std::string()
                            : fmt::format("{} is not a {} of 0 or more", token, what);
      },
      ">= 0");
}

CLI::Validator finite_real() {
  return CLI::Validator(
      [](std::string& token) {
        double value = 0.0;
        return scan_real_option(token, value);
      },
      "");
}

CLI::Validator whole_number(std::int64_t lowest, std::int64_t highest, const std::string& what) {
  const std::string range = highest == std::numeric_limits<std::int64_t>::max()
                                ? fmt::format("of {} or more", lowest)
                                : fmt::format("from {} to {}", lowest, highest);
  return CLI::Validator(
      [=](std::string& token) {
        const io::ScannedNumber<std::int64_t> scanned =
            io::scan_signed(token, io::NumberType::Int64);
        if (scanned.fault == io::NumberFault::OutOfRange ||
            (scanned.ok() && (scanned.value < lowest || scanned.value > highest))) {
          return fmt::format("{} is not a {} {}", token, what, range);
        }
        if (!scanned.ok()) return io::bad_number_message(token, scanned.fault, scanned.type);
        return std::string();
      },
      "");
}

}  // namespace strata::cli
