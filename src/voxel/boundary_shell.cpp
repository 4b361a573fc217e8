#include "strata/voxel/boundary_shell.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <span>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/group_by_key.hpp"
#include "core/huge_pages.hpp"
#include "strata/core/error.hpp"
#include "voxel/triangle_distance_filter_internal.hpp"

namespace strata {

namespace {

/// ceil(x) and floor(x) for x well inside the range of the type: a cast and a compare, where
/// std::ceil and std::floor are library calls on the baseline x86-64 the project builds for.
std::int64_t ceil_index(double x) {
  const auto i = static_cast<std::int64_t>(x);
  return static_cast<double>(i) < x ? i + 1 : i;
}
std::int64_t floor_index(double x) {
  const auto i = static_cast<std::int64_t>(x);
  return static_cast<double>(i) > x ? i - 1 : i;
}

/// The bits of columns first .. last of a word whose bit 0 is column `base` (base <= first <=
/// last < base + 64).
std::uint64_t run_bits(std::int64_t first, std::int64_t last, std::int64_t base) {
  const std::int64_t n = last - first + 1;
  return (n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1) << (first - base);
}

/// Bit i set when cells[i] is Interior, for i < 64 and i < available (the cells there are);
/// the bits from `wanted` on may be left clear.
std::uint64_t interior_bits(const CellClass* cells, std::size_t available,
                            [[maybe_unused]] std::size_t wanted) {
  const auto* codes = reinterpret_cast<const std::uint8_t*>(cells);
  const auto interior = static_cast<std::uint8_t>(CellClass::Interior);
#if defined(__SSE2__)
  // Sixteen cells a compare, their bits gathered by one movemask; a box of 32 columns or fewer
  // (most patches') takes two.
  const __m128i want = _mm_set1_epi8(static_cast<char>(interior));
  const auto sixteen = [&](int q) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(codes + 16 * q));
    const auto mask = static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(v, want)));
    return static_cast<std::uint64_t>(mask) << (16 * q);
  };
  if (wanted <= 32 && available >= 32) return sixteen(0) | sixteen(1);
  if (available >= 64) return sixteen(0) | sixteen(1) | sixteen(2) | sixteen(3);
#endif
  std::uint64_t bits = 0;
  for (std::size_t i = 0; i < std::min<std::size_t>(available, 64); ++i) {
    bits |= static_cast<std::uint64_t>(codes[i] == interior) << i;
  }
  return bits;
}

/// The cells along one axis of the grid: centre i at base + (i + 0.5) d, for i in [0, n).
struct GridAxis {
  double base, d, inv_d;
  std::uint32_t n;
  GridAxis(double base_, double d_, std::uint32_t n_)
      : base(base_), d(d_), inv_d(1.0 / d_), n(n_) {}

  /// The indices of the centres in [lo, hi] widened by 1e-12 of its ends, and perhaps one more
  /// at an end that a centre only rounding away from the bound would leave out: the cells a
  /// facet may reach, for the exact test to decide. i0 > i1 when there is none.
  std::pair<std::int64_t, std::int64_t> cells_reaching(double lo, double hi) const {
    const double count = static_cast<double>(n);
    // The rounding of these few operations, relative to the magnitudes involved, and the
    // 1e-12 of the bounds.
    const double pad =
        1e-9 + (2e-12 * std::max(std::fabs(lo), std::fabs(hi)) + 1e-14 * std::fabs(base)) * inv_d;
    const std::int64_t i0 = std::max<std::int64_t>(
        0, ceil_index(std::clamp((lo - base) * inv_d - 0.5 - pad, -1.0, count)));
    const std::int64_t i1 =
        floor_index(std::clamp((hi - base) * inv_d - 0.5 + pad, -1.0, count - 1.0));
    return {i0, i1};
  }

  /// The indices of the centres in [lo, hi], to the rounding of a few operations: a guess for
  /// a caller that checks what it takes (a centre it misses is left to the exact test).
  std::pair<std::int64_t, std::int64_t> centres_within(double lo, double hi) const {
    const double last = static_cast<double>(n) - 1.0;
    // Bounded so that the casts hold; a NaN takes the lower bound, an empty range.
    const auto bounded = [](double v, double low, double high) {
      return v >= low ? (v <= high ? v : high) : low;
    };
    return {ceil_index(bounded((lo - base) * inv_d - 0.5, 0.0, last + 1.0)),
            floor_index(bounded((hi - base) * inv_d - 0.5, -1.0, last))};
  }
};

/// The x-y bounding box of the part of triangle abc within z in [z_lo, z_hi]; false if none.
bool slab_footprint(const Vec3& a, const Vec3& b, const Vec3& c, double z_lo, double z_hi,
                    double box[4]) {
  const double z_min = std::min({a.z, b.z, c.z});
  const double z_max = std::max({a.z, b.z, c.z});
  if (z_min >= z_lo && z_max <= z_hi) {
    // Within the slab (most facets of a fine mesh): the footprint is the facet's own box.
    box[0] = std::min({a.x, b.x, c.x});
    box[1] = std::min({a.y, b.y, c.y});
    box[2] = std::max({a.x, b.x, c.x});
    box[3] = std::max({a.y, b.y, c.y});
    return true;
  }
  box[0] = box[1] = std::numeric_limits<double>::infinity();
  box[2] = box[3] = -std::numeric_limits<double>::infinity();
  bool any = false;
  const auto add = [&](double x, double y) {
    box[0] = std::min(box[0], x);
    box[1] = std::min(box[1], y);
    box[2] = std::max(box[2], x);
    box[3] = std::max(box[3], y);
    any = true;
  };
  const Vec3* v[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const Vec3& p = *v[i];
    const Vec3& q = *v[(i + 1) % 3];
    if (p.z >= z_lo && p.z <= z_hi) add(p.x, p.y);
    for (const double z : {z_lo, z_hi}) {
      if ((p.z < z && q.z > z) || (p.z > z && q.z < z)) {
        const double s = (z - p.z) / (q.z - p.z);
        add(p.x + s * (q.x - p.x), p.y + s * (q.y - p.y));
      }
    }
  }
  return any;
}

/// The runs of both a and b, into `out` (cleared first).
void intersect_runs(std::span<const SolidRun> a, std::span<const SolidRun> b,
                    std::vector<SolidRun>& out) {
  out.clear();
  std::size_t p = 0, q = 0;
  while (p < a.size() && q < b.size()) {
    const std::uint32_t lo = std::max(a[p].begin, b[q].begin);
    const std::uint32_t hi = std::min(a[p].end, b[q].end);
    if (lo < hi) out.push_back({lo, hi});
    if (a[p].end < b[q].end) {
      ++p;
    } else {
      ++q;
    }
  }
}

/// Sets `count` cells from `at` to `code`.
void set_cells(CellClass* at, std::size_t count, CellClass code) {
  std::memset(at, static_cast<int>(code), count);
}

