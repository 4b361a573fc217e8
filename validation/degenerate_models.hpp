#pragma once

#include <string>
#include <vector>

#include "strata/mesh/triangle_soup.hpp"

namespace strata::validation {

/// A model built to sit on the ties of the slicing rules, with the grid it was built for.
struct GeneratedModel {
  std::string name;     ///< file-name friendly, e.g. "box-faces-on-ties"
  std::string defects;  ///< what the model does to the slicer, for the report
  TriangleSoup soup;
  /// The aligned grid: cells of this size (x, y and layers) from the bounding box's minimum
  /// corner put the model's features on cell centres, scanlines and layer planes.
  double cell_mm = 1.0;
};

/// The degenerate models of the validation suite. All coordinates are float32 values (held as
/// double), so each model is bit-identical to its binary STL. With the aligned grid (origin at
/// the bounding box minimum, cell `cell_mm`), the models place on purpose: facets, edges and
/// vertices on layer planes z = z0 + (k + 1/2) d, on scanlines y = y0 + (j + 1/2) d and on cell
/// centres; coplanar facets; slivers and needles; zero-area and duplicate facets; T-junctions
/// (open and sealed); non-manifold edges and vertices; open meshes; overlapping, nested,
/// hollow and inverted shells; features thinner than a cell; and a part at machine
/// coordinates (x = 1500 mm, y = 900 mm) with 0.1 mm features.
std::vector<GeneratedModel> degenerate_models();

}  // namespace strata::validation
