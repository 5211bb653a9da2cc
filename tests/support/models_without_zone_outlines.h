// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace krp::test {

/// A copy of the shipped office models (models/office_two_zone) in a fresh temporary folder
/// (tempDir(name)), as krp-train-map wrote them before it kept the zones beside the models: no
/// zones.yaml and none named in the manifest, so the zone search needs the user's zones.
std::string modelsWithoutZoneOutlines(const std::string& name);

}  // namespace krp::test
