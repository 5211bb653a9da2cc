// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/bench/classification_scores.h"
#include "mrpt_krp_plugin/bench/feature_zone_classifier.h"
#include "mrpt_krp_plugin/sim/world.h"

namespace krp {

/// The thesis's comparisons with classical methods, on our worlds: zoning by SIFT and ORB
/// matching against the shipped CNN (its Table 4.4), and the pose from the keypoint alignment
/// against ICP started from the zone's centre (its Table 4.5).
struct ThesisComparisonParams {
  int references_per_zone = 30;  ///< submaps per zone in the SIFT/ORB reference database
  int tests_per_zone = 50;       ///< held-out submaps per zone, the same for every method
  uint64_t seed = 1;             ///< every pose, scan and clutter draw derives from it
  double clearance_m = 0.3;      ///< sampled poses keep this far from mapped obstacles [m]
  /// Unmapped objects (the world's clutter settings) in every scene: the thesis's scenes had
  /// added objects and occlusions, which is where it found SIFT and ORB failing.
  bool clutter = true;
  /// ICP from the zone's centre first pairs points this far apart: the centre is metres from the
  /// robot, and the refiner's default (1 m, for a hypothesis already close) would not move it.
  double icp_start_correspondence_m = 5.0;
  /// A pose counts as right within this distance and heading of the truth [m], [deg].
  double right_within_m = 0.5;
  double right_within_deg = 10.0;
  FeatureZoneClassifierParams features;
};

/// One held-out submap: its zone and pose, each classifier's answer (-1 = none) and each
/// alignment's pose (none when the method proposed nothing).
struct ThesisSample {
  int zone = -1;
  mrpt::math::TPose2D truth;
  int cnn = -1, sift = -1, orb = -1;
  std::optional<mrpt::math::TPose2D> keypoints;      ///< keypoint alignment alone (RANSAC + weighted LSQ)
  std::optional<mrpt::math::TPose2D> keypoints_icp;  ///< the same, refined by ICP against the map
  mrpt::math::TPose2D icp_from_centre;               ///< ICP from the zone's centre, true heading
};

struct AlignmentScores {
  std::string method;
  int answered = 0;  ///< samples the method gave a pose for
  int samples = 0;
  double rmse_m = 0, median_m = 0, rmse_deg = 0;  ///< over answered samples
  double right_share = 0;                         ///< of all samples: within right_within_m/_deg
};

struct ThesisComparison {
  std::string world, lidar, models_dir;
  std::vector<std::string> zone_names;
  ThesisComparisonParams params;
  std::vector<ThesisSample> samples;
  ClassificationScores cnn, sift, orb;
  std::vector<AlignmentScores> alignment;  ///< keypoints, keypoints + ICP, ICP from the zone's centre
};

/// Runs the comparison for the models in `models_dir` (trained for `world` and its lidar
/// profile `lidar`, with the zones of `world`). Progress goes to `progress`.
ThesisComparison runThesisComparison(const World& world, const std::string& lidar, const std::string& models_dir,
                                     const ThesisComparisonParams& params, std::ostream& progress);

/// Position and heading scores of one alignment method over the samples.
AlignmentScores scoreAlignment(const std::string& method, const std::vector<mrpt::math::TPose2D>& truth,
                               const std::vector<std::optional<mrpt::math::TPose2D>>& estimate,
                               double right_within_m, double right_within_deg);

}  // namespace krp
