#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace strata::test {

/// The whole content of a file, as bytes; empty when it cannot be read.
std::string read_file(const std::filesystem::path& path);

/// Writes `bytes` as the whole content of the file at `path`; fails the current test when it
/// cannot.
void write_file(const std::filesystem::path& path, std::string_view bytes);

}  // namespace strata::test
