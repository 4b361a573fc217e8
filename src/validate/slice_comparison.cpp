#include "strata/validate/slice_comparison.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <unordered_map>

#include "strata/core/error.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/fill/scanline_fill.hpp"
#include "strata/slice/slice_float.hpp"
#include "strata/validate/contour_metrics.hpp"
#include "validate/bucket_grid_internal.hpp"
#include "validate/model_scale_internal.hpp"

namespace strata::validate {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::uint64_t kShellSampleSeed = 0x9e3779b97f4a7c15ULL;

bool is_solid(CellClass c) { return c != CellClass::Empty; }

/// Inclusive index ranges of the solid cells seen so far.
struct IndexBox {
  bool any = false;
  std::uint32_t i0 = 0, i1 = 0, j0 = 0, j1 = 0, k0 = 0, k1 = 0;

  void add(std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    if (!any) {
      any = true;
      i0 = i1 = i;
      j0 = j1 = j;
      k0 = k1 = k;
      return;
    }
    i0 = std::min(i0, i);
    i1 = std::max(i1, i);
    j0 = std::min(j0, j);
    j1 = std::max(j1, j);
    k0 = std::min(k0, k);
    k1 = std::max(k1, k);
  }

  /// Adds the solid cells of layer k (nx * ny classes, row-major).
  void add_layer(std::span<const CellClass> cells, std::uint32_t nx, std::uint32_t ny,
                 std::uint32_t k) {
    for (std::uint32_t j = 0; j < ny; ++j) {
      const CellClass* row = cells.data() + std::size_t{j} * nx;
      std::uint32_t first = 0;
      while (first < nx && row[first] == CellClass::Empty) ++first;
      if (first == nx) continue;
      std::uint32_t last = nx - 1;
      while (row[last] == CellClass::Empty) --last;
      add(first, j, k);
      add(last, j, k);
    }
  }

  /// The union of the cells' boxes, mm.
  Bbox3 to_mm(const GridSpec& g) const {
    Bbox3 box;
    if (!any) return box;
    box.add({g.x0 + static_cast<double>(i0) * g.dx, g.y0 + static_cast<double>(j0) * g.dy,
             g.z0 + static_cast<double>(k0) * g.dz});
    box.add({g.x0 + static_cast<double>(i1 + 1) * g.dx, g.y0 + static_cast<double>(j1 + 1) * g.dy,
             g.z0 + static_cast<double>(k1 + 1) * g.dz});
    return box;
  }
};

/// What lies near a tie in one row of a layer.
struct RowTies {
  /// Cells with a centre at most this far right (plus the tolerance) may be decided by a tie:
  /// a crossing whose existence hangs on a segment end point on the scanline or on a facet
  /// vertex on the layer plane.
  double tie_max_x = -std::numeric_limits<double>::infinity();
  std::vector<double> crossings;  ///< x of the crossings, sorted
};

/// The facts about one layer that explain differing cells, computed when the layer has some.
struct LayerAnalysis {
  std::uint32_t layer = 0;
  LayerSegments segments;
  std::vector<std::uint8_t> solid_rule;   ///< the fast rule, recomputed
  std::vector<std::uint8_t> solid_other;  ///< nonzero <-> evenodd swapped
  struct Footprint {
    double x_max, y_min, y_max;
  };
  std::vector<Footprint> plane_ties;  ///< facets with a vertex within the tolerance of zk
  std::unordered_map<std::uint32_t, RowTies> rows;
};

Bbox3 grid_box(const GridSpec& g) {
  Bbox3 box;
  box.add({g.x0, g.y0, g.z0});
  box.add({g.x0 + static_cast<double>(g.nx) * g.dx, g.y0 + static_cast<double>(g.ny) * g.dy,
           g.z0 + static_cast<double>(g.nz) * g.dz});
  return box;
}

Bbox3 merged(Bbox3 a, const Bbox3& b) {
  if (!b.empty()) {
    a.add(b.min);
    a.add(b.max);
  }
  return a;
}

}  // namespace

