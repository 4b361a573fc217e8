// PLY reader (ASCII, binary little and big endian), hand-written rather than CGAL::IO::read_PLY
// because CGAL 5.5's reader ignores every element but `vertex` and `face`: a model stored as
// triangle strips (common-3d-test-models/data/igea.ply in the corpus, element `tristrips`) reads
// as zero faces. It also cannot say on which line or byte a file is bad. Only geometry is read:
// `vertex` x, y, z (any numeric type), `face` vertex_indices / vertex_index lists, and
// `tristrips` vertex_indices lists (strips separated by -1). Other elements and properties are
// skipped according to their declared types.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/read_mesh_internal.hpp"
#include "strata/io/scan_number.hpp"

namespace strata::io::detail {
namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<PlyType> parse_type(std::string_view word) {
  if (word == "char" || word == "int8") return PlyType::Int8;
  if (word == "uchar" || word == "uint8") return PlyType::UInt8;
  if (word == "short" || word == "int16") return PlyType::Int16;
  if (word == "ushort" || word == "uint16") return PlyType::UInt16;
  if (word == "int" || word == "int32") return PlyType::Int32;
  if (word == "uint" || word == "uint32") return PlyType::UInt32;
  if (word == "float" || word == "float32") return PlyType::Float32;
  if (word == "double" || word == "float64") return PlyType::Float64;
  return std::nullopt;
}

std::size_t size_of(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      break;
  }
  return 8;
}

