#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "strata/core/result.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::io::detail {

/// Size of the binary STL header (80 bytes of free text, then the uint32 facet count).
inline constexpr std::size_t kStlBinaryHeaderBytes = 84;
/// Size of one binary STL facet record: normal, three corners (12 float32), attribute uint16.
inline constexpr std::size_t kStlBinaryFacetBytes = 50;

/// How the byte count of a file relates to the facet count its binary STL header declares.
enum class StlBinaryFit {
  TooShort,       ///< fewer than 84 bytes: no binary header at all
  Exact,          ///< 84 + 50 * count == size
  TrailingBytes,  ///< 84 + 50 * count < size and fewer than 50 bytes are left over
  Mismatch,       ///< the file is shorter, or longer by a whole facet or more
};

/// What the binary reading of a file's first 84 bytes says about it.
struct StlBinaryLayout {
  StlBinaryFit fit = StlBinaryFit::TooShort;
  std::uint32_t declared_facets = 0;  ///< the header's count (0 when TooShort)
  std::uint64_t expected_bytes = 0;   ///< 84 + 50 * declared_facets
  std::uint64_t trailing_bytes = 0;   ///< bytes after the last declared facet (TrailingBytes)
};

/// Reads the binary header count and compares it with the size. Decides nothing about ASCII.
StlBinaryLayout stl_binary_layout(std::string_view bytes);

/// The same from a file's first bytes (its first 84, when it has them) and its whole size.
StlBinaryLayout stl_binary_layout(std::string_view head, std::uint64_t size);

/// Binary STL records a block at a time: a pointer to the `count` records from facet `first` on,
/// copied into `scratch` where they must be; nullptr when they cannot be read.
using StlRecordBlocks = std::function<const char*(std::uint32_t first, std::uint32_t count,
                                                  std::vector<char>& scratch)>;

/// Reads a binary STL of this layout (Exact or TrailingBytes) of `size` bytes in all, whose
/// records come from `blocks`: from memory, or from a file without holding all of it.
Result<TriangleSoup> read_stl_records(const StlRecordBlocks& blocks, std::uint64_t size,
                                      std::string_view name, const StlBinaryLayout& layout,
                                      const ReadLimits& limits);

/// True when the bytes begin with `solid` (any case) after an optional UTF-8 byte order mark and
/// optional whitespace: the precondition for trying the ASCII grammar.
bool starts_with_solid(std::string_view bytes);

}  // namespace strata::io::detail