/// The first ring of a layer: every solid cell is Interior, or Boundary when one of its
/// 6-neighbours is empty (outside the grid counts as empty; a missing layer is outside); every
/// other cell Empty. Each of the nx * ny cells of `out` is written; returns the Boundary cells.
/// Row by row, on runs: a cell is Interior when it lies in a run of its row shrunk by one at
/// either end (both row neighbours solid) and in the runs of the rows beside it and of the same
/// row in the layers beside. On the grid's border rows, and when a layer beside is missing, every
/// solid cell touches the outside.
std::uint64_t first_ring(const SolidRows& here, const SolidRows* below, const SolidRows* above,
                         CellClass* out) {
  const std::uint32_t nx = here.nx();
  const std::uint32_t ny = here.ny();
  std::vector<SolidRun> inner, scratch;
  std::uint64_t boundary = 0;
  for (std::uint32_t j = 0; j < ny; ++j) {
    const auto runs = here.row(j);
    CellClass* o = out + std::size_t{j} * nx;
    inner.clear();
    if (!runs.empty() && j != 0 && j + 1 != ny && below != nullptr && above != nullptr) {
      for (const SolidRun& r : runs) {
        if (r.end - r.begin > 2) inner.push_back({r.begin + 1, r.end - 1});
      }
      for (const auto side : {here.row(j - 1), here.row(j + 1), below->row(j), above->row(j)}) {
        if (inner.empty()) break;
        intersect_runs(inner, side, scratch);
        std::swap(inner, scratch);
      }
    }
    // Each inner run lies within one run of the row.
    std::uint32_t at = 0;
    std::size_t q = 0;
    for (const SolidRun& r : runs) {
      set_cells(o + at, r.begin - at, CellClass::Empty);
      at = r.begin;
      for (; q < inner.size() && inner[q].begin < r.end; ++q) {
        set_cells(o + at, inner[q].begin - at, CellClass::Boundary);
        set_cells(o + inner[q].begin, inner[q].end - inner[q].begin, CellClass::Interior);
        boundary += inner[q].begin - at;
        at = inner[q].end;
      }
      set_cells(o + at, r.end - at, CellClass::Boundary);
      boundary += r.end - at;
      at = r.end;
    }
    set_cells(o + at, nx - at, CellClass::Empty);
  }
  return boundary;
}

/// A facet's box in the frame of its patch's slab (n, u, v), [lo[a], hi[a]] along each axis a,
/// within the slab's own box.
struct FrameBox {
  double lo[3], hi[3];
};

/// The coordinates of p along the frame's axes.
std::array<double, 3> frame_coordinates(const Vec3 (&axes)[3], const Vec3& p) {
  std::array<double, 3> out;
  for (int a = 0; a < 3; ++a) out[a] = axes[a].x * p.x + axes[a].y * p.y + axes[a].z * p.z;
  return out;
}

/// The box of a facet's corners in the slab's frame, widened by the slab's margin (1e-9 of the
/// patch's coordinates' scale): far above the rounding of the dot products and the frame's
/// departure from orthonormal.
FrameBox facet_frame_box(const Vec3 (&axes)[3], double margin, const Vec3* const* corner) {
  std::array<double, 3> q[3];
  for (int c = 0; c < 3; ++c) q[c] = frame_coordinates(axes, *corner[c]);
  FrameBox box{};
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = std::min({q[0][a], q[1][a], q[2][a]}) - margin;
    box.hi[a] = std::max({q[0][a], q[1][a], q[2][a]}) + margin;
  }
  return box;
}

/// Whether p is certainly at least t from the box [lo[a], hi[a]] of x, y and z (t2_far being
/// t^2 widened by 1e-9): BoundaryShell::beyond_frame_box for a point known exactly, each
/// difference within an ulp of its own magnitude and the sum of their squares within a few, far
/// inside the margins. Kept apart from it because the hot few-candidate pass then subtracts no
/// error. A sum that overflowed proves nothing.
bool beyond_box(const Vec3& p, const double (&lo)[3], const double (&hi)[3], double t2_far) {
  const double q[3] = {p.x, p.y, p.z};
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max({lo[a] - q[a], 0.0, q[a] - hi[a]});
    sum += d * d;
  }
  return std::isfinite(sum) && sum * (1.0 - 1e-9) >= t2_far;
}

/// Whether p is closer than t to the facet with these corners. Its filter is built on the
/// first call: the boxes of many facets hold no cell to test.
bool facet_closer_than(std::optional<detail::TriangleDistanceFilter>& filter,
                       const Vec3* const* corner, double t, const Vec3& p) {
  if (!filter) filter.emplace(*corner[0], *corner[1], *corner[2], t);
  return filter->closer_than(p);
}

}  // namespace

BoundaryShell::FramePoint BoundaryShell::frame_point(const Vec3 (&axes)[3], const Vec3& p) {
  const std::array<double, 3> q = frame_coordinates(axes, p);
  return {{q[0], q[1], q[2]}, 1e-9 * (std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z) + 1.0)};
}

bool BoundaryShell::beyond_frame_box(const FramePoint& p, const double (&lo)[3],
                                     const double (&hi)[3], double t2_far) {
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max({lo[a] - p.q[a] - p.error, 0.0, p.q[a] - hi[a] - p.error});
    sum += d * d;
  }
  return std::isfinite(sum) && sum * (1.0 - 1e-9) >= t2_far;
}

/// The slab of a patch's facets across their area-weighted mean normal, widened by a margin far
/// above the rounding of these sums and of the row arithmetic that uses it (1e-9 of the largest
/// coordinate), so that it leaves out only points the exact test would reject. Unusable when the
/// normals cancel out (a thin sheet seen from both sides).
BoundaryShell::Slab BoundaryShell::slab_of(std::span<const std::array<VertexIndex, 3>> triangles,
                                           const std::vector<Vec3>& vertices) {
  Vec3 sum{0, 0, 0};
  double scale = 0.0;
  for (const auto& tri : triangles) {
    const Vec3& a = vertices[tri[0]];
    const Vec3& b = vertices[tri[1]];
    const Vec3& c = vertices[tri[2]];
    const Vec3 u{b.x - a.x, b.y - a.y, b.z - a.z};
    const Vec3 v{c.x - a.x, c.y - a.y, c.z - a.z};
    sum = {sum.x + (u.y * v.z - u.z * v.y), sum.y + (u.z * v.x - u.x * v.z),
           sum.z + (u.x * v.y - u.y * v.x)};
    for (const Vec3* p : {&a, &b, &c}) {
      scale = std::max({scale, std::fabs(p->x), std::fabs(p->y), std::fabs(p->z)});
    }
  }
  Slab out;
  const double length = std::sqrt(sum.x * sum.x + sum.y * sum.y + sum.z * sum.z);
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(scale)) return out;
  const Vec3 n{sum.x / length, sum.y / length, sum.z / length};
  // The tangents: u across n and the axis least along it, v across n and u.
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  const Vec3 least =
      ax <= ay && ax <= az ? Vec3{1, 0, 0} : (ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  const Vec3 across{n.y * least.z - n.z * least.y, n.z * least.x - n.x * least.z,
                    n.x * least.y - n.y * least.x};
  const double across_length =
      std::sqrt(across.x * across.x + across.y * across.y + across.z * across.z);
  const Vec3 u{across.x / across_length, across.y / across_length, across.z / across_length};
  out.axis[0] = n;
  out.axis[1] = u;
  out.axis[2] = {n.y * u.z - n.z * u.y, n.z * u.x - n.x * u.z, n.x * u.y - n.y * u.x};
  for (int a = 0; a < 3; ++a) {
    out.lo[a] = std::numeric_limits<double>::infinity();
    out.hi[a] = -std::numeric_limits<double>::infinity();
  }
  for (const auto& tri : triangles) {
    for (const VertexIndex corner : tri) {
      const std::array<double, 3> q = frame_coordinates(out.axis, vertices[corner]);
      for (int a = 0; a < 3; ++a) {
        out.lo[a] = std::min(out.lo[a], q[a]);
        out.hi[a] = std::max(out.hi[a], q[a]);
      }
    }
  }
  // The computed n, u and v are unit and orthogonal to a few ulps, and each dot product is off
  // by a few ulps of the coordinates' scale: 1e-9 of it covers both with room to spare.
  out.margin = 1e-9 * (scale + 1.0);
  for (int a = 0; a < 3; ++a) {
    out.lo[a] -= out.margin;
    out.hi[a] += out.margin;
  }
  out.usable = true;
  return out;
}

