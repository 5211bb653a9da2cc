// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/contained_run.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {
/// The child's exit status when `work` threw something other than an InputError: not a crash.
constexpr int kThrewExit = 3;
/// The child's exit status when `work` threw an InputError, sent down the pipe.
constexpr int kInputErrorExit = 4;

void writeAll(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent then sees a short message and says so
    p += n;
    size -= static_cast<size_t>(n);
  }
}

/// A string as its length then its bytes.
void writeString(int fd, const std::string& s) {
  const uint64_t size = s.size();
  writeAll(fd, &size, sizeof size);
  writeAll(fd, s.data(), s.size());
}

/// Everything the child wrote, until it closed its end.
std::string readAll(int fd) {
  std::string out;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return out;
    out.append(buffer, static_cast<size_t>(n));
  }
}

/// Takes one length-prefixed string off the front of `bytes`; false when it is cut short.
bool takeString(std::string& bytes, std::string& s) {
  uint64_t size = 0;
  if (bytes.size() < sizeof size) return false;
  std::memcpy(&size, bytes.data(), sizeof size);
  if (bytes.size() - sizeof size < size) return false;
  s = bytes.substr(sizeof size, size);
  bytes.erase(0, sizeof size + size);
  return true;
}

void runChild(const std::function<void()>& work, int message_fd, unsigned timeout_s) {
  ::alarm(timeout_s);  // SIGALRM ends a reader that never returns
  int status = 0;
  try {
    work();
  } catch (const InputError& e) {
    writeString(message_fd, e.input());
    writeString(message_fd, e.problem());
    status = kInputErrorExit;
  } catch (...) {
    status = kThrewExit;
  }
  ::close(message_fd);
  ::_exit(status);
}
}  // namespace

void runContained(const std::function<void()>& work, const std::string& input, const std::string& what,
                  const ContainedRunParams& params) {
  int message_pipe[2];
  if (::pipe(message_pipe) != 0)
    throw InputError(input, std::string("cannot start the check of ") + what + ": " + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(message_pipe[0]);
    ::close(message_pipe[1]);
    throw InputError(input, std::string("cannot start the check of ") + what + ": " + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(message_pipe[0]);
    runChild(work, message_pipe[1], params.timeout_s);
  }
  ::close(message_pipe[1]);
  // Read before waiting: a long message would otherwise fill the pipe and stall the child.
  std::string message = readAll(message_pipe[0]);
  ::close(message_pipe[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw InputError(input, std::string("lost the check of ") + what + ": " + std::strerror(errno));
  }
  if (WIFEXITED(status) && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == kThrewExit)) return;
  if (WIFEXITED(status) && WEXITSTATUS(status) == kInputErrorExit) {
    std::string error_input, error_problem;
    if (takeString(message, error_input) && takeString(message, error_problem))
      throw InputError(error_input, error_problem);
    throw InputError(input, what + " refused the file, and its message was cut short");
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGALRM)
      throw InputError(input, what + " did not finish in " + std::to_string(params.timeout_s) + " s");
    throw InputError(input, what + " crashed (signal " + std::to_string(sig) + ", " + ::strsignal(sig) +
                                "): the file is corrupt");
  }
  // A sanitizer or a fuzzer reports a crash by exiting with its own status.
  throw InputError(input, what + " failed (exit status " + std::to_string(WEXITSTATUS(status)) +
                              "): the file is corrupt");
}

}  // namespace krp
