// The part of 3MF input that strata controls: lib3mf has parsed the package, this places the
// build's objects. It trusts nothing lib3mf checks (indices, references, nesting), because it is
// also fed arbitrary data by the fuzz target fuzz/fuzz_3mf_assembly.cpp.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "io/model_3mf_internal.hpp"
#include "io/read_mesh_internal.hpp"

namespace strata::io::detail {
namespace {

std::string_view type_name(Object3mfType type) {
  switch (type) {
    case Object3mfType::Model:
      return "model";
    case Object3mfType::SolidSupport:
      return "solidsupport";
    case Object3mfType::Support:
      return "support";
    case Object3mfType::Surface:
      return "surface";
    case Object3mfType::Other:
      return "other";
  }
  return "other";
}

/// Only these enclose material (core spec §4.1); support and surface meshes are not filled.
bool is_solid(Object3mfType type) {
  return type == Object3mfType::Model || type == Object3mfType::SolidSupport;
}

std::string object_label(const Model3mf::Object& object) {
  return object.name.empty() ? fmt::format("object {}", object.id)
                             : fmt::format("object {} ('{}')", object.id, object.name);
}

/// The map that applies `inner` first, then `outer`.
Affine3 compose(const Affine3& outer, const Affine3& inner) {
  Affine3 out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      double v = outer.m[r][0] * inner.m[0][c] + outer.m[r][1] * inner.m[1][c] +
                 outer.m[r][2] * inner.m[2][c];
      if (c == 3) v += outer.m[r][3];
      out.m[r][c] = v;
    }
  }
  return out;
}

double determinant(const Affine3& t) {
  const auto& m = t.m;
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// An identity transform maps each coordinate to itself exactly (1 * x + 0 * y + 0 * z + 0), so a
/// 3MF of an STL's float coordinates slices as the STL does.
Vec3 apply(const Affine3& t, const std::array<float, 3>& p, double factor) {
  const double x = p[0];
  const double y = p[1];
  const double z = p[2];
  const auto& m = t.m;
  return Vec3{(m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3]) * factor,
              (m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3]) * factor,
              (m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3]) * factor};
}

