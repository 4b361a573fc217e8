#pragma once

#include <cstdint>
#include <string>

namespace strata {

/// `n` in decimal with a comma between groups of three digits, as the text reports print
/// counts: 1234567 -> "1,234,567".
std::string with_thousands(std::uint64_t n);

}  // namespace strata
