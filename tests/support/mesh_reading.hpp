#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>

#include "strata/core/diagnostic.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::test {

/// A file of the repository's adversarial meshes: data/adversarial/<name>.
std::filesystem::path adversarial(std::string_view name);

/// A file of the shared corpus by its path in MANIFEST.tsv.
std::filesystem::path corpus_file(std::string_view relative);

/// The first diagnostic of `soup` with `code`; null when there is none.
const Diagnostic* find_diagnostic(const TriangleSoup& soup, std::string_view code);

/// True when `part` occurs in `text`.
bool contains(std::string_view text, std::string_view part);

/// Reads the mesh file at `path`; fails the current test unless it reads with `facets`
/// triangles and a diagnostic of `code`.
void expect_read_with_diagnostic(const std::filesystem::path& path, std::size_t facets,
                                 std::string_view code);

/// Reads the mesh file at `path`; fails the current test unless reading fails with a message
/// containing `part` and, when `place` is given, the location `path` followed by `place`
/// (":5" for line 5).
void expect_refused(const std::filesystem::path& path, std::string_view part,
                    std::optional<std::string_view> place = std::nullopt);

}  // namespace strata::test
