#include "cli/load_model.hpp"

#include <chrono>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::cli {

std::string model_stem(const std::filesystem::path& path) {
  std::filesystem::path name = path.filename();
  if (name.extension() == ".gz" || name.extension() == ".GZ") name = name.stem();
  std::string stem = name.stem().string();
  return stem.empty() ? std::string("model") : stem;
}

Error about_model(Error error, const std::filesystem::path& model) {
  if (error.location.empty()) error.location = model.string();
  return error;
}

Result<LoadedModel> load_model(const std::filesystem::path& path,
                               const io::CoordinateScale& scale) {
  using Clock = std::chrono::steady_clock;
  LoadedModel model;
  model.path = path;
  model.stem = model_stem(path);
  model.scale = scale;
  const auto t0 = Clock::now();
  auto soup = io::read_mesh(path, {}, scale);
  if (!soup) return soup.error();
  model.soup = std::move(soup).value();
  const auto t1 = Clock::now();
  model.mesh = weld_vertices(model.soup);
  const auto t2 = Clock::now();
  model.seconds_read = std::chrono::duration<double>(t1 - t0).count();
  model.seconds_weld = std::chrono::duration<double>(t2 - t1).count();
  return model;
}

}  // namespace strata::cli
