// The read floor of bench/compare: what strata slice does before any slicing — read the model
// (io::read_mesh) and weld its corners (weld_vertices) — and nothing else, through the public
// API. Prints the counts so the work is not optimised away.
// Usage: strata_read_floor MODEL
#include <cstdio>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fputs("usage: strata_read_floor MODEL\n", stderr);
    return 2;
  }
  auto soup = strata::io::read_mesh(argv[1]);
  if (!soup) {
    std::fprintf(stderr, "strata_read_floor: %s\n", soup.error().to_string().c_str());
    return 1;
  }
  const strata::IndexedMesh mesh = strata::weld_vertices(*soup);
  std::printf("facets %zu vertices %zu\n", mesh.triangles.size(), mesh.vertices.size());
  return 0;
}
