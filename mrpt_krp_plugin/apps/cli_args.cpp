// SPDX-License-Identifier: BSD-3-Clause
#include "cli_args.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp::apps {

CliArgs::CliArgs(std::string program, std::string summary, std::vector<Option> options)
    : program_(std::move(program)), summary_(std::move(summary)), options_(std::move(options)) {}

std::vector<std::string> CliArgs::optionNames() const {
  std::vector<std::string> names;
  for (const auto& o : options_) names.push_back(o.name);
  return names;
}

const CliArgs::Option& CliArgs::option(const std::string& name) const {
  for (const auto& o : options_)
    if (o.name == name) return o;
  throw InputError("--" + name, "unknown option\n" + usage());
}

bool CliArgs::parse(int argc, char** argv) {
  command_line_ = program_;
  for (int i = 1; i < argc; ++i) command_line_ += std::string(" ") + argv[i];
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::cout << usage();
      return false;
    }
    if (a.rfind("--", 0) != 0) throw InputError(a, "unexpected argument (options start with --)\n" + usage());
    std::string name = a.substr(2), value;
    const auto eq = name.find('=');
    if (eq != std::string::npos) value = name.substr(eq + 1), name = name.substr(0, eq);
    const Option& o = option(name);
    if (o.value_hint.empty()) {
      value = "1";
    } else if (eq == std::string::npos) {
      if (i + 1 >= argc) throw InputError("--" + name, "needs a value " + o.value_hint + "\n" + usage());
      value = argv[++i];
    }
    values_[name] = value;
  }
  return true;
}

bool CliArgs::has(const std::string& name) const { return values_.count(name) > 0; }
bool CliArgs::flag(const std::string& name) const { option(name); return values_.count(name) > 0; }

std::string CliArgs::get(const std::string& name) const {
  const Option& o = option(name);
  const auto it = values_.find(name);
  return it != values_.end() ? it->second : o.default_value;
}

double CliArgs::number(const std::string& name) const {
  const std::string s = get(name);
  size_t used = 0;
  double v = NAN;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
  }
  if (used != s.size() || !std::isfinite(v)) throw InputError("--" + name, "'" + s + "' is not a number");
  return v;
}

long long CliArgs::integer(const std::string& name) const {
  const double v = number(name);
  if (v != std::floor(v)) throw InputError("--" + name, "'" + get(name) + "' is not an integer");
  return static_cast<long long>(v);
}

long long wholeNumberInRange(const std::string& flag, const std::string& text, double value, long long lo, long long hi) {
  if (value != std::floor(value) || value < static_cast<double>(lo) || value > static_cast<double>(hi))
    throw InputError("--" + flag, "'" + text + "' must be a whole number from " + std::to_string(lo) + " to " +
                                      std::to_string(hi));
  return static_cast<long long>(value);
}

long long CliArgs::integerInRange(const std::string& name, long long lo, long long hi) const {
  return wholeNumberInRange(name, get(name), number(name), lo, hi);
}

uint64_t CliArgs::seed(const std::string& name) const {
  const long long v = integer(name);
  if (v < 0) throw InputError("--" + name, "'" + get(name) + "' is negative; seeds are >= 0");
  return static_cast<uint64_t>(v);
}

std::vector<std::string> CliArgs::list(const std::string& name) const {
  std::vector<std::string> out;
  std::stringstream ss(get(name));
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::vector<long long> CliArgs::integerList(const std::string& name) const {
  std::vector<long long> out;
  for (const auto& item : list(name)) {
    size_t used = 0;
    long long v = 0;
    try {
      v = std::stoll(item, &used);
    } catch (const std::exception&) {
    }
    if (used == 0 || used != item.size()) throw InputError("--" + name, "'" + item + "' is not an integer");
    out.push_back(v);
  }
  return out;
}

std::string CliArgs::usage() const {
  std::ostringstream o;
  o << "Usage: " << program_ << " [options]\n" << summary_ << "\n\nOptions:\n";
  for (const auto& opt : options_) {
    std::string left = "  --" + opt.name + (opt.value_hint.empty() ? "" : " " + opt.value_hint);
    o << left << std::string(left.size() < 34 ? 34 - left.size() : 1, ' ') << opt.help;
    if (!opt.default_value.empty()) o << " (default: " << opt.default_value << ")";
    o << "\n";
  }
  o << "  --help                            this text\n";
  return o.str();
}

int runMain(const std::string& program, int (*body)(int, char**), int argc, char** argv) {
  try {
    return body(argc, argv);
  } catch (const InputError& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": failed: " << e.what() << "\n";
    return 1;
  }
}

std::string worldFilePath(const std::string& w, const std::string& world_dir) {
  namespace fs = std::filesystem;
  const fs::path p = w.find(".yaml") != std::string::npos ? fs::path(w) : fs::path(world_dir) / w / (w + ".world.yaml");
  if (!fs::exists(p)) throw InputError(p.string(), "world file not found (run krp-make-worlds, or check --world-dir)");
  return p.string();
}

}  // namespace krp::apps
