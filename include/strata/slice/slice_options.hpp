#pragma once

#include <optional>

#include "strata/mesh/vec3.hpp"
#include "strata/slice/layer_range.hpp"

namespace strata {

inline constexpr double kDefaultLayerHeightMm = 0.1;
inline constexpr double kDefaultCellSizeMm = 0.1;
inline constexpr double kDefaultShellThicknessMm = 0.5;

/// How a cell centre's crossings decide whether it is solid (SPEC §2).
enum class FillRule {
  NonZero,  ///< winding number != 0: union of all shells
  EvenOdd,  ///< odd number of crossings: the published parity rule
  Winding,  ///< generalized winding number >= 1/2, for open meshes
};

/// How the boundary shell is measured (SPEC §2).
enum class ShellMode {
  Distance,  ///< centre closer than t to the mesh surface (true Euclidean distance)
  Layers,    ///< n = int(t / d) rings of 6-neighbours, the published rule
};

/// The grid of cells: sizes in millimetres, origin defaulting to the mesh's minimum corner.
struct GridOptions {
  double dx_mm = kDefaultCellSizeMm;
  double dy_mm = kDefaultCellSizeMm;
  double dz_mm = kDefaultLayerHeightMm;
  std::optional<Vec3> origin;
};

/// Everything that decides the cells of a slice run.
struct SliceOptions {
  GridOptions grid;
  double shell_mm = kDefaultShellThicknessMm;
  ShellMode shell_mode = ShellMode::Distance;
  FillRule fill_rule = FillRule::NonZero;
  /// Shift of every scanline in +y, mm; 0 is the exact symbolic rule, 0.0001 the published mode.
  double scan_offset_mm = 0.0;
  /// Worker threads; 0 lets TBB decide.
  int threads = 0;
  /// Layers computed together before the shell window moves on (memory vs parallelism).
  int batch_layers = 16;
  /// Classify the cells even when no sink reads them, for the summary's counts and volume. When
  /// false and no sink needs cells (contour outputs alone), the shell and the classification are
  /// skipped and SliceSummary::cells_classified is false: the work not asked for is not done.
  bool always_classify = true;
  /// The layers to slice, in indices of the grid the whole model defines (SPEC §3.1b); the
  /// default is every layer. A range decides the same cells as a whole run in its layers: the
  /// shell step also slices the layers around it that the shell reaches, and no others.
  LayerRange layers;
};

/// The command line's name of a fill rule: "nonzero", "evenodd", "winding".
const char* to_string(FillRule rule);
/// The command line's name of a shell mode: "distance", "layers".
const char* to_string(ShellMode mode);

}  // namespace strata
