// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/confidence_calibration.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/yaml_file.h"

namespace krp {

namespace {
// How far inside (0, 1) a raw confidence is kept: logit(1e-9) is about -21, still finite.
constexpr double kConfidenceMargin = 1e-9;

double finiteNumber(const YAML::Node& root, const char* key, const std::string& path) {
  if (!root[key]) throw InputError(path, std::string("missing '") + key + "'");
  double v = 0;
  try {
    v = root[key].as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(path, std::string("'") + key + "' is not a number");
  }
  if (!std::isfinite(v)) throw InputError(path, std::string("'") + key + "' is not finite");
  return v;
}

ConfidenceCalibration interpretCalibration(const YAML::Node& root, const std::string& path) {
  if (!root.IsMap()) throw InputError(path, "expected a mapping with 'slope' and 'offset'");
  rejectUnknownYamlKeys(root, {"slope", "offset", "answers", "fitted_by"}, path);
  ConfidenceCalibration c;
  c.slope = finiteNumber(root, "slope", path);
  c.offset = finiteNumber(root, "offset", path);
  if (c.slope <= 0) throw InputError(path, "'slope' must be positive (a better fit must keep a higher confidence)");
  if (root["answers"]) c.answers = static_cast<int>(finiteNumber(root, "answers", path));
  if (root["fitted_by"]) c.fitted_by = root["fitted_by"].as<std::string>();
  return c;
}
}  // namespace

double confidenceLogit(double raw) {
  const double p = std::clamp(raw, kConfidenceMargin, 1.0 - kConfidenceMargin);
  return std::log(p / (1.0 - p));
}

double calibrateConfidence(const ConfidenceCalibration& calibration, double raw) {
  if (calibration.isIdentity()) return raw;
  const double z = calibration.slope * confidenceLogit(raw) + calibration.offset;
  return 1.0 / (1.0 + std::exp(-z));
}

ConfidenceCalibration readConfidenceCalibration(const std::string& path) {
  return readYamlFile(path, [&](const YAML::Node& root) { return interpretCalibration(root, path); });
}

void writeConfidenceCalibration(const ConfidenceCalibration& calibration, const std::string& path) {
  std::ostringstream o;
  o.precision(10);
  o << "# Relocalizer confidence calibration (Platt scaling): calibrated = sigmoid(slope * logit(raw) + offset).\n"
    << "slope: " << calibration.slope << "\noffset: " << calibration.offset << "\nanswers: " << calibration.answers
    << "\nfitted_by: " << YAML::Node(calibration.fitted_by) << "\n";
  writeFileAtomically(path, o.str());
}

}  // namespace krp