const char* to_string(DifferenceReason reason) {
  switch (reason) {
    case DifferenceReason::ScanOffset:
      return "scan-offset";
    case DifferenceReason::Shell:
      return "shell";
    case DifferenceReason::NearDegenerate:
      return "near-degenerate";
    case DifferenceReason::FillRule:
      return "fill-rule";
    case DifferenceReason::Unexplained:
      break;
  }
  // The last case shares the return after the switch: no line is left that no value reaches.
  return "unexplained";
}

const char* to_string(AreaMethod method) {
  switch (method) {
    case AreaMethod::Identical:
      return "identical";
    case AreaMethod::Arrangement:
      return "arrangement";
    case AreaMethod::AreaOnly:
      return "area-only";
    case AreaMethod::NotCompared:
      break;
  }
  // The last case shares the return after the switch: no line is left that no value reaches.
  return "not-compared";
}

struct SliceComparison::State {
  State(const IndexedMesh& m, const GridSpec& g, const SliceOptions& o, const ValidateOptions& v)
      : mesh(m), grid(g), options(o), vopts(v), rng(kShellSampleSeed) {
    tolerance = vopts.near_tie_relative * detail::coordinate_scale(mesh.bounds());
    report.grid = grid;
    report.options = options;
    offset_cells.resize(grid.nz);
    solid_differences.assign(grid.nz, 0);
    shell_pending.assign(grid.nz, 0);
    boundary.resize(grid.nz);
    const double dmin = std::min({grid.dx, grid.dy, grid.dz});
    // How far (in layers) a change in solidity can move the interior/boundary mark: one
    // neighbour in distance mode (the distance part does not depend on the cells), the rings
    // in layers mode.
    shell_reach = options.shell_mode == ShellMode::Layers
                      ? std::max<std::uint32_t>(
                            1, static_cast<std::uint32_t>(std::min(1e6, options.shell_mm / dmin)))
                      : 1;
  }

  std::uint64_t cell_index(std::uint32_t i, std::uint32_t j) const {
    return std::uint64_t{j} * grid.nx + i;
  }

  bool offset_changed(std::uint32_t k, std::uint64_t c) const {
    const auto& v = offset_cells[k];
    return std::binary_search(v.begin(), v.end(), c);
  }

  const LayerAnalysis& analyse(std::uint32_t k);
  const RowTies& row_ties(LayerAnalysis& a, std::uint32_t j);
  DifferenceReason explain(std::uint32_t i, std::uint32_t j, std::uint32_t k, CellClass fast,
                           CellClass exact);
  void compare_contours(const LayerResult& fast, const LayerResult& exact, LayerComparison& out);
  void measure_fast(const LayerResult& fast);
  void measure_shell_layer(std::uint32_t k, const std::vector<CellClass>& cells,
                           const std::vector<CellClass>* below,
                           const std::vector<CellClass>* above);
  void measure_model();

  const IndexedMesh& mesh;
  GridSpec grid;
  SliceOptions options;
  ValidateOptions vopts;
  double tolerance = 0.0;
  std::uint32_t shell_reach = 1;
  ValidationReport report;
  double seconds = 0.0;

  // Scan offset: the cells it changes, per layer, sorted (j * nx + i).
  std::vector<std::vector<std::uint64_t>> offset_cells;
  std::size_t offset_remembered = 0;
  bool offset_truncated = false;

  // Differences: per layer, cells that differ in solidity, and cells that differ only in the
  // shell mark, whose reason is settled at the end.
  std::vector<std::uint64_t> solid_differences;
  std::vector<std::uint64_t> shell_pending;
  std::optional<FacetLayerRanges> ranges;
  std::optional<LayerAnalysis> analysis;

  // Measurements of the fast path's cells.
  IndexBox fast_box;
  IndexBox exact_box;
  std::vector<std::vector<std::uint64_t>> boundary;  // per layer, sorted (j * nx + i)
  std::uint64_t boundary_count = 0;
  bool boundary_overflow = false;
  std::vector<CellClass> window_below;  // layer window_k - 1
  std::vector<CellClass> window_mid;    // layer window_k, not yet measured for the shell
  std::int64_t window_k = -1;
  std::vector<Vec3> shell_samples;
  std::uint64_t shell_candidates = 0;
  std::mt19937_64 rng;
};

