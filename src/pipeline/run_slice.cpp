#include "strata/pipeline/run_slice.hpp"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <new>
#include <optional>
#include <string>

#include "strata/core/internal_failure.hpp"
#include "strata/voxel/boundary_shell.hpp"

namespace strata {

namespace {

constexpr std::size_t kMaxOpenChainReports = 1000;
// Memory the layers in flight may take (their classes, one byte a cell, beside solid cells kept
// as runs; two batches: one being written while the next is computed).
constexpr double kBatchMemoryBytes = 2.0e9;

/// "3, 4, 5" for the first few layers that `has` picks, "3, 4, 5, ..." when there are more.
template <class Has>
std::string first_layers(const std::vector<LayerStats>& layers, Has has) {
  constexpr std::size_t kShown = 5;
  std::string out;
  std::size_t shown = 0;
  for (const LayerStats& l : layers) {
    if (!has(l)) continue;
    if (shown == kShown) return out + ", ...";
    out += (shown++ == 0 ? "" : ", ") + std::to_string(l.layer);
  }
  return out;
}

/// Issue 4 item 4: say which layers' loops cross or nest wrongly, and what the contours are then.
void add_loop_diagnostics(SliceSummary& summary) {
  const auto tail = [&](auto has) {
    std::uint32_t outlined = 0;
    std::uint32_t total = 0;
    for (const LayerStats& l : summary.layers) {
      if (!has(l)) continue;
      ++total;
      outlined += l.outline ? 1 : 0;
    }
    if (outlined == total) return std::string(": contours are the outline of the filled region");
    if (outlined == 0) return std::string(": contours are the chained loops");
    return fmt::format(": contours are the outline of the filled region in {} of them", outlined);
  };
  if (summary.crossing_loop_layers > 0) {
    const auto has = [](const LayerStats& l) { return l.loops_cross; };
    summary.diagnostics.push_back(
        {Severity::Warning, "contours.loops_cross",
         fmt::format("loops cross or touch each other in {} layers (first: {}){}",
                     summary.crossing_loop_layers, first_layers(summary.layers, has), tail(has))});
  }
  if (summary.misnested_layers > 0) {
    const auto has = [](const LayerStats& l) { return l.misnested; };
    summary.diagnostics.push_back(
        {Severity::Warning, "contours.loops_misnested",
         fmt::format("nested loops do not alternate in orientation in {} layers (first: {}){}",
                     summary.misnested_layers, first_layers(summary.layers, has), tail(has))});
  }
}

/// A layer ready to be written: its cells, their counts, and what each sink prepared of it.
struct ClassifiedLayer {
  /// nx * ny classes, or none when the cells are not wanted. Not cleared when allocated: the
  /// shell writes every class.
  std::unique_ptr<CellClass[]> classes;
  std::size_t class_count = 0;
  std::span<CellClass> cells() { return {classes.get(), class_count}; }
  std::uint64_t interior = 0;
  std::uint64_t boundary = 0;
  std::vector<std::unique_ptr<PreparedLayer>> prepared;  ///< by sink
};

Result<SliceSummary> run_layers(const IndexedMesh& mesh, const GridSpec& grid,
                                const SliceOptions& options, LayerKernel& kernel,
                                std::span<LayerSink* const> sinks,
                                const ProgressCallback& progress) {
  const auto started = std::chrono::steady_clock::now();
  std::optional<tbb::global_control> thread_limit;
  if (options.threads > 0) {
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism,
                         static_cast<std::size_t>(options.threads));
  }
  auto span = resolve_layer_range(options.layers, grid.nz);
  if (!span) return span.error();
  const std::uint32_t first = span->first;
  const std::uint32_t end = span->end;
  SliceSummary summary;
  summary.grid = grid;
  summary.range = *span;
  summary.layers.resize(span->count());

  // Contour outputs alone need no cell: then neither the shell nor the classification is run.
  const bool classify =
      options.always_classify ||
      std::any_of(sinks.begin(), sinks.end(), [](const LayerSink* s) { return s->needs_cells(); });
  summary.cells_classified = classify;
  kernel.want_cells(classify);
  kernel.want_hatches(std::any_of(sinks.begin(), sinks.end(),
                                  [](const LayerSink* s) { return s->needs_hatches(); }));
  const std::uint32_t reach =
      classify ? BoundaryShell::reach_layers(grid, options.shell_mode, options.shell_mm) : 0;
  // A range also slices the layers around it that the shell reads (their cells are not sent),
  // so that its cells are those of a whole run; the work is the range's plus the shell's reach.
  const std::uint32_t lo = first > reach ? first - reach : 0;
  const std::uint32_t hi = end + std::min(reach, grid.nz - end);

