// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/progress_bar.h"

#include <unistd.h>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace krp {

ProgressBar::ProgressBar(std::string label, std::size_t total, std::ostream& out)
    : label_(std::move(label)),
      total_(total == 0 ? 1 : total),
      out_(out),
      interactive_(&out == &std::cerr ? isatty(STDERR_FILENO) : (&out == &std::cout && isatty(STDOUT_FILENO))),
      start_(std::chrono::steady_clock::now()) {}

void ProgressBar::advance(std::size_t steps, const std::string& note) {
  done_ += steps;
  if (done_ > total_) done_ = total_;
  draw(note);
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  done_ = total_;
  draw("");
  if (interactive_) out_ << "\n";
  out_.flush();
}

static std::string formatSeconds(double s) {
  std::ostringstream o;
  const int total = static_cast<int>(s + 0.5);
  if (total >= 3600) o << total / 3600 << "h" << std::setw(2) << std::setfill('0') << (total % 3600) / 60 << "m";
  else if (total >= 60) o << total / 60 << "m" << std::setw(2) << std::setfill('0') << total % 60 << "s";
  else o << total << "s";
  return o.str();
}

void ProgressBar::draw(const std::string& note) {
  const double frac = static_cast<double>(done_) / static_cast<double>(total_);
  const int percent = static_cast<int>(frac * 100.0);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = done_ > 0 ? elapsed * (1.0 - frac) / frac : 0.0;
  if (!interactive_) {
    const int bucket = percent / kLogEveryPercent;
    if (bucket == last_logged_percent_ && done_ != total_) return;
    if (done_ == total_ && last_logged_percent_ == 100) return;
    last_logged_percent_ = (done_ == total_) ? 100 : bucket;
  }
  std::ostringstream line;
  const int filled = static_cast<int>(frac * kBarWidth);
  line << label_ << " [" << std::string(filled, '#') << std::string(kBarWidth - filled, '.') << "] " << std::setw(3)
       << percent << "% " << done_ << "/" << total_ << "  " << formatSeconds(elapsed) << " elapsed, ~"
       << formatSeconds(eta) << " left";
  if (!note.empty()) line << "  " << note;
  if (interactive_) out_ << "\r" << line.str() << "\033[K" << std::flush;
  else out_ << line.str() << "\n" << std::flush;
}

}  // namespace krp