const LayerAnalysis& SliceComparison::State::analyse(std::uint32_t k) {
  if (analysis && analysis->layer == k) return *analysis;
  if (!ranges) ranges = facet_layer_ranges(mesh, grid);
  LayerAnalysis a;
  a.layer = k;
  std::vector<FacetIndex> candidates;
  const double zk = grid.zk(k);
  for (FacetIndex f = 0; f < mesh.triangles.size(); ++f) {
    if (ranges->first[f] <= k && k <= ranges->last[f]) candidates.push_back(f);
    const Vec3& p = mesh.corner(f, 0);
    const Vec3& q = mesh.corner(f, 1);
    const Vec3& r = mesh.corner(f, 2);
    if (std::fabs(p.z - zk) <= tolerance || std::fabs(q.z - zk) <= tolerance ||
        std::fabs(r.z - zk) <= tolerance) {
      a.plane_ties.push_back(
          {std::max({p.x, q.x, r.x}), std::min({p.y, q.y, r.y}), std::max({p.y, q.y, r.y})});
    }
  }
  a.segments = slice_layer(mesh, candidates, grid, k);
  const FillRule other =
      options.fill_rule == FillRule::EvenOdd ? FillRule::NonZero : FillRule::EvenOdd;
  a.solid_rule = scanline_fill(mesh, a.segments, grid, options.fill_rule, options.scan_offset_mm,
                               {.cells = true, .hatches = false})
                     .solid.cells();
  a.solid_other = scanline_fill(mesh, a.segments, grid, other, options.scan_offset_mm,
                                {.cells = true, .hatches = false})
                      .solid.cells();
  analysis = std::move(a);
  return *analysis;
}

const RowTies& SliceComparison::State::row_ties(LayerAnalysis& a, std::uint32_t j) {
  if (const auto it = a.rows.find(j); it != a.rows.end()) return it->second;
  RowTies row;
  const double y = grid.yc(j) + options.scan_offset_mm;
  for (const LayerSegment& s : a.segments.segments) {
    const Point2& p = s.start;
    const Point2& q = s.end;
    if (std::fabs(p.y - y) <= tolerance || std::fabs(q.y - y) <= tolerance) {
      row.tie_max_x = std::max({row.tie_max_x, p.x, q.x});
    } else if ((p.y < y) != (q.y < y)) {
      row.crossings.push_back(p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y));
    }
  }
  for (const auto& f : a.plane_ties) {
    if (f.y_min - tolerance <= y && y <= f.y_max + tolerance) {
      row.tie_max_x = std::max(row.tie_max_x, f.x_max);
    }
  }
  std::sort(row.crossings.begin(), row.crossings.end());
  return a.rows.emplace(j, std::move(row)).first->second;
}

DifferenceReason SliceComparison::State::explain(std::uint32_t i, std::uint32_t j, std::uint32_t k,
                                                 CellClass fast, CellClass exact) {
  const std::uint64_t c = cell_index(i, j);
  if (offset_changed(k, c)) return DifferenceReason::ScanOffset;
  if (is_solid(fast) == is_solid(exact)) return DifferenceReason::Shell;
  analyse(k);
  const RowTies& row = row_ties(*analysis, j);
  const double xc = grid.xc(i);
  if (xc <= row.tie_max_x + tolerance) return DifferenceReason::NearDegenerate;
  const auto near = std::lower_bound(row.crossings.begin(), row.crossings.end(), xc - tolerance);
  if (near != row.crossings.end() && *near <= xc + tolerance) {
    return DifferenceReason::NearDegenerate;
  }
  if (analysis->solid_rule[c] != analysis->solid_other[c]) return DifferenceReason::FillRule;
  return DifferenceReason::Unexplained;
}

