#include "strata/io/write_stl.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "strata/io/output_file.hpp"

namespace strata::io {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kFacetBytes = 50;
constexpr std::string_view kSolidName = "strata";

// C++ leaves the conversion of an out-of-range double to float undefined; spell
// out the IEEE result instead (overflow to a signed infinity, NaN stays NaN).
float to_float(double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (std::isnan(v)) return std::numeric_limits<float>::quiet_NaN();
  if (v > kMax) return std::numeric_limits<float>::infinity();
  if (v < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(v);
}

using Corners = std::array<std::array<float, 3>, 3>;

Corners rounded_corners(const std::array<Vec3, 3>& t) {
  Corners c{};
  for (std::size_t i = 0; i < 3; ++i) c[i] = {to_float(t[i].x), to_float(t[i].y), to_float(t[i].z)};
  return c;
}

// The normal of the corners as written, so that a reader recomputing it from
// the file agrees.
std::array<float, 3> facet_normal(const Corners& c) {
  const double ux = double{c[1][0]} - c[0][0];
  const double uy = double{c[1][1]} - c[0][1];
  const double uz = double{c[1][2]} - c[0][2];
  const double vx = double{c[2][0]} - c[0][0];
  const double vy = double{c[2][1]} - c[0][1];
  const double vz = double{c[2][2]} - c[0][2];
  const double nx = uy * vz - uz * vy;
  const double ny = uz * vx - ux * vz;
  const double nz = ux * vy - uy * vx;
  const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
  if (!(len > 0) || !std::isfinite(len)) return {0.0F, 0.0F, 0.0F};
  return {static_cast<float>(nx / len), static_cast<float>(ny / len), static_cast<float>(nz / len)};
}

// Little-endian whatever the host's byte order.
char* store_u32(char* at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) *at++ = static_cast<char>((v >> (8 * i)) & 0xFFU);
  return at;
}

char* store_f32(char* at, float f) { return store_u32(at, std::bit_cast<std::uint32_t>(f)); }

// A file is encoded in chunks of this many facets, so that writing a large
// model does not hold a second copy of it in memory.
constexpr std::size_t kChunkFacets = 1 << 16;

using Facets = std::span<const std::array<Vec3, 3>>;

void append_binary_header(std::string& out, std::size_t num_facets) {
  out.append(kSolidName);
  out.resize(out.size() + kHeaderBytes - kSolidName.size(), '\0');
  std::array<char, 4> count{};
  store_u32(count.data(), static_cast<std::uint32_t>(num_facets));
  out.append(count.data(), count.size());
}

void append_binary_facets(std::string& out, Facets facets) {
  const std::size_t start = out.size();
  out.resize(start + kFacetBytes * facets.size());
  char* at = out.data() + start;
  for (const auto& t : facets) {
    const Corners c = rounded_corners(t);
    for (const float f : facet_normal(c)) at = store_f32(at, f);
    for (const auto& corner : c) {
      for (const float f : corner) at = store_f32(at, f);
    }
    *at++ = '\0';  // attribute byte count, uint16 zero
    *at++ = '\0';
  }
}

void append_ascii_header(std::string& out) { out += fmt::format("solid {}\n", kSolidName); }

void append_ascii_footer(std::string& out) { out += fmt::format("endsolid {}\n", kSolidName); }

// Appends " x y z\n" with each value as printf's %.9g would print it
// (std::to_chars with a precision is specified that way, and is several times
// faster than fmt here). 9 significant digits identify every float32
// (FLT_DECIMAL_DIG), and the printed value is so close to the float that a
// reader going through double rounds it back to the same float.
void append_triple(std::string& out, const std::array<float, 3>& v) {
  std::array<char, 3 * 20 + 1> buffer{};
  char* at = buffer.data();
  char* const end = buffer.data() + buffer.size();
  for (const float f : v) {
    *at++ = ' ';
    at = std::to_chars(at, end, double{f}, std::chars_format::general, 9).ptr;
  }
  *at++ = '\n';
  out.append(buffer.data(), at);
}

void append_ascii_facets(std::string& out, Facets facets) {
  for (const auto& t : facets) {
    const Corners c = rounded_corners(t);
    out += "  facet normal";
    append_triple(out, facet_normal(c));
    out += "    outer loop\n";
    for (const auto& p : c) {
      out += "      vertex";
      append_triple(out, p);
    }
    out += "    endloop\n  endfacet\n";
  }
}

void append_header(std::string& out, const TriangleSoup& soup, StlEncoding encoding) {
  if (encoding == StlEncoding::Binary) {
    append_binary_header(out, soup.triangles.size());
  } else {
    append_ascii_header(out);
  }
}

void append_facets(std::string& out, Facets facets, StlEncoding encoding) {
  if (encoding == StlEncoding::Binary) {
    append_binary_facets(out, facets);
  } else {
    append_ascii_facets(out, facets);
  }
}

void append_footer(std::string& out, StlEncoding encoding) {
  if (encoding == StlEncoding::Ascii) append_ascii_footer(out);
}

}  // namespace

std::string stl_bytes(const TriangleSoup& soup, StlEncoding encoding) {
  std::string out;
  append_header(out, soup, encoding);
  append_facets(out, soup.triangles, encoding);
  append_footer(out, encoding);
  return out;
}

Result<void> write_stl(const std::filesystem::path& path, const TriangleSoup& soup,
                       StlEncoding encoding) {
  const std::string name = path.string();
  if (soup.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
    return Error{
        ErrorCode::BadInput,
        fmt::format("{} facets do not fit the 32-bit count of an STL file", soup.triangles.size()),
        name};
  }
  constexpr double kMax = std::numeric_limits<float>::max();
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    for (const Vec3& p : soup.triangles[f]) {
      for (const double v : {p.x, p.y, p.z}) {
        if (!(std::fabs(v) <= kMax)) {
          return Error{ErrorCode::BadInput,
                       fmt::format("coordinate {} cannot be stored as a float32 STL value", v),
                       fmt::format("{}: facet {}", name, f)};
        }
      }
    }
  }
  auto file = OutputFile::create(path);
  if (!file) return file.error();
  std::string chunk;
  append_header(chunk, soup, encoding);
  const Facets all(soup.triangles);
  for (std::size_t begin = 0; begin < all.size(); begin += kChunkFacets) {
    append_facets(chunk, all.subspan(begin, std::min(kChunkFacets, all.size() - begin)), encoding);
    file->write(chunk);
    chunk.clear();
  }
  append_footer(chunk, encoding);
  file->write(chunk);
  return file->commit();
}

}  // namespace strata::io
