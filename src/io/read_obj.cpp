// Wavefront OBJ reader, hand-written rather than CGAL::IO::read_OBJ because CGAL 5.5's reader is
// weak on inputs we must handle:
//  - it rejects backslash line continuations (trimesh/models/wallhole.obj in the corpus) and any
//    statement outside its list (`l` polylines, for example), failing the whole file;
//  - after each corner it skips to the next space, so tab-separated corners are lost silently;
//  - it maps the invalid index 0 to "the next vertex", a silently wrong face when vertices follow;
//  - it cannot say on which line a file is bad.
// Only geometry is read: `v` (x y z, optional w or colour ignored) and `f` (v, v/vt, v//vn,
// v/vt/vn corners; negative indices count back from the last vertex). Everything else is skipped.
#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "io/read_mesh_internal.hpp"
#include "io/text_format_internal.hpp"
#include "strata/io/scan_number.hpp"

namespace strata::io::detail {
namespace {

std::string quote(std::string_view text) { return quote_input(text, 40); }

class ObjReader {
 public:
  ObjReader(std::string_view text, std::string_view name, const ReadLimits& limits)
      : name_(name), limits_(limits), lines_(text, limits.max_line_bytes) {}

  Result<PolygonSoup> read();
  Diagnostics take_diagnostics() {
    Diagnostics out;
    tally_.flush_into(out);
    return out;
  }

 private:
  /// The next logical line (continuations joined into `joined_`); false at the end.
  bool next_line(std::string_view& line);
  std::string location() const { return fmt::format("{}:{}", name_, statement_line_); }
  Error error_here(std::string message) const {
    return Error{ErrorCode::BadInput, std::move(message), location()};
  }
  Result<void> read_vertex(std::string_view rest);
  Result<void> read_face(std::string_view rest);

  std::string_view name_;
  const ReadLimits& limits_;
  detail::TextLines lines_;
  std::size_t statement_line_ = 0;
  bool joined_too_long_ = false;
  std::string joined_;
  PolygonSoup soup_;
  DiagnosticTally tally_{"line"};
};

bool ObjReader::next_line(std::string_view& line) {
  if (!lines_.next(line)) return false;
  statement_line_ = lines_.number();
  auto continued = [](std::string_view text) {
    while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
    return !text.empty() && text.back() == '\\';
  };
  if (!continued(line)) return true;
  joined_.clear();
  std::string_view piece = line;
  for (;;) {
    while (!piece.empty() && is_blank(piece.back())) piece.remove_suffix(1);
    if (piece.empty() || piece.back() != '\\') {
      joined_ += piece;
      break;
    }
    piece.remove_suffix(1);
    joined_ += piece;
    joined_ += ' ';
    if (joined_.size() > limits_.max_line_bytes) {
      joined_too_long_ = true;
      return false;
    }
    if (!lines_.next(piece)) break;
  }
  line = joined_;
  return true;
}

Result<void> ObjReader::read_vertex(std::string_view rest) {
  // double, not rounded: SPEC §2
  std::array<double, 3> p{};
  const auto here = [&] { return location(); };
  if (auto r = scan_vertex(rest, NumberType::Float64, here, p); !r) return r;
  soup_.points.push_back(p);
  return {};
}

Result<void> ObjReader::read_face(std::string_view rest) {
  const std::size_t first = soup_.corners.size();
  for (std::string_view corner = next_token(rest); !corner.empty(); corner = next_token(rest)) {
    const std::string_view index_text = corner.substr(0, corner.find('/'));
    if (index_text.empty()) {
      return error_here(fmt::format("face corner {} has no vertex index", quote(corner)));
    }
    const ScannedNumber<std::int64_t> scanned = scan_signed(index_text, NumberType::Int64);
    if (!scanned.ok()) return bad_number(location(), index_text, scanned);
    const std::int64_t index = scanned.value;
    const auto defined = static_cast<std::int64_t>(soup_.points.size());
    if (index == 0) {
      return error_here("face uses vertex index 0; OBJ indices count from 1");
    }
    if (index < 0) {
      // Not -index > defined: negating the smallest long long overflows.
      if (index < -defined) {
        return error_here(fmt::format(
            "face uses relative vertex index {}, but only {} vertices are defined so far", index,
            defined));
      }
      soup_.corners.push_back(static_cast<std::size_t>(defined + index));
    } else {
      // Checked once all vertices are known: some writers put vertices after the faces.
      soup_.corners.push_back(static_cast<std::size_t>(index - 1));
    }
  }
  if (soup_.corners.size() - first > 2 &&
      soup_.num_faces() + soup_.corners.size() - first - 2 > limits_.max_triangles) {
    return error_here(fmt::format("more than the limit of {} facets", limits_.max_triangles));
  }
  soup_.face_offsets.push_back(soup_.corners.size());
  soup_.face_lines.push_back(statement_line_);
  return {};
}

Result<PolygonSoup> ObjReader::read() {
  std::string_view line;
  while (next_line(line)) {
    std::string_view rest = line;
    const std::string_view word = next_token(rest);
    if (word.empty() || word.front() == '#') continue;
    if (word == "v") {
      if (auto r = read_vertex(rest); !r) return r.error();
    } else if (word == "f" || word == "fo") {
      if (auto r = read_face(rest); !r) return r.error();
    } else if (word == "vt" || word == "vn" || word == "vp" || word == "g" || word == "o" ||
               word == "s" || word == "usemtl" || word == "mtllib" || word == "l" || word == "p") {
      // Texture, normals, grouping, materials and lower-dimensional elements: not geometry.
    } else {
      tally_.add("obj.unknown_statement", Severity::Warning, statement_line_, [&] {
        return fmt::format("{}:{}: statement {} ignored (only v and f are read)", name_,
                           statement_line_, quote(word));
      });
    }
  }
  if (joined_too_long_ || lines_.too_long()) {
    return Error{ErrorCode::BadInput,
                 fmt::format("line longer than the limit of {} bytes", limits_.max_line_bytes),
                 fmt::format("{}:{}", name_, lines_.number())};
  }
  return std::move(soup_);
}

}  // namespace

Result<TriangleSoup> read_obj_bytes(std::string_view bytes, std::string_view name,
                                    const ReadLimits& limits) {
  ObjReader reader(bytes, name, limits);
  Result<PolygonSoup> polygons = reader.read();
  if (!polygons) return polygons.error();
  Result<TriangleSoup> soup = triangulate_polygons(*polygons, name, "OBJ", 1, limits);
  if (!soup) return soup;
  Diagnostics own = reader.take_diagnostics();
  soup->diagnostics.insert(soup->diagnostics.begin(), own.begin(), own.end());
  soup->format = "obj";
  return soup;
}

}  // namespace strata::io::detail
