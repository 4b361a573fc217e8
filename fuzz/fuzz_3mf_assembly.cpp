// The part of 3MF input that strata controls (io::detail::assemble_3mf_mesh), fed a model decoded
// from the bytes, then weld and slice. lib3mf, which parses the zip and the XML, is not fuzzed
// here; the assembly trusts nothing it checks (indices, references, nesting, finite values).
//
// The bytes, read in order until they run out (a record cut short is dropped):
//   unit     1 byte: micron, millimeter, centimeter, inch, foot, meter (mod 6)
//   records  1 tag byte each (mod 4):
//     0  mesh object, small coordinates: id, type (mod 5), vertex count n, n x 3 int8 (half
//        millimetres), triangle count m, m x 3 vertex indices (1 byte each, may be out of range)
//     1  mesh object, float32 coordinates (any bits): as 0 with 4-byte little-endian floats
//     2  components object: id, component count c, c x (object id, transform)
//     3  build item: object id, transform
//   transform  1 byte k: 0 = identity; otherwise 9 bytes picking the linear part's entries from
//              kEntries and 3 int8 translations
// The same bytes also go, as a zip archive, through append_empty_zip_entry (the thumbnail that
// the reader adds before it retries lib3mf), strata's other code on the 3MF path.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>

#include "fuzz_support.hpp"
#include "io/model_3mf_internal.hpp"
#include "io/read_mesh_internal.hpp"

namespace {

using strata::io::detail::Affine3;
using strata::io::detail::Model3mf;
using strata::io::detail::Object3mfType;

constexpr std::array<double, 8> kEntries{0.0, 1.0, -1.0, 2.0, 0.5, -0.5, 3.0, -2.0};
constexpr std::array<std::pair<double, const char*>, 6> kUnits{{{0.001, "micron"},
                                                                {1.0, "millimeter"},
                                                                {10.0, "centimeter"},
                                                                {25.4, "inch"},
                                                                {304.8, "foot"},
                                                                {1000.0, "meter"}}};

class Decoder {
 public:
  explicit Decoder(std::string_view bytes) : bytes_(bytes) {}

  std::optional<std::uint8_t> byte() {
    if (at_ >= bytes_.size()) return std::nullopt;
    return static_cast<std::uint8_t>(bytes_[at_++]);
  }
  std::optional<float> float32() {
    if (bytes_.size() - at_ < 4) return std::nullopt;
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) {
      bits |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(bytes_[at_ + i])) << (8 * i);
    }
    at_ += 4;
    float value = 0;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  std::optional<Affine3> transform() {
    const auto kind = byte();
    if (!kind) return std::nullopt;
    Affine3 t;
    if (*kind == 0) return t;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        const auto b = byte();
        if (!b) return std::nullopt;
        t.m[r][c] = kEntries[*b % kEntries.size()];
      }
    }
    for (int r = 0; r < 3; ++r) {
      const auto b = byte();
      if (!b) return std::nullopt;
      t.m[r][3] = static_cast<std::int8_t>(*b);
    }
    return t;
  }

 private:
  std::string_view bytes_;
  std::size_t at_ = 0;
};

std::optional<Model3mf::Object> mesh_object(Decoder& in, bool float_coordinates) {
  Model3mf::Object object;
  const auto id = in.byte();
  const auto type = in.byte();
  const auto num_vertices = in.byte();
  if (!id || !type || !num_vertices) return std::nullopt;
  object.id = *id;
  object.type = static_cast<Object3mfType>(*type % 5);
  for (int v = 0; v < *num_vertices; ++v) {
    std::array<float, 3> p{};
    for (float& c : p) {
      if (float_coordinates) {
        const auto f = in.float32();
        if (!f) return std::nullopt;
        c = *f;
      } else {
        const auto b = in.byte();
        if (!b) return std::nullopt;
        c = 0.5f * static_cast<float>(static_cast<std::int8_t>(*b));
      }
    }
    object.vertices.push_back(p);
  }
  const auto num_triangles = in.byte();
  if (!num_triangles) return std::nullopt;
  for (int t = 0; t < *num_triangles; ++t) {
    std::array<std::uint32_t, 3> corners{};
    for (std::uint32_t& c : corners) {
      const auto b = in.byte();
      if (!b) return std::nullopt;
      c = *b;
    }
    object.triangles.push_back(corners);
  }
  return object;
}

std::optional<Model3mf::Object> components_object(Decoder& in) {
  Model3mf::Object object;
  object.is_mesh = false;
  const auto id = in.byte();
  const auto count = in.byte();
  if (!id || !count) return std::nullopt;
  object.id = *id;
  for (int c = 0; c < *count; ++c) {
    const auto child = in.byte();
    if (!child) return std::nullopt;
    const auto transform = in.transform();
    if (!transform) return std::nullopt;
    object.components.push_back({*child, *transform});
  }
  return object;
}

Model3mf decode(std::string_view bytes) {
  Decoder in(bytes);
  Model3mf model;
  if (const auto unit = in.byte()) {
    const auto& [mm, name] = kUnits[*unit % kUnits.size()];
    model.millimetres_per_unit = mm;
    model.unit_name = name;
  }
  while (const auto tag = in.byte()) {
    switch (*tag % 4) {
      case 0:
      case 1: {
        auto object = mesh_object(in, *tag % 4 == 1);
        if (!object) return model;
        model.objects.push_back(std::move(*object));
        break;
      }
      case 2: {
        auto object = components_object(in);
        if (!object) return model;
        model.objects.push_back(std::move(*object));
        break;
      }
      default: {
        const auto id = in.byte();
        if (!id) return model;
        const auto transform = in.transform();
        if (!transform) return model;
        model.build.push_back({*id, *transform});
        break;
      }
    }
  }
  return model;
}

}  // namespace

/// An archive with the entry appended ends with an end record and holds the entry: appending it
/// again is refused.
void check_zip_append(std::string_view bytes) {
  constexpr std::string_view kName = "Metadata/thumbnail.png";
  const auto patched = strata::io::detail::append_empty_zip_entry(bytes, kName);
  if (!patched) return;
  const bool ends_with_end_record =
      patched->size() >= 22 && patched->compare(patched->size() - 22, 4, "PK\x05\x06") == 0;
  strata::fuzz::check(
      ends_with_end_record && !strata::io::detail::append_empty_zip_entry(*patched, kName),
      "an appended zip entry is not found again");
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = strata::fuzz::as_bytes(data, size);
  check_zip_append(bytes);
  const Model3mf model = decode(bytes);
  const strata::io::ReadLimits limits = strata::fuzz::read_limits();
  const auto soup = strata::io::detail::assemble_3mf_mesh(model, "fuzz.3mf", limits, {});
  if (!soup) {
    strata::fuzz::check_read_error(soup.error());
    return 0;
  }
  strata::fuzz::check_soup(*soup, limits);
  strata::fuzz::slice_small(*soup, strata::fuzz::hash_bytes(bytes));
  return 0;
}
