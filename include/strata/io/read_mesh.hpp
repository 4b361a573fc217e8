#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

#include "strata/core/result.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::io {

/// Limits against hostile input: a file that claims more than this fails fast with a message.
struct ReadLimits {
  std::size_t max_triangles = 200'000'000;
  std::size_t max_line_bytes = 1 << 20;
};

/// Reads a triangle mesh: STL (binary or ASCII, told apart by content, not by extension or the
/// word `solid`), OBJ, OFF or PLY (polygons triangulated as fans), any of them gzip-compressed.
/// STL ASCII numbers are rounded to the nearest float32 (SPEC §2).
/// @return the soup, with warnings for odd-but-readable input; or Error{BadInput} whose location
///         names the file and the line (ASCII) or facet (binary), and whose message says what was
///         expected. A file with no triangles is an error.
Result<TriangleSoup> read_mesh(const std::filesystem::path& path, const ReadLimits& limits = {});

/// Reads STL from bytes already in memory; `name` is used in messages.
Result<TriangleSoup> read_stl_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits = {});

}  // namespace strata::io
