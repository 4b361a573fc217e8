#include "strata/diagnose/mesh_report_json.hpp"

#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace strata::diagnose {
namespace {

using json = nlohmann::ordered_json;

json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json point(const Vec3& p) { return json::array({number(p.x), number(p.y), number(p.z)}); }

json location(FacetIndex f) { return f; }
json location(std::size_t index) { return index; }
json location(const Vec3& p) { return point(p); }
json location(const EdgeLocation& e) { return json::array({point(e.from), point(e.to)}); }
json location(const PointPair& p) { return json::array({point(p.first), point(p.second)}); }
json location(const FacetPair& p) { return json::array({p.first, p.second}); }

template <class T>
json occurrences(const Occurrences<T>& o) {
  json where = json::array();
  for (const T& x : o.locations) where.push_back(location(x));
  return {{"count", o.count}, {"first", where}};
}

json bounds(const Bbox3& box) {
  if (box.empty()) return nullptr;
  return {{"min", point(box.min)},
          {"max", point(box.max)},
          {"size", point({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z})}};
}

}  // namespace

std::string mesh_report_json(const MeshReport& r) {
  json shells = json::array();
  for (std::size_t s = 0; s < r.shells.size() && s < kMaxLocations; ++s) {
    const ShellReport& shell = r.shells[s];
    shells.push_back({{"facets", shell.num_facets},
                      {"first_facet", shell.first_facet},
                      {"closed", shell.is_closed},
                      {"balanced", shell.is_balanced},
                      {"signed_volume_mm3", number(shell.signed_volume_mm3)},
                      {"cavity", shell.is_cavity},
                      {"inverted", shell.is_inverted}});
  }

  json near = occurrences(r.near_vertices);
  near["tolerance_mm"] = number(r.near_vertex_tolerance_mm);
  near["truncated"] = r.near_vertices_truncated;

  json boundary = occurrences(r.boundary_edges);
  boundary["loops"] = r.num_boundary_loops;

  json normals = nullptr;
  if (r.normals_checked) {
    normals = {{"flipped", occurrences(r.flipped_normals)},
               {"zero", occurrences(r.zero_normals)},
               {"non_finite", occurrences(r.non_finite_normals)}};
  }

  json self_intersections = nullptr;
  if (r.self_intersections_checked) {
    self_intersections = occurrences(r.self_intersections);
    self_intersections["truncated"] = r.self_intersections_truncated;
  }

  const json out = {
      {"input_facets", r.num_input_facets},
      {"facets", r.num_facets},
      {"vertices", r.num_vertices},
      {"bounds_mm", bounds(r.bounds)},
      {"surface_area_mm2", number(r.surface_area_mm2)},
      {"volume_mm3", number(r.volume_mm3)},
      {"near_vertices", near},
      {"non_manifold_vertices", occurrences(r.non_manifold_vertices)},
      {"degenerate_facets", occurrences(r.degenerate_facets)},
      {"duplicate_facets", occurrences(r.duplicate_facets)},
      {"boundary_edges", boundary},
      {"non_manifold_edges", occurrences(r.non_manifold_edges)},
      {"inconsistent_edges", occurrences(r.inconsistent_edges)},
      {"unbalanced_edges", occurrences(r.unbalanced_edges)},
      {"shells",
       {{"count", r.shells.size()},
        {"closed", r.num_closed_shells},
        {"inverted", occurrences(r.inverted_shells)},
        {"first", shells}}},
      {"stored_normals", normals},
      {"self_intersections", self_intersections},
      {"verdict", verdict_name(r.verdict)},
      {"reason", r.verdict_reason},
  };
  return out.dump();
}

}  // namespace strata::diagnose
