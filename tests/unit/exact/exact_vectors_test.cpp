// The conformance vectors of ../shared/vectors sliced by the exact path: every cell of every
// layer must match the expected cells file.

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "exact_test_support.hpp"
#include "strata/io/read_cells.hpp"
#include "strata/io/read_mesh.hpp"

namespace strata {
namespace {

struct Vector {
  std::string model;
  double cell;
  double layer;
  double shell;
  ShellMode mode;
  FillRule rule;
  std::string expected;
};

void PrintTo(const Vector& v, std::ostream* os) { *os << v.expected; }

std::vector<Vector> vectors() {
  return {
      {"tetrahedron.stl", 1, 1, 1.5, ShellMode::Distance, FillRule::NonZero,
       "tetrahedron__cell1_layer1_shell1.5_distance_nonzero.cells"},
      {"tetrahedron.stl", 0.5, 0.25, 1, ShellMode::Layers, FillRule::NonZero,
       "tetrahedron__cell0.5_layer0.25_shell1_layers_nonzero.cells"},
      {"stacked_boxes.stl", 1, 1, 1, ShellMode::Layers, FillRule::NonZero,
       "stacked_boxes__cell1_layer1_shell1_layers_nonzero.cells"},
      {"stacked_boxes.stl", 0.5, 0.5, 0.6, ShellMode::Distance, FillRule::EvenOdd,
       "stacked_boxes__cell0.5_layer0.5_shell0.6_distance_evenodd.cells"},
      {"walls_through_centres.stl", 1, 1, 1, ShellMode::Layers, FillRule::NonZero,
       "walls_through_centres__cell1_layer1_shell1_layers_nonzero.cells"},
      {"overlapping_boxes.stl", 1, 1, 1, ShellMode::Layers, FillRule::NonZero,
       "overlapping_boxes__cell1_layer1_shell1_layers_nonzero.cells"},
      {"overlapping_boxes.stl", 1, 1, 1, ShellMode::Layers, FillRule::EvenOdd,
       "overlapping_boxes__cell1_layer1_shell1_layers_evenodd.cells"},
  };
}

std::filesystem::path vectors_dir() { return std::filesystem::path(STRATA_SHARED_DIR) / "vectors"; }

class ExactVectors : public ::testing::TestWithParam<Vector> {};

TEST_P(ExactVectors, CellsMatchTheExpectedFile) {
  const Vector& v = GetParam();
  auto soup = io::read_mesh(vectors_dir() / v.model);
  ASSERT_TRUE(soup.has_value()) << soup.error().to_string();
  const IndexedMesh mesh = weld_vertices(*soup);
  SliceOptions o;
  o.grid = GridOptions{v.cell, v.cell, v.layer, std::nullopt};
  o.shell_mm = v.shell;
  o.shell_mode = v.mode;
  o.fill_rule = v.rule;
  const auto grid = make_grid(mesh.bounds(), o.grid);
  ASSERT_TRUE(grid.has_value());
  const auto expected = io::read_cells(vectors_dir() / v.expected);
  ASSERT_TRUE(expected.has_value()) << expected.error().to_string();
  const GridSpec& g = expected->header.grid;
  ASSERT_EQ(grid->nx, g.nx);
  ASSERT_EQ(grid->ny, g.ny);
  ASSERT_EQ(grid->nz, g.nz);

  const auto r = exact_test::run_exact(mesh, *grid, o);
  ASSERT_TRUE(r.ok);
  std::size_t differ = 0;
  for (std::uint32_t k = 0; k < g.nz; ++k) {
    for (std::uint32_t j = 0; j < g.ny; ++j) {
      for (std::uint32_t i = 0; i < g.nx; ++i) {
        const CellClass got = r.sink.cells[k][std::size_t{j} * g.nx + i];
        if (got != expected->at(i, j, k)) {
          if (differ < 5) {
            ADD_FAILURE() << "cell (" << i << ", " << j << ", " << k << "): got "
                          << static_cast<int>(got) << ", expected "
                          << static_cast<int>(expected->at(i, j, k));
          }
          ++differ;
        }
      }
    }
  }
  EXPECT_EQ(differ, 0u);
}

INSTANTIATE_TEST_SUITE_P(Exact, ExactVectors, ::testing::ValuesIn(vectors()),
                         [](const ::testing::TestParamInfo<Vector>& info) {
                           std::string name = info.param.expected;
                           name = name.substr(0, name.find(".cells"));
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace strata
