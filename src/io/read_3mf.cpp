// 3MF input through lib3mf 1.x (the 3MF Consortium's reference library, its C interface): lib3mf
// opens the zip package and parses the model's XML; this file copies what it read into plain
// types (Model3mf) and hands them to assemble_3mf_mesh, which places the build.
#include <Common/NMR_ErrorConst.h>
#include <Model/COM/NMR_DLLInterfaces.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "io/model_3mf_internal.hpp"
#include "io/read_mesh_internal.hpp"

namespace strata::io::detail {
namespace {

/// One lib3mf instance (model, reader, iterator, object ...), released when it goes out of scope.
class Lib3mfHandle {
 public:
  Lib3mfHandle() = default;
  ~Lib3mfHandle() {
    if (instance_ != nullptr) NMR::lib3mf_release(instance_);
  }
  Lib3mfHandle(const Lib3mfHandle&) = delete;
  Lib3mfHandle& operator=(const Lib3mfHandle&) = delete;

  NMR::PLib3MFBase* get() const { return instance_; }
  /// Where a lib3mf function writes a new instance; releases the one held before.
  NMR::PLib3MFBase** out() {
    if (instance_ != nullptr) NMR::lib3mf_release(instance_);
    instance_ = nullptr;
    return &instance_;
  }

 private:
  NMR::PLib3MFBase* instance_ = nullptr;
};

struct Lib3mfError {
  unsigned code = 0;
  std::string message;
};

Lib3mfError last_error(NMR::PLib3MFBase* instance) {
  DWORD code = 0;
  LPCSTR message = nullptr;
  if (instance == nullptr || NMR::lib3mf_getlasterror(instance, &code, &message) != LIB3MF_OK) {
    return {};
  }
  return Lib3mfError{static_cast<unsigned>(code), message != nullptr ? message : ""};
}

/// What a failure of lib3mf's reader means for the user; lib3mf's own words in parentheses.
std::string describe_read_error(const Lib3mfError& error) {
  const std::string lib3mf = fmt::format("lib3mf: {}", error.message);
  switch (error.code) {
    case NMR_ERROR_COULDNOTREADZIPFILE:
      return fmt::format("not a 3MF file: not a zip archive, or a damaged one ({})", lib3mf);
    case NMR_ERROR_COULDNOTCREATEOPCPART:
      return fmt::format(
          "the 3MF package lacks a part its relationships name (the 3D model?) "
          "({})",
          lib3mf);
    case NMR_ERROR_INVALIDMODELNODEINDEX:
    case NMR_ERROR_INVALIDMODELCOORDINATEINDICES:
      // lib3mf stops inside its XML parser and tells neither the object nor the triangle.
      return fmt::format(
          "a triangle of the 3MF model refers to a vertex index that is out of "
          "range or repeated within the triangle ({})",
          lib3mf);
    case NMR_ERROR_INVALIDMODELCOORDINATES:
      return fmt::format(
          "a vertex of the 3MF model has a coordinate that is not a finite number "
          "in float range ({})",
          lib3mf);
    case NMR_ERROR_COULDNOTFINDBUILDITEMOBJECT:
    case NMR_ERROR_COULDNOTFINDCOMPONENTOBJECT:
      return fmt::format("the 3MF model refers to an object it does not define before ({})",
                         lib3mf);
    default:
      break;
  }
  // lib3mf numbers the errors of its XML parser from 0x9000.
  if ((error.code & 0xF000u) == 0x9000u) {
    return fmt::format("the 3MF model's XML is malformed ({})", lib3mf);
  }
  return fmt::format("lib3mf cannot read the 3MF file: {} (error 0x{:X})", error.message,
                     error.code);
}

/// A lib3mf call that should not fail once the model is read; when it does, the error names the
/// step and lib3mf's message.
Result<void> check(LIB3MFRESULT result, NMR::PLib3MFBase* instance, std::string_view step,
                   std::string_view name) {
  if (result == LIB3MF_OK) return {};
  const Lib3mfError error = last_error(instance);
  return Error{ErrorCode::BadInput,
               fmt::format("lib3mf cannot {}: {} (error 0x{:X})", step, error.message, error.code),
               std::string(name)};
}

/// The unit's millimetres and the name the file uses for it (core spec §3.4).
std::pair<double, std::string> unit_of(DWORD unit) {
  switch (unit) {
    case NMR::MODELUNIT_MICROMETER:
      return {0.001, "micron"};
    case NMR::MODELUNIT_CENTIMETER:
      return {10.0, "centimeter"};
    case NMR::MODELUNIT_INCH:
      return {25.4, "inch"};
    case NMR::MODELUNIT_FOOT:
      return {304.8, "foot"};
    case NMR::MODELUNIT_METER:
      return {1000.0, "meter"};
    default:
      return {1.0, "millimeter"};
  }
}

Object3mfType type_of(DWORD type) {
  switch (type) {
    case NMR::MODELOBJECTTYPE_MODEL:
      return Object3mfType::Model;
    case NMR::MODELOBJECTTYPE_SUPPORT:
      return Object3mfType::Support;
    case NMR::MODELOBJECTTYPE_SOLIDSUPPORT:
      return Object3mfType::SolidSupport;
    case NMR::MODELOBJECTTYPE_SURFACE:
      return Object3mfType::Surface;
    default:
      return Object3mfType::Other;
  }
}

Affine3 affine_of(const NMR::MODELTRANSFORM& t) {
  Affine3 out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) out.m[r][c] = t.m_fFields[r][c];
  }
  return out;
}

