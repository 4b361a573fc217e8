#pragma once

#include <cstdio>
#include <filesystem>
#include <string_view>

#include "strata/core/result.hpp"

namespace strata::io {

/// A file written under a temporary name in its target folder and renamed into place by
/// commit(), so a failed run never leaves a partial file. Destroying it uncommitted removes the
/// temporary. Not copyable; movable.
///
/// Failures to create, write or rename are reported as Error{BadInput} whose location is the
/// final path and whose message carries the system's reason ("No space left on device").
class OutputFile {
 public:
  OutputFile() = default;
  ~OutputFile();
  /// Takes over `other`'s temporary file; `other` is left holding none.
  OutputFile(OutputFile&& other) noexcept;
  /// Removes this file's uncommitted temporary, then takes over `other`'s.
  OutputFile& operator=(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Creates `<path>.tmp-<pid>-<n>` for writing (binary mode). The folder must exist.
  static Result<OutputFile> create(const std::filesystem::path& path);

  /// Appends bytes; the first write error is remembered and reported by commit().
  void write(std::string_view bytes);
  /// The open stream, for libraries that write through a FILE*; errors on it are caught by
  /// commit() too. nullptr once committed or discarded.
  std::FILE* stream() { return file_; }
  /// The final path.
  const std::filesystem::path& path() const { return path_; }
  /// The temporary path while the file is open; empty once committed or discarded.
  const std::filesystem::path& temp_path() const { return temp_path_; }

  /// Flushes, closes and renames the temporary onto the final path (replacing a file of that
  /// name). On failure the temporary is removed.
  Result<void> commit();
  /// Closes and removes the temporary (idempotent, never throws).
  void discard() noexcept;

 private:
  std::filesystem::path path_;
  std::filesystem::path temp_path_;
  std::FILE* file_ = nullptr;
  bool failed_ = false;
  int errno_ = 0;  ///< errno of the first failed write
};

/// Writes `content` to `path` atomically (temporary in the same folder, then rename), e.g. the
/// JSON report. The folder must exist.
/// @return Error{BadInput} naming the path when the file cannot be written.
Result<void> write_text_file(const std::filesystem::path& path, std::string_view content);

}  // namespace strata::io
