// GCC 12 at -O3 reports a default-constructed Boost adjacency_list edge property as "maybe
// uninitialized" when CGAL's split_graph_into_polylines copies it (a false positive in Boost
// code this file instantiates); the warning is silenced for this file only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <CGAL/AABB_halfedge_graph_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "exact/exact_rounding.hpp"
#include "soup/orient_soup_visitor.hpp"
#include "strata/validate/contour_metrics.hpp"
#include "validate/model_scale_internal.hpp"
#include "validate/reference_slicer_internal.hpp"

namespace strata::validate {

const char* to_string(ReferenceSkip skip) {
  switch (skip) {
    case ReferenceSkip::None:
      return "none";
    case ReferenceSkip::Off:
      return "off";
    case ReferenceSkip::TooManyFacets:
      return "too-many-facets";
    case ReferenceSkip::Empty:
      return "empty";
    case ReferenceSkip::NonManifold:
      return "non-manifold";
    case ReferenceSkip::Inconsistent:
      return "inconsistent-orientation";
    case ReferenceSkip::NotClosed:
      return "not-closed";
    case ReferenceSkip::Failed:
      break;
  }
  // The last case shares the return after the switch: no line is left that no value reaches.
  return "failed";
}

namespace detail {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Clock = std::chrono::steady_clock;
using Kernel = CGAL::Epeck;
using Point3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point3>;
// The slicer's default tree: an AABB tree of the mesh's edges, built by its constructor.
using Slicer = CGAL::Polygon_mesh_slicer<Mesh, Kernel>;
using Polygon = std::array<std::size_t, 3>;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The double nearest to an exact value (ties to even), rounded as the exact path rounds its
/// points, so equal exact points give equal doubles.
double nearest_double(const Kernel::FT& value) {
  return exact::detail::round_to_double(CGAL::exact(value));
}

double shoelace(const std::vector<Point2>& points) {
  double twice = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point2& p = points[i];
    const Point2& q = points[(i + 1) % points.size()];
    twice += p.x * q.y - q.x * p.y;
  }
  return twice / 2.0;
}

Contour closed_contour(std::vector<Point2> points) {
  Contour c;
  c.points = std::move(points);
  c.is_closed = true;
  c.signed_area_mm2 = shoelace(c.points);
  c.kind = c.signed_area_mm2 < 0.0 ? LoopKind::Hole : LoopKind::Outer;
  return c;
}

Contour open_contour(std::vector<Point2> points) {
  Contour c;
  c.points = std::move(points);
  c.is_closed = false;
  c.kind = LoopKind::Open;
  return c;
}

bool point_less(const Point2& a, const Point2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

}  // namespace

void join_chains(std::vector<std::vector<Point2>> chains, ReferenceSection& out) {
  std::multimap<Point2, std::size_t, decltype(&point_less)> by_start(&point_less);
  for (std::size_t i = 0; i < chains.size(); ++i) by_start.emplace(chains[i].front(), i);
  std::vector<bool> used(chains.size(), false);
  // A chain leaves by_start when it is used, so the first chain starting at p is free.
  const auto take_from = [&](const Point2& p) -> std::size_t {
    const auto it = by_start.lower_bound(p);
    if (it == by_start.end() || point_less(p, it->first)) return chains.size();
    const std::size_t i = it->second;
    by_start.erase(it);
    return i;
  };
  for (std::size_t seed = 0; seed < chains.size(); ++seed) {
    if (used[seed]) continue;
    used[seed] = true;
    for (auto it = by_start.begin(); it != by_start.end(); ++it) {
      if (it->second == seed) {
        by_start.erase(it);
        break;
      }
    }
    std::vector<Point2> loop = chains[seed];
    const Point2 first = loop.front();
    bool closed = false;
    while (true) {
      if (loop.back() == first && loop.size() > 1) {
        closed = true;
        break;
      }
      const std::size_t next = take_from(loop.back());
      if (next == chains.size()) break;
      used[next] = true;
      loop.insert(loop.end(), chains[next].begin() + 1, chains[next].end());
    }
    if (closed) {
      loop.pop_back();
      out.contours.push_back(closed_contour(std::move(loop)));
    } else {
      ++out.open_after_joining;
      out.contours.push_back(open_contour(std::move(loop)));
    }
  }
}

struct ReferenceSlicer::Impl {
  ReferenceSlicerFigures figures;
  Mesh mesh;
  std::unique_ptr<Slicer> slicer;
  std::vector<double> vertex_z;  ///< z of the vertices the facets use, sorted
  std::vector<double> flat_z;    ///< z of the facets parallel to the planes, sorted, unique

