#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "strata/mesh/triangle_soup.hpp"

namespace strata::test {

/// A zip archive of `entries` (name, content) in that order, stored without compression: enough
/// for a 3MF package, and a way to build broken ones.
std::string make_zip(const std::vector<std::pair<std::string, std::string>>& entries);

/// The parts of a 3MF package in order: [Content_Types].xml, _rels/.rels naming
/// /3D/3dmodel.model as the 3D model, and `model_xml` as that part (3D/3dmodel.model, last).
std::vector<std::pair<std::string, std::string>> package_parts(std::string_view model_xml);

/// make_zip(package_parts(model_xml)): a 3MF file.
std::string make_3mf(std::string_view model_xml);

/// The XML of a 3MF model part: <model unit="..."> with <resources> and <build> around the given
/// elements (from mesh_object_xml, components_object_xml, build_item_xml).
std::string model_xml(std::string_view unit, std::string_view resources, std::string_view build);

/// An <object type="..."> with a <mesh>; coordinates are written with 9 significant digits, so a
/// float32 reads back exactly.
std::string mesh_object_xml(int id, const std::vector<std::array<float, 3>>& vertices,
                            const std::vector<std::array<std::uint32_t, 3>>& triangles,
                            std::string_view type = "model");

/// A mesh object holding the soup's triangles, each with its own three vertices (so that a
/// degenerate triangle keeps three distinct indices, as 3MF requires); coordinates as float32.
std::string mesh_object_xml(int id, const TriangleSoup& soup);

/// One component of a components object: the object it places and its transform attribute
/// ("m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32"; empty for none).
struct ComponentXml {
  int object_id = 0;
  std::string transform;
};

/// An <object type="model"> with <components>.
std::string components_object_xml(int id, const std::vector<ComponentXml>& components);

/// A build <item>, with a transform attribute when `transform` is not empty.
std::string build_item_xml(int object_id, std::string_view transform = {});

/// The 8 vertices and 12 outward triangles of the box [0, size.x] x [0, size.y] x [0, size.z].
struct BoxMesh {
  std::vector<std::array<float, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};
BoxMesh make_box_mesh(float x, float y, float z);

/// The signed volume of a soup (positive for an outward-oriented closed surface), in mm³.
double signed_volume(const TriangleSoup& soup);

}  // namespace strata::test