BoundaryShell::BoundaryShell(const IndexedMesh& mesh, const GridSpec& grid, ShellMode mode,
                             double thickness_mm)
    : mesh_(mesh),
      grid_(grid),
      mode_(mode),
      thickness_mm_(thickness_mm),
      reach_(reach_layers(grid, mode, thickness_mm)) {
  if (mode_ == ShellMode::Layers) {
    unequal_sizes_ = !(grid_.dx == grid_.dy && grid_.dy == grid_.dz);
    rings_ = reach_;
    return;
  }
  if (!(thickness_mm_ > 0.0)) return;
  const std::size_t nf = mesh_.triangles.size();
  // The arrays below are filled once: huge pages spare a fault per 4 KiB.
  // Patches: the facets whose centroids share a box of kPatchCells cells by kPatchLayers layers,
  // counted from the mesh's lowest corner. A facet's box is the key it is sorted by, beside its
  // index, so the sort reads no other array.
  // Members without initialisers, unlike std::pair's: the array is not zeroed first.
  struct PatchKey {
    std::uint64_t first;
    FacetIndex second;
    bool operator<(const PatchKey& o) const {
      return first != o.first ? first < o.first : second < o.second;
    }
  };
  auto by_patch = std::make_unique_for_overwrite<PatchKey[]>(nf);
  advise_huge_pages(by_patch.get(), nf * sizeof(PatchKey));
  const Vec3 low = mesh_.bounds().min;
  const auto box_index = [](double offset, double size) {
    const double q = std::floor(offset / size);
    return static_cast<std::uint64_t>(std::clamp(q, 0.0, 2097151.0));  // 21 bits
  };
  const double patch_x = kPatchCells * grid_.dx;
  const double patch_y = kPatchCells * grid_.dy;
  const double patch_z = kPatchLayers * grid_.dz;
  tbb::parallel_for(std::size_t{0}, nf, [&](std::size_t f) {
    const auto& t = mesh_.triangles[f];
    const Vec3& a = mesh_.vertices[t[0]];
    const Vec3& b = mesh_.vertices[t[1]];
    const Vec3& c = mesh_.vertices[t[2]];
    const double cx = (a.x + b.x + c.x) / 3.0;
    const double cy = (a.y + b.y + c.y) / 3.0;
    const double cz = (a.z + b.z + c.z) / 3.0;
    by_patch[f] =
        PatchKey{box_index(cz - low.z, patch_z) << 42 | box_index(cy - low.y, patch_y) << 21 |
                     box_index(cx - low.x, patch_x),
                 static_cast<FacetIndex>(f)};
  });
  // Ordered by box, ties by index. When the boxes the facets span are no more than the facets, by
  // counting (in facet order within a box, on the threads); otherwise by a parallel sort.
  constexpr std::uint64_t kAxis = (std::uint64_t{1} << 21) - 1;
  struct BoxCounts {
    std::uint64_t x = 1, y = 1, z = 1;
  };
  const BoxCounts boxes = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, nf, 1 << 14), BoxCounts{},
      [&](const tbb::blocked_range<std::size_t>& range, BoxCounts counts) {
        for (std::size_t f = range.begin(); f < range.end(); ++f) {
          const std::uint64_t key = by_patch[f].first;
          counts.x = std::max(counts.x, (key & kAxis) + 1);
          counts.y = std::max(counts.y, (key >> 21 & kAxis) + 1);
          counts.z = std::max(counts.z, (key >> 42) + 1);
        }
        return counts;
      },
      [](const BoxCounts& a, const BoxCounts& b) {
        return BoxCounts{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
      });
  if (boxes.x * boxes.y * boxes.z <= nf) {
    const auto box_of = [&](std::uint64_t key) {
      return ((key >> 42) * boxes.y + (key >> 21 & kAxis)) * boxes.x + (key & kAxis);
    };
    auto sorted = std::make_unique_for_overwrite<PatchKey[]>(nf);
    group_by_key<std::uint32_t>(
        boxes.x * boxes.y * boxes.z, nf,
        [&](std::size_t f, auto&& visit) { visit(box_of(by_patch[f].first), by_patch[f]); },
        [&](std::size_t) { return sorted.get(); });
    by_patch = std::move(sorted);
  } else {
    tbb::parallel_sort(by_patch.get(), by_patch.get() + nf);
  }
  // A patch begins where the key changes. The sorted keys are cut into blocks that count their
  // beginnings, then number them from the count of the blocks before: in parallel, one result.
  const auto begins_patch = [&](std::size_t r) {
    return r == 0 || by_patch[r].first != by_patch[r - 1].first;
  };
  constexpr std::size_t kBlock = 256;  // small: the tests' meshes span several blocks
  const std::size_t blocks = (nf + kBlock - 1) / kBlock;
  const auto rows_of = [&](std::size_t block) {
    return std::pair{block * kBlock, std::min(nf, (block + 1) * kBlock)};
  };
  std::vector<std::uint32_t> patches_before(blocks + 1, 0);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t block) {
    const auto [first, last] = rows_of(block);
    std::uint32_t count = 0;
    for (std::size_t r = first; r < last; ++r) count += begins_patch(r) ? 1 : 0;
    patches_before[block + 1] = count;
  });
  std::partial_sum(patches_before.begin(), patches_before.end(), patches_before.begin());
  std::vector<Patch> patches(patches_before[blocks]);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t block) {
    const auto [first, last] = rows_of(block);
    std::uint32_t q = patches_before[block];
    for (std::size_t r = first; r < last; ++r) {
      if (begins_patch(r)) patches[q++].begin = static_cast<std::uint32_t>(r);
    }
  });
  for (std::size_t q = 0; q < patches.size(); ++q) {
    patches[q].end = q + 1 < patches.size() ? patches[q + 1].begin : static_cast<std::uint32_t>(nf);
  }
  // The facets in patch order, and their vertices copied in the order these facets first use
  // them: the layers read both in sequence rather than gathering corners from across the mesh
  // (a vertex load missed the cache in most facets of a large mesh). A vertex's first use is the
  // least of its corner positions 3 r + corner, found in parallel; the numbering then takes one
  // pass over the positions that are first uses.
  // Written whole below, by the threads: not zeroed on one thread first.
  triangles_by_patch_ = std::make_unique_for_overwrite<std::array<VertexIndex, 3>[]>(nf);
  advise_huge_pages(triangles_by_patch_.get(), nf * sizeof(std::array<VertexIndex, 3>));
  constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
  STRATA_ASSERT(3 * nf < kUnused, "corner positions are numbered in 32 bits");
  std::vector<std::atomic<std::uint32_t>> first_use(mesh_.vertices.size());
  tbb::parallel_for(std::size_t{0}, first_use.size(),
                    [&](std::size_t v) { first_use[v].store(kUnused, std::memory_order_relaxed); });
  tbb::parallel_for(std::size_t{0}, patches.size(), [&](std::size_t q) {
    Patch& patch = patches[q];
    for (std::uint32_t r = patch.begin; r < patch.end; ++r) {
      const FacetIndex f = by_patch[r].second;
      const auto& tri = mesh_.triangles[f];
      triangles_by_patch_[r] = tri;
      for (int corner = 0; corner < 3; ++corner) {
        const auto position = static_cast<std::uint32_t>(3 * r + static_cast<std::size_t>(corner));
        std::atomic<std::uint32_t>& first = first_use[tri[corner]];
        std::uint32_t seen = first.load(std::memory_order_relaxed);
        while (position < seen &&
               !first.compare_exchange_weak(seen, position, std::memory_order_relaxed)) {
        }
      }
    }
  });
  // Each patch numbers the vertices it uses first, from the count of those in the patches
  // before it: the patches count theirs, and number them, in parallel.
  const auto starts_vertex = std::make_unique_for_overwrite<std::uint8_t[]>(3 * nf);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, 3 * nf, 1 << 16), [&](const auto& r) {
    std::fill(starts_vertex.get() + r.begin(), starts_vertex.get() + r.end(), std::uint8_t{0});
  });
  tbb::parallel_for(std::size_t{0}, first_use.size(), [&](std::size_t v) {
    const std::uint32_t first = first_use[v].load(std::memory_order_relaxed);
    if (first != kUnused) starts_vertex[first] = 1;
  });
  const auto first_uses = [&](const Patch& patch) {
    return std::span(starts_vertex.get() + 3 * std::size_t{patch.begin},
                     3 * std::size_t{patch.end - patch.begin});
  };
  tbb::parallel_for(std::size_t{0}, patches.size(), [&](std::size_t q) {
    const auto starts = first_uses(patches[q]);
    patches[q].vertex_end = static_cast<VertexIndex>(std::count(starts.begin(), starts.end(), 1));
  });
  VertexIndex next = 0;
  for (Patch& patch : patches) {
    patch.vertex_begin = next;
    next += patch.vertex_end;
    patch.vertex_end = next;
  }
  std::vector<VertexIndex> renumbered(mesh_.vertices.size(), kUnused);
  tbb::parallel_for(std::size_t{0}, patches.size(), [&](std::size_t q) {
    const Patch& patch = patches[q];
    const auto starts = first_uses(patch);
    VertexIndex number = patch.vertex_begin;
    for (std::size_t k = 0; k < starts.size(); ++k) {
      if (starts[k] == 0) continue;
      const std::size_t position = 3 * std::size_t{patch.begin} + k;
      renumbered[triangles_by_patch_[position / 3][position % 3]] = number++;
    }
  });
  reserve_huge_pages(vertices_by_patch_, next);
  vertices_by_patch_.resize(next);
  tbb::parallel_for(std::size_t{0}, renumbered.size(), [&](std::size_t v) {
    if (renumbered[v] != kUnused) vertices_by_patch_[renumbered[v]] = mesh_.vertices[v];
  });
  tbb::parallel_for(std::size_t{0}, patches.size(), [&](std::size_t q) {
    Patch& patch = patches[q];
    // Its facets' z-range, from their corners as they are read here.
    patch.zmin = std::numeric_limits<double>::infinity();
    patch.zmax = -std::numeric_limits<double>::infinity();
    for (std::uint32_t r = patch.begin; r < patch.end; ++r) {
      for (VertexIndex& v : triangles_by_patch_[r]) {
        v = renumbered[v];
        const Vec3& p = vertices_by_patch_[v];
        patch.zmin = std::min(patch.zmin, p.z);
        patch.zmax = std::max(patch.zmax, p.z);
        patch.facet_lo = {std::min(patch.facet_lo.x, p.x), std::min(patch.facet_lo.y, p.y), 0.0};
        patch.facet_hi = {std::max(patch.facet_hi.x, p.x), std::max(patch.facet_hi.y, p.y), 0.0};
      }
    }
    for (std::uint32_t v = patch.vertex_begin; v < patch.vertex_end; ++v) {
      const Vec3& p = vertices_by_patch_[v];
      patch.vertex_lo = {std::min(patch.vertex_lo.x, p.x), std::min(patch.vertex_lo.y, p.y), 0.0};
      patch.vertex_hi = {std::max(patch.vertex_hi.x, p.x), std::max(patch.vertex_hi.y, p.y), 0.0};
    }
    // A patch's slab serves every layer: the facets a layer tests are some of the patch's.
    patch.slab =
        slab_of(std::span(triangles_by_patch_.get() + patch.begin, patch.end - patch.begin),
                vertices_by_patch_);
  });
  // A total order (no two patches begin at one facet): any sort gives the one result.
  tbb::parallel_sort(patches.begin(), patches.end(), [](const Patch& a, const Patch& b) {
    return a.zmin != b.zmin ? a.zmin < b.zmin : a.begin < b.begin;
  });
  patches_ = std::move(patches);
  zmin_sorted_.resize(patches_.size());
  zmax_prefix_max_.resize(patches_.size());
  double running = -std::numeric_limits<double>::infinity();
  for (std::size_t q = 0; q < patches_.size(); ++q) {
    zmin_sorted_[q] = patches_[q].zmin;
    running = std::max(running, patches_[q].zmax);
    zmax_prefix_max_[q] = running;
  }
}