  void refuse(ReferenceSkip why, std::string message) {
    figures.skipped = why;
    figures.reason = std::move(message);
  }

  void build(const IndexedMesh& input);
};

void ReferenceSlicer::Impl::build(const IndexedMesh& input) {
  std::vector<Polygon> polygons;
  polygons.reserve(input.triangles.size());
  std::vector<bool> used(input.vertices.size(), false);
  for (const auto& t : input.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      ++figures.degenerate_facets_dropped;
      continue;
    }
    polygons.push_back({t[0], t[1], t[2]});
    for (const VertexIndex v : t) used[v] = true;
  }
  if (polygons.empty()) {
    refuse(ReferenceSkip::Empty, "no facet with three distinct corners");
    return;
  }
  std::vector<Point3> points;
  points.reserve(input.vertices.size());
  for (const Vec3& v : input.vertices) points.emplace_back(v.x, v.y, v.z);

  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    // Tell non-manifold from inconsistently oriented: orienting a copy duplicates the points of
    // non-manifold vertices and edges, and only reverses facets otherwise.
    std::vector<Point3> copy_points = points;
    std::vector<Polygon> copy_polygons = polygons;
    const soup::OrientSoupCounts counters = soup::orient_soup(copy_points, copy_polygons);
    const std::size_t duplicated = counters.points_added;
    if (!counters.oriented || duplicated > 0 || !counters.non_manifold_edges.empty()) {
      refuse(ReferenceSkip::NonManifold,
             fmt::format("not a 2-manifold: {} non-manifold edges; orienting the facets "
                         "duplicates {} points",
                         counters.non_manifold_edges.size(), duplicated));
    } else if (counters.reversed > 0) {
      refuse(ReferenceSkip::Inconsistent,
             fmt::format("facets oriented against their neighbours ({} turned over to make "
                         "the orientation consistent)",
                         counters.reversed));
    } else {
      refuse(ReferenceSkip::NonManifold, "the facets do not form a polygon mesh");
    }
    return;
  }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (!CGAL::is_closed(mesh)) {
    std::uint64_t border = 0;
    for (const auto h : mesh.halfedges()) {
      if (mesh.is_border(h)) ++border;
    }
    refuse(ReferenceSkip::NotClosed, fmt::format("not closed: {} border edges", border));
    return;
  }
  for (std::size_t v = 0; v < input.vertices.size(); ++v) {
    if (used[v]) vertex_z.push_back(input.vertices[v].z);
  }
  std::sort(vertex_z.begin(), vertex_z.end());
  for (const Polygon& p : polygons) {
    const double z = input.vertices[p[0]].z;
    if (input.vertices[p[1]].z == z && input.vertices[p[2]].z == z) flat_z.push_back(z);
  }
  std::sort(flat_z.begin(), flat_z.end());
  flat_z.erase(std::unique(flat_z.begin(), flat_z.end()), flat_z.end());
  slicer = std::make_unique<Slicer>(mesh);
  figures.ran = true;
  figures.skipped = ReferenceSkip::None;
}

ReferenceSlicer::ReferenceSlicer(const IndexedMesh& mesh, std::size_t max_facets)
    : impl_(std::make_unique<Impl>()) {
  const auto started = Clock::now();
  Impl& d = *impl_;
  d.figures.facets = mesh.triangles.size();
  d.figures.max_facets = max_facets;
  if (mesh.triangles.size() > max_facets) {
    d.refuse(ReferenceSkip::TooManyFacets,
             fmt::format("{} facets, over the cap of {}", mesh.triangles.size(), max_facets));
  } else {
    try {
      d.build(mesh);
    } catch (const std::exception& e) {
      d.slicer.reset();
      d.figures.ran = false;
      d.refuse(ReferenceSkip::Failed, fmt::format("CGAL failed building the mesh: {}", e.what()));
    }
  }
  d.figures.build_seconds = seconds_since(started);
}

ReferenceSlicer::~ReferenceSlicer() = default;

bool ReferenceSlicer::ready() const { return impl_->slicer != nullptr; }

const ReferenceSlicerFigures& ReferenceSlicer::figures() const { return impl_->figures; }

