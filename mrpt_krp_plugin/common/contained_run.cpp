// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/contained_run.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {
/// The child's exit status when `work` threw: not a crash.
constexpr int kThrewExit = 3;
}  // namespace

void runContained(const std::function<void()>& work, const std::string& input, const std::string& what,
                  const ContainedRunParams& params) {
  const pid_t pid = ::fork();
  if (pid < 0) throw InputError(input, std::string("cannot start the check of ") + what + ": " + std::strerror(errno));
  if (pid == 0) {
    ::alarm(params.timeout_s);  // SIGALRM ends a reader that never returns
    int status = 0;
    try {
      work();
    } catch (...) {
      status = kThrewExit;
    }
    ::_exit(status);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw InputError(input, std::string("lost the check of ") + what + ": " + std::strerror(errno));
  }
  if (WIFEXITED(status) && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == kThrewExit)) return;
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
