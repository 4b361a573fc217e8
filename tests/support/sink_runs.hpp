#pragma once

// Helpers of the export and cells tests: a scratch folder, layers built by hand, running a sink
// over them and reading back what it wrote.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "strata/pipeline/layer_sink.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"

namespace strata::io::testing {

/// A fresh folder under the system's temporary folder, removed with everything in it.
using ScratchDir = ::strata::test::TempDir;

/// One layer's data, owned (LayerResult only refers to it).
struct LayerData {
  std::uint32_t layer = 0;
  double z_mm = 0.0;
  std::vector<CellClass> cells;
  LayerContours contours;
  std::vector<HatchSegment> hatches;

  LayerResult result() const { return LayerResult{layer, z_mm, cells, contours, hatches}; }
};

inline CellClass code(int c) { return static_cast<CellClass>(c); }

inline std::vector<CellClass> codes(std::initializer_list<int> values) {
  std::vector<CellClass> out;
  for (int v : values) out.push_back(code(v));
  return out;
}

/// A contour of `kind`, closed unless the kind is Open, nested `depth` loops deep.
inline Contour loop(std::vector<Point2> points, LoopKind kind, int depth = 0) {
  Contour c;
  c.points = std::move(points);
  c.is_closed = kind != LoopKind::Open;
  c.kind = kind;
  c.depth = depth;
  return c;
}

/// The 5 x 3 x 2 grid of the tests: origin (-1.5, 2.25, 0.125), cells 0.5 x 0.25 x 1, shell 0.75.
inline SliceRunInfo small_run() {
  SliceRunInfo run;
  run.grid.x0 = -1.5;
  run.grid.y0 = 2.25;
  run.grid.z0 = 0.125;
  run.grid.dx = 0.5;
  run.grid.dy = 0.25;
  run.grid.dz = 1.0;
  run.grid.nx = 5;
  run.grid.ny = 3;
  run.grid.nz = 2;
  run.options.shell_mm = 0.75;
  run.model_name = "part";
  return run;
}

/// Layers of small_run(): layer 0 has 5 empty, 6 interior, 4 boundary cells; layer 1 has 0, 3, 12.
inline std::vector<LayerData> small_layers() {
  std::vector<LayerData> layers(2);
  layers[0].layer = 0;
  layers[0].z_mm = 0.625;
  layers[0].cells = codes({0, 1, 3, 3, 1,  //
                           3, 0, 1, 0, 0,  //
                           1, 1, 1, 3, 0});
  layers[1].layer = 1;
  layers[1].z_mm = 1.625;
  layers[1].cells = codes({3, 3, 3, 3, 3,  //
                           3, 1, 1, 1, 3,  //
                           3, 3, 3, 3, 3});
  return layers;
}

/// begin, every layer, finish; stops at the first error.
inline Result<void> run_sink(LayerSink& sink, const SliceRunInfo& run,
                             const std::vector<LayerData>& layers) {
  if (auto ok = sink.begin(run); !ok) return ok;
  for (const auto& layer : layers) {
    if (auto ok = sink.add_layer(layer.result()); !ok) return ok;
  }
  return sink.finish();
}

/// run_sink the way the engine runs a sink: every layer is prepared first, on another thread and
/// last layer first, then added in order with what was prepared of it.
inline Result<void> run_sink_prepared(LayerSink& sink, const SliceRunInfo& run,
                                      const std::vector<LayerData>& layers) {
  if (auto ok = sink.begin(run); !ok) return ok;
  std::vector<std::unique_ptr<PreparedLayer>> prepared(layers.size());
  std::thread worker([&] {
    for (std::size_t i = layers.size(); i-- > 0;) {
      prepared[i] = sink.prepare_layer(layers[i].result());
    }
  });
  worker.join();
  for (std::size_t i = 0; i < layers.size(); ++i) {
    if (auto ok = sink.add_prepared_layer(layers[i].result(), std::move(prepared[i])); !ok) {
      return ok;
    }
  }
  return sink.finish();
}

/// run_sink; a test failure, with the error, when it fails.
inline void expect_run(LayerSink& sink, const SliceRunInfo& run,
                       const std::vector<LayerData>& layers) {
  auto ok = run_sink(sink, run, layers);
  EXPECT_TRUE(ok) << ok.error().to_string();
}

/// expect_run, then the bytes of the file `written` (empty when it is missing).
inline std::string run_and_read(LayerSink& sink, const SliceRunInfo& run,
                                const std::vector<LayerData>& layers,
                                const std::filesystem::path& written) {
  expect_run(sink, run, layers);
  return ::strata::test::read_file(written);
}

/// Every file and folder below `dir`, relative, sorted.
inline std::vector<std::string> list_tree(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    names.push_back(std::filesystem::relative(entry.path(), dir).generic_string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

/// Number of non-overlapping occurrences of `needle` in `text`.
inline std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t pos = text.find(needle); pos != std::string::npos;
       pos = text.find(needle, pos + needle.size())) {
    ++count;
  }
  return count;
}

/// The lines of a text.
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The sink contract every file writer keeps: a sink destroyed after begin and one layer, never
/// finished, leaves nothing in `dir` (no file, no folder it created).
inline void expect_destroyed_unfinished_sink_leaves_nothing(std::unique_ptr<LayerSink> sink,
                                                            const ScratchDir& dir) {
  const std::vector<LayerData> layers = small_layers();
  ASSERT_TRUE(sink->begin(small_run()));
  ASSERT_TRUE(sink->add_layer(layers[0].result()));
  sink.reset();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

/// The sink contract of a single-file writer: over both `layers` of small_run(), nothing is
/// under the final name `file` (in `dir`) until finish, and then that file only.
inline void expect_file_only_after_finish(LayerSink& sink, const std::vector<LayerData>& layers,
                                          const ScratchDir& dir, const std::string& file) {
  ASSERT_TRUE(sink.begin(small_run()));
  ASSERT_TRUE(sink.add_layer(layers[0].result()));
  ASSERT_TRUE(sink.add_layer(layers[1].result()));
  EXPECT_FALSE(std::filesystem::exists(dir / file));
  ASSERT_TRUE(sink.finish());
  EXPECT_TRUE(std::filesystem::exists(dir / file));
  EXPECT_EQ(list_tree(dir.path()), std::vector<std::string>{file});
}

}  // namespace strata::io::testing
