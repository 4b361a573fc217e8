#include "support/three_mf_package.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <cstddef>

namespace strata::test {
namespace {

void put16(std::string& out, unsigned v) {
  out += static_cast<char>(v & 0xFF);
  out += static_cast<char>((v >> 8) & 0xFF);
}

void put32(std::string& out, unsigned long v) {
  put16(out, static_cast<unsigned>(v & 0xFFFF));
  put16(out, static_cast<unsigned>((v >> 16) & 0xFFFF));
}

}  // namespace

std::string make_zip(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::string out;
  std::string directory;
  for (const auto& [name, content] : entries) {
    const unsigned long crc = crc32(0L, reinterpret_cast<const Bytef*>(content.data()),
                                    static_cast<uInt>(content.size()));
    const auto offset = static_cast<unsigned long>(out.size());
    // Local file header (APPNOTE 4.3.7): version 2.0, no flags, stored, no time.
    put32(out, 0x04034b50);
    put16(out, 20);
    put16(out, 0);
    put16(out, 0);
    put16(out, 0);
    put16(out, 0x21);  // 1980-01-01
    put32(out, crc);
    put32(out, content.size());
    put32(out, content.size());
    put16(out, static_cast<unsigned>(name.size()));
    put16(out, 0);
    out += name;
    out += content;
    // Its central directory entry (4.3.12).
    put32(directory, 0x02014b50);
    put16(directory, 20);
    put16(directory, 20);
    put16(directory, 0);
    put16(directory, 0);
    put16(directory, 0);
    put16(directory, 0x21);
    put32(directory, crc);
    put32(directory, content.size());
    put32(directory, content.size());
    put16(directory, static_cast<unsigned>(name.size()));
    put16(directory, 0);
    put16(directory, 0);
    put16(directory, 0);
    put16(directory, 0);
    put32(directory, 0);
    put32(directory, offset);
    directory += name;
  }
  const auto directory_offset = static_cast<unsigned long>(out.size());
  out += directory;
  // End of central directory record (4.3.16).
  put32(out, 0x06054b50);
  put16(out, 0);
  put16(out, 0);
  put16(out, static_cast<unsigned>(entries.size()));
  put16(out, static_cast<unsigned>(entries.size()));
  put32(out, directory.size());
  put32(out, directory_offset);
  put16(out, 0);
  return out;
}

std::vector<std::pair<std::string, std::string>> package_parts(std::string_view model_xml) {
  const std::string content_types =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\">"
      "<Default Extension=\"rels\" "
      "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/>"
      "<Default Extension=\"model\" "
      "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>";
  const std::string rels =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">"
      "<Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
      "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>";
  return {{"[Content_Types].xml", content_types},
          {"_rels/.rels", rels},
          {"3D/3dmodel.model", std::string(model_xml)}};
}

std::string make_3mf(std::string_view model_xml) { return make_zip(package_parts(model_xml)); }

std::string model_xml(std::string_view unit, std::string_view resources, std::string_view build) {
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"{}\" xml:lang=\"en-US\" "
      "xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n<resources>\n{}"
      "</resources>\n<build>\n{}</build>\n</model>\n",
      unit, resources, build);
}

std::string mesh_object_xml(int id, const std::vector<std::array<float, 3>>& vertices,
                            const std::vector<std::array<std::uint32_t, 3>>& triangles,
                            std::string_view type) {
  std::string out = fmt::format("<object id=\"{}\" type=\"{}\"><mesh><vertices>\n", id, type);
  for (const auto& v : vertices) {
    out += fmt::format("<vertex x=\"{:.9g}\" y=\"{:.9g}\" z=\"{:.9g}\"/>\n", v[0], v[1], v[2]);
  }
  out += "</vertices><triangles>\n";
  for (const auto& t : triangles) {
    out += fmt::format("<triangle v1=\"{}\" v2=\"{}\" v3=\"{}\"/>\n", t[0], t[1], t[2]);
  }
  out += "</triangles></mesh></object>\n";
  return out;
}

std::string mesh_object_xml(int id, const TriangleSoup& soup) {
  std::vector<std::array<float, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  vertices.reserve(3 * soup.triangles.size());
  triangles.reserve(soup.triangles.size());
  for (const auto& triangle : soup.triangles) {
    const auto first = static_cast<std::uint32_t>(vertices.size());
    for (const Vec3& p : triangle) {
      vertices.push_back(
          {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    }
    triangles.push_back({first, first + 1, first + 2});
  }
  return mesh_object_xml(id, vertices, triangles);
}

std::string components_object_xml(int id, const std::vector<ComponentXml>& components) {
  std::string out = fmt::format("<object id=\"{}\" type=\"model\"><components>\n", id);
  for (const ComponentXml& c : components) {
    out += c.transform.empty() ? fmt::format("<component objectid=\"{}\"/>\n", c.object_id)
                               : fmt::format("<component objectid=\"{}\" transform=\"{}\"/>\n",
                                             c.object_id, c.transform);
  }
  out += "</components></object>\n";
  return out;
}

std::string build_item_xml(int object_id, std::string_view transform) {
  return transform.empty()
             ? fmt::format("<item objectid=\"{}\"/>\n", object_id)
             : fmt::format("<item objectid=\"{}\" transform=\"{}\"/>\n", object_id, transform);
}

BoxMesh make_box_mesh(float x, float y, float z) {
  BoxMesh box;
  for (int i = 0; i < 8; ++i) {
    box.vertices.push_back({(i & 1) ? x : 0.0f, (i & 2) ? y : 0.0f, (i & 4) ? z : 0.0f});
  }
  // Two triangles per face, counter-clockwise seen from outside.
  box.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return box;
}

double signed_volume(const TriangleSoup& soup) {
  double six_volume = 0.0;
  for (const auto& t : soup.triangles) {
    const Vec3& a = t[0];
    const Vec3& b = t[1];
    const Vec3& c = t[2];
    six_volume += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
                  a.z * (b.x * c.y - b.y * c.x);
  }
  return six_volume / 6.0;
}

}  // namespace strata::test
