// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace krp::apps {

// Upper ends of the apps' count settings, far above any sensible value, so that a typo (an extra
// zero or three) is refused rather than run for hours.
constexpr long long kMaxParticles = 10'000'000;
constexpr long long kMaxZones = 1000;

/// `value`, given as `text` for `--flag`, as a whole number from lo to hi; InputError naming the
/// flag and the range otherwise. CliArgs::integerInRange and INI-read settings share it.
long long wholeNumberInRange(const std::string& flag, const std::string& text, double value, long long lo, long long hi);

/// `--key value` / `--flag` parsing with a declared set of options, so a mistyped flag is
/// an error with the usage text rather than silently ignored.
class CliArgs {
 public:
  struct Option {
    std::string name;       ///< without dashes
    std::string value_hint; ///< empty for a boolean flag
    std::string help;
    std::string default_value;
  };

  CliArgs(std::string program, std::string summary, std::vector<Option> options);

  /// Parses argv; returns false (after printing usage) for --help; throws InputError on bad input.
  bool parse(int argc, char** argv);

  std::string get(const std::string& name) const;
  bool has(const std::string& name) const;   ///< given on the command line
  bool flag(const std::string& name) const;
  double number(const std::string& name) const;
  long long integer(const std::string& name) const;
  /// A whole number from lo to hi (a count: a negative one must not wrap to billions).
  long long integerInRange(const std::string& name, long long lo, long long hi) const;
  /// A seed: a whole number, 0 or more (a negative one would wrap to another seed unnoticed).
  uint64_t seed(const std::string& name) const;
  std::vector<std::string> list(const std::string& name) const;  ///< comma-separated
  std::vector<long long> integerList(const std::string& name) const;  ///< comma-separated integers
  std::string usage() const;
  /// The declared options' names, in declaration order.
  std::vector<std::string> optionNames() const;
  std::string commandLine() const { return command_line_; }

 private:
  const Option& option(const std::string& name) const;
  std::string program_, summary_, command_line_;
  std::vector<Option> options_;
  std::map<std::string, std::string> values_;
};

/// A world given by name (looked up as DIR/NAME/NAME.world.yaml) or as a *.world.yaml path.
/// Throws InputError if the file does not exist.
std::string worldFilePath(const std::string& name_or_path, const std::string& world_dir);

/// Runs `body`, turning exceptions into a message on stderr and exit code 2 (bad input) or 1.
int runMain(const std::string& program, int (*body)(int, char**), int argc, char** argv);

}  // namespace krp::apps
