#pragma once

#include <filesystem>
#include <string>

#include "strata/core/result.hpp"
#include "strata/io/length_unit.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::cli {

/// A model read and welded, with what the CLI reports about it.
struct LoadedModel {
  std::filesystem::path path;
  std::string stem;  ///< file name without its extensions (.stl, .stl.gz)
  TriangleSoup soup;
  IndexedMesh mesh;
  io::CoordinateScale scale;  ///< how the file's coordinates were converted to mm
  double seconds_read = 0.0;
  double seconds_weld = 0.0;
};

/// Reads (converting the coordinates to mm by `scale`) and welds a model; Error{BadInput} names
/// the file.
Result<LoadedModel> load_model(const std::filesystem::path& path,
                               const io::CoordinateScale& scale = {});

/// `error` located at the model when it names no place (a grid too large for the model, say),
/// so that every message about a model names its file.
Error about_model(Error error, const std::filesystem::path& model);

/// The model's stem: "part.stl.gz" -> "part".
std::string model_stem(const std::filesystem::path& path);

}  // namespace strata::cli