std::uint32_t BoundaryShell::reach_layers(const GridSpec& grid, ShellMode mode,
                                          double thickness_mm) {
  if (mode != ShellMode::Layers) return 1;
  const double n = std::floor(thickness_mm / std::min({grid.dx, grid.dy, grid.dz}));
  return static_cast<std::uint32_t>(std::clamp(n, 1.0, 255.0));
}

BoundaryShell::ClassCounts BoundaryShell::classify(std::uint32_t k, const SolidLayerLookup& solid,
                                                   std::span<CellClass> out) const {
  const SolidRows* here = solid(k);
  STRATA_ASSERT(here != nullptr && here->nx() == grid_.nx && here->ny() == grid_.ny,
                "the layer classified has its solid cells");
  STRATA_ASSERT(out.size() == grid_.cells_per_layer(), "a class for each cell of the layer");
  // Solid cells, and the first ring: a solid cell with an empty 6-neighbour.
  std::uint64_t boundary = first_ring(*here, solid(static_cast<std::int64_t>(k) - 1),
                                      solid(static_cast<std::int64_t>(k) + 1), out.data());
  if (mode_ == ShellMode::Distance) {
    boundary += mark_near_surface(k, out);
  } else if (rings_ > 1) {
    boundary += mark_rings(k, solid, out);
  }
  return {here->count() - boundary, boundary};
}

