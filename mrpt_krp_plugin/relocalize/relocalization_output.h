// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/relocalize/relocalizer.h"

namespace krp {

/// The result as JSON: verdict, reason, zone probabilities by name, hypotheses (pose, yaw in
/// degrees, 3x3 covariance row-major, zone, fit, confidence), stage times.
nlohmann::json relocalizationJson(const RelocalizationResult& result, const std::vector<std::string>& zone_names);

/// The result as a few lines of text for a terminal.
std::string relocalizationText(const RelocalizationResult& result, const std::vector<std::string>& zone_names);

/// The map with every hypothesis drawn as an arrow (best in green, the others in orange, a
/// circle of one standard deviation), the true pose in blue when known; written as PNG atomically.
void writeHypothesesPng(const mrpt::maps::COccupancyGridMap2D& map, const RelocalizationResult& result,
                        const std::optional<mrpt::math::TPose2D>& truth, const std::string& png_path);

}  // namespace krp
