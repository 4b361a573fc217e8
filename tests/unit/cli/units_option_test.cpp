// --units and --scale through the command line: a model exported in metres, or at another scale,
// slices to the cells of its millimetre original, and the report records how it was read.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "strata/io/write_stl.hpp"
#include "support/corpus.hpp"
#include "support/read_file.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"
#include "support/text_meshes.hpp"

namespace strata {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::run_cli;

/// A corpus part of 10 x 20 x 8 mm (binary STL) whose every float32 coordinate v has a metre
/// copy float32(v / 1000) that reads back, times 1000 and rounded to float32, as v.
const fs::path kPart = "prusaslicer/resources/shapes/universal wall mount hole.stl";

/// The soup with every coordinate mapped by `f`.
template <class F>
TriangleSoup transformed(TriangleSoup soup, F f) {
  for (auto& triangle : soup.triangles) {
    for (Vec3& corner : triangle) corner = Vec3{f(corner.x), f(corner.y), f(corner.z)};
  }
  return soup;
}

// Not inlined: GCC 12 at -O3 vectorises the premise's loop below and drops this round trip in
// the vector lanes (x and y compared as products, z rounded), failing the test in Release only.
[[gnu::noinline]] double as_float32(double v) { return static_cast<double>(static_cast<float>(v)); }

/// Slices `model` with `extra` options into `dir` (cells and the report), expecting success.
void slice(const fs::path& model, const fs::path& dir, std::vector<std::string> extra) {
  std::vector<std::string> args{"slice",    model.string(), "-o",      dir.string(),
                                "--cell",   "0.25",         "--layer", "0.25",
                                "--format", "cells,json",   "-q"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto run = run_cli(args);
  ASSERT_EQ(run.exit_code, 0) << run.err;
}

TEST(UnitsOption, MetreCopyWithUnitsMGivesTheCellsOfTheMillimetreOriginal) {
  const test::TempDir tmp("units");
  const fs::path original = test::corpus_dir() / kPart;
  const auto soup = io::read_mesh(original);
  ASSERT_TRUE(soup) << soup.error().to_string();
  const TriangleSoup metres = transformed(*soup, [](double v) { return as_float32(v / 1000.0); });
  // The premise of the comparison: every coordinate comes back exactly.
  for (std::size_t t = 0; t < soup->triangles.size(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const Vec3& m = metres.triangles[t][c];
      ASSERT_EQ(soup->triangles[t][c], (Vec3{as_float32(m.x * 1000.0), as_float32(m.y * 1000.0),
                                             as_float32(m.z * 1000.0)}))
          << "facet " << t;
    }
  }
  ASSERT_TRUE(io::write_stl(tmp / "part-m.stl", metres, io::StlEncoding::Binary));

  slice(original, tmp / "mm", {});
  slice(tmp / "part-m.stl", tmp / "m", {"--units", "m"});
  const std::string expected = read_file(tmp / "mm" / "universal wall mount hole.cells");
  ASSERT_GT(expected.size(), 80u);
  EXPECT_EQ(read_file(tmp / "m" / "part-m.cells"), expected);

  const auto report = nlohmann::json::parse(read_file(tmp / "m" / "part-m.json"));
  EXPECT_EQ(report["model"]["units"], "m");
  EXPECT_EQ(report["model"]["scale"], 1.0);
  const auto original_report =
      nlohmann::json::parse(read_file(tmp / "mm" / "universal wall mount hole.json"));
  EXPECT_EQ(original_report["model"]["units"], "mm");
  EXPECT_EQ(report["model"]["bbox_min_mm"], original_report["model"]["bbox_min_mm"]);
  EXPECT_EQ(report["model"]["bbox_max_mm"], original_report["model"]["bbox_max_mm"]);
}

TEST(UnitsOption, ScaleByAPowerOfTwoUndoesADoubledCopy) {
  // Doubling a float32 and halving it again is exact: any model gives its own cells back.
  const test::TempDir tmp("units");
  const fs::path original = test::corpus_dir() / kPart;
  const auto soup = io::read_mesh(original);
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_TRUE(io::write_stl(tmp / "double.stl", transformed(*soup, [](double v) { return 2 * v; }),
                            io::StlEncoding::Binary));
  slice(original, tmp / "mm", {});
  slice(tmp / "double.stl", tmp / "half", {"--scale", "0.5"});
  EXPECT_EQ(read_file(tmp / "half" / "double.cells"),
            read_file(tmp / "mm" / "universal wall mount hole.cells"));
  const auto report = nlohmann::json::parse(read_file(tmp / "half" / "double.json"));
  EXPECT_EQ(report["model"]["units"], "mm");
  EXPECT_EQ(report["model"]["scale"], 0.5);
}

TEST(UnitsOption, CheckReadsInTheAskedUnit) {
  const test::TempDir tmp("units");
  const fs::path obj = tmp / "inch.obj";
  test::write_text_file(obj,
                        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                        "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const auto run = run_cli({"check", obj.string(), "--units", "in", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  // The tetrahedron of 1 inch edges: volume 25.4^3 / 6 mm3.
  EXPECT_DOUBLE_EQ(report["volume_mm3"].get<double>(), 25.4 * 25.4 * 25.4 / 6.0);
}

TEST(UnitsOption, UnknownUnitIsAUsageError) {
  const auto run = run_cli({"slice", "part.stl", "--units", "ft"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--units"), std::string::npos) << run.err;
  const auto scale = run_cli({"check", "part.stl", "--scale", "0"});
  EXPECT_EQ(scale.exit_code, 2);
  EXPECT_EQ(scale.err,
            "strata: --scale: 0 is not a positive scale factor\nRun with --help for more "
            "information.\n");
}

}  // namespace
}  // namespace strata
