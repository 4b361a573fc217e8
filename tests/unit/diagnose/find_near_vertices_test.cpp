#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

#include "diagnose/find_near_vertices_internal.hpp"

namespace strata::diagnose::detail {
namespace {

/// The search by its definition, one vertex after the other: vertex i checks the higher vertices
/// of the cells (twice the tolerance wide, from the bounds' corner) its ball meets, cell by cell
/// in order of (x, y, z) and each cell's vertices in increasing order. Each check in that order,
/// with the pair it finds, if any.
std::vector<std::optional<PointPair>> every_check(const IndexedMesh& mesh, double tolerance) {
  const Bbox3 bounds = mesh.bounds();
  const double cell = 2.0 * tolerance;
  using Cell = std::tuple<std::int64_t, std::int64_t, std::int64_t>;
  const auto cell_of = [&](const Vec3& p, double shift) {
    return Cell{static_cast<std::int64_t>(std::floor((p.x - bounds.min.x + shift) / cell)),
                static_cast<std::int64_t>(std::floor((p.y - bounds.min.y + shift) / cell)),
                static_cast<std::int64_t>(std::floor((p.z - bounds.min.z + shift) / cell))};
  };
  std::vector<std::pair<Cell, VertexIndex>> sorted;
  for (VertexIndex v = 0; v < mesh.vertices.size(); ++v) {
    sorted.push_back({cell_of(mesh.vertices[v], 0.0), v});
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::optional<PointPair>> checks;
  for (VertexIndex i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const auto [x0, y0, z0] = cell_of(p, -tolerance);
    const auto [x1, y1, z1] = cell_of(p, tolerance);
    for (std::int64_t x = x0; x <= x1; ++x) {
      for (std::int64_t y = y0; y <= y1; ++y) {
        for (std::int64_t z = z0; z <= z1; ++z) {
          const auto first = std::lower_bound(sorted.begin(), sorted.end(),
                                              std::pair{Cell{x, y, z}, VertexIndex{0}});
          for (auto it = first; it != sorted.end() && it->first == Cell{x, y, z}; ++it) {
            if (it->second <= i) continue;
            const Vec3& q = mesh.vertices[it->second];
            const double dx = q.x - p.x, dy = q.y - p.y, dz = q.z - p.z;
            checks.push_back(dx * dx + dy * dy + dz * dz < tolerance * tolerance
                                 ? std::optional<PointPair>(PointPair{p, q})
                                 : std::nullopt);
          }
        }
      }
    }
  }
  return checks;
}

/// What the search finds when it stops at the check past `max_checks` and keeps `limit` pairs.
NearVertices one_by_one(const std::vector<std::optional<PointPair>>& checks, std::size_t max_checks,
                        std::size_t limit) {
  NearVertices out;
  out.truncated = max_checks < checks.size();
  for (std::size_t k = 0; k < std::min(max_checks, checks.size()); ++k) {
    if (!checks[k]) continue;
    ++out.pairs.count;
    if (out.pairs.locations.size() < limit) out.pairs.locations.push_back(*checks[k]);
  }
  return out;
}

/// 70,000 vertices (several rounds of stretches on one, two or four threads) in a 40 mm cube,
/// a tenth of them planted next to an earlier one (closer than the tolerance or just past it), a
/// few of those in threes.
IndexedMesh scattered_vertices() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(0.0, 40.0);
  std::uniform_real_distribution<double> offset(-0.4, 0.4);
  IndexedMesh mesh;
  while (mesh.vertices.size() < 70'000) {
    if (mesh.vertices.size() > 10 && rng() % 10 == 0) {
      const Vec3 near = mesh.vertices[rng() % mesh.vertices.size()];
      mesh.vertices.push_back({near.x + offset(rng), near.y + offset(rng), near.z + offset(rng)});
    } else {
      mesh.vertices.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
    }
  }
  return mesh;
}

void expect_same(const NearVertices& found, const NearVertices& expected) {
  EXPECT_EQ(found.truncated, expected.truncated);
  EXPECT_EQ(found.pairs.count, expected.pairs.count);
  ASSERT_EQ(found.pairs.locations.size(), expected.pairs.locations.size());
  for (std::size_t k = 0; k < found.pairs.locations.size(); ++k) {
    const PointPair& a = found.pairs.locations[k];
    const PointPair& b = expected.pairs.locations[k];
    ASSERT_TRUE(a.first == b.first && a.second == b.second) << "pair " << k;
  }
}

TEST(FindNearVertices, FindsWhatCheckingOneVertexAfterTheOtherFinds) {
  const IndexedMesh mesh = scattered_vertices();
  constexpr double kTolerance = 0.25;
  constexpr std::size_t kAll = std::numeric_limits<std::size_t>::max();
  const auto checks = every_check(mesh, kTolerance);
  const NearVertices every = one_by_one(checks, kAll, kAll);
  ASSERT_GT(every.pairs.count, 1000U);  // planted pairs, and the random ones that happen to be
  for (const int threads : {1, 2, 4}) {
    SCOPED_TRACE(threads);
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    expect_same(find_near_vertices(mesh, mesh.bounds(), kTolerance, kAll, kAll), every);
    // The first few pairs kept, every one counted.
    expect_same(find_near_vertices(mesh, mesh.bounds(), kTolerance, kAll, 7),
                one_by_one(checks, kAll, 7));
  }
}

TEST(FindNearVertices, StopsAtTheCheckWhereOneVertexAfterTheOtherWould) {
  const IndexedMesh mesh = scattered_vertices();
  constexpr double kTolerance = 0.25;
  constexpr std::size_t kAll = std::numeric_limits<std::size_t>::max();
  const auto checks = every_check(mesh, kTolerance);
  const std::size_t total = checks.size();
  ASSERT_GT(total, 20'000U);
  // Limits in the first stretch, in the middle of later rounds (a round is 4 stretches of 8,192
  // vertices a thread), and at the end.
  for (const std::size_t max_checks :
       {std::size_t{0}, std::size_t{5'000}, total / 2 + 17, total - 1, total}) {
    SCOPED_TRACE(max_checks);
    const NearVertices expected = one_by_one(checks, max_checks, kAll);
    for (const int threads : {1, 2}) {
      SCOPED_TRACE(threads);
      const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      expect_same(find_near_vertices(mesh, mesh.bounds(), kTolerance, max_checks, kAll), expected);
    }
  }
}

TEST(FindNearVertices, AllInOneCellAreEachPairOnce) {
  // Ten copies of each of two points 0.15 apart, all in one cell: 45 pairs of copies of each,
  // and none across.
  IndexedMesh mesh;
  for (int k = 0; k < 10; ++k) {
    mesh.vertices.push_back({0.0, 0.0, 0.0});
    mesh.vertices.push_back({0.15, 0.0, 0.0});
  }
  mesh.vertices.push_back({5.0, 5.0, 5.0});
  const NearVertices found = find_near_vertices(mesh, mesh.bounds(), 0.1, 1'000, 1'000);
  EXPECT_FALSE(found.truncated);
  EXPECT_EQ(found.pairs.count, 90U);
  expect_same(found, one_by_one(every_check(mesh, 0.1), 1'000, 1'000));
}

}  // namespace
}  // namespace strata::diagnose::detail