std::uint64_t BoundaryShell::mark_near_surface(std::uint32_t k, std::span<CellClass> out) const {
  const double t = thickness_mm_;
  if (!(t > 0.0) || patches_.empty()) return 0;
  std::uint64_t marked = 0;
  const double z = grid_.zk(k);
  // Facets whose z-range meets [z - t, z + t]; the slab is widened a little so that rounding in
  // these double bounds can only add candidates, never drop one (the predicate decides).
  const double slack = t * 1e-9 + std::fabs(z) * 1e-15;
  const double z_lo = z - t - slack;
  const double z_hi = z + t + slack;
  const std::size_t end =
      std::upper_bound(zmin_sorted_.begin(), zmin_sorted_.end(), z_hi) - zmin_sorted_.begin();
  // Skip the leading patches that all end below the slab (their running max of zmax is too low).
  const std::size_t begin =
      std::lower_bound(zmax_prefix_max_.begin(), zmax_prefix_max_.begin() + end, z_lo) -
      zmax_prefix_max_.begin();
  const GridAxis x_axis(grid_.x0, grid_.dx, grid_.nx);
  const GridAxis y_axis(grid_.y0, grid_.dy, grid_.ny);
  // First every patch's vertices, so that the facets below test only the cells no vertex of any
  // patch is closer than t to (a patch's box reaches into its neighbours' shell).
  for (std::size_t q = begin; q < end; ++q) {
    const Patch& patch = patches_[q];
    if (patch.zmax < z_lo) continue;
    const auto [pi0, pi1] = x_axis.centres_within(patch.vertex_lo.x - t, patch.vertex_hi.x + t);
    const auto [pj0, pj1] = y_axis.centres_within(patch.vertex_lo.y - t, patch.vertex_hi.y + t);
    const auto vertices = std::span(vertices_by_patch_)
                              .subspan(patch.vertex_begin, patch.vertex_end - patch.vertex_begin);
    // A box wider than a word or taller than the words kept (a shell many cells thick) is taken
    // a tile of them at a time.
    const auto mark_tile = [&](std::int64_t ti0, std::int64_t ti1, std::int64_t tj0,
                               std::int64_t rows) {
      std::uint64_t interior[kMaxPatchRows];
      gather_interior(out, ti0, ti1, tj0, rows, interior);
      if (std::any_of(interior, interior + rows, [](std::uint64_t w) { return w != 0; })) {
        marked += mark_near_vertices(vertices, z, ti0, ti1, tj0, rows, interior, out);
      }
    };
    for_each_tile(pi0, pi1, pj0, pj1, mark_tile);
  }
  constexpr double kNarrowFromCells = 8.0;
  // Every facet's reach lies within the box of the patch's corners widened by t (the margin
  // only widens it; a facet found outside is tested as before, below).
  const double reach = t * (1.0 + 1e-6);
  std::vector<FacetReach> small;
  double box[4];
  Candidates candidates;
  FewCandidate few_points[kFewCandidates];
  const double t2_far = far_squared();
  for (std::size_t q = begin; q < end; ++q) {
    const Patch& patch = patches_[q];
    if (patch.zmax < z_lo) continue;
    // The patch's candidates first: where the vertices and the slab leave none (more than half
    // of the patches of a layer on a fine mesh), no facet of it is looked at.
    const auto [ci0, ci1] =
        x_axis.cells_reaching(patch.facet_lo.x - reach, patch.facet_hi.x + reach);
    const auto [cj0, cj1] =
        y_axis.cells_reaching(patch.facet_lo.y - reach, patch.facet_hi.y + reach);
    if (ci0 > ci1 || cj0 > cj1) continue;
    bool gathered = ci1 - ci0 < 64 && cj1 - cj0 < kMaxPatchRows;
    // When the candidates are very few (as in many patches that have any), a facet whose box
    // in the slab's frame is t from each of them marks nothing, and is passed by before its
    // reach in the layer is worked out. The candidates are every cell any facet of the patch
    // could still mark, so this holds for wide facets too.
    std::size_t few = 0;
    if (gathered) {
      gather_candidates(ci0, ci1, cj0, cj1 - cj0 + 1, patch.slab, z, out, candidates);
      if (candidates.none()) continue;
      if (patch.slab.usable) few = list_few_candidates(candidates, z, few_points);
    }
    small.clear();
    for (std::uint32_t r = patch.begin; r < patch.end; ++r) {
      const auto& tri = triangles_by_patch_[r];
      const Vec3& a = vertices_by_patch_[tri[0]];
      const Vec3& b = vertices_by_patch_[tri[1]];
      const Vec3& c = vertices_by_patch_[tri[2]];
      const double z_min = std::min({a.z, b.z, c.z});
      const double z_max = std::max({a.z, b.z, c.z});
      if (z_max < z_lo || z_min > z_hi) continue;
      if (few != 0) {
        // The facet's box in x, y and z first (its corners' own coordinates, no rounding but
        // that of the distance's few operations, which the margins cover), then its box in
        // the slab's frame, which is tighter for a tilted facet but takes nine products a
        // corner.
        const double box_lo[3] = {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), z_min};
        const double box_hi[3] = {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), z_max};
        const bool near_box = std::any_of(few_points, few_points + few, [&](const FewCandidate& p) {
          return !beyond_box(p.centre, box_lo, box_hi, t2_far);
        });
        if (!near_box) continue;
        const Vec3* corners[3] = {&a, &b, &c};
        const FrameBox frame_box = facet_frame_box(patch.slab.axis, patch.slab.margin, corners);
        const bool near_frame_box =
            std::any_of(few_points, few_points + few, [&](const FewCandidate& p) {
              return !beyond_frame_box(p.frame, frame_box.lo, frame_box.hi, t2_far);
            });
        if (!near_frame_box) continue;
      }
      if (!slab_footprint(a, b, c, z_lo, z_hi, box)) continue;
      // A point closer than t to the facet is closer than sqrt(t^2 - gap^2) to it across the
      // layer, gap being the facet's z-distance from the layer's plane: the far layers of the
      // slab search a narrower box. The margins only widen it.
      const double gap = z < z_min ? z_min - z : (z > z_max ? z - z_max : 0.0);
      const double across = t * t - gap * gap * (1.0 - 1e-12);
      const double grow = across > 0.0 ? std::sqrt(across) * (1.0 + 1e-9) + t * 1e-9 : t * 1e-9;
      const auto [i0_box, i1_box] = x_axis.cells_reaching(box[0] - grow, box[2] + grow);
      const auto [j0, j1] = y_axis.cells_reaching(box[1] - grow, box[3] + grow);
      if (i0_box > i1_box || j0 > j1) continue;
      // Small facets are tested together, cell by cell over the patch's box (below): a cell
      // is visited once for the patch rather than once for each of its facets. Narrowing a row
      // to the stretch near the facet pays only on wide facets.
      if ((box[2] - box[0]) * x_axis.inv_d < kNarrowFromCells) {
        small.push_back({{&a, &b, &c}, i0_box, i1_box, j0, j1});
        gathered = gathered && candidates.hold(small.back());
        continue;
      }
      marked += mark_near_wide_facet(a, b, c, z, box, grow, i0_box, i1_box, j0, j1, out);
      // The candidates no longer show the cells it marked.
      gathered = false;
    }
    if (small.empty()) continue;
    if (gathered) {
      marked += test_candidates(small, patch.slab, candidates, z, out);
    } else {
      marked += mark_near_small_facets(small, patch.slab, z, out);
    }
  }
  return marked;
}

