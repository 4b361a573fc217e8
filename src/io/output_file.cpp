#include "strata/io/output_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>

namespace strata::io {

namespace {

// Numbers the temporaries of one process so that several files written at once into the same
// folder (the layers of a PNG stack, two sinks of one run) never share a name.
std::atomic<unsigned> temp_counter{0};

Error write_error(const std::filesystem::path& path, std::string_view what, int err) {
  return Error{ErrorCode::BadInput, fmt::format("{}: {}", what, std::strerror(err)), path.string()};
}

}  // namespace

OutputFile::~OutputFile() { discard(); }

OutputFile::OutputFile(OutputFile&& other) noexcept
    : path_(std::move(other.path_)),
      temp_path_(std::move(other.temp_path_)),
      file_(std::exchange(other.file_, nullptr)),
      failed_(std::exchange(other.failed_, false)),
      errno_(std::exchange(other.errno_, 0)) {
  other.temp_path_.clear();
}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
  if (this != &other) {
    discard();
    path_ = std::move(other.path_);
    temp_path_ = std::move(other.temp_path_);
    other.temp_path_.clear();
    file_ = std::exchange(other.file_, nullptr);
    failed_ = std::exchange(other.failed_, false);
    errno_ = std::exchange(other.errno_, 0);
  }
  return *this;
}

Result<OutputFile> OutputFile::create(const std::filesystem::path& path) {
  if (path.empty() || !path.has_filename()) {
    return Error{ErrorCode::Usage, "an output file needs a file name", path.string()};
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return Error{ErrorCode::BadInput, "cannot write the file: a folder of that name exists",
                 path.string()};
  }
  const auto pid = static_cast<long>(::getpid());
  // "x" (exclusive) never opens a file that is already there: a leftover temporary of a crashed
  // run with the same pid is skipped rather than clobbered.
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::filesystem::path temp = path;
    temp += fmt::format(".tmp-{}-{}", pid, temp_counter.fetch_add(1));
    errno = 0;
    std::FILE* file = std::fopen(temp.c_str(), "wbx");
    if (file == nullptr) {
      if (errno == EEXIST) continue;
      return write_error(path, "cannot create the file", errno);
    }
    // Large buffer: the writers emit many small pieces (rows, numbers).
    std::setvbuf(file, nullptr, _IOFBF, std::size_t{1} << 20);
    OutputFile out;
    out.path_ = path;
    out.temp_path_ = std::move(temp);
    out.file_ = file;
    return out;
  }
  return Error{ErrorCode::BadInput, "cannot create a temporary file beside it", path.string()};
}

void OutputFile::write(std::string_view bytes) {
  if (file_ == nullptr || failed_ || bytes.empty()) return;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) {
    failed_ = true;
    errno_ = errno != 0 ? errno : EIO;
  }
}

Result<void> OutputFile::commit() {
  if (file_ == nullptr) {
    return Error{ErrorCode::Internal, "commit of an output file that is not open", path_.string()};
  }
  int err = failed_ ? errno_ : 0;
  if (err == 0 && (std::fflush(file_) != 0 || std::ferror(file_) != 0)) err = errno ? errno : EIO;
  const int close_result = std::fclose(file_);
  file_ = nullptr;
  if (err == 0 && close_result != 0) err = errno ? errno : EIO;
  if (err != 0) {
    discard();
    return write_error(path_, "cannot write the file", err);
  }
  std::error_code ec;
  std::filesystem::rename(temp_path_, path_, ec);
  if (ec) {
    discard();
    return Error{ErrorCode::BadInput,
                 fmt::format("cannot rename the finished temporary onto it: {}", ec.message()),
                 path_.string()};
  }
  temp_path_.clear();
  return {};
}

void OutputFile::discard() noexcept {
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
  if (!temp_path_.empty()) {
    std::error_code ec;
    std::filesystem::remove(temp_path_, ec);
    temp_path_.clear();
  }
  failed_ = false;
  errno_ = 0;
}

Result<void> write_text_file(const std::filesystem::path& path, std::string_view content) {
  auto out = OutputFile::create(path);
  if (!out) return out.error();
  out->write(content);
  return out->commit();
}

}  // namespace strata::io
