// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <string>

namespace krp {

/// A one-line text progress bar with elapsed time and an estimate of the time left.
/// Draws on a terminal with carriage returns; on a pipe or CI log it prints a line every
/// `log_every_percent` so logs stay short.
class ProgressBar {
 public:
  ProgressBar(std::string label, std::size_t total, std::ostream& out);
  void advance(std::size_t steps = 1, const std::string& note = "");
  void finish();

 private:
  void draw(const std::string& note);

  std::string label_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::ostream& out_;
  bool interactive_;
  int last_logged_percent_ = -1;
  static constexpr int kLogEveryPercent = 10;  ///< log line interval on non-terminals [%]
  static constexpr int kBarWidth = 30;         ///< characters
  std::chrono::steady_clock::time_point start_;
  bool finished_ = false;
};

}  // namespace krp
