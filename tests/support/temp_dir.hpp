#pragma once

#include <filesystem>
#include <string_view>

namespace strata::test {

/// A new, empty directory with a unique name under the system temporary folder
/// (std::filesystem::temp_directory_path(), i.e. $TMPDIR or /tmp), removed with everything in it
/// when the object is destroyed. Not copyable; movable.
///
///     TempDir dir;
///     write_stl(dir / "cube.stl", make_box(...));
class TempDir {
 public:
  /// Creates `<tmp>/strata-<prefix>-XXXXXX`; throws std::runtime_error when that fails.
  explicit TempDir(std::string_view prefix = "test");
  ~TempDir();
  TempDir(TempDir&& other) noexcept;
  TempDir& operator=(TempDir&& other) noexcept;
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// The directory (absolute); empty after being moved from.
  const std::filesystem::path& path() const { return path_; }
  /// A path inside the directory (nothing is created).
  std::filesystem::path operator/(const std::filesystem::path& name) const { return path_ / name; }

 private:
  void remove() noexcept;
  std::filesystem::path path_;
};

}  // namespace strata::test
