#include "strata/export/svg_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "support/sink_runs.hpp"

namespace strata::io {
namespace {

using test::read_file;
using testing::count_of;
using testing::LayerData;
using testing::list_tree;
using testing::loop;
using testing::run_sink;
using testing::ScratchDir;
using testing::small_layers;
using testing::small_run;

/// Layer 1 of small_run() gets: a hole (depth 1) listed before its outer loop, a second outer
/// loop inside the hole, an open chain, and two hatch segments.
std::vector<LayerData> layers_with_nested_loops() {
  auto layers = small_layers();
  LayerContours& c = layers[1].contours;
  c.loops.push_back(loop({{-1.0, 2.5}, {-1.0, 2.75}, {0.5, 2.75}, {0.5, 2.5}}, LoopKind::Hole, 1));
  c.loops.push_back(
      loop({{-1.25, 2.375}, {0.75, 2.375}, {0.75, 2.875}, {-1.25, 2.875}}, LoopKind::Outer, 0));
  c.loops.push_back(loop({{-0.5, 2.55}, {0.0, 2.55}, {0.0, 2.7}}, LoopKind::Outer, 2));
  c.loops.push_back(loop({{0.875, 2.3}, {0.9, 2.6}, {0.95, 2.9}}, LoopKind::Open, 0));
  c.open_chains = 1;
  layers[1].hatches = {{0, -1.25, 0.75}, {2, -1.25, -1.0}};
  return layers;
}

std::string write_layers(const ScratchDir& dir, const SliceRunInfo& run) {
  auto sink = make_svg_writer(dir.path(), "part");
  return testing::run_and_read(*sink, run, layers_with_nested_loops(), dir / "svg/part_00001.svg");
}

TEST(SvgWriter, WritesOneFileALayerWithFiveDigitIndex) {
  ScratchDir dir;
  write_layers(dir, small_run());
  EXPECT_EQ(list_tree(dir.path()),
            (std::vector<std::string>{"svg", "svg/part_00000.svg", "svg/part_00001.svg"}));
}

TEST(SvgWriter, DrawsOnePathPerLoopAndOneForTheHatches) {
  ScratchDir dir;
  const std::string svg = write_layers(dir, small_run());
  EXPECT_EQ(count_of(svg, "<path "), 5u);
  EXPECT_EQ(count_of(svg, "<path class=\"outer\""), 2u);
  EXPECT_EQ(count_of(svg, "<path class=\"hole\""), 1u);
  EXPECT_EQ(count_of(svg, "<path class=\"open\""), 1u);
  EXPECT_EQ(count_of(svg, "<path class=\"hatch\""), 1u);
  EXPECT_EQ(count_of(svg, "<circle class=\"open-end\""), 2u);
}

TEST(SvgWriter, EmptyLayerHasNoPaths) {
  ScratchDir dir;
  write_layers(dir, small_run());
  const std::string svg = read_file(dir / "svg/part_00000.svg");
  EXPECT_EQ(count_of(svg, "<path "), 0u);
  EXPECT_EQ(count_of(svg, "</svg>"), 1u);
}

TEST(SvgWriter, ClosedLoopsCloseAndOpenChainsDoNot) {
  ScratchDir dir;
  const std::string svg = write_layers(dir, small_run());
  EXPECT_NE(svg.find("<path class=\"hole\" d=\"M -1 -2.5 L -1 -2.75 L 0.5 -2.75 L 0.5 -2.5 Z\"/>"),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find("<path class=\"open\" d=\"M 0.875 -2.3 L 0.9 -2.6 L 0.95 -2.9\"/>"),
            std::string::npos)
      << svg;
}

TEST(SvgWriter, LoopsAreDrawnByIncreasingDepth) {
  ScratchDir dir;
  const std::string svg = write_layers(dir, small_run());
  const auto outer = svg.find("<path class=\"outer\" d=\"M -1.25");
  const auto hole = svg.find("<path class=\"hole\"");
  const auto island = svg.find("<path class=\"outer\" d=\"M -0.5");
  ASSERT_NE(outer, std::string::npos);
  ASSERT_NE(hole, std::string::npos);
  ASSERT_NE(island, std::string::npos);
  EXPECT_LT(outer, hole);
  EXPECT_LT(hole, island);
}

TEST(SvgWriter, HatchesLieOnTheRowCentresPlusTheScanOffset) {
  ScratchDir dir;
  SliceRunInfo run = small_run();
  run.options.scan_offset_mm = 0.0001;
  const std::string svg = write_layers(dir, run);
  const std::string expected =
      fmt::format("<path class=\"hatch\" d=\"M -1.25 {} H 0.75 M -1.25 {} H -1\"/>",
                  -(run.grid.yc(0) + 0.0001), -(run.grid.yc(2) + 0.0001));
  EXPECT_NE(svg.find(expected), std::string::npos) << expected << "\n" << svg;
}

TEST(SvgWriter, ViewBoxCoversTheGridWithYFlipped) {
  ScratchDir dir;
  const std::string svg = write_layers(dir, small_run());
  const auto at = svg.find("viewBox=\"");
  ASSERT_NE(at, std::string::npos);
  double x = 0, y = 0, w = 0, h = 0;
  ASSERT_EQ(std::sscanf(svg.c_str() + at, "viewBox=\"%lf %lf %lf %lf\"", &x, &y, &w, &h), 4);
  // Grid: x in [-1.5, 1], y in [2.25, 3]; SVG y = -y, so [-3, -2.25].
  EXPECT_LE(x, -1.5);
  EXPECT_GE(x + w, 1.0);
  EXPECT_LE(y, -3.0);
  EXPECT_GE(y + h, -2.25);
  EXPECT_LT(w, 2.5 * 1.5);  // a margin, not a different drawing
  EXPECT_NE(svg.find("<rect class=\"grid\" x=\"-1.5\" y=\"-3\" width=\"2.5\" height=\"0.75\"/>"),
            std::string::npos);
}

TEST(SvgWriter, TitleNamesTheLayerAndZ) {
  ScratchDir dir;
  const std::string svg = write_layers(dir, small_run());
  EXPECT_NE(svg.find("<title>part layer 1 z=1.625 mm</title>"), std::string::npos);
  EXPECT_NE(svg.find(">part layer 1 z=1.625 mm</text>"), std::string::npos);
}

TEST(SvgWriter, TitleEscapesTheMarkupCharactersOfTheStem) {
  ScratchDir dir;
  auto sink = make_svg_writer(dir.path(), "a&b<c>\"d'e");
  ASSERT_TRUE(run_sink(*sink, small_run(), layers_with_nested_loops()));
  const std::string svg = read_file(dir / "svg/a&b<c>\"d'e_00000.svg");
  EXPECT_NE(svg.find("<title>a&amp;b&lt;c&gt;&quot;d&apos;e layer 0 z=0.625 mm</title>"),
            std::string::npos)
      << svg;
}

TEST(SvgWriter, AbortRemovesEarlierLayersAndTheFoldersItCreated) {
  ScratchDir dir;
  auto sink = make_svg_writer(dir / "out", "part");
  auto layers = layers_with_nested_loops();
  ASSERT_TRUE(sink->begin(small_run()));
  ASSERT_TRUE(sink->add_layer(layers[0].result()));
  ASSERT_TRUE(sink->add_layer(layers[1].result()));
  ASSERT_TRUE(sink->finish());
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(SvgWriter, StemWithAFolderSeparatorIsRefused) {
  ScratchDir dir;
  auto sink = make_svg_writer(dir.path(), "../part");
  auto begun = sink->begin(small_run());
  ASSERT_FALSE(begun);
  EXPECT_EQ(begun.error().code, ErrorCode::Usage);
  sink->abort();
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(SvgWriter, StemThatIsEmptyIsRefused) {
  ScratchDir dir;
  auto sink = make_svg_writer(dir.path(), "");
  auto begun = sink->begin(small_run());
  ASSERT_FALSE(begun);
  EXPECT_EQ(begun.error().code, ErrorCode::Usage);
  EXPECT_EQ(begun.error().message, "SVG writer: the file stem '' must be a plain, non-empty name");
  EXPECT_EQ(begun.error().location, (dir / "svg").string());
}

TEST(SvgWriter, ALoopWithoutPointsIsNotDrawn) {
  ScratchDir dir;
  auto layers = small_layers();
  layers[0].contours.loops.push_back(loop({}, LoopKind::Outer, 0));
  auto sink = make_svg_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), layers));
  EXPECT_EQ(count_of(read_file(dir / "svg/part_00000.svg"), "<path "), 0u);
}

TEST(SvgWriter, AClosedLoopOfTheOpenKindIsDrawnAsAnOpenChain) {
  ScratchDir dir;
  auto layers = small_layers();
  Contour chain = loop({{0, 2.5}, {0.5, 2.5}, {0.5, 3}}, LoopKind::Open, 0);
  chain.is_closed = true;  // the kind decides
  layers[0].contours.loops.push_back(chain);
  auto sink = make_svg_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), layers));
  const std::string svg = read_file(dir / "svg/part_00000.svg");
  EXPECT_NE(svg.find("<path class=\"open\" d=\"M 0 -2.5 L 0.5 -2.5 L 0.5 -3\"/>"),
            std::string::npos)
      << svg;
  EXPECT_EQ(count_of(svg, "<circle class=\"open-end\""), 2u);
}

TEST(SvgWriter, HatchesLongerThanTheWriteBufferAreAllDrawn) {
  // 6000 segments make a path of about 150 KiB, handed to the file in pieces of 64 KiB.
  ScratchDir dir;
  auto layers = small_layers();
  for (int h = 0; h < 6000; ++h)
    layers[0].hatches.push_back({static_cast<std::uint32_t>(h % 3), -1.25, 0.75});
  auto sink = make_svg_writer(dir.path(), "part");
  ASSERT_TRUE(run_sink(*sink, small_run(), layers));
  const std::string svg = read_file(dir / "svg/part_00000.svg");
  EXPECT_EQ(count_of(svg, "<path class=\"hatch\""), 1u);
  EXPECT_EQ(count_of(svg, " H 0.75"), 6000u);
  const double y2 = small_run().grid.yc(2);
  EXPECT_EQ(count_of(svg, fmt::format("M -1.25 {} H 0.75", -y2)), 2000u);
  EXPECT_NE(svg.find("H 0.75\"/>\n<text"), std::string::npos);
}

}  // namespace
}  // namespace strata::io
