#pragma once

// What strata-validation works with: its options, the models it validates and what it keeps of
// each run, shared by the steps in models.cpp, runs.cpp, comparison.cpp and report.cpp.

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "strata/mesh/triangle_soup.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/validate/validate_model.hpp"

namespace strata::validation {

namespace fs = std::filesystem;
using strata::validate::kDifferenceReasonCount;
using strata::validate::ReferenceSkip;

/// What the command line asked.
struct RunnerOptions {
  bool quick = false;
  fs::path corpus = fs::path(STRATA_SHARED_DIR) / "corpus";
  std::uint64_t max_bytes = 5'000'000;
  double max_cells = 1.0e6;
  std::uint32_t max_layers = 64;
  fs::path out = fs::path(STRATA_VALIDATION_DIR) / "REPORT.md";
  fs::path write_models;
  bool strict = false;
  std::vector<std::string> only;
};

inline constexpr std::size_t kQuickCorpusFiles = 10;
// The aligned grid of a corpus model divides its largest extent into whole cells; the other
// grid uses an odd cell size and an origin shifted by odd fractions of a cell.
inline constexpr double kOddCellFactor = 1.0731;
inline constexpr double kGeneratedOddCellFactor = 0.2713;
inline constexpr double kShiftX = 0.377, kShiftY = 0.291, kShiftZ = 0.413;
// Layers a run overlays exactly when the two paths' contours differ at rounding level only
// (layers with larger differences are always overlaid).
inline constexpr std::uint32_t kOverlayLayers = 16;
// The shell thickness asked in every run, in cells.
inline constexpr double kShellCells = 2.0;

/// A model to validate: generated or from the corpus.
struct ModelCase {
  std::string name;
  std::string source;  ///< "generated" or "corpus"
  std::string defects;
  std::uint64_t bytes = 0;
  std::function<strata::Result<strata::TriangleSoup>()> load;
  std::optional<double> aligned_cell_mm;  ///< generated models: the cell they were built for
};

/// What the report keeps of one run.
struct RunRecord {
  std::string grid_name;  ///< "aligned" or "shifted"
  FillRule rule = FillRule::NonZero;
  GridSpec grid;
  std::optional<std::string> fast_error;
  std::optional<std::string> exact_error;
  std::uint64_t cells_compared = 0;
  std::uint64_t cells_differing = 0;
  std::array<std::uint64_t, kDifferenceReasonCount> by_reason{};
  std::vector<strata::validate::CellDifference> first_differences;
  double max_hausdorff_mm = 0.0;
  double max_symmetric_difference_mm2 = 0.0;
  std::uint32_t layers_with_open_chains = 0;
  std::uint32_t layers_area_only = 0;
  std::uint32_t layers_overlaid = 0;
  std::uint32_t layers_overlay_skipped = 0;
  double mesh_volume_mm3 = 0.0;
  double fast_cell_volume_mm3 = 0.0;
  double exact_contour_volume_mm3 = 0.0;
  bool exact_ran = false;
  double fast_seconds = 0.0;
  double exact_seconds = 0.0;
  double comparison_seconds = 0.0;
  std::optional<double> surface_to_boundary_mm;
  double shell_min_mm = 0.0;
  double asked_shell_mm = 0.0;
  // The reference slicer (CGAL Polygon_mesh_slicer), over the layers whose plane holds no
  // vertex unless said otherwise.
  bool ref_ran = false;
  ReferenceSkip ref_skipped = ReferenceSkip::Off;
  std::string ref_reason;
  std::uint32_t ref_layers = 0;
  std::uint32_t ref_layers_at_vertex = 0;
  /// Layers whose regions differ from a path's (symmetric difference above the tolerance).
  std::uint32_t ref_differing = 0;
  /// Layers without a vertex on the plane that a path outlined (compared by region only).
  std::uint32_t ref_outlined = 0;
  /// Layers whose plane holds a vertex and whose contours differ from either path's.
  std::uint32_t ref_differing_at_vertex = 0;
  double ref_hausdorff_exact_mm = 0.0;
  double ref_hausdorff_fast_mm = 0.0;
  double ref_symmetric_difference_mm2 = 0.0;  ///< the larger of vs exact and vs fast
  std::uint64_t ref_open_polylines = 0;
  double ref_seconds = 0.0;
};

struct ModelRecord {
  ModelCase model;
  std::optional<std::string> read_error;
  std::size_t facets = 0;
  std::vector<RunRecord> runs;
  double seconds = 0.0;
};

}  // namespace strata::validation