void SliceComparison::State::compare_contours(const LayerResult& fast, const LayerResult& exact,
                                              LayerComparison& out) {
  const auto count = [](const LayerContours& contours, ContourCounts& counts) {
    for (const Contour& c : contours.loops) {
      counts.points += static_cast<std::uint32_t>(c.points.size());
      if (c.kind == LoopKind::Outer) ++counts.outer_loops;
      if (c.kind == LoopKind::Hole) ++counts.holes;
      if (c.kind == LoopKind::Open) ++counts.open_chains;
    }
    counts.area_mm2 = contours.area_mm2;
  };
  count(fast.contours, out.fast);
  count(exact.contours, out.exact);
  if (out.fast.outer_loops != out.exact.outer_loops || out.fast.holes != out.exact.holes ||
      out.fast.open_chains != out.exact.open_chains) {
    ++report.layers_with_different_counts;
  }
  if (out.has_open_chains()) ++report.layers_with_open_chains;
  if (!vopts.compare_contours) {
    out.area_method = AreaMethod::NotCompared;
    return;
  }
  if (same_loop_edges(fast.contours.loops, exact.contours.loops)) {
    out.area_method = AreaMethod::Identical;
    // Equal loop edges and no open chain: the same vertices on the same segments.
    out.hausdorff_mm =
        out.has_open_chains() ? hausdorff_distance(fast.contours.loops, exact.contours.loops) : 0.0;
  } else {
    out.hausdorff_mm = hausdorff_distance(fast.contours.loops, exact.contours.loops);
    const bool counts_differ = out.fast.outer_loops != out.exact.outer_loops ||
                               out.fast.holes != out.exact.holes ||
                               out.fast.open_chains != out.exact.open_chains;
    const bool rounding_only = !counts_differ && out.hausdorff_mm <= tolerance;
    const std::uint32_t budget = vopts.max_overlay_layers;
    const std::uint32_t stride =
        budget == 0 ? 1 : std::max<std::uint32_t>(1, (grid.nz + budget - 1) / budget);
    if (!rounding_only || fast.layer % stride == 0) {
      const SymmetricDifference sd =
          symmetric_difference(fast.contours.loops, exact.contours.loops, options.fill_rule);
      out.symmetric_difference_mm2 = sd.area_mm2;
      out.area_method = sd.method;
      if (sd.method == AreaMethod::Arrangement) ++report.layers_arrangement;
      if (sd.method == AreaMethod::AreaOnly) ++report.layers_area_only;
    } else {
      out.area_method = AreaMethod::NotCompared;
      ++report.layers_overlay_skipped;
    }
  }
  report.max_hausdorff_all_mm = std::max(report.max_hausdorff_all_mm, out.hausdorff_mm);
  if (!out.has_open_chains()) {
    report.max_hausdorff_mm = std::max(report.max_hausdorff_mm, out.hausdorff_mm);
    report.max_symmetric_difference_mm2 =
        std::max(report.max_symmetric_difference_mm2, out.symmetric_difference_mm2);
    report.total_symmetric_difference_mm2 += out.symmetric_difference_mm2;
  }
}

void SliceComparison::State::measure_fast(const LayerResult& fast) {
  const std::uint32_t k = fast.layer;
  std::vector<std::uint64_t>& layer_boundary = boundary[k];
  fast_box.add_layer(fast.cells, grid.nx, grid.ny, k);
  if (!boundary_overflow) {
    for (std::uint64_t c = 0; c < fast.cells.size(); ++c) {
      if (fast.cells[c] == CellClass::Boundary) layer_boundary.push_back(c);
    }
  }
  boundary_count += layer_boundary.size();
  if (boundary_count > vopts.max_boundary_cells) {
    boundary_overflow = true;
    for (auto& b : boundary) std::vector<std::uint64_t>().swap(b);
  }
  // The shell of layer k - 1 can be measured once layer k is known.
  std::vector<CellClass> current(fast.cells.begin(), fast.cells.end());
  if (window_k >= 0 && window_k + 1 == static_cast<std::int64_t>(k)) {
    measure_shell_layer(static_cast<std::uint32_t>(window_k), window_mid,
                        window_below.empty() ? nullptr : &window_below, &current);
    window_below = std::move(window_mid);
  } else {
    window_below.clear();
    if (window_k >= 0) {
      measure_shell_layer(static_cast<std::uint32_t>(window_k), window_mid, nullptr, nullptr);
    }
  }
  window_mid = std::move(current);
  window_k = k;
}

