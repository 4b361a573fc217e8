// The OpenVDB peer of bench/compare: a narrow-band signed distance field of a binary STL
// (openvdb::tools::meshToLevelSet) at 0.1 mm voxels, then its interior mask
// (openvdb::tools::sdfInteriorMask) — a solid grid with a surface band, the work strata's cells
// do. The band's half width defaults to 5 voxels, strata's 0.5 mm shell. Prints the active voxel
// counts so the work is not optimised away.
// Usage: strata_peer_openvdb_level_set MODEL.stl [VOXEL_MM [HALF_WIDTH_VOXELS]]
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/MeshToVolume.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "binary_stl.hpp"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fputs("usage: strata_peer_openvdb_level_set MODEL.stl [VOXEL_MM [HALF_WIDTH_VOXELS]]\n",
               stderr);
    return 2;
  }
  try {
    const double voxel_mm = argc > 2 ? std::stod(argv[2]) : 0.1;
    const float half_width = argc > 3 ? std::stof(argv[3]) : 5.0f;
    const auto stl = strata::bench::read_binary_stl(argv[1]);
    openvdb::initialize();
    std::vector<openvdb::Vec3s> points;
    points.reserve(stl.vertices.size());
    for (const auto& v : stl.vertices) points.emplace_back(v[0], v[1], v[2]);
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(stl.triangles.size());
    for (const auto& t : stl.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    const auto transform = openvdb::math::Transform::createLinearTransform(voxel_mm);
    const auto distance = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points,
                                                                             triangles, half_width);
    const auto interior = openvdb::tools::sdfInteriorMask(*distance);
    std::printf("band voxels %llu interior voxels %llu\n",
                static_cast<unsigned long long>(distance->activeVoxelCount()),
                static_cast<unsigned long long>(interior->activeVoxelCount()));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "strata_peer_openvdb_level_set: %s\n", e.what());
    return 1;
  }
}