std::uint64_t BoundaryShell::mark_near_small_facets(std::span<const FacetReach> facets,
                                                    const Slab& slab, double z,
                                                    std::span<CellClass> out) const {
  std::int64_t pi0 = facets[0].i0, pi1 = facets[0].i1, pj0 = facets[0].j0, pj1 = facets[0].j1;
  for (const FacetReach& m : facets) {
    pi0 = std::min(pi0, m.i0);
    pi1 = std::max(pi1, m.i1);
    pj0 = std::min(pj0, m.j0);
    pj1 = std::max(pj1, m.j1);
  }
  // A tile of words at a time, each facet over the part of its box in the tile.
  Candidates candidates;
  std::vector<FacetReach> in_tile;
  std::uint64_t marked = 0;
  const auto test_tile = [&](std::int64_t ti0, std::int64_t ti1, std::int64_t tj0,
                             std::int64_t rows) {
    gather_candidates(ti0, ti1, tj0, rows, slab, z, out, candidates);
    if (candidates.none()) return;
    const std::int64_t tj1 = tj0 + rows - 1;
    in_tile.clear();
    for (const FacetReach& f : facets) {
      if (f.i1 < ti0 || f.i0 > ti1 || f.j1 < tj0 || f.j0 > tj1) continue;
      in_tile.push_back({{f.corner[0], f.corner[1], f.corner[2]},
                         std::max(f.i0, ti0),
                         std::min(f.i1, ti1),
                         std::max(f.j0, tj0),
                         std::min(f.j1, tj1)});
    }
    marked += test_candidates(in_tile, slab, candidates, z, out);
  };
  for_each_tile(pi0, pi1, pj0, pj1, test_tile);
  return marked;
}

void BoundaryShell::gather_candidates(std::int64_t pi0, std::int64_t pi1, std::int64_t pj0,
                                      std::int64_t rows, const Slab& slab, double z,
                                      std::span<const CellClass> out,
                                      Candidates& candidates) const {
  const double t = thickness_mm_;
  candidates.pi0 = pi0;
  candidates.pj0 = pj0;
  candidates.rows = rows;
  // The interior cells of the box, a bit each (bit i - pi0 of row j - pj0): a cell is read once
  // for the patch, and each facet visits only the interior cells of its box.
  std::uint64_t* interior = candidates.interior;
  gather_interior(out, pi0, pi1, pj0, rows, interior);
  // Cells beyond the slab of the patch's facets, widened by t, are farther than t from each of
  // them: most of the patch's box past the shell, which no facet then tests.
  if (slab.usable) {
    const Vec3& n = slab.n();
    const double lo = slab.lo[0] - t;
    const double hi = slab.hi[0] + t;
    const double t2_far = far_squared();
    const GridAxis x_axis(grid_.x0, grid_.dx, grid_.nx);
    // A product rather than a quotient a row: a few ulps of the bounds, far inside the margin
    // cells_reaching adds (2e-12 of them).
    const double inv_nx = 1.0 / n.x;
    for (std::int64_t r = 0; r < rows; ++r) {
      if (interior[r] == 0) continue;
      const double yc = grid_.yc(static_cast<std::uint32_t>(pj0 + r));
      // n · p = n.x x + rest along the row.
      const double rest = n.y * yc + n.z * z;
      const double rest_error = 1e-9 * (std::fabs(yc) + std::fabs(z) + 1.0);
      std::int64_t i0 = pi0;
      std::int64_t i1 = pi1;
      if (std::fabs(n.x) < 1e-6) {
        // Nearly across the row: the row is in the slab or not as a whole (|n.x x| adds at most
        // 1e-6 of the coordinates, inside the bound below).
        const double spread = 1e-6 * (std::fabs(grid_.xc(static_cast<std::uint32_t>(pi0))) +
                                      std::fabs(grid_.xc(static_cast<std::uint32_t>(pi1))));
        if (rest + spread + rest_error < lo || rest - spread - rest_error > hi) i1 = i0 - 1;
      } else {
        double x_lo = (lo - rest_error - rest) * inv_nx;
        double x_hi = (hi + rest_error - rest) * inv_nx;
        if (x_lo > x_hi) std::swap(x_lo, x_hi);
        const auto [a0, a1] = x_axis.cells_reaching(x_lo, x_hi);
        i0 = std::max(i0, a0);
        i1 = std::min(i1, a1);
      }
      std::uint64_t keep = 0;
      if (i0 <= i1) {
        keep = run_bits(i0, i1, pi0);
      }
      interior[r] &= keep;
      // The box of the frame: a cell beside the patch, within the slab but past its facets'
      // extent along the tangents (near a neighbour's facets), is dropped here. The frame
      // coordinates of those kept serve each facet's box too (test_candidates).
      for (std::uint64_t left = interior[r]; left != 0; left &= left - 1) {
        const int bit = std::countr_zero(left);
        FramePoint& p = candidates.frame[static_cast<std::size_t>(r) * 64 + bit];
        p = frame_point(slab.axis, cell_centre(pi0 + bit, pj0 + r, z));
        if (beyond_frame_box(p, slab.lo, slab.hi, t2_far)) {
          interior[r] &= ~(std::uint64_t{1} << bit);
        }
      }
    }
  }
  // The kept rows that still hold an interior cell: a facet visits only those (the vertices
  // leave none in many patches).
  candidates.first_row = 0;
  candidates.last_row = rows - 1;
  while (candidates.first_row < rows && interior[candidates.first_row] == 0) {
    ++candidates.first_row;
  }
  while (candidates.last_row >= candidates.first_row && interior[candidates.last_row] == 0) {
    --candidates.last_row;
  }
}

