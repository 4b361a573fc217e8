#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "strata/core/result.hpp"
#include "strata/io/length_unit.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::io::detail {

/// An affine map as 3MF stores it (core spec §3.3, one row of lib3mf's MODELTRANSFORM a row
/// here): a point p maps to p'_r = m[r][0] x + m[r][1] y + m[r][2] z + m[r][3].
struct Affine3 {
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
};

/// What an object is for (3MF core spec §4.1): `model` and `solidsupport` are solids to fill;
/// `support` and `surface` are not; `other` must not be built.
enum class Object3mfType { Model, SolidSupport, Support, Surface, Other };

/// The content of a 3MF file's model as lib3mf reads it, in plain types: the input of
/// assemble_3mf_mesh, so that the part strata controls can be tested and fuzzed without a zip.
struct Model3mf {
  /// Millimetres in one unit of the file (3MF's micron ... meter); 1 for millimeter.
  double millimetres_per_unit = 1.0;
  /// The unit as the file names it ("millimeter", "inch", ...), for messages.
  std::string unit_name = "millimeter";

  struct Component {
    std::uint32_t object_id = 0;
    Affine3 transform;
  };
  struct Object {
    std::uint32_t id = 0;
    std::string name;  ///< may be empty
    Object3mfType type = Object3mfType::Model;
    bool is_mesh = true;                         ///< a mesh object; otherwise a components object
    std::vector<std::array<float, 3>> vertices;  ///< mesh objects
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into vertices
    std::vector<Component> components;                    ///< components objects
  };
  struct BuildItem {
    std::uint32_t object_id = 0;
    Affine3 transform;
  };

  std::vector<Object> objects;
  std::vector<BuildItem> build;
};

/// How deep components may nest (a build item's object is depth 1); real files use 2 or 3.
inline constexpr int kMax3mfComponentDepth = 64;

/// The triangles of every build item (in build order; each object's triangles in file order, its
/// components in order), with the components' and the item's transforms applied (composed in
/// double) and the coordinates converted to millimetres: millimetres_per_unit * scale.scale.
/// A transform with a negative determinant reverses the vertex order of the triangles it places,
/// so that a mirrored solid stays a solid (core spec §3.3). Objects of type support, surface and
/// other are left out with a warning ("3mf.object_left_out"); a unit other than millimetres gives
/// an Info "3mf.unit"; a singular transform a warning "3mf.singular_transform".
/// @param name  the file, for messages and locations
/// @return the soup (format "3mf"), or Error{BadInput} located at the file and, where it applies,
///         "object 3 ('name'), triangle 7" or "build item 2": a vertex index out of range, an
///         object id defined twice or not at all, components that contain themselves or nest
///         deeper than kMax3mfComponentDepth, more triangles than limits.max_triangles, a
///         coordinate that is not finite once placed, or no triangle at all; Error{Usage} when
///         scale.units is not millimetres (the file states its own unit) or scale.scale is not
///         finite and positive
Result<TriangleSoup> assemble_3mf_mesh(const Model3mf& model, std::string_view name,
                                       const ReadLimits& limits, const CoordinateScale& scale);

}  // namespace strata::io::detail
