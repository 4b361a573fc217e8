#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace strata::test {

/// The text mesh formats (and PLY's two real property types) whose numbers strata reads through
/// one scanner.
enum class TextMeshFormat { StlAscii, Obj, Off, PlyFloat, PlyDouble };

/// Every TextMeshFormat, for table-driven tests.
std::vector<TextMeshFormat> all_text_mesh_formats();

/// A short name without blanks: "stl_ascii", "obj", "off", "ply_float", "ply_double".
std::string_view format_name(TextMeshFormat format);

/// A small mesh file as text, and where in it the token under test is.
struct TextMesh {
  std::string file_name;       ///< e.g. "triangle.ply" (the extension selects the reader)
  std::string text;            ///< the whole file
  std::size_t token_line = 0;  ///< the line (from 1) that holds the token
};

/// The triangle (0,0,0) (1,0,0) (0,1,0), with the x coordinate of its second corner written as
/// `token`, verbatim. The triangle reads as one triangle whose corner 1 is that vertex.
TextMesh triangle_with_x(TextMeshFormat format, std::string_view token);

/// Writes `text` byte for byte to `path` and returns the path; throws std::runtime_error when it
/// cannot.
std::filesystem::path write_text_file(const std::filesystem::path& path, std::string_view text);

}  // namespace strata::test
