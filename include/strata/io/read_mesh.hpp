#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

#include "strata/core/result.hpp"
#include "strata/io/length_unit.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::io {

/// Limits against hostile input: a file that claims more than this fails fast with a message.
struct ReadLimits {
  std::size_t max_triangles = 200'000'000;
  std::size_t max_line_bytes = 1 << 20;
  /// A `.gz` input that inflates to more bytes than this fails (against compression bombs).
  std::size_t max_decompressed_bytes = std::size_t{1} << 34;
};

/// Reads a triangle mesh: STL (binary or ASCII, told apart by content, not by extension or the
/// word `solid`), OBJ, OFF or PLY (polygons triangulated as fans), any of them gzip-compressed,
/// or 3MF (through lib3mf: every mesh object of the build items, the build items' and the
/// components' transforms applied, converted from the unit the file states).
/// STL ASCII numbers are rounded to the nearest float32 (SPEC §2); 3MF coordinates are float32
/// as lib3mf reads them, placed in double; other formats are read as double. The format is
/// decided by content first (gzip magic, `ply` magic, binary STL size, leading `solid`), then by
/// the extension (of the name without `.gz`); a name ending in `.3mf`, or a zip archive without
/// extension, is read as 3MF. AMF and other zip archives fail with "unsupported format".
/// @return the soup (soup.format is "stl-binary", "stl-ascii", "obj", "off", "ply" or "3mf", with
///         "+gz" appended when compressed), with warnings for odd-but-readable input; or
///         Error{BadInput} whose location names the file and, where it applies, the line
///         ("path:12", text formats; lines of the decompressed text for .gz), the facet
///         ("path: facet 7", binary STL, counted from 0) or the 3MF object and triangle
///         ("path: object 3 ('name'), triangle 7", counted from 0), and whose message says what
///         was wrong. A file with no triangles is an error.
/// @param scale  the unit of the file's coordinates and a factor: the coordinates read are
///               converted to millimetres (CoordinateScale); a coordinate that overflows its type
///               once scaled is Error{BadInput} naming the facet, a scale that is not finite and
///               positive Error{Usage}. A 3MF file states its own unit: only the factor applies to
///               it, and a unit other than millimetres is Error{Usage}.
Result<TriangleSoup> read_mesh(const std::filesystem::path& path, const ReadLimits& limits = {},
                               const CoordinateScale& scale = {});

/// Same as read_mesh for bytes already in memory: `name` is used in messages and its extension
/// (after stripping `.gz`) for the dispatch to OBJ/OFF/PLY, exactly as a path's would be.
Result<TriangleSoup> read_mesh_bytes(std::string_view bytes, std::string_view name,
                                     const ReadLimits& limits = {},
                                     const CoordinateScale& scale = {});

/// Reads STL from bytes already in memory; `name` is used in messages.
/// Binary when 84 + 50 * count == size (count = uint32 at offset 80), or when the file is longer
/// by fewer than 50 stray bytes (warning "stl.trailing_bytes"); otherwise ASCII when it starts
/// with `solid` and parses as ASCII STL; otherwise an error saying how the size disagrees with the
/// header's count. Warnings (codes "stl.*"): non-finite or missing stored normals (normal set to
/// zero, facet kept), polygons of 4+ vertices (fan), facets of fewer than 3 vertices (skipped),
/// missing `endsolid`/`endfacet`, text after keywords or after the last solid.
Result<TriangleSoup> read_stl_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits = {});

}  // namespace strata::io
