#include <fmt/format.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>

#include "contour/chain_segments.hpp"
#include "contour/loop_check.hpp"
#include "exact/exact_arrangement_internal.hpp"
#include "exact/exact_cut_internal.hpp"
#include "exact/exact_fill_internal.hpp"
#include "exact/exact_kernel_internal.hpp"
#include "exact/exact_loops_internal.hpp"
#include "exact/exact_soup_internal.hpp"
#include "strata/core/internal_failure.hpp"
#include "strata/exact/slice_exact.hpp"
#include "strata/slice/slice_float.hpp"

namespace strata {
namespace exact::detail {
namespace {

/// The exact crossing points of a layer as a LoopChecker geometry: the rounded points, within
/// half an ulp of the exact ones, filter; the rationals decide.
class ExactPointGeometry {
 public:
  explicit ExactPointGeometry(const ExactLayer& layer) : layer_(layer) {
    double largest = 0.0;
    for (const ExactPoint2& p : layer.points) {
      largest = std::max({largest, std::fabs(p.x.rounded), std::fabs(p.y.rounded)});
    }
    // Rounded to nearest: |rounded - exact| <= 2^-53 |rounded| for normal values, 2^-1075 below.
    margin_ = largest * 0x1p-52 + 0x1p-1000;
  }

  Point2 approx(strata::detail::SegmentEnd p) const { return point(p).rounded(); }
  double margin() const { return margin_; }
  std::uint64_t key(strata::detail::SegmentEnd p) const {
    const ExactSegment& s = layer_.segments[p.segment];
    return strata::detail::crossed_edge_key(p.end == 0 ? s.start_edge : s.end_edge);
  }
  int exact_orientation(strata::detail::SegmentEnd a, strata::detail::SegmentEnd b,
                        strata::detail::SegmentEnd c) const {
    const ExactPoint2& pa = point(a);
    const ExactPoint2& pb = point(b);
    const ExactPoint2& pc = point(c);
    const Rational r = (pb.x.exact() - pa.x.exact()) * (pc.y.exact() - pa.y.exact()) -
                       (pb.y.exact() - pa.y.exact()) * (pc.x.exact() - pa.x.exact());
    return sign_of(r);
  }
  int exact_compare_x(strata::detail::SegmentEnd a, strata::detail::SegmentEnd b) const {
    return sign_of(point(a).x.exact() - point(b).x.exact());
  }
  int exact_compare_y(strata::detail::SegmentEnd a, strata::detail::SegmentEnd b) const {
    return sign_of(point(a).y.exact() - point(b).y.exact());
  }

 private:
  static int sign_of(const Rational& r) {
    const Rational zero(0);
    return r < zero ? -1 : (zero < r ? 1 : 0);
  }
  const ExactPoint2& point(strata::detail::SegmentEnd p) const {
    const ExactSegment& s = layer_.segments[p.segment];
    return p.end == 0 ? layer_.start_of(s) : layer_.end_of(s);
  }

  const ExactLayer& layer_;
  double margin_ = 0.0;
};

}  // namespace

Result<void> check_mesh_for_exact(const IndexedMesh& mesh) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3& p = mesh.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return Error{
          ErrorCode::BadInput,
          fmt::format("vertex {} has a non-finite coordinate ({}, {}, {})", v, p.x, p.y, p.z),
          {}};
    }
  }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (const VertexIndex v : mesh.triangles[f]) {
      if (v >= mesh.vertices.size()) {
        return Error{ErrorCode::BadInput,
                     fmt::format("facet {} refers to vertex {}, but the mesh has {} vertices", f, v,
                                 mesh.vertices.size()),
                     {}};
      }
    }
  }
  return {};
}

ExactKernel::ExactKernel(const IndexedMesh& mesh, const GridSpec& grid, const SliceOptions& options,
                         ContourMethod method)
    : mesh_(mesh), grid_(grid), options_(options), method_(method) {
  // The halfedge structure (its own sorts run in parallel) is built beside the facets' normals
  // and layers: with two threads, the one of them that would otherwise wait.
  tbb::parallel_invoke([&] { soup_ = std::make_unique<SoupMesh>(mesh); },
                       [&] {
                         normal_x_signs_ = facet_normal_x_signs(mesh);
                         // The fast path's grouping: the double planes are the same on both.
                         sweep_.group(mesh, grid);
                       });
}

ExactKernel::~ExactKernel() = default;

void ExactKernel::prepare_batch(std::uint32_t k0, std::uint32_t k1) { sweep_.advance(k0, k1); }

