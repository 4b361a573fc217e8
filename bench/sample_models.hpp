#pragma once

// The sample models of data/ the stage benchmarks run on, read and welded once a process, and
// the list of a model's facets a stage takes when no sweep has narrowed them.

#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::bench {

struct SampleModel {
  TriangleSoup soup;  ///< as read (the diagnosis reads its stored normals)
  IndexedMesh mesh;   ///< welded
};

/// The model at data/NAME, e.g. "real/rear_case.stl". Throws when it cannot be read.
inline const SampleModel& sample_model(const std::string& name) {
  static std::map<std::string, SampleModel> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    auto soup = io::read_mesh(std::string(STRATA_DATA_DIR) + "/" + name);
    if (!soup) throw std::runtime_error(soup.error().to_string());
    IndexedMesh mesh = weld_vertices(*soup);
    it = cache.emplace(name, SampleModel{std::move(*soup), std::move(mesh)}).first;
  }
  return it->second;
}

/// Every facet of `mesh`, in order: a layer's candidates when no sweep has narrowed them.
inline std::vector<FacetIndex> all_facets(const IndexedMesh& mesh) {
  std::vector<FacetIndex> all(mesh.triangles.size());
  std::iota(all.begin(), all.end(), FacetIndex{0});
  return all;
}

}  // namespace strata::bench