ReferenceSection ReferenceSlicer::slice(double z_mm) const {
  std::vector<std::vector<Point3>> polylines;
  (*impl_->slicer)(Kernel::Plane_3(0, 0, 1, -z_mm), std::back_inserter(polylines));
  ReferenceSection out;
  std::vector<std::vector<Point2>> open;
  for (const std::vector<Point3>& line : polylines) {
    if (line.empty()) continue;
    std::vector<Point2> points;
    points.reserve(line.size());
    for (const Point3& p : line) points.push_back({nearest_double(p.x()), nearest_double(p.y())});
    if (line.size() == 1) {
      ++out.isolated_points;
      out.contours.push_back(open_contour(std::move(points)));
    } else if (line.front() == line.back()) {
      ++out.closed_polylines;
      points.pop_back();
      out.contours.push_back(closed_contour(std::move(points)));
    } else {
      ++out.open_polylines;
      open.push_back(std::move(points));
    }
  }
  join_chains(std::move(open), out);
  return out;
}

std::uint32_t ReferenceSlicer::vertices_on_plane(double z_mm) const {
  const auto [lo, hi] = std::equal_range(impl_->vertex_z.begin(), impl_->vertex_z.end(), z_mm);
  return static_cast<std::uint32_t>(hi - lo);
}

bool ReferenceSlicer::facet_on_plane(double z_mm) const {
  return std::binary_search(impl_->flat_z.begin(), impl_->flat_z.end(), z_mm);
}

// ---- comparison

struct ReferenceComparison::State {
  State(const IndexedMesh& mesh, const GridSpec& g, const SliceOptions& o, const ValidateOptions& v)
      : grid(g), options(o), vopts(v) {
    const double scale = coordinate_scale(mesh.bounds());
    tolerance = vopts.near_tie_relative * scale;
    area_tolerance = tolerance * scale;
    const std::uint32_t budget = vopts.max_overlay_layers;
    stride = budget == 0 ? 1 : std::max<std::uint32_t>(1, (grid.nz + budget - 1) / budget);
    if (vopts.reference_slicer) {
      slicer.emplace(mesh, vopts.reference_max_facets);
      figures = slicer->figures();
      if (!slicer->ready()) slicer.reset();
    } else {
      figures.skipped = ReferenceSkip::Off;
      figures.reason = "turned off";
      figures.facets = mesh.triangles.size();
      figures.max_facets = vopts.reference_max_facets;
    }
  }

  struct Against {
    double hausdorff_mm = 0.0;
    double area_mm2 = 0.0;
    AreaMethod method = AreaMethod::Identical;
    bool differs = false;
    bool region_differs = false;
    bool outlined = false;  ///< the path outlined the layer: compared by region only
  };

  Against compare(const ReferenceSection& ref, const LayerContours& other, std::uint32_t k);

  GridSpec grid;
  SliceOptions options;
  ValidateOptions vopts;
  double tolerance = 0.0;
  double area_tolerance = 0.0;
  std::uint32_t stride = 1;
  std::optional<ReferenceSlicer> slicer;
  ReferenceSlicerFigures figures;
};

ReferenceComparison::State::Against ReferenceComparison::State::compare(const ReferenceSection& ref,
                                                                        const LayerContours& other,
                                                                        std::uint32_t k) {
  Against out;
  out.hausdorff_mm = hausdorff_distance(ref.contours, other.loops);
  if (same_loop_edges(ref.contours, other.loops)) {
    out.method = AreaMethod::Identical;
  } else {
    const auto closed = [](const std::vector<Contour>& contours) {
      return std::count_if(contours.begin(), contours.end(),
                           [](const Contour& c) { return c.is_closed; });
    };
    const bool rounding_only =
        closed(ref.contours) == closed(other.loops) && out.hausdorff_mm <= tolerance;
    if (!rounding_only || k % stride == 0) {
      const SymmetricDifference sd =
          symmetric_difference(ref.contours, other.loops, options.fill_rule);
      out.area_mm2 = sd.area_mm2;
      out.method = sd.method;
    } else {
      out.method = AreaMethod::NotCompared;
      ++figures.layers_overlay_skipped;
    }
  }
  out.region_differs = out.area_mm2 > area_tolerance;
  out.outlined = other.outline;
  // An outline has no reason to share the slicer's loops (it drops the walls between crossing
  // or touching loops); only the region it bounds is comparable.
  out.differs = out.region_differs || (!out.outlined && !(out.hausdorff_mm <= tolerance));
  return out;
}

ReferenceComparison::ReferenceComparison(const IndexedMesh& mesh, const GridSpec& grid,
                                         const SliceOptions& options,
                                         const ValidateOptions& validate_options)
    : state_(std::make_unique<State>(mesh, grid, options, validate_options)) {}