bool is_integer(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

/// What an ASCII value of the type is scanned as: integers with their declared range, `float` and
/// `double` alike as double (SPEC §2: formats other than STL are read as double).
NumberType number_type(PlyType type) {
  switch (type) {
    case PlyType::Int8:
      return NumberType::Int8;
    case PlyType::UInt8:
      return NumberType::UInt8;
    case PlyType::Int16:
      return NumberType::Int16;
    case PlyType::UInt16:
      return NumberType::UInt16;
    case PlyType::Int32:
      return NumberType::Int32;
    case PlyType::UInt32:
      return NumberType::UInt32;
    case PlyType::Float32:
    case PlyType::Float64:
      break;
  }
  return NumberType::Float64;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  ///< first byte after the end_header line
  std::size_t body_line = 0;    ///< line number of that byte (ASCII)
  DiagnosticTally skipped_lines{"line"};
};

/// A header line for a message: at most 40 characters, control bytes as \xNN.
std::string quote_line(std::string_view line) {
  constexpr std::size_t kMaxChars = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < line.size() && i < kMaxChars; ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    if (c < 0x20 || c == 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  if (line.size() > kMaxChars) out += "...";
  return out + "'";
}

Error error_at(std::string location, std::string message) {
  return Error{ErrorCode::BadInput, std::move(message), std::move(location)};
}

Result<PlyHeader> parse_header(std::string_view bytes, std::string_view name,
                               const ReadLimits& limits) {
  PlyHeader header;
  std::size_t pos = 0;
  std::size_t line_number = 0;
  bool format_seen = false;
  for (;;) {
    if (pos >= bytes.size()) {
      return error_at(fmt::format("{}:{}", name, line_number), "PLY header has no end_header line");
    }
    ++line_number;
    const std::size_t window = std::min(bytes.size() - pos, limits.max_line_bytes + 1);
    const std::size_t eol_rel = bytes.substr(pos, window).find('\n');
    if (eol_rel == std::string_view::npos && window > limits.max_line_bytes) {
      return error_at(fmt::format("{}:{}", name, line_number),
                      fmt::format("line longer than the limit of {} bytes", limits.max_line_bytes));
    }
    const std::size_t eol = eol_rel == std::string_view::npos ? bytes.size() : pos + eol_rel;
    std::string_view line = bytes.substr(pos, eol - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = eol + 1;
    const std::string where = fmt::format("{}:{}", name, line_number);

    std::string_view rest = line;
    const std::string_view word = next_token(rest);
    if (line_number == 1) {
      if (word != "ply") return error_at(where, "not a PLY file: the first line is not 'ply'");
      continue;
    }
    if (word.empty() || word == "comment" || word == "obj_info") continue;
    if (word == "format") {
      const std::string_view encoding = next_token(rest);
      if (encoding == "ascii") {
        header.encoding = PlyEncoding::Ascii;
      } else if (encoding == "binary_little_endian") {
        header.encoding = PlyEncoding::BinaryLittleEndian;
      } else if (encoding == "binary_big_endian") {
        header.encoding = PlyEncoding::BinaryBigEndian;
      } else {
        return error_at(where, fmt::format("unknown PLY format '{}'", encoding.substr(0, 40)));
      }
      format_seen = true;
    } else if (word == "element") {
      PlyElement element;
      element.name = std::string(next_token(rest));
      const std::string_view count = next_token(rest);
      if (element.name.empty() || count.empty()) {
        return error_at(where, "PLY element line needs a name and a count");
      }
      const ScannedNumber<std::uint64_t> scanned = scan_unsigned(count, NumberType::UInt64);
      if (!scanned.ok()) return bad_number(where, count, scanned);
      element.count = scanned.value;
      header.elements.push_back(std::move(element));
    } else if (word == "property") {
      if (header.elements.empty()) return error_at(where, "PLY property before any element");
      PlyProperty property;
      std::string_view type_word = next_token(rest);
      if (type_word == "list") {
        property.is_list = true;
        const auto count_type = parse_type(next_token(rest));
        type_word = next_token(rest);
        if (!count_type || !is_integer(*count_type)) {
          return error_at(where, "PLY list property needs an integer count type");
        }
        property.count_type = *count_type;
      }
      const auto type = parse_type(type_word);
      if (!type) {
        return error_at(where,
                        fmt::format("unknown PLY property type '{}'", type_word.substr(0, 40)));
      }
      property.type = *type;
      property.name = std::string(next_token(rest));
      header.elements.back().properties.push_back(std::move(property));
    } else if (word == "end_header") {
      if (!format_seen) return error_at(where, "PLY header has no format line");
      header.body_offset = std::min(pos, bytes.size());
      header.body_line = line_number + 1;
      return header;
    } else {
      // Some writers put free text in the header without the `comment` keyword (Blender 2.47:
      // "Created by Blender3D 247 - www.blender.org"); assimp and MeshLab skip such lines.
      header.skipped_lines.add("ply.header_line_skipped", Severity::Warning, line_number, [&] {
        return fmt::format(
            "{}: PLY header line {} skipped: it is not an element, property, format, comment, "
            "obj_info or end_header line",
            where, quote_line(line));
      });
    }
  }
}

/// Reads values one after the other from an ASCII body (whitespace-separated, across lines).
class AsciiBody {
 public:
  AsciiBody(std::string_view body, std::size_t first_line, std::string_view name)
      : body_(body), line_(first_line), name_(name) {}

  bool read(PlyType type, double& value) {
    const std::string_view token = next();
    if (token.empty()) return false;
    const NumberType number = number_type(type);
    NumberFault fault = NumberFault::None;
    if (!is_integer(type)) {
      const ScannedNumber<double> scanned = scan_real(token, number);
      fault = scanned.fault;
      value = scanned.value;
    } else if (type == PlyType::Int8 || type == PlyType::Int16 || type == PlyType::Int32) {
      const ScannedNumber<std::int64_t> scanned = scan_signed(token, number);
      fault = scanned.fault;
      value = static_cast<double>(scanned.value);  // at most 32 bits: exact
    } else {
      const ScannedNumber<std::uint64_t> scanned = scan_unsigned(token, number);
      fault = scanned.fault;
      value = static_cast<double>(scanned.value);
    }
    if (fault != NumberFault::None) {
      bad_token_ = BadToken{token, fault, number};
      return false;
    }
    return true;
  }
  std::size_t remaining() const { return body_.size() - pos_; }
  std::size_t line() const { return line_; }
  std::string where() const { return fmt::format("{}:{}", name_, line_); }
  /// Why the last read failed, `context` naming the item: the bad-number message for a token
  /// that is not a number of the declared type, else `context` and the problem.
  Error failure(std::string_view context) const {
    if (bad_token_) {
      return bad_number(where(), bad_token_->token, bad_token_->fault, bad_token_->type);
    }
    return error_at(where(), fmt::format("{}: {}", context, problem_));
  }

 private:
  struct BadToken {
    std::string_view token;
    NumberFault fault;
    NumberType type;
  };

  std::string_view next() {
    for (;;) {
      while (pos_ < body_.size() && (is_blank(body_[pos_]) || body_[pos_] == '\r')) ++pos_;
      if (pos_ < body_.size() && body_[pos_] == '\n') {
        ++line_;
        ++pos_;
        continue;
      }
      break;
    }
    const std::size_t start = pos_;
    while (pos_ < body_.size() && !is_blank(body_[pos_]) && body_[pos_] != '\n' &&
           body_[pos_] != '\r') {
      ++pos_;
    }
    if (start == pos_) problem_ = "file ends early (truncated?)";
    return body_.substr(start, pos_ - start);
  }
  std::string_view body_;
  std::size_t pos_ = 0;
  std::size_t line_;
  std::string_view name_;
  std::string problem_;
  std::optional<BadToken> bad_token_;
};

/// Reads values from a binary body of either byte order.
class BinaryBody {
 public:
  BinaryBody(std::string_view body, std::size_t body_offset, bool big_endian, std::string_view name)
      : body_(body), offset_(body_offset), big_endian_(big_endian), name_(name) {}

  bool read(PlyType type, double& value) {
    const std::size_t size = size_of(type);
    if (body_.size() - pos_ < size) {
      problem_ = "file ends early (truncated?)";
      return false;
    }
    unsigned char raw[8];
    std::memcpy(raw, body_.data() + pos_, size);
    pos_ += size;
    if (big_endian_ != (std::endian::native == std::endian::big)) std::reverse(raw, raw + size);
    switch (type) {
      case PlyType::Int8:
        value = static_cast<std::int8_t>(raw[0]);
        break;
      case PlyType::UInt8:
        value = raw[0];
        break;
      case PlyType::Int16:
        value = load<std::int16_t>(raw);
        break;
      case PlyType::UInt16:
        value = load<std::uint16_t>(raw);
        break;
      case PlyType::Int32:
        value = load<std::int32_t>(raw);
        break;
      case PlyType::UInt32:
        value = load<std::uint32_t>(raw);
        break;
      case PlyType::Float32:
        value = load<float>(raw);
        break;
      case PlyType::Float64:
        value = load<double>(raw);
        break;
    }
    return true;
  }
  std::size_t remaining() const { return body_.size() - pos_; }
  std::size_t line() const { return 0; }
  std::string where() const { return fmt::format("{}: byte {}", name_, offset_ + pos_); }
  /// Why the last read failed, `context` naming the item.
  Error failure(std::string_view context) const {
    return error_at(where(), fmt::format("{}: {}", context, problem_));
  }

 private:
  template <class T>
  static T load(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof value);
    return value;
  }

  std::string_view body_;
  std::size_t pos_ = 0;
  std::size_t offset_;
  bool big_endian_;
  std::string_view name_;
  std::string problem_;
};

enum class Role { Vertex, Face, Strips, Other };

template <class Body>
Result<void> read_body(const PlyHeader& header, Body& body, std::string_view name,
                       const ReadLimits& limits, PolygonSoup& soup, Diagnostics& diagnostics) {
  const bool ascii = header.encoding == PlyEncoding::Ascii;
  std::size_t strip_degenerates = 0;
  bool vertices_seen = false;
  std::vector<std::int64_t> list;

  for (const PlyElement& element : header.elements) {
    Role role = Role::Other;
    if (element.name == "vertex" || element.name == "vertices") role = Role::Vertex;
    if (element.name == "face" || element.name == "faces") role = Role::Face;
    if (element.name == "tristrips") role = Role::Strips;
    if (role == Role::Vertex && vertices_seen) role = Role::Other;

    // Which property feeds what.
    int xyz[3] = {-1, -1, -1};
    int indices = -1;
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (role == Role::Vertex && !property.is_list) {
        if (property.name == "x") xyz[0] = static_cast<int>(p);
        if (property.name == "y") xyz[1] = static_cast<int>(p);
        if (property.name == "z") xyz[2] = static_cast<int>(p);
      }
      if ((role == Role::Face || role == Role::Strips) && property.is_list &&
          (property.name == "vertex_indices" || property.name == "vertex_index") && indices < 0) {
        indices = static_cast<int>(p);
      }
    }
    if (role == Role::Vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)) {
      return error_at(std::string(name), "PLY vertex element lacks an x, y or z property");
    }
    if ((role == Role::Face || role == Role::Strips) && indices < 0) {
      return error_at(std::string(name),
                      fmt::format("PLY {} element has no vertex_indices list", element.name));
    }
    // An element without properties takes no bytes, so any count of it reads nothing; looping
    // over a count of up to 2^64 - 1 empty items would not end.
    if (element.properties.empty()) continue;
    // Every item takes at least one byte (binary) or two (ASCII): a count beyond that is a lie
    // and must not size an allocation.
    const std::uint64_t plausible = std::min<std::uint64_t>(element.count, body.remaining());
    if (role == Role::Vertex) {
      soup.points.reserve(plausible);
      vertices_seen = true;
    }

    for (std::uint64_t item = 0; item < element.count; ++item) {
      std::array<double, 3> point{};
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        double value = 0.0;
        if (!property.is_list) {
          if (!body.read(property.type, value)) {
            return body.failure(fmt::format("PLY {} {} of {}", element.name, item, element.count));
          }
          for (int k = 0; k < 3; ++k) {
            if (xyz[k] == static_cast<int>(p)) point[k] = value;
          }
          continue;
        }
        double count_value = 0.0;
        if (!body.read(property.count_type, count_value)) {
          return body.failure(fmt::format("PLY {} {} of {}", element.name, item, element.count));
        }
        if (count_value < 0 || count_value > static_cast<double>(body.remaining())) {
          return error_at(body.where(),
                          fmt::format("PLY {} {}: list of {} entries, more than the file holds",
                                      element.name, item, count_value));
        }
        const auto count = static_cast<std::size_t>(count_value);
        const bool wanted = static_cast<int>(p) == indices;
        if (wanted) list.clear();
        for (std::size_t k = 0; k < count; ++k) {
          if (!body.read(property.type, value)) {
            return body.failure(fmt::format("PLY {} {} of {}", element.name, item, element.count));
          }
          if (wanted) {
            // A float-typed list, or a 64-bit integer rounded up to 2^63 on its way through
            // double, may hold values no vertex index can be; converting them is undefined.
            if (!(value >= -0x1p63 && value < 0x1p63 && value == std::floor(value))) {
              return error_at(body.where(),
                              fmt::format("PLY {} {}: vertex index {} is not a whole number of "
                                          "magnitude below 2^63",
                                          element.name, item, value));
            }
            list.push_back(static_cast<std::int64_t>(value));
          }
        }
      }
      if (role == Role::Vertex) {
        soup.points.push_back(point);
        continue;
      }
      if (role == Role::Other) continue;
      const std::size_t line = body.line();
      auto add_face = [&](std::initializer_list<std::int64_t> corners) {
        for (const std::int64_t c : corners) soup.corners.push_back(static_cast<std::size_t>(c));
        soup.face_offsets.push_back(soup.corners.size());
        if (ascii) soup.face_lines.push_back(line);
      };
      if (role == Role::Face) {
        for (const std::int64_t c : list) {
          if (c < 0) {
            return error_at(body.where(),
                            fmt::format("PLY face {} uses the negative vertex index {}", item, c));
          }
          soup.corners.push_back(static_cast<std::size_t>(c));
        }
        soup.face_offsets.push_back(soup.corners.size());
        if (ascii) soup.face_lines.push_back(line);
      } else {
        // Triangle strips, -1 separating strips; every other triangle is flipped to keep the
        // strip's orientation. Triangles with a repeated index only join strips: not faces.
        std::size_t start = 0;
        for (std::size_t k = 0; k <= list.size(); ++k) {
          if (k < list.size() && list[k] >= 0) continue;
          if (k < list.size() && list[k] != -1) {
            return error_at(body.where(),
                            fmt::format("PLY strip uses the negative vertex index {}", list[k]));
          }
          for (std::size_t t = start; t + 2 < k; ++t) {
            const std::int64_t a = list[t], b = list[t + 1], c = list[t + 2];
            if (a == b || b == c || a == c) {
              ++strip_degenerates;
              continue;
            }
            if ((t - start) % 2 == 0) {
              add_face({a, b, c});
            } else {
              add_face({b, a, c});
            }
          }
          start = k + 1;
        }
      }
      if (soup.num_faces() > limits.max_triangles) {
        return error_at(body.where(),
                        fmt::format("more than the limit of {} facets", limits.max_triangles));
      }
    }
  }
  if (strip_degenerates > 0) {
    diagnostics.push_back(Diagnostic{
        Severity::Info, "ply.strip_joins",
        fmt::format("{}: {} triangles of the strips repeat a vertex (strip joins); not faces, "
                    "skipped",
                    name, strip_degenerates)});
  }
  if (body.remaining() > 0 && !ascii) {
    diagnostics.push_back(Diagnostic{
        Severity::Warning, "ply.trailing_bytes",
        fmt::format("{}: {} bytes after the last element ignored", name, body.remaining())});
  }
  return {};
}

}  // namespace

