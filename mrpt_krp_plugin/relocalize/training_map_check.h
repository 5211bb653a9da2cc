// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include "mrpt_krp_plugin/inference/model_manifest.h"

namespace krp {

/// How closely a map must match the one the models were trained on.
struct TrainingMapCheckParams {
  /// The map's cell size may differ from the one trained on by this much [m] (float rounding).
  double resolution_tolerance_m = 1e-4;
  /// A landmark sits on the map's structure when an occupied cell lies within this distance [m]:
  /// landmarks are corners, jambs and rack ends picked on the training map's walls.
  double landmark_wall_distance_m = 0.3;
  /// At least this share of all zones' landmarks must sit on the map's structure [0..1]. On the
  /// training map every landmark does; on the project's other worlds at most 58 % of another
  /// world's landmarks happen to lie near a wall, so a few edits to a map still pass.
  double min_landmark_share_on_walls = 0.75;
};

/// The share of the manifest's landmarks (all zones) that lie inside `map` and within
/// `landmark_wall_distance_m` of one of its occupied cells; 1 when there are none.
double landmarkShareOnWalls(const ModelManifest& manifest, const mrpt::maps::COccupancyGridMap2D& map,
                            const TrainingMapCheckParams& params = {});

/// Refuses a map the models were not trained on (InputError naming the manifest): another cell
/// size, a landmark outside it, or too few of the landmarks on its walls. Models trained on one map propose poses in
/// that map's frame; on another map they would be confidently wrong, so they must not load.
void requireTrainingMap(const ModelManifest& manifest, const mrpt::maps::COccupancyGridMap2D& map,
                        const TrainingMapCheckParams& params = {});

}  // namespace krp
