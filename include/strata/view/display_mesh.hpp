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

/// The display mesh of `mesh`: every facet when it has at most `max_facets`; otherwise a
/// simplification to about `max_facets` facets by edge collapse (CGAL's
/// Surface_mesh_simplification, shortest edges first, on the mesh oriented and made manifold by
/// CGAL's polygon soup functions). Degenerate facets are left out of a simplified mesh. Only
/// the picture uses it: slicing always uses every facet of the model.
DisplayMesh make_display_mesh(const IndexedMesh& mesh, std::size_t max_facets);

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
