#include "support/text_meshes.hpp"

#include <fstream>
#include <stdexcept>
#include <string>

namespace strata::test {

std::vector<TextMeshFormat> all_text_mesh_formats() {
  return {TextMeshFormat::StlAscii, TextMeshFormat::Obj, TextMeshFormat::Off,
          TextMeshFormat::PlyFloat, TextMeshFormat::PlyDouble};
}

std::string_view format_name(TextMeshFormat format) {
  switch (format) {
    case TextMeshFormat::StlAscii:
      return "stl_ascii";
    case TextMeshFormat::Obj:
      return "obj";
    case TextMeshFormat::Off:
      return "off";
    case TextMeshFormat::PlyFloat:
      return "ply_float";
    case TextMeshFormat::PlyDouble:
      return "ply_double";
  }
  return "unknown";
}

TextMesh triangle_with_x(TextMeshFormat format, std::string_view token) {
  const std::string x(token);
  switch (format) {
    case TextMeshFormat::StlAscii:
      return {"triangle.stl",
              "solid t\n"
              " facet normal 0 0 1\n"
              "  outer loop\n"
              "   vertex 0 0 0\n"
              "   vertex " +
                  x +
                  " 0 0\n"
                  "   vertex 0 1 0\n"
                  "  endloop\n"
                  " endfacet\n"
                  "endsolid t\n",
              5};
    case TextMeshFormat::Obj:
      return {"triangle.obj", "v 0 0 0\nv " + x + " 0 0\nv 0 1 0\nf 1 2 3\n", 2};
    case TextMeshFormat::Off:
      return {"triangle.off", "OFF\n3 1 0\n0 0 0\n" + x + " 0 0\n0 1 0\n3 0 1 2\n", 4};
    case TextMeshFormat::PlyFloat:
    case TextMeshFormat::PlyDouble: {
      const std::string type = format == TextMeshFormat::PlyFloat ? "float" : "double";
      return {"triangle.ply",
              "ply\n"
              "format ascii 1.0\n"
              "element vertex 3\n"
              "property " +
                  type + " x\nproperty " + type + " y\nproperty " + type +
                  " z\n"
                  "element face 1\n"
                  "property list uchar int vertex_indices\n"
                  "end_header\n"
                  "0 0 0\n" +
                  x + " 0 0\n0 1 0\n3 0 1 2\n",
              11};
    }
  }
  throw std::logic_error("triangle_with_x: unknown format");
}

std::filesystem::path write_text_file(const std::filesystem::path& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
  return path;
}

}  // namespace strata::test
