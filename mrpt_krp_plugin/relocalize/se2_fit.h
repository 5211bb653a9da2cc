// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <vector>

namespace krp {

/// A point seen in the robot frame and the map point it is believed to be.
struct Correspondence2D {
  mrpt::math::TPoint2D robot;  ///< robot frame (x forward, y left) [m]
  mrpt::math::TPoint2D map;    ///< map (grid) frame [m]
  double weight = 1.0;         ///< relative trust, > 0
};

struct Se2FitParams {
  /// Position noise assumed for a keypoint when the residuals cannot estimate it (a two-point
  /// fit is exact) or estimate it below this: about one submap pixel [m].
  double min_point_std_m = 0.15;
};

/// The robot pose that maps the robot-frame points onto their map points.
struct Se2Fit {
  mrpt::math::TPose2D pose;          ///< robot pose in the map frame
  mrpt::math::CMatrixDouble33 cov;   ///< of (x, y, yaw), from the residuals
  double rms_m = 0.0;                ///< weighted RMS residual [m]
};

/// Weighted least squares (closed-form 2D Procrustes). Needs two correspondences whose robot
/// points are distinct; throws std::invalid_argument otherwise.
Se2Fit fitSe2(const std::vector<Correspondence2D>& corrs, const Se2FitParams& params = {});

/// Distance between where `pose` puts the robot point and its map point [m].
double residualM(const mrpt::math::TPose2D& pose, const Correspondence2D& c);

}  // namespace krp