void SliceComparison::State::measure_shell_layer(std::uint32_t k,
                                                 const std::vector<CellClass>& cells,
                                                 const std::vector<CellClass>* below,
                                                 const std::vector<CellClass>* above) {
  const std::uint32_t nx = grid.nx;
  const std::uint32_t ny = grid.ny;
  for (std::uint32_t j = 0; j < ny; ++j) {
    for (std::uint32_t i = 0; i < nx; ++i) {
      const std::uint64_t c = std::uint64_t{j} * nx + i;
      if (cells[c] != CellClass::Interior) continue;
      const auto boundary_at = [&](std::uint64_t q) { return cells[q] == CellClass::Boundary; };
      const bool touches = (i > 0 && boundary_at(c - 1)) || (i + 1 < nx && boundary_at(c + 1)) ||
                           (j > 0 && boundary_at(c - nx)) || (j + 1 < ny && boundary_at(c + nx)) ||
                           (below && (*below)[c] == CellClass::Boundary) ||
                           (above && (*above)[c] == CellClass::Boundary);
      if (!touches) continue;
      ++shell_candidates;
      const Vec3 centre{grid.xc(i), grid.yc(j), grid.zk(k)};
      if (shell_samples.size() < vopts.max_shell_samples) {
        shell_samples.push_back(centre);
      } else {
        const std::uint64_t r = rng() % shell_candidates;
        if (r < shell_samples.size()) shell_samples[r] = centre;
      }
    }
  }
}