ReferenceComparison::~ReferenceComparison() = default;

void ReferenceComparison::add_layer(const LayerResult* fast, const LayerResult* exact) {
  State& s = *state_;
  if (!s.slicer || (!fast && !exact)) return;
  ReferenceSlicerFigures& f = s.figures;
  const std::uint32_t k = fast ? fast->layer : exact->layer;
  const double z = s.grid.zk(k);

  auto started = Clock::now();
  ReferenceSection section;
  try {
    section = s.slicer->slice(z);
  } catch (const std::exception& e) {
    f.ran = false;
    f.skipped = ReferenceSkip::Failed;
    f.reason = fmt::format("CGAL failed slicing layer {} (z {}): {}", k, z, e.what());
    s.slicer.reset();
    return;
  }
  f.slice_seconds += seconds_since(started);

  started = Clock::now();
  ReferenceLayerComparison l;
  l.layer = k;
  l.z_mm = z;
  l.closed_polylines = section.closed_polylines;
  l.open_polylines = section.open_polylines;
  l.isolated_points = section.isolated_points;
  l.open_after_joining = section.open_after_joining;
  l.vertices_on_plane = s.slicer->vertices_on_plane(z);
  l.facet_on_plane = s.slicer->facet_on_plane(z);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  l.hausdorff_exact_mm = l.hausdorff_fast_mm = kNaN;
  l.symmetric_difference_exact_mm2 = l.symmetric_difference_fast_mm2 = kNaN;
  l.area_method_exact = l.area_method_fast = AreaMethod::NotCompared;
  const bool at_vertex = l.vertex_on_plane();
  const auto fold = [&](const State::Against& a, double& max_h, double& max_a, double& max_h_all,
                        double& max_a_all, std::uint32_t& differing,
                        std::uint32_t& differing_at_vertex, std::uint32_t& region_differing,
                        std::uint32_t& outlined) {
    max_h_all = std::max(max_h_all, a.hausdorff_mm);
    max_a_all = std::max(max_a_all, a.area_mm2);
    if (at_vertex) {
      if (a.differs) ++differing_at_vertex;
    } else {
      if (a.outlined) {
        ++outlined;
      } else {
        max_h = std::max(max_h, a.hausdorff_mm);
      }
      max_a = std::max(max_a, a.area_mm2);
      if (a.differs) ++differing;
      if (a.region_differs) ++region_differing;
    }
  };
  if (exact) {
    const State::Against a = s.compare(section, exact->contours, k);
    l.hausdorff_exact_mm = a.hausdorff_mm;
    l.symmetric_difference_exact_mm2 = a.area_mm2;
    l.area_method_exact = a.method;
    l.differs_from_exact = a.differs;
    fold(a, f.max_hausdorff_exact_mm, f.max_symmetric_difference_exact_mm2,
         f.max_hausdorff_exact_all_mm, f.max_symmetric_difference_exact_all_mm2,
         f.layers_differing_exact, f.layers_differing_exact_at_vertex,
         f.layers_region_differing_exact, f.layers_outlined_exact);
  }
  if (fast) {
    const State::Against a = s.compare(section, fast->contours, k);
    l.hausdorff_fast_mm = a.hausdorff_mm;
    l.symmetric_difference_fast_mm2 = a.area_mm2;
    l.area_method_fast = a.method;
    l.differs_from_fast = a.differs;
    fold(a, f.max_hausdorff_fast_mm, f.max_symmetric_difference_fast_mm2,
         f.max_hausdorff_fast_all_mm, f.max_symmetric_difference_fast_all_mm2,
         f.layers_differing_fast, f.layers_differing_fast_at_vertex, f.layers_region_differing_fast,
         f.layers_outlined_fast);
  }
  ++f.layers_compared;
  if (at_vertex) ++f.layers_vertex_on_plane;
  if (l.facet_on_plane) ++f.layers_facet_on_plane;
  f.polylines += section.closed_polylines + section.open_polylines + section.isolated_points;
  f.open_polylines += section.open_polylines;
  f.isolated_points += section.isolated_points;
  f.open_after_joining += section.open_after_joining;
  f.layers.push_back(l);
  f.compare_seconds += seconds_since(started);
}

ReferenceSlicerFigures ReferenceComparison::finish() { return std::move(state_->figures); }

}  // namespace detail
}  // namespace strata::validate