std::size_t BoundaryShell::list_few_candidates(const Candidates& candidates, double z,
                                               FewCandidate (&points)[kFewCandidates]) const {
  std::size_t count = 0;
  for (std::int64_t r = candidates.first_row; r <= candidates.last_row; ++r) {
    for (std::uint64_t left = candidates.interior[r]; left != 0; left &= left - 1) {
      if (count == kFewCandidates) return 0;
      const int bit = std::countr_zero(left);
      points[count++] = {candidates.frame[static_cast<std::size_t>(r) * 64 + bit],
                         cell_centre(candidates.pi0 + bit, candidates.pj0 + r, z)};
    }
  }
  return count;
}

std::uint64_t BoundaryShell::test_candidates(std::span<const FacetReach> facets, const Slab& slab,
                                             Candidates& candidates, double z,
                                             std::span<CellClass> out) const {
  const std::uint32_t nx = grid_.nx;
  const std::int64_t pi0 = candidates.pi0;
  const std::int64_t pj0 = candidates.pj0;
  std::uint64_t* interior = candidates.interior;
  // A facet's box in the frame of the patch's slab, where the patch's facets lie flat: most
  // candidates beside a facet are farther than t from that box, and are passed by without the
  // facet's filter, whose set-up costs more than many such tests.
  const double t2_far = far_squared();
  std::optional<detail::TriangleDistanceFilter> filter;
  FrameBox frame_box{};
  std::uint64_t marked = 0;
  for (const FacetReach& facet : facets) {
    filter.reset();
    bool framed = false;
    const std::uint64_t in_box = run_bits(facet.i0, facet.i1, pi0);
    const std::int64_t j_end = std::min(facet.j1, pj0 + candidates.last_row);
    for (std::int64_t j = std::max(facet.j0, pj0 + candidates.first_row); j <= j_end; ++j) {
      const std::int64_t r = j - pj0;
      std::uint64_t left = interior[r] & in_box;
      while (left != 0) {
        const int bit = std::countr_zero(left);
        left &= left - 1;
        const std::int64_t i = pi0 + bit;
        if (slab.usable) {
          if (!framed) {
            frame_box = facet_frame_box(slab.axis, slab.margin, facet.corner);
            framed = true;
          }
          const FramePoint& q = candidates.frame[static_cast<std::size_t>(r) * 64 + bit];
          if (beyond_frame_box(q, frame_box.lo, frame_box.hi, t2_far)) continue;
        }
        const Vec3 p = cell_centre(i, j, z);
        if (facet_closer_than(filter, facet.corner, thickness_mm_, p)) {
          out[static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(i)] = CellClass::Boundary;
          interior[r] &= ~(std::uint64_t{1} << bit);
          ++marked;
        }
      }
    }
  }
  return marked;
}

void BoundaryShell::gather_interior(std::span<const CellClass> cells, std::int64_t pi0,
                                    std::int64_t pi1, std::int64_t pj0, std::int64_t rows,
                                    std::uint64_t* interior) const {
  const std::uint64_t columns = run_bits(pi0, pi1, pi0);
  for (std::int64_t r = 0; r < rows; ++r) {
    const std::size_t at =
        static_cast<std::size_t>(pj0 + r) * grid_.nx + static_cast<std::size_t>(pi0);
    interior[r] = interior_bits(cells.data() + at, std::min<std::size_t>(64, cells.size() - at),
                                static_cast<std::size_t>(pi1 - pi0 + 1)) &
                  columns;
  }
}

std::uint64_t BoundaryShell::mark_near_vertices(std::span<const Vec3> vertices, double z,
                                                std::int64_t pi0, std::int64_t pi1,
                                                std::int64_t pj0, std::int64_t rows,
                                                std::uint64_t* interior,
                                                std::span<CellClass> out) const {
  const double t = thickness_mm_;
  const double t2 = t * t;
  const std::uint32_t nx = grid_.nx;
  const GridAxis x_axis(grid_.x0, grid_.dx, grid_.nx);
  const GridAxis y_axis(grid_.y0, grid_.dy, grid_.ny);
  // |p - v|^2 is a sum of three squares of rounded differences: its computed value is within
  // 8 u of the true one, and t * t within u of t^2. The 1e-12 margins cover both by far, so
  // this holds only where the true |p - v| is less than t. The ranges of rows and cells are
  // guesses: the first and last interior cell of a run are checked, and the distance is convex
  // along the row, so every cell between them is closer too; a cell a guess leaves out is left
  // to the facets.
  const double accept_below = t2 * (1.0 - 1e-12);
  const auto certainly_closer = [&](double dx, double dyz2) {
    return (dx * dx + dyz2) * (1.0 + 1e-12) < accept_below;
  };
  std::uint64_t marked = 0;
  for (const Vec3& v : vertices) {
    const double dz = z - v.z;
    const double dz2 = dz * dz;
    if (!(dz2 < t2)) continue;
    const double reach = std::sqrt(t2 - dz2);
    const auto [j0, j1] = y_axis.centres_within(v.y - reach, v.y + reach);
    const std::int64_t r0 = std::max<std::int64_t>(j0 - pj0, 0);
    const std::int64_t r1 = std::min<std::int64_t>(j1 - pj0, rows - 1);
    if (r0 > r1) continue;
    const auto [c0, c1] = x_axis.centres_within(v.x - reach, v.x + reach);
    const std::int64_t b0 = std::max(c0, pi0);
    const std::int64_t b1 = std::min(c1, pi1);
    if (b0 > b1) continue;
    // The columns the vertex reaches: a row with no interior cell among them is passed by
    // (most rows, once the first vertices of the patch have marked their cells).
    const std::uint64_t reached = run_bits(b0, b1, pi0);
    for (std::int64_t r = r0; r <= r1; ++r) {
      if ((interior[r] & reached) == 0) continue;
      const double dy = grid_.yc(static_cast<std::uint32_t>(pj0 + r)) - v.y;
      const double dyz2 = dy * dy + dz2;
      if (!(dyz2 < t2)) continue;
      // The interior cells the vertex reaches in the layer, its outermost ones dropped until both
      // ends are certainly closer: a row where the vertex reaches no interior cell costs no check.
      std::uint64_t hits = interior[r] & reached;
      const auto closer_at = [&](int bit) {
        return certainly_closer(grid_.xc(static_cast<std::uint32_t>(pi0 + bit)) - v.x, dyz2);
      };
      while (hits != 0 && !closer_at(std::countr_zero(hits))) hits &= hits - 1;
      while (hits != 0 && !closer_at(63 - std::countl_zero(hits))) {
        hits &= ~(std::uint64_t{1} << (63 - std::countl_zero(hits)));
      }
      if (hits == 0) continue;
      interior[r] &= ~hits;
      // Counted as they are marked: std::popcount is a library call on the baseline x86-64.
      CellClass* row = out.data() + static_cast<std::size_t>(pj0 + r) * nx;
      while (hits != 0) {
        row[pi0 + std::countr_zero(hits)] = CellClass::Boundary;
        hits &= hits - 1;
        ++marked;
      }
    }
  }
  return marked;
}

