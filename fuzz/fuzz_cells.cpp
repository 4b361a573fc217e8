// Cells files, binary and ASCII. The reader takes a path, so each input is written to an
// in-memory file (memfd) and read back through /proc/self/fd, with the streaming reader, the
// summary and the whole-file reader.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_support.hpp"
#include "strata/io/read_cells.hpp"

namespace {

/// One memfd for the whole fuzzing session, truncated and rewritten for each input.
class MemoryFile {
 public:
  MemoryFile() : fd_(memfd_create("fuzz.cells", 0)) {
    if (fd_ < 0) {
      std::perror("memfd_create");
      std::abort();
    }
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  const std::string& write(const std::uint8_t* data, std::size_t size) {
    if (ftruncate(fd_, 0) != 0) std::abort();
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n = pwrite(fd_, data + done, size - done, static_cast<off_t>(done));
      if (n <= 0) std::abort();
      done += static_cast<std::size_t>(n);
    }
    return path_;
  }

 private:
  int fd_;
  std::string path_;
};

void check(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "fuzz check failed: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static MemoryFile file;
  const std::string& path = file.write(data, size);

  const strata::Result<strata::io::CellsSummary> summary = strata::io::summarize_cells(path);
  if (!summary) {
    strata::fuzz::check_read_error(summary.error());
  } else {
    const strata::GridSpec& g = summary->header.grid;
    check(summary->layer_counts.size() == g.nz, "one count per layer");
    check(summary->class_counts[0] + summary->class_counts[1] + summary->class_counts[2] ==
              g.cell_count(),
          "every cell is counted once");
  }

  const strata::Result<strata::io::CellsFile> whole = strata::io::read_cells(path);
  check(whole.has_value() == summary.has_value(), "read_cells and summarize_cells agree");
  if (whole) {
    check(whole->cells.size() == whole->header.grid.cell_count(), "read_cells holds every cell");
  }
  return 0;
}
