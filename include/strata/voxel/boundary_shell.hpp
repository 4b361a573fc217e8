#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "strata/fill/solid_rows.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"
#include "strata/voxel/cell_class.hpp"

namespace strata {

/// Returns the solid cells of layer k (nx by ny), or nullptr when k lies outside the grid (outside
/// counts as empty). Layers within reach_layers() of the one being classified must be available.
using SolidLayerLookup = std::function<const SolidRows*(std::int64_t k)>;

/// Marks the boundary shell (SPEC §2). A solid cell is Boundary when one of its 6-neighbours is
/// empty, or when it lies in the surface layer of thickness t:
/// - Distance: its centre is closer than t to the mesh surface (true Euclidean distance to the
///   facets, squared distances compared with t^2).
/// - Layers: it is within n = int(t / d) rings of cells (d the smallest cell size), the first ring
///   being the cells with an empty 6-neighbour, each further ring the solid 6-neighbours of the
///   one before.
/// The mesh and grid must outlive the marker. classify() is safe to call from several threads.
class BoundaryShell {
 public:
  /// Prepares the marker of a shell `thickness_mm` thick (Distance mode: groups the facets into
  /// patches of neighbours and sorts the patches by z).
  BoundaryShell(const IndexedMesh& mesh, const GridSpec& grid, ShellMode mode, double thickness_mm);

  /// How many layers on each side of k classify(k) reads.
  std::uint32_t reach_layers() const { return reach_; }
  /// The same, known before the marker is built (a slice plans its layers while it is).
  static std::uint32_t reach_layers(const GridSpec& grid, ShellMode mode, double thickness_mm);
  /// The ring count n of the Layers mode (at least 1: cells that touch the outside are always
  /// boundary).
  std::uint32_t rings() const { return rings_; }
  /// True when the Layers mode had to take the smallest of unequal cell sizes.
  bool unequal_cell_sizes() const { return unequal_sizes_; }

  /// The cells of each solid class in a layer.
  struct ClassCounts {
    std::uint64_t interior = 0;
    std::uint64_t boundary = 0;
  };
  /// Classifies layer k into `out` (nx * ny classes, row-major; each is written, so it need not
  /// be cleared first), and counts its classes (from the runs and the cells the shell marks,
  /// without another pass over the layer).
  ClassCounts classify(std::uint32_t k, const SolidLayerLookup& solid,
                       std::span<CellClass> out) const;

