#include "fuzz_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "strata/mesh/weld_vertices.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slicer/slice_model.hpp"

namespace strata::fuzz {
namespace {

/// Meshes with more triangles are read but not sliced, to keep a run in milliseconds.
constexpr std::size_t kMaxSliceTriangles = 4096;
/// Coordinates beyond this (1e15 mm, a million kilometres) are not sliced: products of such
/// coordinates leave the range where the grid arithmetic means anything.
constexpr double kMaxSliceCoordinateMm = 1e15;
/// An axis along which the mesh spans less than this (1e-30 mm) gets a single cell of 1 mm: cells
/// of denormal size send every decision to the exact fallback, seconds a layer.
constexpr double kMinSliceExtentMm = 1e-30;
constexpr std::uint32_t kMaxCellsXY = 64;
constexpr std::uint32_t kMaxCellsZ = 16;

/// Checks what the pipeline promises every sink: layers in order, nx * ny valid classes each.
class CheckingSink final : public LayerSink {
 public:
  Result<void> begin(const SliceRunInfo& run) override {
    grid_ = run.grid;
    begun_ = true;
    return {};
  }
  Result<void> add_layer(const LayerResult& layer) override {
    check(begun_, "add_layer before begin");
    check(layer.layer == next_, "layers arrive in increasing k without gaps");
    check(layer.layer < grid_.nz, "layer index inside the grid");
    check(layer.cells.size() == grid_.cells_per_layer(), "a layer has nx * ny cells");
    for (const CellClass c : layer.cells) {
      check(c == CellClass::Empty || c == CellClass::Interior || c == CellClass::Boundary,
            "cell class is 00, 01 or 11");
    }
    for (const Contour& loop : layer.contours.loops) {
      check(!loop.points.empty(), "a contour has points");
      for (const Point2& p : loop.points) {
        check(std::isfinite(p.x) && std::isfinite(p.y), "contour points are finite");
      }
    }
    ++next_;
    return {};
  }
  Result<void> finish() override {
    check(next_ == grid_.nz, "every layer reaches the sink before finish");
    finished_ = true;
    return {};
  }
  void abort() noexcept override { fail("abort called on a sink of a run that cannot fail"); }

  bool finished() const { return finished_; }

 private:
  GridSpec grid_;
  std::uint32_t next_ = 0;
  bool begun_ = false;
  bool finished_ = false;
};

}  // namespace

void fail(const char* what) {
  std::fprintf(stderr, "fuzz check failed: %s\n", what);
  std::fflush(stderr);
  std::abort();
}

void check(bool condition, const char* what) {
  if (!condition) fail(what);
}

io::ReadLimits read_limits() {
  io::ReadLimits limits;
  limits.max_triangles = 1 << 14;
  limits.max_line_bytes = 1 << 16;
  limits.max_decompressed_bytes = 1 << 22;
  return limits;
}

std::uint64_t hash_bytes(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

void check_read_error(const Error& error) {
  check(error.code == ErrorCode::BadInput, "a read error is Error{BadInput}");
  check(!error.message.empty(), "a read error has a message");
}

void check_soup(const TriangleSoup& soup, const io::ReadLimits& limits) {
  check(!soup.triangles.empty(), "a successful read has triangles");
  check(soup.triangles.size() <= limits.max_triangles, "a read respects max_triangles");
  check(soup.stored_normals.empty() || soup.stored_normals.size() == soup.triangles.size(),
        "stored normals are absent or one per triangle");
  check(!soup.format.empty(), "a successful read names the format");
  for (const auto& triangle : soup.triangles) {
    for (const Vec3& p : triangle) {
      check(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z),
            "coordinates of a read mesh are finite");
    }
  }
}

void slice_small(const TriangleSoup& soup, std::uint64_t seed) {
  if (soup.triangles.size() > kMaxSliceTriangles) return;
  const IndexedMesh mesh = weld_vertices(soup);
  check(mesh.triangles.size() == soup.triangles.size(), "weld keeps every triangle");
  const Bbox3 box = mesh.bounds();
  if (box.empty()) return;
  const std::array<double, 3> lo{box.min.x, box.min.y, box.min.z};
  const std::array<double, 3> hi{box.max.x, box.max.y, box.max.z};
  for (int a = 0; a < 3; ++a) {
    if (!(std::fabs(lo[a]) <= kMaxSliceCoordinateMm && std::fabs(hi[a]) <= kMaxSliceCoordinateMm))
      return;
  }

  // Cells per axis and options, all picked by the input's hash.
  // Mostly coarse grids (fast runs, many inputs a second), now and then up to the caps.
  const bool fine = (seed >> 23) % 8 == 0;
  const std::uint32_t n_xy =
      1 + static_cast<std::uint32_t>(seed % (fine ? kMaxCellsXY - 1 : kMaxCellsXY / 4));
  const std::uint32_t n_z =
      1 + static_cast<std::uint32_t>((seed >> 8) % (fine ? kMaxCellsZ - 1 : kMaxCellsZ / 4));
  const std::array<std::uint32_t, 3> n{n_xy, n_xy, n_z};
  std::array<double, 3> d{};
  for (int a = 0; a < 3; ++a) {
    const double extent = hi[a] - lo[a];
    d[a] = extent >= kMinSliceExtentMm ? extent / n[a] : 1.0;
    if (!(d[a] > 0) || !std::isfinite(d[a])) return;  // an extent too small to divide
  }
  SliceOptions options;
  options.grid = GridOptions{d[0], d[1], d[2], std::nullopt};
  options.shell_mode = (seed >> 16) & 1 ? ShellMode::Layers : ShellMode::Distance;
  options.fill_rule = (seed >> 17) & 1 ? FillRule::EvenOdd : FillRule::NonZero;
  options.scan_offset_mm = (seed >> 18) & 1 ? 1e-4 : 0.0;
  constexpr std::array<double, 4> kShellInCells{0.0, 0.5, 1.0, 2.5};
  // In units of the smallest cell size: at most two rings of cells in `layers` mode, however
  // unequal the sizes (the ring count of a thicker shell costs time, not coverage).
  options.shell_mm = kShellInCells[(seed >> 19) & 3] * std::min({d[0], d[1], d[2]});
  options.batch_layers = 1 + static_cast<int>((seed >> 21) & 3);
  options.threads = 1;

  const Result<GridSpec> grid = make_grid(box, options.grid);
  if (!grid) return;
  if (grid->nx > kMaxCellsXY || grid->ny > kMaxCellsXY || grid->nz > kMaxCellsZ) return;

  CheckingSink sink;
  LayerSink* sinks[] = {&sink};
  const Result<SliceSummary> summary = slice_model(mesh, *grid, options, sinks);
  if (!summary) {
    std::fprintf(stderr, "slice_model: %s\n", summary.error().to_string().c_str());
    fail("slice_model fails with no sink error and a supported fill rule");
  }
  check(sink.finished(), "the sink is finished");
  check(summary->layers.size() == grid->nz, "one LayerStats per layer");
  check(summary->class_counts[1] + summary->class_counts[2] <= grid->cell_count(),
        "no more solid cells than cells");
}

void read_and_slice(std::string_view bytes, std::string_view name) {
  const io::ReadLimits limits = read_limits();
  const Result<TriangleSoup> soup = io::read_mesh_bytes(bytes, name, limits);
  if (!soup) {
    check_read_error(soup.error());
    return;
  }
  check_soup(*soup, limits);
  slice_small(*soup, hash_bytes(bytes));
}

}  // namespace strata::fuzz