bool is_finite(const Vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

class Assembler {
 public:
  Assembler(const Model3mf& model, std::string_view name, const ReadLimits& limits, double factor)
      : model_(model), name_(name), limits_(limits), factor_(factor) {}

  Result<TriangleSoup> run();

 private:
  enum class Visit { No, OnPath, Done };

  Error error_at(std::string place, std::string message) const {
    return Error{ErrorCode::BadInput, std::move(message),
                 place.empty() ? std::string(name_) : fmt::format("{}: {}", name_, place)};
  }
  Result<void> index_objects();
  std::optional<std::size_t> find(std::uint32_t id) const {
    const auto it = by_id_.find(id);
    return it == by_id_.end() ? std::nullopt : std::optional<std::size_t>(it->second);
  }
  /// Checks an object and what it contains, once each, and counts the triangles it places
  /// (saturating above the limit, so that repeated components cannot overflow the count).
  Result<std::size_t> check_and_count(std::size_t index, int depth);
  Result<void> emit(std::size_t index, const Affine3& transform);

  const Model3mf& model_;
  std::string_view name_;
  const ReadLimits& limits_;
  double factor_;
  std::unordered_map<std::uint32_t, std::size_t> by_id_;
  std::vector<Visit> visit_;
  std::vector<std::size_t> count_;
  std::size_t left_out_ = 0;
  DiagnosticTally tally_{"object"};
  TriangleSoup soup_;
};

Result<void> Assembler::index_objects() {
  by_id_.reserve(model_.objects.size());
  for (std::size_t i = 0; i < model_.objects.size(); ++i) {
    const auto [it, added] = by_id_.emplace(model_.objects[i].id, i);
    if (!added) {
      return error_at(object_label(model_.objects[i]),
                      fmt::format("the id {} is defined twice", model_.objects[i].id));
    }
  }
  visit_.assign(model_.objects.size(), Visit::No);
  count_.assign(model_.objects.size(), 0);
  return {};
}

Result<std::size_t> Assembler::check_and_count(std::size_t index, int depth) {
  const Model3mf::Object& object = model_.objects[index];
  if (visit_[index] == Visit::Done) return count_[index];
  if (visit_[index] == Visit::OnPath) {
    return error_at(object_label(object), "its components contain the object itself");
  }
  if (depth > kMax3mfComponentDepth) {
    return error_at(object_label(object),
                    fmt::format("components nest deeper than {} levels", kMax3mfComponentDepth));
  }
  visit_[index] = Visit::OnPath;
  const std::size_t cap = limits_.max_triangles + 1;
  std::size_t count = 0;
  if (!is_solid(object.type)) {
    ++left_out_;
    tally_.add("3mf.object_left_out", Severity::Warning, object.id, [&] {
      return fmt::format("{}: {} is of type {}, not a solid to fill: left out", name_,
                         object_label(object), type_name(object.type));
    });
  } else if (object.is_mesh) {
    const std::size_t num_vertices = object.vertices.size();
    for (std::size_t t = 0; t < object.triangles.size(); ++t) {
      for (const std::uint32_t v : object.triangles[t]) {
        if (v >= num_vertices) {
          return error_at(
              fmt::format("{}, triangle {}", object_label(object), t),
              num_vertices == 0
                  ? fmt::format("vertex index {} is out of range: the object has no vertices", v)
                  : fmt::format("vertex index {} is out of range: the object has {} vertices "
                                "(indices 0 to {})",
                                v, num_vertices, num_vertices - 1));
        }
      }
    }
    count = std::min(object.triangles.size(), cap);
  } else {
    for (std::size_t c = 0; c < object.components.size(); ++c) {
      const std::uint32_t id = object.components[c].object_id;
      const std::optional<std::size_t> child = find(id);
      if (!child) {
        return error_at(fmt::format("{}, component {}", object_label(object), c),
                        fmt::format("refers to object {}, which the file does not define", id));
      }
      Result<std::size_t> placed = check_and_count(*child, depth + 1);
      if (!placed) return placed.error();
      count = std::min(count + *placed, cap);
    }
  }
  visit_[index] = Visit::Done;
  count_[index] = count;
  return count;
}

Result<void> Assembler::emit(std::size_t index, const Affine3& transform) {
  const Model3mf::Object& object = model_.objects[index];
  if (!is_solid(object.type)) return {};
  if (!object.is_mesh) {
    for (const Model3mf::Component& component : object.components) {
      // check_and_count found every child: find() cannot fail here.
      const Result<void> placed =
          emit(*find(component.object_id), compose(transform, component.transform));
      if (!placed) return placed;
    }
    return {};
  }
  if (object.triangles.empty()) return {};
  const double det = determinant(transform);
  if (det == 0.0) {
    tally_.add("3mf.singular_transform", Severity::Warning, object.id, [&] {
      return fmt::format(
          "{}: {} is placed by a singular transform (determinant 0): its "
          "triangles are flat",
          name_, object_label(object));
    });
  }
  // Core spec §3.3: a mirroring transform must not turn a solid inside out.
  const bool mirrored = det < 0.0;
  for (std::size_t t = 0; t < object.triangles.size(); ++t) {
    const auto& corners = object.triangles[t];
    std::array<Vec3, 3> triangle{apply(transform, object.vertices[corners[0]], factor_),
                                 apply(transform, object.vertices[corners[1]], factor_),
                                 apply(transform, object.vertices[corners[2]], factor_)};
    for (const Vec3& p : triangle) {
      if (!is_finite(p)) {
        return error_at(fmt::format("{}, triangle {}", object_label(object), t),
                        fmt::format("a corner is ({}, {}, {}) mm once placed by the transforms "
                                    "and converted from {}: not a finite number",
                                    p.x, p.y, p.z, model_.unit_name));
      }
    }
    if (mirrored) std::swap(triangle[1], triangle[2]);
    soup_.triangles.push_back(triangle);
  }
  return {};
}

Result<TriangleSoup> Assembler::run() {
  if (Result<void> indexed = index_objects(); !indexed) return indexed.error();
  const std::size_t cap = limits_.max_triangles + 1;
  std::size_t total = 0;
  for (std::size_t i = 0; i < model_.build.size(); ++i) {
    const std::uint32_t id = model_.build[i].object_id;
    const std::optional<std::size_t> object = find(id);
    if (!object) {
      return error_at(fmt::format("build item {}", i),
                      fmt::format("refers to object {}, which the file does not define", id));
    }
    Result<std::size_t> placed = check_and_count(*object, 1);
    if (!placed) return placed.error();
    total = std::min(total + *placed, cap);
  }
  if (total > limits_.max_triangles) {
    return error_at({}, fmt::format("the 3MF build places more than {} triangles (the limit)",
                                    limits_.max_triangles));
  }
  if (total == 0) {
    if (model_.build.empty()) return error_at({}, "no mesh to slice: the 3MF build has no item");
    return error_at(
        {}, fmt::format("no mesh to slice: the objects of the 3MF build's {} item{} hold no "
                        "triangle{}",
                        model_.build.size(), model_.build.size() == 1 ? "" : "s",
                        left_out_ == 0 ? std::string()
                                       : fmt::format(" ({} object{} left out by type)", left_out_,
                                                     left_out_ == 1 ? "" : "s")));
  }
  soup_.triangles.reserve(total);
  for (const Model3mf::BuildItem& item : model_.build) {
    if (Result<void> placed = emit(*find(item.object_id), item.transform); !placed) {
      return placed.error();
    }
  }
  soup_.format = "3mf";
  if (model_.millimetres_per_unit != 1.0) {
    soup_.diagnostics.push_back(
        Diagnostic{Severity::Info, "3mf.unit",
                   fmt::format("{}: the file's unit is {}: coordinates converted to millimetres "
                               "(x {})",
                               name_, model_.unit_name, model_.millimetres_per_unit)});
  }
  tally_.flush_into(soup_.diagnostics);
  return std::move(soup_);
}

}  // namespace

Result<TriangleSoup> assemble_3mf_mesh(const Model3mf& model, std::string_view name,
                                       const ReadLimits& limits, const CoordinateScale& scale) {
  if (!(scale.scale > 0.0) || !std::isfinite(scale.scale)) {
    return Error{ErrorCode::Usage,
                 fmt::format("the scale factor must be a finite number > 0, got {}", scale.scale),
                 {}};
  }
  if (scale.units != LengthUnit::Millimetre) {
    return Error{ErrorCode::Usage,
                 fmt::format("a 3MF file states its own unit ({}) and is converted from it; a unit "
                             "({}) cannot be given for its coordinates, only a scale factor",
                             model.unit_name, length_unit_name(scale.units)),
                 std::string(name)};
  }
  if (!(model.millimetres_per_unit > 0.0) || !std::isfinite(model.millimetres_per_unit)) {
    return Error{ErrorCode::BadInput,
                 fmt::format("the unit {} is not a finite length > 0", model.unit_name),
                 std::string(name)};
  }
  return Assembler(model, name, limits, model.millimetres_per_unit * scale.scale).run();
}

}  // namespace strata::io::detail
