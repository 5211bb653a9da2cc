// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

#include "mrpt_krp_plugin/submap/local_grid.h"
#include "mrpt_krp_plugin/submap/submap_params.h"

namespace krp {

/// A scan and where the robot was when it took it, relative to the robot's current pose
/// (identity for the newest scan; odometry deltas for older ones).
struct PosedScan {
  const mrpt::obs::CObservation2DRangeScan* scan = nullptr;
  mrpt::poses::CPose2D robot_pose;
};

/// The local grid and how much of the input went into it.
struct Submap {
  LocalGrid grid;
  int beams_used = 0;      ///< beams that painted free space or an obstacle
  int beams_rejected = 0;  ///< NaN, infinite or negative ranges
  int hits = 0;            ///< beams that ended on an obstacle
};

/// Builds the robot-centric submap by ray casting every beam: cells a beam crossed are free,
/// cells where it ended are occupied (obstacles win over free space), the rest unknown. The robot
/// is drawn at `image_heading_rad` (LocalGrid); `params.orientation` is not consulted here.
/// Throws InputError for unreadable scans or bad parameters.
Submap buildSubmap(const std::vector<PosedScan>& scans, const SubmapParams& params,
                   double image_heading_rad = kHeadingUpRad);

/// One scan taken at the robot's current pose.
Submap buildSubmap(const mrpt::obs::CObservation2DRangeScan& scan, const SubmapParams& params,
                   double image_heading_rad = kHeadingUpRad);

/// The image headings a submap of this scan is drawn at under `params.orientation`: heading up
/// alone, or the four wall-aligned candidates (wallAlignedImageHeadings).
std::vector<double> submapImageHeadings(const mrpt::obs::CObservation2DRangeScan& scan, const SubmapParams& params);

}  // namespace krp
