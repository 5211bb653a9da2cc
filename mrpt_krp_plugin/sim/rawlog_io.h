// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <string>
#include <vector>

#include "mrpt_krp_plugin/sim/trial.h"

namespace krp {

/// The odometry uncertainty written into each action (MRPT's Gaussian motion model), which
/// the particle filter samples from. Deliberately wider than the simulated odometry error.
struct OdometryModelParams {
  double min_std_xy_m = 0.02;          ///< [m]
  double min_std_phi_deg = 2.0;        ///< [deg]
  double xy_std_per_m = 0.10;          ///< a1 [m/m]
  double xy_std_per_rad = 0.01;        ///< a2 [m/rad]
  double phi_std_per_m_deg = 3.0;      ///< a3 [deg/m]
  double phi_std_per_rad = 0.10;       ///< a4 [rad/rad]

  mrpt::obs::CActionRobotMovement2D::TMotionModelOptions toMrpt() const;
};

/// One filter update's input: an action (odometry) and a sensory frame (the scan).
struct RawlogStep {
  mrpt::obs::CActionCollection::Ptr action;
  mrpt::obs::CSensoryFrame::Ptr observations;
};

/// One step: the odometry increment since the previous step, with `model`'s noise, and a scan.
RawlogStep makeRawlogStep(const mrpt::poses::CPose2D& odometry_increment,
                          const mrpt::obs::CObservation2DRangeScan::Ptr& scan, const OdometryModelParams& model = {});

/// Writes a trial as an MRPT rawlog (actions-observations format, one pair per step) and
/// a ground-truth text file (`step x y phi distance_m`, grid frame), atomically.
void writeTrialRawlog(const Trial& trial, const std::string& rawlog_path, const std::string& ground_truth_path,
                      const OdometryModelParams& model = {});

/// Builds the steps of a trial in memory, exactly as `writeTrialRawlog` writes them.
std::vector<RawlogStep> trialToSteps(const Trial& trial, const OdometryModelParams& model = {});

/// Reads an actions-observations rawlog. A step's action may be missing (identity motion).
/// Throws InputError for a missing, unreadable or truncated file or one with no scan.
std::vector<RawlogStep> readRawlog(const std::string& path);

/// Reads `step x y phi [distance_m]` lines ('#' comments); throws InputError.
std::vector<mrpt::math::TPose2D> readGroundTruth(const std::string& path, std::vector<double>* distance_m = nullptr);

}  // namespace krp
