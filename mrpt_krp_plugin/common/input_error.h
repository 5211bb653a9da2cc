// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <stdexcept>
#include <string>

namespace krp {

/// An input the program cannot use. The message always names the input (a file, a key,
/// a flag) and the problem, so that a user can fix it without reading the source.
class InputError : public std::runtime_error {
 public:
  InputError(std::string input, std::string problem)
      : std::runtime_error(input + ": " + problem), input_(std::move(input)), problem_(std::move(problem)) {}

  const std::string& input() const { return input_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string input_;
  std::string problem_;
};

}  // namespace krp
