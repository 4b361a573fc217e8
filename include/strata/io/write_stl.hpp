#pragma once

#include <filesystem>
#include <string>

#include "strata/core/result.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::io {

/// The two encodings of an STL file.
enum class StlEncoding { Ascii, Binary };

/// Encodes a soup as STL in memory (see write_stl for the layout).
/// Coordinates are rounded to the nearest float32; the normal written with each facet is
/// computed from its corners as rounded (right-hand rule, (b - a) x (c - a), normalised; zero for
/// a degenerate facet), never taken from `soup.stored_normals`.
/// - Binary: an 80-byte header "strata" padded with zero bytes (it never starts with "solid"),
///   the little-endian uint32 facet count, then 50 bytes a facet (normal, three corners as
///   little-endian float32, a zero uint16 attribute).
/// - ASCII: `solid strata` ... `endsolid strata`, every number printed with 9 significant digits
///   (`%.9g`), enough for each float32 to read back to the same bits; lines end with '\n'.
/// @pre every coordinate finite and within float32 range (write_stl checks this; here a
///      violation is encoded as whatever the conversion gives) and fewer than 2^32 facets.
std::string stl_bytes(const TriangleSoup& soup, StlEncoding encoding);

/// Writes a soup as an STL file; see stl_bytes for the encoding. The file is written under a
/// temporary name in the target folder and renamed into place, so a failure leaves no partial
/// file behind. Reading the file back with read_mesh gives the soup's coordinates rounded to
/// float32 (bit-identical when they already were float32 values) in the same order.
/// @return Error{BadInput} when a coordinate is not finite or overflows float32 (location names
///         the facet), or when the soup has 2^32 facets or more; or the error of
///         io::OutputFile (naming the path) when the file cannot be created, written or renamed.
Result<void> write_stl(const std::filesystem::path& path, const TriangleSoup& soup,
                       StlEncoding encoding = StlEncoding::Binary);

}  // namespace strata::io