Result<TriangleSoup> read_ply_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits) {
  Result<PlyHeader> header = parse_header(bytes, name, limits);
  if (!header) return header.error();
  PolygonSoup polygons;
  Diagnostics diagnostics;
  const std::string_view body_bytes = bytes.substr(header->body_offset);
  Result<void> body_read;
  if (header->encoding == PlyEncoding::Ascii) {
    AsciiBody body(body_bytes, header->body_line, name);
    body_read = read_body(*header, body, name, limits, polygons, diagnostics);
  } else {
    BinaryBody body(body_bytes, header->body_offset,
                    header->encoding == PlyEncoding::BinaryBigEndian, name);
    body_read = read_body(*header, body, name, limits, polygons, diagnostics);
  }
  if (!body_read) return body_read.error();
  Result<TriangleSoup> soup = triangulate_polygons(polygons, name, "PLY", 0, limits);
  if (!soup) return soup;
  soup->diagnostics.insert(soup->diagnostics.begin(), diagnostics.begin(), diagnostics.end());
  Diagnostics header_warnings;  // in file order: the header's before the body's
  header->skipped_lines.flush_into(header_warnings);
  soup->diagnostics.insert(soup->diagnostics.begin(), header_warnings.begin(),
                           header_warnings.end());
  soup->format = "ply";
  return soup;
}

}  // namespace strata::io::detail
