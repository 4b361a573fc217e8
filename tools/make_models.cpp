// strata-make-models: writes the generated sample models of data/ (see data/SOURCES.md).
//
//   strata-make-models OUT_DIR
//
// Exit codes as the strata command: 0 success, 1 a file could not be written, 2 bad usage.

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <system_error>
#include <vector>

#include "strata/io/write_stl.hpp"
#include "strata/mesh/primitive_models.hpp"

namespace {

using strata::TriangleSoup;
using strata::io::StlEncoding;

struct SampleModel {
  std::string file_name;
  StlEncoding encoding;
  TriangleSoup soup;
  double reference_volume_mm3;  // the analytic solid the model stands for
};

// Divergence theorem; printed so that a regenerated file can be checked at a glance.
double polyhedron_volume_mm3(const TriangleSoup& soup) {
  double six_v = 0;
  for (const auto& [a, b, c] : soup.triangles) {
    six_v += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
             a.z * (b.x * c.y - b.y * c.x);
  }
  return six_v / 6;
}

// The two test shapes of entity slicing, a tetrahedron (the 10 mm corner) and a ring, plus a
// sphere fine enough that its volume is within 1% of the ball's (0.22% at 4 subdivisions).
constexpr double kRingOuterMm = 20;
constexpr double kRingInnerMm = 12;
constexpr double kRingHeightMm = 10;
constexpr int kRingSegments = 128;
constexpr double kSphereRadiusMm = 10;
constexpr int kSphereSubdivisions = 4;

std::vector<SampleModel> sample_models() {
  namespace mesh = strata::mesh;
  const double ring_volume = std::numbers::pi * kRingHeightMm *
                             (kRingOuterMm * kRingOuterMm - kRingInnerMm * kRingInnerMm);
  const double ball_volume = 4.0 / 3.0 * std::numbers::pi * std::pow(kSphereRadiusMm, 3);
  std::vector<SampleModel> models;
  models.push_back({"tetrahedron.stl", StlEncoding::Binary, mesh::make_tetrahedron(), 1000.0 / 6});
  models.push_back(
      {"tetrahedron_ascii.stl", StlEncoding::Ascii, mesh::make_tetrahedron(), 1000.0 / 6});
  models.push_back({"ring.stl", StlEncoding::Binary,
                    mesh::make_ring(kRingOuterMm, kRingInnerMm, kRingHeightMm, kRingSegments),
                    ring_volume});
  models.push_back({"sphere.stl", StlEncoding::Binary,
                    mesh::make_sphere(kSphereRadiusMm, kSphereSubdivisions), ball_volume});
  return models;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    fmt::print(stderr,
               "usage: strata-make-models OUT_DIR\n"
               "writes tetrahedron.stl, tetrahedron_ascii.stl, ring.stl and sphere.stl\n");
    return argc == 2 ? 0 : 2;
  }
  const std::filesystem::path out_dir = argv[1];
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) {
    fmt::print(stderr, "strata-make-models: cannot create {}: {}\n", out_dir.string(),
               ec.message());
    return 1;
  }
  for (const auto& model : sample_models()) {
    const auto path = out_dir / model.file_name;
    const auto written = strata::io::write_stl(path, model.soup, model.encoding);
    if (!written) {
      fmt::print(stderr, "strata-make-models: {}\n", written.error().to_string());
      return 1;
    }
    const double volume = polyhedron_volume_mm3(model.soup);
    fmt::print("{}: {} facets, {}, volume {:.4f} mm^3 ({:+.3f}% vs the true solid)\n",
               path.string(), model.soup.triangles.size(),
               model.encoding == StlEncoding::Binary ? "binary" : "ASCII", volume,
               100 * (volume / model.reference_volume_mm3 - 1));
  }
  return 0;
}
