#pragma once

/// @file
/// strata for library users: the common path in one include. Read a mesh, check it, slice it
/// with options into cells (and any other output), read the cells back.
///
/// @code
/// #include "strata/strata.hpp"
///
/// strata::Result<std::uint64_t> solid_cells(const std::filesystem::path& model,
///                                           const std::filesystem::path& cells_file) {
///   // Read (STL, OBJ, OFF, PLY, any of them gzip-compressed) and weld exactly.
///   auto soup = strata::io::read_mesh(model);
///   if (!soup) return soup.error();
///   const strata::IndexedMesh mesh = strata::weld_vertices(*soup);
///
///   // Check: open edges, orientation, self-intersections; the verdict says whether it slices.
///   const strata::diagnose::MeshReport report = strata::diagnose::diagnose_mesh(mesh, *soup);
///   if (report.verdict == strata::diagnose::Verdict::NeedsRepair) {
///     // report.verdict_reason says why; strata::repair::repair_mesh() can fix many meshes.
///   }
///
///   // Slice: 0.1 mm cells and layers, a 0.5 mm boundary shell, the nonzero fill rule.
///   strata::SliceOptions options;
///   options.grid = strata::GridOptions{0.1, 0.1, 0.1, std::nullopt};
///   options.shell_mm = 0.5;
///   auto grid = strata::make_grid(mesh.bounds(), options.grid);
///   if (!grid) return grid.error();
///   const auto writer = strata::io::make_cells_writer(cells_file);
///   strata::LayerSink* sinks[] = {writer.get()};
///   auto summary = strata::slice_model(mesh, *grid, options, sinks);
///   if (!summary) return summary.error();  // every sink was aborted: no partial file
///
///   // Read back: every cell is Empty, Interior or Boundary.
///   auto cells = strata::io::read_cells(cells_file);
///   if (!cells) return cells.error();
///   std::uint64_t solid = 0;
///   for (const strata::CellClass c : cells->cells) solid += c != strata::CellClass::Empty;
///   return solid;  // == summary->class_counts[1] + summary->class_counts[2]
/// }
/// @endcode
///
/// Every function returns Result<T>: a value or an Error{code, message, location} saying what
/// was wrong; nothing prints or exits. The modules behind these calls (`include/strata/<module>/`)
/// offer the rest: the exact path (exact/slice_exact.hpp), other outputs (export/), repair
/// (repair/), validation of the fast path against the exact one (validate/).

#include "strata/core/error.hpp"
#include "strata/core/result.hpp"
#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/diagnose/mesh_report.hpp"
#include "strata/export/cells_writer.hpp"
#include "strata/io/read_cells.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"
#include "strata/slicer/slice_model.hpp"
#include "strata/voxel/cell_class.hpp"
