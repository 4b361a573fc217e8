#include "strata/mesh/indexed_mesh.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace strata {
namespace {

/// The definition: the vertices added to an empty box one by one, in order.
Bbox3 box_one_by_one(const std::vector<Vec3>& vertices) {
  Bbox3 box;
  for (const Vec3& v : vertices) box.add(v);
  return box;
}

/// Bit for bit, so that -0 and +0 differ.
void expect_same_box(const Bbox3& got, const Bbox3& want) {
  const auto bits = [](const Vec3& p) {
    return std::vector<std::uint64_t>{std::bit_cast<std::uint64_t>(p.x),
                                      std::bit_cast<std::uint64_t>(p.y),
                                      std::bit_cast<std::uint64_t>(p.z)};
  };
  EXPECT_EQ(bits(got.min), bits(want.min));
  EXPECT_EQ(bits(got.max), bits(want.max));
}

TEST(IndexedMeshBounds, NoVerticesGiveTheEmptyBox) {
  const IndexedMesh mesh;
  EXPECT_TRUE(mesh.bounds().empty());
}

TEST(IndexedMeshBounds, AFewVerticesGiveTheirBox) {
  IndexedMesh mesh;
  mesh.vertices = {{1, -2, 3}, {-4, 5, 0.5}, {2, 2, -6}};
  const Bbox3 box = mesh.bounds();
  EXPECT_EQ(box.min, (Vec3{-4, -2, -6}));
  EXPECT_EQ(box.max, (Vec3{2, 5, 3}));
}

TEST(IndexedMeshBounds, ALargeMeshGivesTheBoxOfOnePassOnAnyNumberOfThreads) {
  // Enough vertices for many pieces. The bounds are zeros of both signs, met first at
  // different places (the first seen is kept), and NaN coordinates, which a box never takes.
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> inside(0.25, 0.75);
  constexpr std::size_t kVertices = 1'000'003;
  for (const bool negative_first : {false, true}) {
    SCOPED_TRACE(negative_first ? "-0 first" : "+0 first");
    IndexedMesh mesh;
    mesh.vertices.resize(kVertices);
    for (Vec3& v : mesh.vertices) v = {inside(random), inside(random), inside(random)};
    const double first = negative_first ? -0.0 : 0.0;
    const double second = -first;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // x: the least bound is zero, met at a piece's start, its end and a third time later.
    mesh.vertices[65'536].x = first;
    mesh.vertices[131'071].x = second;
    mesh.vertices[900'000].x = first;
    // y and z: the greatest bound, 1, and zeros as the least, in a late piece only.
    mesh.vertices[3].y = 1.0;
    mesh.vertices[999'999].y = 1.0;
    mesh.vertices[500'000].z = second;
    mesh.vertices[500'001].z = first;
    mesh.vertices[42].z = nan;
    mesh.vertices[kVertices - 1] = {nan, nan, nan};
    const Bbox3 want = box_one_by_one(mesh.vertices);
    ASSERT_EQ(std::signbit(want.min.x), negative_first);
    ASSERT_EQ(std::signbit(want.min.z), !negative_first);
    for (const std::size_t threads : {1U, 2U, 4U}) {
      SCOPED_TRACE("threads " + std::to_string(threads));
      const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      expect_same_box(mesh.bounds(), want);
    }
  }
}

}  // namespace
}  // namespace strata
