#include "support/file_size_limit.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace strata::test {

FileSizeLimit::FileSizeLimit(std::uint64_t bytes) {
  if (::getrlimit(RLIMIT_FSIZE, &saved_limit_) != 0) {
    throw std::runtime_error(std::string("getrlimit(RLIMIT_FSIZE): ") + std::strerror(errno));
  }
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  if (::sigaction(SIGXFSZ, &ignore, &saved_action_) != 0) {
    throw std::runtime_error(std::string("sigaction(SIGXFSZ): ") + std::strerror(errno));
  }
  rlimit lowered = saved_limit_;
  lowered.rlim_cur = static_cast<rlim_t>(bytes);
  if (::setrlimit(RLIMIT_FSIZE, &lowered) != 0) {
    const int err = errno;
    ::sigaction(SIGXFSZ, &saved_action_, nullptr);
    throw std::runtime_error(std::string("setrlimit(RLIMIT_FSIZE): ") + std::strerror(err));
  }
}

FileSizeLimit::~FileSizeLimit() {
  ::setrlimit(RLIMIT_FSIZE, &saved_limit_);
  ::sigaction(SIGXFSZ, &saved_action_, nullptr);
}

}  // namespace strata::test
