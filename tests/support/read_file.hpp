#pragma once

#include <filesystem>
#include <string>

namespace strata::test {

/// The whole content of a file, as bytes; empty when it cannot be read.
std::string read_file(const std::filesystem::path& path);

}  // namespace strata::test