void SliceComparison::State::measure_model() {
  ModelFigures& m = report.model;
  m.asked_shell_mm = options.shell_mm;
  {
    TriangleSoup soup;
    soup.triangles.reserve(mesh.triangles.size());
    for (FacetIndex f = 0; f < mesh.triangles.size(); ++f) {
      soup.triangles.push_back({mesh.corner(f, 0), mesh.corner(f, 1), mesh.corner(f, 2)});
    }
    diagnose::DiagnoseOptions d;
    d.check_self_intersections = false;
    d.near_vertex_mm = 0.0;
    const diagnose::MeshReport mesh_report = diagnose::diagnose_mesh(mesh, soup, d);
    m.mesh_volume_mm3 = mesh_report.volume_mm3;
    m.surface_area_mm2 = mesh_report.surface_area_mm2;
    m.mesh_bounds = mesh_report.bounds;
  }
  const Bbox3 cover = merged(grid_box(grid), m.mesh_bounds);

  // Surface -> boundary cell centres.
  if (boundary_overflow) {
    report.diagnostics.push_back(
        {Severity::Info, "validate.boundary_cells",
         fmt::format("the surface-to-shell distance was not measured: more than {} boundary "
                     "cells",
                     vopts.max_boundary_cells)});
  } else if (boundary_count > 0 && !mesh.triangles.empty()) {
    std::vector<std::uint64_t> cells;
    cells.reserve(boundary_count);
    const std::uint64_t per_layer = grid.cells_per_layer();
    for (std::uint32_t k = 0; k < grid.nz; ++k) {
      for (const std::uint64_t c : boundary[k]) cells.push_back(std::uint64_t{k} * per_layer + c);
      std::vector<std::uint64_t>().swap(boundary[k]);
    }
    const auto centre = [&](std::size_t item) {
      const std::uint64_t id = cells[item];
      const std::uint64_t k = id / per_layer;
      const std::uint64_t c = id % per_layer;
      return Vec3{grid.xc(static_cast<std::uint32_t>(c % grid.nx)),
                  grid.yc(static_cast<std::uint32_t>(c / grid.nx)),
                  grid.zk(static_cast<std::uint32_t>(k))};
    };
    const detail::BucketGrid3 index(cover, cells.size(), [&](std::size_t item) {
      Bbox3 b;
      b.add(centre(item));
      return b;
    });
    double h = 0.0;
    std::uint64_t samples = 0;
    const auto sample = [&](const Vec3& p) {
      ++samples;
      const double d = index.nearest(
          p,
          [&](std::uint32_t item) {
            const Vec3 q = centre(item);
            return std::sqrt((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) +
                             (p.z - q.z) * (p.z - q.z));
          },
          h);
      h = std::max(h, d);
    };
    const std::size_t budget = std::max<std::size_t>(1, vopts.max_surface_samples);
    const std::size_t nv = mesh.vertices.size();
    const std::size_t vertex_step =
        std::max<std::size_t>(1, (nv + budget / 2 - 1) / (budget / 2 + 1));
    for (std::size_t v = 0; v < nv; v += vertex_step) sample(mesh.vertices[v]);
    const std::size_t nf = mesh.triangles.size();
    const std::size_t left = budget > samples ? budget - samples : 1;
    const std::size_t facet_step = std::max<std::size_t>(1, (4 * nf + left - 1) / left);
    for (std::size_t f = 0; f < nf; f += facet_step) {
      const Vec3& a = mesh.corner(static_cast<FacetIndex>(f), 0);
      const Vec3& b = mesh.corner(static_cast<FacetIndex>(f), 1);
      const Vec3& c = mesh.corner(static_cast<FacetIndex>(f), 2);
      sample({(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2});
      sample({(b.x + c.x) / 2, (b.y + c.y) / 2, (b.z + c.z) / 2});
      sample({(c.x + a.x) / 2, (c.y + a.y) / 2, (c.z + a.z) / 2});
      sample({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3});
    }
    m.surface_to_boundary_mm = h;
    m.surface_samples = samples;
  }

  // Interior cells next to the shell -> surface.
  m.shell.cells = shell_candidates;
  if (!shell_samples.empty() && !mesh.triangles.empty()) {
    const detail::BucketGrid3 facets(cover, mesh.triangles.size(), [&](std::size_t f) {
      Bbox3 b;
      for (int c = 0; c < 3; ++c) b.add(mesh.corner(static_cast<FacetIndex>(f), c));
      return b;
    });
    double lo = std::numeric_limits<double>::infinity();
    double hi = 0.0;
    double sum = 0.0;
    for (const Vec3& p : shell_samples) {
      const double d = facets.nearest(p, [&](std::uint32_t f) {
        return detail::point_triangle_distance(p, mesh.corner(f, 0), mesh.corner(f, 1),
                                               mesh.corner(f, 2));
      });
      lo = std::min(lo, d);
      hi = std::max(hi, d);
      sum += d;
    }
    m.shell.measured = shell_samples.size();
    m.shell.min_mm = lo;
    m.shell.max_mm = hi;
    m.shell.mean_mm = sum / static_cast<double>(shell_samples.size());
  }
}

SliceComparison::SliceComparison(const IndexedMesh& mesh, const GridSpec& grid,
                                 const SliceOptions& options,
                                 const ValidateOptions& validate_options)
    : state_(std::make_unique<State>(mesh, grid, options, validate_options)) {}

SliceComparison::~SliceComparison() = default;

void SliceComparison::add_scan_offset_layer(std::uint32_t k, std::span<const CellClass> with_offset,
                                            std::span<const CellClass> without_offset) {
  State& s = *state_;
  STRATA_ASSERT(k < s.grid.nz, "scan offset layer outside the grid");
  STRATA_ASSERT(with_offset.size() == s.grid.cells_per_layer() &&
                    without_offset.size() == s.grid.cells_per_layer(),
                "scan offset layers must hold nx * ny cells");
  ScanOffsetFigures& f = s.report.scan_offset;
  f.measured = true;
  f.offset_mm = s.options.scan_offset_mm;
  for (std::uint64_t c = 0; c < with_offset.size(); ++c) {
    if (with_offset[c] == without_offset[c]) continue;
    ++f.cells_changed;
    const auto i = static_cast<std::uint32_t>(c % s.grid.nx);
    const auto j = static_cast<std::uint32_t>(c / s.grid.nx);
    if (f.cells.size() < s.vopts.max_listed_cells) {
      f.cells.push_back({i, j, k, with_offset[c], without_offset[c]});
    }
    if (s.offset_remembered < s.vopts.max_remembered_offset_cells) {
      s.offset_cells[k].push_back(c);
      ++s.offset_remembered;
    } else {
      s.offset_truncated = true;
    }
  }
}

void SliceComparison::add_layers(const LayerResult& fast, const LayerResult& exact) {
  const auto started = Clock::now();
  State& s = *state_;
  const GridSpec& g = s.grid;
  STRATA_ASSERT(fast.layer == exact.layer, "layers of both paths must have the same k");
  STRATA_ASSERT(fast.layer < g.nz, "layer outside the grid");
  STRATA_ASSERT(
      fast.cells.size() == g.cells_per_layer() && exact.cells.size() == g.cells_per_layer(),
      "layers must hold nx * ny cells");
  const std::uint32_t k = fast.layer;
  LayerComparison cmp;
  cmp.layer = k;
  cmp.z_mm = g.zk(k);
  s.exact_box.add_layer(exact.cells, g.nx, g.ny, k);
  if (!std::equal(fast.cells.begin(), fast.cells.end(), exact.cells.begin())) {
    for (std::uint32_t j = 0; j < g.ny; ++j) {
      const std::uint64_t row = std::uint64_t{j} * g.nx;
      for (std::uint32_t i = 0; i < g.nx; ++i) {
        const CellClass a = fast.cells[row + i];
        const CellClass b = exact.cells[row + i];
        if (a == b) continue;
        ++cmp.cells_differing;
        if (is_solid(a) != is_solid(b)) ++s.solid_differences[k];
        const DifferenceReason reason = s.explain(i, j, k, a, b);
        if (reason == DifferenceReason::Shell) {
          ++s.shell_pending[k];
        } else {
          ++s.report.differing_by_reason[static_cast<std::size_t>(reason)];
        }
        if (s.report.differences.size() < s.vopts.max_listed_cells) {
          s.report.differences.push_back({i, j, k, a, b, reason});
        }
      }
    }
  }
  s.report.cells_differing += cmp.cells_differing;
  s.report.cells_compared += g.cells_per_layer();
  ++s.report.layers_compared;
  s.compare_contours(fast, exact, cmp);
  s.report.layers.push_back(cmp);
  s.measure_fast(fast);
  s.seconds += std::chrono::duration<double>(Clock::now() - started).count();
  if (s.vopts.progress) s.vopts.progress(k + 1, g.nz);
}

void SliceComparison::add_fast_layer(const LayerResult& fast) {
  const auto started = Clock::now();
  State& s = *state_;
  STRATA_ASSERT(fast.layer < s.grid.nz, "layer outside the grid");
  STRATA_ASSERT(fast.cells.size() == s.grid.cells_per_layer(), "layers must hold nx * ny cells");
  s.measure_fast(fast);
  s.seconds += std::chrono::duration<double>(Clock::now() - started).count();
  if (s.vopts.progress) s.vopts.progress(fast.layer + 1, s.grid.nz);
}

ValidationReport SliceComparison::finish() {
  const auto started = Clock::now();
  State& s = *state_;
  if (s.window_k >= 0) {
    s.measure_shell_layer(static_cast<std::uint32_t>(s.window_k), s.window_mid,
                          s.window_below.empty() ? nullptr : &s.window_below, nullptr);
    s.window_k = -1;
  }
  // A cell that differs only in its shell mark is explained when a cell within the shell's reach
  // differs in solidity.
  const auto explained_by_shell = [&](std::uint32_t k) {
    const std::uint32_t lo = k > s.shell_reach ? k - s.shell_reach : 0;
    const std::uint32_t hi = std::min(s.grid.nz - 1, k + s.shell_reach);
    for (std::uint32_t q = lo; q <= hi; ++q) {
      if (s.solid_differences[q] > 0) return true;
    }
    return false;
  };
  for (std::uint32_t k = 0; k < s.grid.nz; ++k) {
    if (s.shell_pending[k] == 0) continue;
    const DifferenceReason r =
        explained_by_shell(k) ? DifferenceReason::Shell : DifferenceReason::Unexplained;
    s.report.differing_by_reason[static_cast<std::size_t>(r)] += s.shell_pending[k];
  }
  for (CellDifference& d : s.report.differences) {
    if (d.reason == DifferenceReason::Shell && !explained_by_shell(d.k)) {
      d.reason = DifferenceReason::Unexplained;
    }
  }
  if (s.offset_truncated) {
    s.report.diagnostics.push_back(
        {Severity::Info, "validate.offset_cells",
         fmt::format("more than {} cells change with the scan offset; differences beyond them "
                     "were not checked against the offset",
                     s.vopts.max_remembered_offset_cells)});
  }
  s.report.fast.solid_bounds = s.fast_box.to_mm(s.grid);
  s.report.exact.solid_bounds = s.exact_box.to_mm(s.grid);
  s.measure_model();
  s.seconds += std::chrono::duration<double>(Clock::now() - started).count();
  s.report.comparison_seconds = s.seconds;
  return std::move(s.report);
}

}  // namespace strata::validate
