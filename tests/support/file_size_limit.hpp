#pragma once

#include <signal.h>
#include <sys/resource.h>

#include <cstdint>

namespace strata::test {

/// Makes this process's writes beyond `bytes` in any one file fail with EFBIG, as on a full disk:
/// lowers the soft RLIMIT_FSIZE and ignores SIGXFSZ (whose default action ends the process).
/// Both are restored when the object is destroyed. Not copyable.
///
///     {
///       FileSizeLimit limit(1000);
///       // a write past byte 1000 of a file now fails
///     }
class FileSizeLimit {
 public:
  /// Throws std::runtime_error when the limit or the signal disposition cannot be set.
  explicit FileSizeLimit(std::uint64_t bytes);
  ~FileSizeLimit();
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_limit_{};
  struct sigaction saved_action_ {};
};

}  // namespace strata::test