std::uint64_t BoundaryShell::mark_near_wide_facet(const Vec3& a, const Vec3& b, const Vec3& c,
                                                  double z, const double box[4], double grow,
                                                  std::int64_t i0_box, std::int64_t i1_box,
                                                  std::int64_t j0, std::int64_t j1,
                                                  std::span<CellClass> out) const {
  const double t = thickness_mm_;
  const std::uint32_t nx = grid_.nx;
  const detail::TriangleDistanceFilter filter(a, b, c, t);
  const GridAxis x_axis(grid_.x0, grid_.dx, grid_.nx);
  detail::TriangleDistanceFilter::RowBound bounds[detail::TriangleDistanceFilter::kMaxRowBounds];
  const int bound_count =
      filter.row_bounds(z, box[1] - grow, box[3] + grow, box[0] - grow, box[2] + grow, bounds);
  std::uint64_t marked = 0;
  for (std::int64_t j = j0; j <= j1; ++j) {
    const double yc = grid_.yc(static_cast<std::uint32_t>(j));
    double x_lo = box[0] - grow;
    double x_hi = box[2] + grow;
    for (int q = 0; q < bound_count; ++q) bounds[q].clip(yc, x_lo, x_hi);
    if (!(x_lo <= x_hi)) continue;
    const auto [row_i0, row_i1] = x_axis.cells_reaching(x_lo, x_hi);
    const std::int64_t i0 = std::max(i0_box, row_i0);
    const std::int64_t i1 = std::min(i1_box, row_i1);
    CellClass* row = out.data() + static_cast<std::size_t>(j) * nx;
    const auto closer = [&](std::int64_t i) {
      return filter.closer_than(Vec3{grid_.xc(static_cast<std::uint32_t>(i)), yc, z});
    };
    // The distance to a triangle is convex along the row, so the centres closer than t form
    // one run: find its first and last interior cell by the exact test, from either end, and
    // every interior cell between them is closer too.
    std::int64_t first_closer = i0;
    while (first_closer <= i1 &&
           (row[first_closer] != CellClass::Interior || !closer(first_closer))) {
      ++first_closer;
    }
    if (first_closer > i1) continue;
    std::int64_t last_closer = i1;
    while (last_closer > first_closer &&
           (row[last_closer] != CellClass::Interior || !closer(last_closer))) {
      --last_closer;
    }
    for (std::int64_t i = first_closer; i <= last_closer; ++i) {
      if (row[i] == CellClass::Interior) {
        row[i] = CellClass::Boundary;
        ++marked;
      }
    }
  }
  return marked;
}

std::uint64_t BoundaryShell::mark_rings(std::uint32_t k, const SolidLayerLookup& solid,
                                        std::span<CellClass> out) const {
  // A solid cell's ring is its count of 6-neighbour steps to the nearest empty cell (outside the
  // grid counts as empty): a shortest path through solid cells to the first ring and one step
  // out. The straight staircase toward the nearest empty cell is such a path, since each cell on
  // it is closer to the cell than that empty cell, so solid. So the ring is the city-block
  // distance to the nearest empty cell, and city-block distance is a sum over the axes: it is
  // found one axis at a time, along z over the n layers on either side, then along the rows and
  // the columns of this layer. Distances are capped at n + 1, which n = 255 still fits in 16
  // bits; a cell is in the shell when its distance is at most n.
  const std::uint32_t n = rings_;
  const std::uint32_t nx = grid_.nx;
  const std::uint32_t ny = grid_.ny;
  const std::size_t cells = grid_.cells_per_layer();
  const auto cap = static_cast<std::uint16_t>(n + 1);
  std::vector<std::uint16_t> distance(cells, 0);
  std::uint16_t* dist = distance.data();
  // Along z: 0 on an empty cell, else the nearest layer within n where the column is empty (a
  // layer beyond the grid is empty throughout).
  const SolidRows& here = *solid(k);
  for (std::uint32_t j = 0; j < ny; ++j) {
    std::uint16_t* row = dist + std::size_t{j} * nx;
    for (const SolidRun& r : here.row(j)) std::fill(row + r.begin, row + r.end, cap);
  }
  std::vector<SolidRun> closed;
  for (std::uint32_t d = 1; d <= n; ++d) {
    const SolidRows* below = solid(static_cast<std::int64_t>(k) - d);
    const SolidRows* above = solid(static_cast<std::int64_t>(k) + d);
    const auto step = static_cast<std::uint16_t>(d);
    if (below == nullptr || above == nullptr) {
      for (std::size_t c = 0; c < cells; ++c) dist[c] = std::min(dist[c], step);
      break;  // nothing farther is nearer
    }
    // Open where either layer is empty: between the runs solid in both.
    for (std::uint32_t j = 0; j < ny; ++j) {
      std::uint16_t* row = dist + std::size_t{j} * nx;
      intersect_runs(below->row(j), above->row(j), closed);
      std::uint32_t at = 0;
      const auto open_until = [&](std::uint32_t end) {
        for (; at < end; ++at) row[at] = std::min(row[at], step);
      };
      for (const SolidRun& r : closed) {
        open_until(r.begin);
        at = r.end;
      }
      open_until(nx);
    }
  }
  // Along each row, both ways; the cells beyond either end are empty.
  for (std::uint32_t j = 0; j < ny; ++j) {
    std::uint16_t* row = dist + std::size_t{j} * nx;
    std::uint16_t next = 1;
    for (std::uint32_t i = 0; i < nx; ++i) {
      row[i] = std::min(row[i], next);
      next = static_cast<std::uint16_t>(row[i] + 1);
    }
    next = 1;
    for (std::uint32_t i = nx; i-- > 0;) {
      row[i] = std::min(row[i], next);
      next = static_cast<std::uint16_t>(row[i] + 1);
    }
  }
  // Along each column, both ways, a row at a time (many cells a step); the rows beyond either
  // end are empty.
  const auto relax_row = [&](std::uint16_t* row, const std::uint16_t* from) {
    for (std::uint32_t i = 0; i < nx; ++i) {
      row[i] = std::min(row[i], static_cast<std::uint16_t>(from[i] + 1));
    }
  };
  const auto relax_edge_row = [&](std::uint16_t* row) {
    for (std::uint32_t i = 0; i < nx; ++i) row[i] = std::min<std::uint16_t>(row[i], 1);
  };
  relax_edge_row(dist);
  for (std::uint32_t j = 1; j < ny; ++j) {
    relax_row(dist + std::size_t{j} * nx, dist + std::size_t{j - 1} * nx);
  }
  relax_edge_row(dist + std::size_t{ny - 1} * nx);
  for (std::uint32_t j = ny - 1; j-- > 0;) {
    relax_row(dist + std::size_t{j} * nx, dist + std::size_t{j + 1} * nx);
  }
  std::uint64_t marked = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    if (out[c] == CellClass::Interior && dist[c] <= n) {
      out[c] = CellClass::Boundary;
      ++marked;
    }
  }
  return marked;
}

}  // namespace strata