  SliceRunInfo run{grid, options, {}, *span};
  for (LayerSink* sink : sinks) {
    if (auto ok = sink->begin(run); !ok) {
      abort_all(sinks);
      return ok.error();
    }
  }

  const double layer_bytes =
      static_cast<double>(std::max<std::uint64_t>(1, grid.cells_per_layer()));
  const std::uint32_t batch = static_cast<std::uint32_t>(
      std::clamp(kBatchMemoryBytes / (4.0 * layer_bytes), 1.0,
                 static_cast<double>(std::max(1, options.batch_layers))));

  std::map<std::int64_t, LayerGeometry> pending;  // computed, not yet sent to the sinks
  std::map<std::int64_t, SolidRows> solids;       // the shell window
  const SolidLayerLookup lookup = [&](std::int64_t q) -> const SolidRows* {
    if (q < 0 || q >= static_cast<std::int64_t>(grid.nz)) return nullptr;
    const auto it = solids.find(q);
    return it == solids.end() ? nullptr : &it->second;
  };

  // Writes layers [from, to), classified and prepared in `layers`, in order.
  const auto write_layers = [&](std::uint32_t from, std::uint32_t to,
                                std::vector<ClassifiedLayer>& layers) -> Result<void> {
    for (std::uint32_t k = from; k < to; ++k) {
      auto node = pending.extract(k);
      LayerGeometry& g = node.mapped();
      ClassifiedLayer& done = layers[k - from];
      LayerStats& stats = summary.layers[k - first];
      stats.layer = k;
      stats.z_mm = grid.zk(k);
      stats.segments = g.segments;
      for (const Contour& loop : g.contours.loops) {
        if (loop.kind == LoopKind::Outer) ++stats.outer_loops;
        if (loop.kind == LoopKind::Hole) ++stats.holes;
        if (loop.kind == LoopKind::Open) {
          ++stats.open_chains;
          if (summary.open_chain_reports.size() < kMaxOpenChainReports) {
            summary.open_chain_reports.push_back(
                {k, loop.points.front(), loop.points.back(),
                 static_cast<std::uint32_t>(loop.points.size() - 1)});
          }
        }
      }
      stats.loops_cross = g.contours.loops_cross;
      stats.misnested = g.contours.misnested;
      stats.outline = g.contours.outline;
      summary.crossing_loop_layers += stats.loops_cross ? 1 : 0;
      summary.misnested_layers += stats.misnested ? 1 : 0;
      summary.outline_layers += stats.outline ? 1 : 0;
      stats.contour_area_mm2 = g.contours.area_mm2;
      stats.interior = done.interior;
      stats.boundary = done.boundary;
      summary.class_counts[1] += stats.interior;
      summary.class_counts[2] += stats.boundary;
      summary.segments += g.segments;
      summary.open_chains += stats.open_chains;
      summary.exact_fallbacks += g.fill.exact_fallbacks;
      summary.contour_volume_mm3 += stats.contour_area_mm2 * grid.dz;
      const LayerResult result{k, grid.zk(k), done.cells(), g.contours, g.fill.hatches};
      for (std::size_t s = 0; s < sinks.size(); ++s) {
        if (auto ok = sinks[s]->add_prepared_layer(result, std::move(done.prepared[s])); !ok) {
          abort_all(sinks);
          return ok;
        }
      }
      done = {};
      if (progress) progress(k + 1 - first, span->count());
    }
    return {};
  };
  const auto compute_batch = [&](std::uint32_t k0, std::uint32_t k1) {
    kernel.prepare_batch(k0, k1);
    std::vector<LayerGeometry> computed(k1 - k0);
    tbb::parallel_for(k0, k1, [&](std::uint32_t k) { computed[k - k0] = kernel.compute_layer(k); });
    return computed;
  };

