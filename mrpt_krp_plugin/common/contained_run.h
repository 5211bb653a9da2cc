// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>

namespace krp {

/// Some third-party readers (MRPT's rawlog deserializer) crash on corrupt input instead of
/// throwing. Running them once in a child process first turns such a crash into an InputError
/// naming the input, and the parent then reads the input for real only once the child could.
struct ContainedRunParams {
  /// The child is killed after this long (a reader stuck in a loop) [s].
  unsigned timeout_s = 300;
};

/// Runs `work` in a forked child. Returns when it finished, or threw anything but an InputError
/// (that exception is the caller's own reader's business and shows again when the caller runs
/// it). Throws the child's InputError itself (same input and problem), so that a file already
/// found bad is not read a second time. Throws InputError(input, ...) when the child died by a
/// signal or exited abnormally, saying what `work` was doing (`what`). The child runs `work` and
/// leaves with _exit, without running exit handlers.
void runContained(const std::function<void()>& work, const std::string& input, const std::string& what,
                  const ContainedRunParams& params = {});

}  // namespace krp
