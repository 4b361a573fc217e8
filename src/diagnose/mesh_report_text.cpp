#include "strata/diagnose/mesh_report_text.hpp"

#include <fmt/format.h>

#include <cstddef>
#include <iterator>
#include <string>
#include <utility>

namespace strata::diagnose {
namespace {

/// How many locations of each defect the text shows (the JSON carries all kept ones).
constexpr std::size_t kShown = 3;

std::string point(const Vec3& p) { return fmt::format("({:.9g}, {:.9g}, {:.9g})", p.x, p.y, p.z); }

std::string location(FacetIndex f) { return fmt::format("facet {}", f); }
std::string location(std::size_t shell) { return fmt::format("shell {}", shell); }
std::string location(const Vec3& p) { return point(p); }
std::string location(const EdgeLocation& e) { return point(e.from) + "-" + point(e.to); }
std::string location(const PointPair& p) { return point(p.first) + " ~ " + point(p.second); }
std::string location(const FacetPair& p) {
  return fmt::format("facets {} & {}", p.first, p.second);
}

template <class... Args>
void put(std::string& out, fmt::format_string<Args...> format, Args&&... args) {
  fmt::format_to(std::back_inserter(out), format, std::forward<Args>(args)...);
}

template <class T>
void line(std::string& out, const char* label, const Occurrences<T>& o,
          const std::string& extra = {}) {
  fmt::format_to(std::back_inserter(out), "  {:<28} {}{}", label, o.count, extra);
  if (!o.locations.empty()) {
    out += "  e.g. ";
    for (std::size_t i = 0; i < o.locations.size() && i < kShown; ++i) {
      if (i > 0) out += ", ";
      out += location(o.locations[i]);
    }
    if (o.count > kShown) out += ", ...";
  }
  out += '\n';
}

}  // namespace

std::string mesh_report_text(const MeshReport& r) {
  std::string out;
  put(out, "  {:<28} {} ({} read)\n", "facets", r.num_facets, r.num_input_facets);
  put(out, "  {:<28} {}\n", "vertices (exact weld)", r.num_vertices);
  if (r.bounds.empty()) {
    put(out, "  {:<28} empty\n", "bounding box");
  } else {
    put(out, "  {:<28} {:.9g} x {:.9g} x {:.9g} mm at {}\n", "bounding box",
        r.bounds.max.x - r.bounds.min.x, r.bounds.max.y - r.bounds.min.y,
        r.bounds.max.z - r.bounds.min.z, point(r.bounds.min));
  }
  put(out, "  {:<28} {:.9g} mm3\n", "volume (exact)", r.volume_mm3);
  put(out, "  {:<28} {:.9g} mm2\n", "surface area", r.surface_area_mm2);
  put(out, "  {:<28} {} ({} closed, {} inverted)\n", "shells", r.shells.size(), r.num_closed_shells,
      r.inverted_shells.count);
  line(out, "boundary edges", r.boundary_edges,
       fmt::format(" in {} loop{}", r.num_boundary_loops, r.num_boundary_loops == 1 ? "" : "s"));
  line(out, "non-manifold edges", r.non_manifold_edges);
  line(out, "inconsistent edges", r.inconsistent_edges);
  line(out, "unbalanced edges", r.unbalanced_edges);
  line(out, "non-manifold vertices", r.non_manifold_vertices);
  line(out, "near-coincident vertices", r.near_vertices,
       fmt::format(" (closer than {:.3g} mm{})", r.near_vertex_tolerance_mm,
                   r.near_vertices_truncated ? ", search cut short" : ""));
  line(out, "degenerate facets", r.degenerate_facets);
  line(out, "duplicate facets", r.duplicate_facets);
  line(out, "inverted shells", r.inverted_shells);
  if (r.normals_checked) {
    line(out, "stored normals flipped", r.flipped_normals);
    line(out, "stored normals zero", r.zero_normals);
    line(out, "stored normals not finite", r.non_finite_normals);
  }
  if (r.self_intersections_checked) {
    line(out, "self-intersecting pairs", r.self_intersections,
         r.self_intersections_truncated ? " (search cut short: at least)" : "");
  } else {
    put(out, "  {:<28} not checked\n", "self-intersecting pairs");
  }
  put(out, "verdict: {} - {}\n", verdict_name(r.verdict), r.verdict_reason);
  return out;
}

}  // namespace strata::diagnose