LayerGeometry ExactKernel::compute_layer(std::uint32_t k) const {
  const std::vector<FacetIndex> candidates = sweep_.candidates(k);
  const double z = grid_.zk(k);
  ExactLayer layer = cut_layer(mesh_, candidates, normal_x_signs_, k, z);

  LayerGeometry geometry;
  geometry.segments = static_cast<std::uint32_t>(layer.segments.size());
  geometry.fill =
      fill_layer(mesh_, layer, grid_, options_.fill_rule, options_.scan_offset_mm, hatches_wanted_);
  if (layer.segments.empty()) {
    ++empty_layers_;
    geometry.contours = finish_contours(k, z, {}, 0);
    return geometry;
  }
  // The layer's loops chained by topology, as the fast path chains them, and checked by the
  // same exact rule (issue 3): only simple loops are taken from the halfedge structure (where
  // they are simple, both chainings give the same loops); any other layer gets the outline of
  // the region the fill rule fills.
  const std::vector<strata::detail::SegmentChain> chains =
      strata::detail::chain_segments(layer.segments);
  const strata::detail::LoopCheck check =
      strata::detail::check_loops(ExactPointGeometry(layer), chains);
  std::optional<std::vector<ExactLoop>> loops;
  if (method_ == ContourMethod::Automatic && check.simple()) loops = soup_->chain_layer(layer);
  if (loops) {
    ++halfedge_layers_;
    geometry.contours = finish_contours(k, z, std::move(*loops), 0);
  } else {
    ++arrangement_layers_;
    ArrangementContours a = arrangement_contours(layer, options_.fill_rule, grid_.x0);
    geometry.contours = finish_contours(k, z, std::move(a.loops), a.open_chains);
    geometry.contours.outline = true;
  }
  geometry.contours.loops_cross = check.contacts;
  geometry.contours.misnested = check.nesting_decided && !check.alternates;
  return geometry;
}

ExactSliceReport ExactKernel::report() const {
  ExactSliceReport r = soup_->repair_report();
  r.halfedge_layers = halfedge_layers_.load();
  r.arrangement_layers = arrangement_layers_.load();
  r.empty_layers = empty_layers_.load();
  return r;
}

}  // namespace exact::detail

namespace {

void add_report_diagnostics(const ExactSliceReport& r, Diagnostics& out) {
  if (r.polygons_removed > 0) {
    out.push_back({Severity::Info, "exact.polygons_removed",
                   fmt::format("exact path: the soup repair removed {} facets (repeated corners or "
                               "duplicates); their segments still count in the cells",
                               r.polygons_removed)});
  }
  if (r.points_duplicated > 0) {
    out.push_back({Severity::Info, "exact.points_duplicated",
                   fmt::format("exact path: orienting the soup duplicated {} non-manifold "
                               "vertices",
                               r.points_duplicated)});
  }
  if (!r.polygon_mesh && r.input_polygons > 0) {
    out.push_back({Severity::Info, "exact.not_a_polygon_mesh",
                   "exact path: the repaired soup is not a polygon mesh; every layer's contours "
                   "come from the exact arrangement of its segments"});
  }
  if (r.polygon_mesh && r.arrangement_layers > 0) {
    out.push_back({Severity::Info, "exact.arrangement_layers",
                   fmt::format("exact path: {} layers were assembled on the exact arrangement "
                               "(their loops did not chain through the halfedge structure, or "
                               "are open, cross, touch or do not alternate in orientation)",
                               r.arrangement_layers)});
  }
}

}  // namespace

Result<SliceSummary> slice_model_exact(const IndexedMesh& mesh, const GridSpec& grid,
                                       const SliceOptions& options,
                                       std::span<LayerSink* const> sinks,
                                       const ProgressCallback& progress, ExactSliceReport* report) {
  if (options.fill_rule == FillRule::Winding) {
    return Error{
        ErrorCode::Usage,
        "fill rule winding is evaluated by the fast path only (solid angles are not exact): "
        "slice with the fast path, or with fill rule nonzero or evenodd",
        {}};
  }
  if (auto ok = exact::detail::check_mesh_for_exact(mesh); !ok) return ok.error();
  bool started = false;
  return catch_internal_failure(
      "exact path",
      [&]() -> Result<SliceSummary> {
        exact::detail::ExactKernel kernel(mesh, grid, options);
        started = true;
        Result<SliceSummary> result = run_slice(mesh, grid, options, kernel, sinks, progress);
        const ExactSliceReport r = kernel.report();
        if (report != nullptr) *report = r;
        if (result) add_report_diagnostics(r, result->diagnostics);
        return result;
      },
      [&] {
        if (started) abort_all(sinks);
      });
}

}  // namespace strata
