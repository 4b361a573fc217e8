#include <fmt/format.h>

#include <cmath>
#include <string>

#include "io/read_mesh_internal.hpp"

namespace strata::io::detail {

Result<TriangleSoup> triangulate_polygons(const PolygonSoup& polygons, std::string_view name,
                                          std::string_view what, std::size_t index_base,
                                          const ReadLimits& limits) {
  const std::size_t num_faces = polygons.num_faces();
  const bool has_lines = polygons.face_lines.size() == num_faces;
  // "name:LINE" when the reader knew the line, "name: face F" otherwise (F counts from 0).
  auto where = [&](std::size_t f) {
    return has_lines ? fmt::format("{}:{}", name, polygons.face_lines[f])
                     : fmt::format("{}: face {}", name, f);
  };
  auto place = [&](std::size_t f) { return has_lines ? polygons.face_lines[f] : f; };

  TriangleSoup soup;
  DiagnosticTally tally(has_lines ? "line" : "face");
  std::vector<bool> checked(polygons.points.size(), false);
  std::size_t skipped = 0;

  for (std::size_t f = 0; f < num_faces; ++f) {
    const std::size_t begin = polygons.face_offsets[f];
    const std::size_t end = polygons.face_offsets[f + 1];
    const std::size_t n = end - begin;
    for (std::size_t c = begin; c < end; ++c) {
      const std::size_t v = polygons.corners[c];
      if (v >= polygons.points.size()) {
        return Error{ErrorCode::BadInput,
                     fmt::format("{} face uses vertex {}, but the file defines {} vertices "
                                 "(numbered from {})",
                                 what, v + index_base, polygons.points.size(), index_base),
                     where(f)};
      }
      if (!checked[v]) {
        const auto& p = polygons.points[v];
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
          return Error{ErrorCode::BadInput,
                       fmt::format("{} vertex {} has a non-finite coordinate ({}, {}, {}); NaN "
                                   "and infinity cannot be sliced",
                                   what, v + index_base, p[0], p[1], p[2]),
                       where(f)};
        }
        checked[v] = true;
      }
    }
    if (n < 3) {
      ++skipped;
      tally.add("mesh.short_face", Severity::Warning, place(f), [&] {
        return fmt::format("{}: {} face has {} corner{}, so no area; skipped", where(f), what, n,
                           n == 1 ? "" : "s");
      });
      continue;
    }
    if (n > 3) {
      tally.add("mesh.polygon_face", Severity::Info, place(f), [&] {
        return fmt::format("{}: {} face with {} corners triangulated as a fan", where(f), what, n);
      });
    }
    if (soup.triangles.size() + (n - 2) > limits.max_triangles) {
      return Error{ErrorCode::BadInput,
                   fmt::format("more than the limit of {} facets", limits.max_triangles), where(f)};
    }
    auto corner = [&](std::size_t c) {
      const auto& p = polygons.points[polygons.corners[begin + c]];
      return Vec3{p[0], p[1], p[2]};
    };
    for (std::size_t k = 1; k + 1 < n; ++k) {
      soup.triangles.push_back({corner(0), corner(k), corner(k + 1)});
    }
  }
  if (soup.triangles.empty()) {
    return Error{ErrorCode::BadInput,
                 skipped == 0 ? fmt::format("no facets: the {} file defines no faces", what)
                              : fmt::format("no facets: all {} {} faces have fewer than 3 corners",
                                            skipped, what),
                 std::string(name)};
  }
  tally.flush_into(soup.diagnostics);
  return soup;
}

}  // namespace strata::io::detail