class Lib3mfModelReader {
 public:
  Lib3mfModelReader(std::string_view name, const ReadLimits& limits)
      : name_(name), limits_(limits) {}

  /// Parses the package; its warnings go to `diagnostics`.
  Result<Model3mf> read(std::string_view bytes, Diagnostics& diagnostics);
  /// lib3mf's error code when its reader failed on the package (0 otherwise).
  unsigned package_error() const { return package_error_; }

 private:
  Result<void> read_warnings(NMR::PLib3MFBase* reader, Diagnostics& diagnostics);
  Result<void> read_object(NMR::PLib3MFBase* object, Model3mf::Object& out);
  Result<void> read_mesh_object(NMR::PLib3MFBase* object, Model3mf::Object& out);
  Result<void> read_components(NMR::PLib3MFBase* object, Model3mf::Object& out);
  Result<void> read_build(NMR::PLib3MFBase* model, Model3mf& out);

  std::string_view name_;
  const ReadLimits& limits_;
  unsigned package_error_ = 0;
};

Result<Model3mf> Lib3mfModelReader::read(std::string_view bytes, Diagnostics& diagnostics) {
  Lib3mfHandle model;
  if (auto r = check(NMR::lib3mf_createmodel(model.out()), nullptr, "create a model", name_); !r) {
    return Error{ErrorCode::Internal, r.error().message, r.error().location};
  }
  Lib3mfHandle reader;
  if (auto r = check(NMR::lib3mf_model_queryreader(model.get(), "3mf", reader.out()), model.get(),
                     "create a 3MF reader", name_);
      !r) {
    return Error{ErrorCode::Internal, r.error().message, r.error().location};
  }
  // lib3mf reads the buffer without writing to it; its interface is not const-correct.
  auto* data = reinterpret_cast<BYTE*>(const_cast<char*>(bytes.data()));
  if (NMR::lib3mf_reader_readfrombuffer(reader.get(), data, bytes.size()) != LIB3MF_OK) {
    const Lib3mfError error = last_error(reader.get());
    package_error_ = error.code;
    return Error{ErrorCode::BadInput, describe_read_error(error), std::string(name_)};
  }
  if (auto r = read_warnings(reader.get(), diagnostics); !r) return r.error();

  Model3mf out;
  DWORD unit = NMR::MODELUNIT_MILLIMETER;
  if (auto r =
          check(NMR::lib3mf_model_getunit(model.get(), &unit), model.get(), "read the unit", name_);
      !r) {
    return r.error();
  }
  std::tie(out.millimetres_per_unit, out.unit_name) = unit_of(unit);

  Lib3mfHandle objects;
  if (auto r = check(NMR::lib3mf_model_getobjects(model.get(), objects.out()), model.get(),
                     "list the objects", name_);
      !r) {
    return r.error();
  }
  for (;;) {
    BOOL more = 0;
    if (auto r = check(NMR::lib3mf_resourceiterator_movenext(objects.get(), &more), objects.get(),
                       "list the objects", name_);
        !r) {
      return r.error();
    }
    if (!more) break;
    Lib3mfHandle object;
    if (auto r = check(NMR::lib3mf_resourceiterator_getcurrent(objects.get(), object.out()),
                       objects.get(), "list the objects", name_);
        !r) {
      return r.error();
    }
    Model3mf::Object& added = out.objects.emplace_back();
    if (auto r = read_object(object.get(), added); !r) return r.error();
  }
  if (auto r = read_build(model.get(), out); !r) return r.error();
  return out;
}