  // A pipeline of rounds: while this thread hands the sinks the layers of the round before (in
  // order, so serial), the pool classifies the layers whose shell window is now complete, has
  // the sinks prepare them (encoding, compression: LayerSink::prepare_layer), and computes the
  // next batch.
  std::uint32_t next_write = first;      // the first layer not yet written
  std::uint32_t classified_end = first;  // layers [next_write, classified_end) are in `ready`
  std::vector<ClassifiedLayer> ready;
  std::vector<ClassifiedLayer> classifying;
  std::vector<const LayerGeometry*> classifying_geometry;
  std::vector<LayerGeometry> computed;
  // The shell's marker is built (its facets grouped, partly on one thread) while the first
  // batch is computed: nothing is classified before both are done.
  std::optional<BoundaryShell> shell;
  {
    tbb::task_group setup;
    if (classify) {
      setup.run([&] { shell.emplace(mesh, grid, options.shell_mode, options.shell_mm); });
    }
    if (lo < hi) computed = compute_batch(lo, std::min(hi, lo + batch));
    setup.wait();
  }
  if (shell && options.shell_mode == ShellMode::Layers && shell->unequal_cell_sizes()) {
    summary.diagnostics.push_back(
        {Severity::Warning, "shell.unequal_cell_sizes",
         fmt::format("shell mode layers with unequal cell sizes ({} x {} x {} mm): rings are "
                     "counted with the smallest, {} rings of {} mm",
                     grid.dx, grid.dy, grid.dz, shell->rings(),
                     std::min({grid.dx, grid.dy, grid.dz}))});
  }
  for (std::uint32_t k0 = lo; k0 < hi; k0 += batch) {
    const std::uint32_t k1 = std::min(hi, k0 + batch);
    for (std::uint32_t k = k0; k < k1; ++k) {
      LayerGeometry& g = computed[k - k0];
      if (classify) solids[k] = std::move(g.fill.solid);
      g.fill.solid = {};
      if (span->contains(k)) pending.emplace(k, std::move(g));
    }
    computed.clear();
    // Layers whose shell window is complete can be classified.
    const std::uint32_t window_end =
        k1 == hi ? end : std::min(end, k1 > reach ? k1 - reach : std::uint32_t{0});
    const std::uint32_t class_from = classified_end;
    const std::uint32_t class_to = std::max(classified_end, window_end);
    classifying.clear();
    classifying.resize(class_to - class_from);
    // The nodes of `pending` stay where they are while this thread extracts the layers before.
    classifying_geometry.clear();
    for (std::uint32_t k = class_from; k < class_to; ++k) {
      classifying_geometry.push_back(&pending.at(k));
    }
    tbb::task_group round;
    round.run([&, k1, class_from, class_to] {
      tbb::parallel_for(class_from, class_to, [&](std::uint32_t k) {
        ClassifiedLayer& done = classifying[k - class_from];
        if (classify) {
          done.class_count = grid.cells_per_layer();
          done.classes = std::make_unique_for_overwrite<CellClass[]>(done.class_count);
          const BoundaryShell::ClassCounts counts = shell->classify(k, lookup, done.cells());
          done.interior = counts.interior;
          done.boundary = counts.boundary;
        }
        const LayerGeometry& g = *classifying_geometry[k - class_from];
        const LayerResult result{k, grid.zk(k), done.cells(), g.contours, g.fill.hatches};
        done.prepared.resize(sinks.size());
        for (std::size_t s = 0; s < sinks.size(); ++s) {
          done.prepared[s] = sinks[s]->prepare_layer(result);
        }
      });
      if (k1 < hi) computed = compute_batch(k1, std::min(hi, k1 + batch));
    });
    // On an early return (a writer failed) the round is cancelled and waited for: it refers to
    // this frame. Its own failure would only repeat that the run failed.
    struct CancelOnReturn {
      tbb::task_group& group;
      ~CancelOnReturn() {
        group.cancel();
        try {
          group.wait();
        } catch (...) {  // NOLINT(bugprone-empty-catch): the run is failing already
        }
      }
    } cancel_on_return{round};
    if (auto ok = write_layers(next_write, classified_end, ready); !ok) return ok.error();
    next_write = classified_end;
    round.wait();  // the round's failure is the run's
    ready = std::move(classifying);
    classified_end = class_to;
    // Keep only the solid layers the next classifications can still reach.
    const std::int64_t keep_from = static_cast<std::int64_t>(classified_end) - reach;
    while (!solids.empty() && solids.begin()->first < keep_from) solids.erase(solids.begin());
  }
  if (auto ok = write_layers(next_write, classified_end, ready); !ok) return ok.error();

  for (LayerSink* sink : sinks) {
    if (auto ok = sink->finish(); !ok) {
      abort_all(sinks);
      return ok.error();
    }
  }
  add_loop_diagnostics(summary);
  if (classify) {
    summary.class_counts[0] =
        grid.cells_per_layer() * span->count() - summary.class_counts[1] - summary.class_counts[2];
  }
  summary.solid_volume_mm3 =
      static_cast<double>(summary.class_counts[1] + summary.class_counts[2]) * grid.dx * grid.dy *
      grid.dz;
  summary.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return summary;
}

}  // namespace

Result<SliceSummary> run_slice(const IndexedMesh& mesh, const GridSpec& grid,
                               const SliceOptions& options, LayerKernel& kernel,
                               std::span<LayerSink* const> sinks,
                               const ProgressCallback& progress) {
  // A failure on a worker thread reaches here through tbb::parallel_for; a caller gets an Error
  // and no partial output, whichever kernel failed.
  return catch_internal_failure(
      kernel.name(), [&] { return run_layers(mesh, grid, options, kernel, sinks, progress); },
      [&] { abort_all(sinks); });
}

}  // namespace strata
