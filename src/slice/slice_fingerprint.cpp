#include "strata/slice/slice_fingerprint.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "core/sha256.hpp"

namespace strata {

std::string cell_options_text(const SliceOptions& o) {
  std::string origin = "auto";
  if (o.grid.origin) {
    origin = fmt::format("{:a},{:a},{:a}", o.grid.origin->x, o.grid.origin->y, o.grid.origin->z);
  }
  return fmt::format(
      "dx={:a};dy={:a};dz={:a};origin={};shell={:a};shell_mode={};fill_rule={};scan_offset={:a}",
      o.grid.dx_mm, o.grid.dy_mm, o.grid.dz_mm, origin, o.shell_mm, to_string(o.shell_mode),
      to_string(o.fill_rule), o.scan_offset_mm);
}

Result<std::string> slice_fingerprint(const std::filesystem::path& model,
                                      std::string_view options_text) {
  const auto close = [](std::FILE* f) { std::fclose(f); };
  std::unique_ptr<std::FILE, decltype(close)> file(std::fopen(model.c_str(), "rb"), close);
  if (!file) {
    return Error{ErrorCode::BadInput,
                 fmt::format("cannot read the model: {}", std::strerror(errno)), model.string()};
  }
  detail::Sha256 hash;
  std::vector<char> buffer(std::size_t{1} << 16);
  std::size_t got = 0;
  while ((got = std::fread(buffer.data(), 1, buffer.size(), file.get())) > 0) {
    hash.update(std::string_view(buffer.data(), got));
  }
  if (std::ferror(file.get())) {
    return Error{ErrorCode::BadInput, "cannot read the model: read error", model.string()};
  }
  // The model's digest has a fixed length, so no model can shift its bytes into the options.
  detail::Sha256 run;
  run.update(hash.hex_digest());
  run.update("\n");
  run.update(options_text);
  return run.hex_digest();
}

}  // namespace strata