 private:
  // The markers below return how many Interior cells they made Boundary.
  std::uint64_t mark_near_surface(std::uint32_t k, std::span<CellClass> out) const;
  /// A facet, with the box of cells of a layer it can reach.
  struct FacetReach {
    const Vec3* corner[3];
    std::int64_t i0, i1, j0, j1;
  };
  /// The rows of a patch's box kept as bit words (a row's interior cells, 64 at most).
  static constexpr std::int64_t kMaxPatchRows = 64;
  /// A slab across a unit direction n that holds a set of triangles: every point q of them has
  /// lo <= n · q <= hi. A point p with n · p outside [lo - t, hi + t] is farther than t from each
  /// of them (|n · (p - q)| <= |p - q|), whatever their shape.
  /// With two unit tangents u, v completing n to a frame, the triangles also lie within the box
  /// [lo[a], hi[a]] along each axis a of (n, u, v): a point's distance to that box bounds its
  /// distance to each triangle from below.
  struct Slab {
    Vec3 axis[3] = {};  ///< n, u, v
    double lo[3] = {}, hi[3] = {};
    /// How far lo and hi were widened (1e-9 of the triangles' coordinates' scale); a box of
    /// some of the triangles in the frame is widened by as much.
    double margin = 0.0;
    bool usable = false;
    const Vec3& n() const { return axis[0]; }
  };
  static Slab slab_of(std::span<const std::array<VertexIndex, 3>> triangles,
                      const std::vector<Vec3>& vertices);
  /// A point's coordinates along the axes of a slab's frame, and the bound 1e-9 of its scale
  /// that each is taken as uncertain by (far above the dot products' rounding).
  struct FramePoint {
    double q[3];
    double error;
  };
  static FramePoint frame_point(const Vec3 (&axes)[3], const Vec3& p);
  /// Whether the point is certainly at least t from the box [lo[a], hi[a]] of the frame (t2_far
  /// being t^2 widened by 1e-9): then it is at least t from every facet inside it (a slab's box,
  /// a facet's). Each term of the squared distance is taken from below by the point's error. A
  /// sum that overflowed (coordinates near the largest doubles) proves nothing.
  static bool beyond_frame_box(const FramePoint& p, const double (&lo)[3], const double (&hi)[3],
                               double t2_far);
  /// t^2 widened by 1e-9: the square a box's distance is held to (beyond_frame_box).
  double far_squared() const { return thickness_mm_ * thickness_mm_ * (1.0 + 1e-9); }
  /// The cells of a box of a layer that a patch's facets may still have to mark: its interior
  /// cells (bit i - pi0 of word j - pj0) within the slab of the patch's facets widened by t.
  struct Candidates {
    std::int64_t pi0 = 0, pj0 = 0, rows = 0;
    std::int64_t first_row = 0, last_row = -1;  ///< the words that hold a bit
    std::uint64_t interior[kMaxPatchRows];
    /// A candidate's centre in the slab's frame (at 64 r + bit), when the slab is usable.
    std::unique_ptr<FramePoint[]> frame =
        std::make_unique_for_overwrite<FramePoint[]>(kMaxPatchRows * 64);
    bool none() const { return first_row > last_row; }
    /// Whether a facet's box of cells lies within the words.
    bool hold(const FacetReach& facet) const {
      return facet.i0 >= pi0 && facet.i1 < pi0 + 64 && facet.j0 >= pj0 && facet.j1 < pj0 + rows;
    }
  };
  /// A candidate's centre, and its coordinates in the slab's frame.
  struct FewCandidate {
    FramePoint frame;
    Vec3 centre;
  };
  /// The candidates of layer z, in `points`, when there are at most kFewCandidates: their
  /// count, or 0 when there are more.
  static constexpr std::size_t kFewCandidates = 4;
  std::size_t list_few_candidates(const Candidates& candidates, double z,
                                  FewCandidate (&points)[kFewCandidates]) const;
  /// Calls visit(i0, i1, j0, rows) for the tiles of at most 64 columns by kMaxPatchRows rows
  /// that cover columns pi0 .. pi1 and rows pj0 .. pj1 (none when either range is empty).
  template <class Visit>
  static void for_each_tile(std::int64_t pi0, std::int64_t pi1, std::int64_t pj0, std::int64_t pj1,
                            const Visit& visit) {
    for (std::int64_t j0 = pj0; j0 <= pj1; j0 += kMaxPatchRows) {
      const std::int64_t rows = std::min(pj1 - j0 + 1, kMaxPatchRows);
      for (std::int64_t i0 = pi0; i0 <= pi1; i0 += 64) visit(i0, std::min(pi1, i0 + 63), j0, rows);
    }
  }
  /// The small facets of a patch, tested over the box they reach together, a tile at a time;
  /// `slab` holds the patch's facets.
  std::uint64_t mark_near_small_facets(std::span<const FacetReach> facets, const Slab& slab,
                                       double z, std::span<CellClass> out) const;
  /// The candidates of columns pi0 .. pi1 (at most 64) and `rows` rows from pj0.
  void gather_candidates(std::int64_t pi0, std::int64_t pi1, std::int64_t pj0, std::int64_t rows,
                         const Slab& slab, double z, std::span<const CellClass> out,
                         Candidates& candidates) const;
  /// Tests the facets on the candidates of their boxes (boxes that `candidates` hold), marking
  /// those closer than t and clearing their bits.
  std::uint64_t test_candidates(std::span<const FacetReach> facets, const Slab& slab,
                                Candidates& candidates, double z, std::span<CellClass> out) const;
  Vec3 cell_centre(std::int64_t i, std::int64_t j, double z) const {
    return {grid_.xc(static_cast<std::uint32_t>(i)), grid_.yc(static_cast<std::uint32_t>(j)), z};
  }
  /// The interior cells of rows pj0 .. pj0 + rows - 1, columns pi0 .. pi1 (at most 64), as bits.
  void gather_interior(std::span<const CellClass> cells, std::int64_t pi0, std::int64_t pi1,
                       std::int64_t pj0, std::int64_t rows, std::uint64_t* interior) const;
  /// Marks the interior cells (bits of `interior`, row r of the box from row pj0, bit i - pi0)
  /// certainly closer than t to one of `vertices`, and clears their bits: they are closer than
  /// t to the surface, and no facet need test them.
  std::uint64_t mark_near_vertices(std::span<const Vec3> vertices, double z, std::int64_t pi0,
                                   std::int64_t pi1, std::int64_t pj0, std::int64_t rows,
                                   std::uint64_t* interior, std::span<CellClass> out) const;
  /// A facet at least kNarrowFromCells wide: each row narrowed to the stretch near the facet.
  std::uint64_t mark_near_wide_facet(const Vec3& a, const Vec3& b, const Vec3& c, double z,
                                     const double box[4], double grow, std::int64_t i0_box,
                                     std::int64_t i1_box, std::int64_t j0, std::int64_t j1,
                                     std::span<CellClass> out) const;
  std::uint64_t mark_rings(std::uint32_t k, const SolidLayerLookup& solid,
                           std::span<CellClass> out) const;

  const IndexedMesh& mesh_;
  GridSpec grid_;
  ShellMode mode_;
  double thickness_mm_;
  std::uint32_t reach_;
  std::uint32_t rings_ = 1;
  bool unequal_sizes_ = false;
  // Distance mode: the facets in patches of neighbours (their centroids in one box of
  // kPatchCells by kPatchCells cells by kPatchLayers layers), the patches sorted by their lowest z
  // with the running maximum of their highest z, so the patches within t of a plane are found by
  // two binary searches.
  static constexpr double kPatchCells = 16.0;
  static constexpr double kPatchLayers = 4.0;
  struct Patch {
    std::uint32_t begin = 0, end = 0;  ///< in triangles_by_patch_
    /// The vertices its facets use first (in vertices_by_patch_): each vertex is in one patch.
    std::uint32_t vertex_begin = 0, vertex_end = 0;
    /// The x-y box of those vertices (z unused); empty when there are none.
    Vec3 vertex_lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                   0.0};
    Vec3 vertex_hi{-std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(), 0.0};
    /// The x-y box of all its facets' corners (z unused).
    Vec3 facet_lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                  0.0};
    Vec3 facet_hi{-std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity(), 0.0};
    double zmin = 0.0, zmax = 0.0;
    Slab slab;
  };
  /// The facets in patch order, into vertices_by_patch_ (an array: filled by the threads, not
  /// zeroed first).
  std::unique_ptr<std::array<VertexIndex, 3>[]> triangles_by_patch_;
  std::vector<Vec3> vertices_by_patch_;  ///< the mesh's vertices in the order patches use them
  std::vector<Patch> patches_;
  std::vector<double> zmin_sorted_;
  std::vector<double> zmax_prefix_max_;
};

}  // namespace strata
