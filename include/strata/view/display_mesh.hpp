#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"

namespace strata::view {

/// The triangles the view page draws: the model's own, or fewer when it has more than a budget.
struct DisplayMesh {
  std::vector<float> positions;        ///< x, y, z of each vertex, in millimetres
  std::vector<std::uint32_t> indices;  ///< three vertex indices a triangle, in the model's order
  std::size_t facets_in_model = 0;
  bool simplified = false;

  /// Triangles drawn.
  std::size_t facets() const { return indices.size() / 3; }
};

/// The most facets make_display_mesh gives to edge collapse, which costs microseconds a facet
/// (5 s for a million); beyond it a mesh is clustered first, in linear time.
inline constexpr std::size_t kCollapseAtMost = 200'000;

/// The display mesh of `mesh`: every facet when it has at most `max_facets`; otherwise about
/// `max_facets` facets. A mesh of more than max(`max_facets`, `collapse_at_most`) facets is first
/// clustered to that many, in linear time: the vertices in each cube of a grid become one at their
/// mean, and a facet is kept when its corners fall in three cubes (each set of three once) and the
/// clustering did not fold it over; the cube is the smallest that keeps few enough. What is
/// still over the budget is simplified by edge collapse (CGAL's Surface_mesh_simplification,
/// shortest edges first, on the mesh oriented and made manifold by CGAL's polygon soup
/// functions). Degenerate and repeated facets are left out of a simplified mesh. Only the
/// picture uses it: slicing always uses every facet of the model.
DisplayMesh make_display_mesh(const IndexedMesh& mesh, std::size_t max_facets,
                              std::size_t collapse_at_most = kCollapseAtMost);

/// Whether the page shows a model already sliced, for the note on a simplified display mesh.
enum class SliceStage { Sliced, NotSlicedYet };

/// How the note on a simplified display mesh writes its facet counts.
enum class CountDigits { Plain, GroupedByThousands };

/// A display mesh with the note the page shows about it.
struct NotedDisplayMesh {
  DisplayMesh mesh;
  /// "display mesh simplified from N to M facets for the browser; slicing used (uses) every
  /// facet" when the mesh was simplified; empty otherwise.
  std::optional<std::string> note;
};

/// make_display_mesh, and the note that says the picture was simplified when it was.
NotedDisplayMesh make_noted_display_mesh(const IndexedMesh& mesh, std::size_t max_facets,
                                         SliceStage stage, CountDigits digits);

}  // namespace strata::view
