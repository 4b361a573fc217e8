#include "support/run_cli.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace strata::test {
namespace {

[[noreturn]] void fail(const std::string& what, int error = errno) {
  throw std::runtime_error("run_cli: " + what + ": " + std::strerror(error));
}

/// Closes a descriptor once; -1 means closed.
void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

/// Standard input for the child: the text in an unlinked temporary file (no pipe, so a child that
/// never reads cannot block the test), or /dev/null.
int stdin_fd(std::string_view text) {
  if (text.empty()) {
    const int fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail("cannot open /dev/null");
    return fd;
  }
  std::FILE* f = std::tmpfile();
  if (f == nullptr) fail("cannot create a temporary file for stdin");
  const int fd = ::fcntl(::fileno(f), F_DUPFD_CLOEXEC, 0);
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
  std::fclose(f);
  if (fd < 0 || !ok || ::lseek(fd, 0, SEEK_SET) != 0) {
    const int error = errno;
    if (fd >= 0) ::close(fd);
    fail("cannot write stdin text", error);
  }
  return fd;
}

}  // namespace

std::filesystem::path cli_path() { return STRATA_CLI_PATH; }

CliRun run_cli(std::vector<std::string> args, std::string_view stdin_text,
               const CliRunOptions& options) {
  const std::string exe = cli_path().string();
  args.insert(args.begin(), exe);
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string dir = options.working_dir.string();

  int in = stdin_fd(stdin_text);
  std::array<int, 2> out_pipe{-1, -1};
  std::array<int, 2> err_pipe{-1, -1};
  // O_CLOEXEC: children spawned concurrently by other threads must not inherit our pipe ends.
  if (::pipe2(out_pipe.data(), O_CLOEXEC) != 0 || ::pipe2(err_pipe.data(), O_CLOEXEC) != 0) {
    const int error = errno;
    close_fd(in);
    close_fd(out_pipe[0]);
    close_fd(out_pipe[1]);
    fail("cannot create pipes", error);
  }

  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    close_fd(in);
    for (int* fd : {&out_pipe[0], &out_pipe[1], &err_pipe[0], &err_pipe[1]}) close_fd(*fd);
    fail("fork failed", error);
  }
  if (pid == 0) {
    // Child: only async-signal-safe calls until exec.
    if (::dup2(in, 0) < 0 || ::dup2(out_pipe[1], 1) < 0 || ::dup2(err_pipe[1], 2) < 0) _exit(126);
    if (!dir.empty() && ::chdir(dir.c_str()) != 0) {
      constexpr char kMsg[] = "run_cli: cannot enter the working directory\n";
      [[maybe_unused]] auto n = ::write(2, kMsg, sizeof kMsg - 1);
      _exit(126);
    }
    ::execv(exe.c_str(), argv.data());
    constexpr char kMsg[] = "run_cli: cannot execute the strata executable\n";
    [[maybe_unused]] auto n = ::write(2, kMsg, sizeof kMsg - 1);
    _exit(127);
  }

  close_fd(in);
  close_fd(out_pipe[1]);
  close_fd(err_pipe[1]);
  CliRun run;
  const auto deadline = std::chrono::steady_clock::now() + options.timeout;
  std::array<pollfd, 2> fds{pollfd{out_pipe[0], POLLIN, 0}, pollfd{err_pipe[0], POLLIN, 0}};
  std::array<std::string*, 2> sinks{&run.out, &run.err};
  std::array<char, 65536> buffer{};
  while (fds[0].fd >= 0 || fds[1].fd >= 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      run.timed_out = true;
      ::kill(pid, SIGKILL);
      break;
    }
    const int ready = ::poll(fds.data(), fds.size(), static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) {
      ::kill(pid, SIGKILL);
      break;
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].fd < 0 || fds[i].revents == 0) continue;
      const ssize_t n = ::read(fds[i].fd, buffer.data(), buffer.size());
      if (n > 0) {
        sinks[i]->append(buffer.data(), static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        close_fd(fds[i].fd);  // end of file, or a broken pipe
      }
    }
  }
  for (auto& p : fds) close_fd(p.fd);  // the read ends; pollfd holds the only copy

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) fail("waitpid failed");
  }
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.term_signal = WTERMSIG(status);
  return run;
}

}  // namespace strata::test