Result<void> Lib3mfModelReader::read_warnings(NMR::PLib3MFBase* reader, Diagnostics& diagnostics) {
  DWORD count = 0;
  if (auto r = check(NMR::lib3mf_reader_getwarningcount(reader, &count), reader,
                     "list its warnings", name_);
      !r) {
    return r;
  }
  // One diagnostic per distinct warning, with a count: vendor files repeat theirs per element.
  std::vector<std::pair<std::string, std::size_t>> seen;
  for (DWORD i = 0; i < count; ++i) {
    DWORD code = 0;
    ULONG needed = 0;
    if (NMR::lib3mf_reader_getwarningutf8(reader, i, &code, nullptr, 0, &needed) != LIB3MF_OK) {
      continue;
    }
    std::string text(needed, '\0');
    if (NMR::lib3mf_reader_getwarningutf8(reader, i, &code, text.data(), needed + 1, &needed) !=
        LIB3MF_OK) {
      continue;
    }
    text.resize(needed);
    if (code == NMR_ERROR_INVALIDMODELUNIT) {
      // lib3mf would read the file in millimetres: a silent factor of up to 1000 is worse than
      // a refusal.
      return Error{ErrorCode::BadInput,
                   fmt::format("the 3MF model's unit is not one of micron, millimeter, "
                               "centimeter, inch, foot, meter (lib3mf: {})",
                               text),
                   std::string(name_)};
    }
    auto it =
        std::find_if(seen.begin(), seen.end(), [&](const auto& s) { return s.first == text; });
    if (it == seen.end()) {
      seen.emplace_back(std::move(text), 1);
    } else {
      ++it->second;
    }
  }
  for (const auto& [text, times] : seen) {
    diagnostics.push_back(
        Diagnostic{Severity::Warning, "3mf.lib3mf_warning",
                   times == 1 ? fmt::format("{}: lib3mf: {}", name_, text)
                              : fmt::format("{}: lib3mf: {} ({} times)", name_, text, times)});
  }
  return {};
}

Result<void> Lib3mfModelReader::read_object(NMR::PLib3MFBase* object, Model3mf::Object& out) {
  DWORD id = 0;
  if (auto r = check(NMR::lib3mf_resource_getresourceid(object, &id), object, "read an object's id",
                     name_);
      !r) {
    return r;
  }
  out.id = id;
  DWORD type = 0;
  if (auto r =
          check(NMR::lib3mf_object_gettype(object, &type), object, "read an object's type", name_);
      !r) {
    return r;
  }
  out.type = type_of(type);
  ULONG needed = 0;
  if (NMR::lib3mf_object_getnameutf8(object, nullptr, 0, &needed) == LIB3MF_OK && needed > 0) {
    std::string text(needed, '\0');
    if (NMR::lib3mf_object_getnameutf8(object, text.data(), needed + 1, &needed) == LIB3MF_OK) {
      text.resize(needed);
      out.name = std::move(text);
    }
  }
  BOOL is_mesh = 0;
  if (auto r = check(NMR::lib3mf_object_ismeshobject(object, &is_mesh), object,
                     "read an object's kind", name_);
      !r) {
    return r;
  }
  out.is_mesh = is_mesh != 0;
  return is_mesh ? read_mesh_object(object, out) : read_components(object, out);
}

Result<void> Lib3mfModelReader::read_mesh_object(NMR::PLib3MFBase* object, Model3mf::Object& out) {
  DWORD num_vertices = 0;
  DWORD num_triangles = 0;
  if (auto r = check(NMR::lib3mf_meshobject_getvertexcount(object, &num_vertices), object,
                     "count an object's vertices", name_);
      !r) {
    return r;
  }
  if (auto r = check(NMR::lib3mf_meshobject_gettrianglecount(object, &num_triangles), object,
                     "count an object's triangles", name_);
      !r) {
    return r;
  }
  if (num_triangles > limits_.max_triangles) {
    return Error{ErrorCode::BadInput,
                 fmt::format("the object has {} triangles, more than the limit of {}",
                             num_triangles, limits_.max_triangles),
                 fmt::format("{}: object {}", name_, out.id)};
  }
  if (num_triangles == 0) return {};
  std::vector<NMR::MODELMESHVERTEX> vertices(num_vertices);
  std::vector<NMR::MODELMESHTRIANGLE> triangles(num_triangles);
  if (num_vertices > 0) {
    if (auto r = check(
            NMR::lib3mf_meshobject_getvertices(object, vertices.data(), num_vertices, nullptr),
            object, "read an object's vertices", name_);
        !r) {
      return r;
    }
  }
  if (auto r = check(NMR::lib3mf_meshobject_gettriangleindices(object, triangles.data(),
                                                               num_triangles, nullptr),
                     object, "read an object's triangles", name_);
      !r) {
    return r;
  }
  out.vertices.reserve(num_vertices);
  for (const NMR::MODELMESHVERTEX& v : vertices) {
    out.vertices.push_back({v.m_fPosition[0], v.m_fPosition[1], v.m_fPosition[2]});
  }
  out.triangles.reserve(num_triangles);
  for (const NMR::MODELMESHTRIANGLE& t : triangles) {
    out.triangles.push_back({t.m_nIndices[0], t.m_nIndices[1], t.m_nIndices[2]});
  }
  return {};
}

