#include "strata/export/cli_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "support/sink_runs.hpp"

namespace strata::io {
namespace {

using test::read_file;
using testing::count_of;
using testing::LayerData;
using testing::lines_of;
using testing::list_tree;
using testing::loop;
using testing::run_sink;
using testing::ScratchDir;
using testing::small_layers;
using testing::small_run;

/// Layer 1 of small_run() gets a hole, an outer loop, an open chain and two hatch segments.
std::vector<LayerData> layers_with_loops_and_a_point() {
  auto layers = small_layers();
  LayerContours& c = layers[1].contours;
  c.loops.push_back(loop({{-1.0, 2.5}, {-1.0, 2.75}, {0.5, 2.75}, {0.5, 2.5}}, LoopKind::Hole));
  c.loops.push_back(
      loop({{-1.25, 2.375}, {0.75, 2.375}, {0.75, 2.875}, {-1.25, 2.875}}, LoopKind::Outer));
  c.loops.push_back(loop({{0.875, 2.3}, {0.9, 2.6}, {0.95, 2.9}}, LoopKind::Open));
  c.loops.push_back(loop({{0.1, 2.5}}, LoopKind::Open));  // a single point: not a polyline
  layers[1].hatches = {{0, -1.25, 0.75}, {2, -1.25, -1.0}};
  return layers;
}

std::string write_cli(const ScratchDir& dir, CliEncoding encoding,
                      const SliceRunInfo& run = small_run()) {
  auto sink = make_cli_writer(dir / "part.cli", encoding);
  return testing::run_and_read(*sink, run, layers_with_loops_and_a_point(), dir / "part.cli");
}

/// The values of every `$$KEY/...` line, split at commas.
std::vector<std::vector<std::string>> commands(const std::string& text, const std::string& key) {
  std::vector<std::vector<std::string>> found;
  const std::string prefix = "$$" + key + "/";
  for (const auto& line : lines_of(text)) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::vector<std::string> values;
    std::string rest = line.substr(prefix.size());
    for (std::size_t start = 0;;) {
      const auto comma = rest.find(',', start);
      values.push_back(rest.substr(start, comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    found.push_back(values);
  }
  return found;
}

TEST(CliWriter, AsciiHeaderHasTheCli20Keys) {
  ScratchDir dir;
  const auto lines = lines_of(write_cli(dir, CliEncoding::Ascii));
  ASSERT_GE(lines.size(), 9u);
  EXPECT_EQ(std::vector<std::string>(lines.begin(), lines.begin() + 9),
            (std::vector<std::string>{"$$HEADERSTART", "$$ASCII", "$$UNITS/00000001.000000",
                                      "$$VERSION/200", "$$LABEL/1,part",
                                      "$$DIMENSION/-1.5,2.25,0.125,1,3,2.125", "$$LAYERS/2",
                                      "$$HEADEREND", "$$GEOMETRYSTART"}));
  EXPECT_EQ(lines.back(), "$$GEOMETRYEND");
}

TEST(CliWriter, AsciiHasALayerCommandPerLayerAtTheLayerTop) {
  ScratchDir dir;
  const auto layers = commands(write_cli(dir, CliEncoding::Ascii), "LAYER");
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_EQ(layers[0], std::vector<std::string>{"1.125"});
  EXPECT_EQ(layers[1], std::vector<std::string>{"2.125"});
}

TEST(CliWriter, AsciiPolylinesCarryDirectionCodes) {
  ScratchDir dir;
  const std::string text = write_cli(dir, CliEncoding::Ascii);
  const auto polylines = commands(text, "POLYLINE");
  ASSERT_EQ(polylines.size(), 3u);  // the one-point chain is skipped
  EXPECT_EQ(polylines[0][1], "0");  // hole, clockwise
  EXPECT_EQ(polylines[1][1], "1");  // outer, counter-clockwise
  EXPECT_EQ(polylines[2][1], "2");  // open
  for (const auto& p : polylines) {
    EXPECT_EQ(p[0], "1");
    EXPECT_EQ(p.size(), 3 + 2 * std::stoul(p[2]));
  }
}

TEST(CliWriter, ClosedLoopsRepeatTheirFirstPoint) {
  ScratchDir dir;
  const auto polylines = commands(write_cli(dir, CliEncoding::Ascii), "POLYLINE");
  ASSERT_EQ(polylines.size(), 3u);
  EXPECT_EQ(polylines[0], (std::vector<std::string>{"1", "0", "5", "-1", "2.5", "-1", "2.75", "0.5",
                                                    "2.75", "0.5", "2.5", "-1", "2.5"}));
  EXPECT_EQ(polylines[2],
            (std::vector<std::string>{"1", "2", "3", "0.875", "2.3", "0.9", "2.6", "0.95", "2.9"}));
}

TEST(CliWriter, HatchesLieOnTheRowCentresPlusTheScanOffset) {
  ScratchDir dir;
  SliceRunInfo run = small_run();
  run.options.scan_offset_mm = 0.0001;
  const auto hatches = commands(write_cli(dir, CliEncoding::Ascii, run), "HATCHES");
  ASSERT_EQ(hatches.size(), 1u);
  const std::string y0 = fmt::format("{}", run.grid.yc(0) + 0.0001);
  const std::string y2 = fmt::format("{}", run.grid.yc(2) + 0.0001);
  EXPECT_EQ(hatches[0],
            (std::vector<std::string>{"1", "2", "-1.25", y0, "0.75", y0, "-1.25", y2, "-1", y2}));
}

TEST(CliWriter, AsciiCoordinatesKeepFullPrecision) {
  ScratchDir dir;
  auto layers = small_layers();
  const double x = 0.1 + 0.2;
  const double y = 2.0 / 3.0;
  layers[0].contours.loops.push_back(loop({{x, y}, {1.0, y}, {1.0, 1.0}}, LoopKind::Outer));
  auto sink = make_cli_writer(dir / "p.cli", CliEncoding::Ascii);
  ASSERT_TRUE(run_sink(*sink, small_run(), layers));
  const auto polylines = commands(read_file(dir / "p.cli"), "POLYLINE");
  ASSERT_EQ(polylines.size(), 1u);
  EXPECT_EQ(std::strtod(polylines[0][3].c_str(), nullptr), x);
  EXPECT_EQ(std::strtod(polylines[0][4].c_str(), nullptr), y);
}

TEST(CliWriter, EmptyModelStillHasEveryLayer) {
  ScratchDir dir;
  auto sink = make_cli_writer(dir / "e.cli", CliEncoding::Ascii);
  ASSERT_TRUE(run_sink(*sink, small_run(), small_layers()));
  const std::string text = read_file(dir / "e.cli");
  EXPECT_EQ(count_of(text, "$$LAYER/"), 2u);
  EXPECT_EQ(count_of(text, "$$POLYLINE/"), 0u);
  EXPECT_EQ(count_of(text, "$$HATCHES/"), 0u);
}

TEST(CliWriter, AClosedLoopOfTheOpenKindIsWrittenAsAnOpenPolyline) {
  ScratchDir dir;
  auto layers = small_layers();
  Contour chain = loop({{0, 2.5}, {0.5, 2.5}, {0.5, 3}}, LoopKind::Open);
  chain.is_closed = true;  // the kind decides: an open chain never gets its first point repeated
  layers[0].contours.loops.push_back(chain);
  auto sink = make_cli_writer(dir / "part.cli", CliEncoding::Ascii);
  ASSERT_TRUE(run_sink(*sink, small_run(), layers));
  const auto polylines = commands(read_file(dir / "part.cli"), "POLYLINE");
  ASSERT_EQ(polylines.size(), 1u);
  EXPECT_EQ(polylines[0],
            (std::vector<std::string>{"1", "2", "3", "0", "2.5", "0.5", "2.5", "0.5", "3"}));
}

TEST(CliWriter, LineBreaksInTheModelNameBecomeSpacesInTheLabel) {
  ScratchDir dir;
  SliceRunInfo run = small_run();
  run.model_name = "two\nlines\rand CR";
  const std::string text = write_cli(dir, CliEncoding::Ascii, run);
  EXPECT_EQ(commands(text, "LABEL"),
            (std::vector<std::vector<std::string>>{{"1", "two lines and CR"}}));
}

/// A closed square of `n` points around the grid's area, all distinct.
Contour long_loop(std::size_t n) {
  std::vector<Point2> points;
  for (std::size_t p = 0; p < n; ++p) points.push_back({-1.0 + 1e-4 * static_cast<double>(p), 2.5});
  return loop(std::move(points), LoopKind::Outer);
}

TEST(CliWriter, AsciiLayersLongerThanTheWriteBufferAreWhole) {
  // 20000 points and 5000 hatches write several times the 64 KiB the writer hands on at once.
  ScratchDir dir;
  auto layers = small_layers();
  layers[0].contours.loops.push_back(long_loop(20000));
  for (int h = 0; h < 5000; ++h) layers[0].hatches.push_back({1, -1.0, 0.5});
  auto sink = make_cli_writer(dir / "part.cli", CliEncoding::Ascii);
  ASSERT_TRUE(run_sink(*sink, small_run(), layers));
  const std::string text = read_file(dir / "part.cli");
  const auto polylines = commands(text, "POLYLINE");
  ASSERT_EQ(polylines.size(), 1u);
  ASSERT_EQ(polylines[0].size(), 3 + 2 * 20001u);
  EXPECT_EQ(polylines[0][2], "20001");
  EXPECT_EQ(polylines[0][3 + 2 * 12345], fmt::format("{}", -1.0 + 1e-4 * 12345));
  EXPECT_EQ(polylines[0][3 + 2 * 20000], "-1");  // closed: the first point again
  const auto hatches = commands(text, "HATCHES");
  ASSERT_EQ(hatches.size(), 1u);
  EXPECT_EQ(hatches[0].size(), 2 + 4 * 5000u);
  EXPECT_EQ(text.substr(text.size() - 14), "$$GEOMETRYEND\n");
}

// ------------------------------------------------------------------------------------ binary

struct BinaryReader {
  const std::string& data;
  std::size_t pos = 0;

  bool has(std::size_t n) const { return pos + n <= data.size(); }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int b = 0; b < 4; ++b)
      v |= std::uint32_t{static_cast<unsigned char>(data[pos + b])} << (8 * b);
    pos += 4;
    return v;
  }
  std::uint16_t u16() {
    const auto v = static_cast<std::uint16_t>(static_cast<unsigned char>(data[pos]) |
                                              (static_cast<unsigned char>(data[pos + 1]) << 8));
    pos += 2;
    return v;
  }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  float f32() {
    const std::uint32_t bits = u32();
    float v = 0;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
};

TEST(CliWriter, BinaryHeaderIsAsciiEndingRightBeforeTheCommands) {
  ScratchDir dir;
  const std::string file = write_cli(dir, CliEncoding::Binary);
  const std::string header =
      "$$HEADERSTART\n$$BINARY\n$$UNITS/00000001.000000\n$$VERSION/200\n$$LABEL/1,part\n"
      "$$DIMENSION/-1.5,2.25,0.125,1,3,2.125\n$$LAYERS/2\n$$HEADEREND";
  ASSERT_GT(file.size(), header.size() + 2);
  EXPECT_EQ(file.substr(0, header.size()), header);
  EXPECT_EQ(static_cast<unsigned char>(file[header.size()]), 127);  // no line break before it
  EXPECT_EQ(count_of(file, "$$GEOMETRY"), 0u);
}

TEST(CliWriter, BinaryStreamHasTheLongCommandCodes) {
  ScratchDir dir;
  const std::string file = write_cli(dir, CliEncoding::Binary);
  BinaryReader in{file, file.find("$$HEADEREND") + 11};
  std::vector<std::uint16_t> codes;
  std::vector<float> layer_z;
  std::vector<std::int32_t> dirs;
  std::vector<float> hatch_values;
  while (in.has(2)) {
    const std::uint16_t code = in.u16();
    codes.push_back(code);
    if (code == kCliLayerLong) {
      ASSERT_TRUE(in.has(4));
      layer_z.push_back(in.f32());
    } else if (code == kCliPolylineLong) {
      ASSERT_TRUE(in.has(12));
      EXPECT_EQ(in.i32(), 1);
      dirs.push_back(in.i32());
      const std::int32_t n = in.i32();
      ASSERT_TRUE(in.has(8 * static_cast<std::size_t>(n)));
      in.pos += 8 * static_cast<std::size_t>(n);
    } else if (code == kCliHatchesLong) {
      ASSERT_TRUE(in.has(8));
      EXPECT_EQ(in.i32(), 1);
      const std::int32_t n = in.i32();
      ASSERT_TRUE(in.has(16 * static_cast<std::size_t>(n)));
      for (int v = 0; v < 4 * n; ++v) hatch_values.push_back(in.f32());
    } else {
      FAIL() << "unknown command " << code << " at byte " << in.pos - 2;
    }
  }
  EXPECT_EQ(in.pos, file.size());
  EXPECT_EQ(codes, (std::vector<std::uint16_t>{127, 127, 130, 130, 130, 132}));
  EXPECT_EQ(layer_z, (std::vector<float>{1.125f, 2.125f}));
  EXPECT_EQ(dirs, (std::vector<std::int32_t>{0, 1, 2}));
  const float y0 = static_cast<float>(small_run().grid.yc(0));
  const float y2 = static_cast<float>(small_run().grid.yc(2));
  EXPECT_EQ(hatch_values, (std::vector<float>{-1.25f, y0, 0.75f, y0, -1.25f, y2, -1.0f, y2}));
}

TEST(CliWriter, BinaryPolylinePointsAreFloat32AndClosed) {
  ScratchDir dir;
  const std::string file = write_cli(dir, CliEncoding::Binary);
  BinaryReader in{file, file.find("$$HEADEREND") + 11};
  in.pos += 2 * 6;  // two layer commands
  ASSERT_EQ(in.u16(), kCliPolylineLong);
  in.pos += 8;  // id, dir
  ASSERT_EQ(in.i32(), 5);
  std::vector<float> xy;
  for (int v = 0; v < 10; ++v) xy.push_back(in.f32());
  EXPECT_EQ(xy, (std::vector<float>{-1, 2.5f, -1, 2.75f, 0.5f, 2.75f, 0.5f, 2.5f, -1, 2.5f}));
}

TEST(CliWriter, AbortRemovesTheFileAndTheFoldersItCreated) {
  ScratchDir dir;
  auto sink = make_cli_writer(dir / "out" / "part.cli", CliEncoding::Binary);
  auto layers = layers_with_loops_and_a_point();
  ASSERT_TRUE(sink->begin(small_run()));
  ASSERT_TRUE(sink->add_layer(layers[0].result()));
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(CliWriter, NoFileUnderTheFinalNameBeforeFinish) {
  ScratchDir dir;
  testing::expect_file_only_after_finish(*make_cli_writer(dir / "part.cli"),
                                         layers_with_loops_and_a_point(), dir, "part.cli");
}

TEST(CliWriter, BinaryLayersLongerThanTheWriteBufferAreWhole) {
  ScratchDir dir;
  auto layers = small_layers();
  layers[0].contours.loops.push_back(long_loop(20000));
  for (int h = 0; h < 5000; ++h) layers[0].hatches.push_back({1, -1.0, 0.5});
  auto sink = make_cli_writer(dir / "part.cli", CliEncoding::Binary);
  ASSERT_TRUE(run_sink(*sink, small_run(), layers));
  const std::string file = read_file(dir / "part.cli");
  const std::size_t start = file.find("$$HEADEREND") + 11;
  // layer (2 + 4), polyline (2 + 12 + 8 a point), hatches (2 + 8 + 16 a segment), layer (2 + 4).
  EXPECT_EQ(file.size() - start, 6 + (14 + 8 * 20001) + (10 + 16 * 5000) + 6);
  BinaryReader in{file, start + 6 + 14 + 8 * 20000};
  EXPECT_EQ(in.f32(), -1.0f);  // the closing point, after the buffer was handed on
  EXPECT_EQ(in.f32(), 2.5f);
  EXPECT_EQ(in.u16(), kCliHatchesLong);
}

}  // namespace
}  // namespace strata::io