Result<void> Lib3mfModelReader::read_components(NMR::PLib3MFBase* object, Model3mf::Object& out) {
  BOOL is_components = 0;
  if (auto r = check(NMR::lib3mf_object_iscomponentsobject(object, &is_components), object,
                     "read an object's kind", name_);
      !r) {
    return r;
  }
  if (!is_components) return {};  // neither mesh nor components: nothing to place
  DWORD count = 0;
  if (auto r = check(NMR::lib3mf_componentsobject_getcomponentcount(object, &count), object,
                     "count an object's components", name_);
      !r) {
    return r;
  }
  out.components.reserve(count);
  for (DWORD i = 0; i < count; ++i) {
    Lib3mfHandle component;
    if (auto r = check(NMR::lib3mf_componentsobject_getcomponent(object, i, component.out()),
                       object, "read a component", name_);
        !r) {
      return r;
    }
    Model3mf::Component& added = out.components.emplace_back();
    DWORD id = 0;
    if (auto r = check(NMR::lib3mf_component_getobjectresourceid(component.get(), &id),
                       component.get(), "read a component's object", name_);
        !r) {
      return r;
    }
    added.object_id = id;
    NMR::MODELTRANSFORM transform{};
    if (auto r = check(NMR::lib3mf_component_gettransform(component.get(), &transform),
                       component.get(), "read a component's transform", name_);
        !r) {
      return r;
    }
    added.transform = affine_of(transform);
  }
  return {};
}

Result<void> Lib3mfModelReader::read_build(NMR::PLib3MFBase* model, Model3mf& out) {
  Lib3mfHandle items;
  if (auto r = check(NMR::lib3mf_model_getbuilditems(model, items.out()), model,
                     "list the build items", name_);
      !r) {
    return r;
  }
  for (;;) {
    BOOL more = 0;
    if (auto r = check(NMR::lib3mf_builditemiterator_movenext(items.get(), &more), items.get(),
                       "list the build items", name_);
        !r) {
      return r;
    }
    if (!more) break;
    Lib3mfHandle item;
    if (auto r = check(NMR::lib3mf_builditemiterator_getcurrent(items.get(), item.out()),
                       items.get(), "list the build items", name_);
        !r) {
      return r;
    }
    Model3mf::BuildItem& added = out.build.emplace_back();
    DWORD id = 0;
    if (auto r = check(NMR::lib3mf_builditem_getobjectresourceid(item.get(), &id), item.get(),
                       "read a build item's object", name_);
        !r) {
      return r;
    }
    added.object_id = id;
    NMR::MODELTRANSFORM transform{};
    if (auto r = check(NMR::lib3mf_builditem_getobjecttransform(item.get(), &transform), item.get(),
                       "read a build item's transform", name_);
        !r) {
      return r;
    }
    added.transform = affine_of(transform);
  }
  return {};
}

}  // namespace

/// Where PrusaSlicer's relationships put the package thumbnail.
constexpr std::string_view kThumbnailPart = "Metadata/thumbnail.png";

Result<TriangleSoup> read_3mf_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits, const CoordinateScale& scale) {
  Diagnostics diagnostics;
  Lib3mfModelReader reader(name, limits);
  Result<Model3mf> model = reader.read(bytes, diagnostics);
  if (!model && reader.package_error() == NMR_ERROR_COULDNOTCREATEOPCPART) {
    // lib3mf 1.8 opens the thumbnail the package's relationships name, and fails when it is
    // missing, as in PrusaSlicer 2.5's command-line exports. An empty thumbnail added in memory
    // lets it read the model; the first error stands when that does not help.
    if (const std::optional<std::string> patched = append_empty_zip_entry(bytes, kThumbnailPart)) {
      Diagnostics retry_diagnostics;
      Result<Model3mf> retried = Lib3mfModelReader(name, limits).read(*patched, retry_diagnostics);
      if (retried) {
        model = std::move(retried);
        diagnostics = std::move(retry_diagnostics);
        diagnostics.push_back(Diagnostic{
            Severity::Warning, "3mf.missing_thumbnail",
            fmt::format("{}: the package's relationships name a thumbnail ({}) it does not "
                        "hold; read without it",
                        name, kThumbnailPart)});
      }
    }
  }
  if (!model) return model.error();
  Result<TriangleSoup> soup = assemble_3mf_mesh(*model, name, limits, scale);
  if (!soup) return soup;
  soup->diagnostics.insert(soup->diagnostics.begin(), diagnostics.begin(), diagnostics.end());
  return soup;
}

}  // namespace strata::io::detail
