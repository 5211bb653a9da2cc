// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPose2D.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "mrpt_krp_plugin/sim/rawlog_io.h"

namespace krp {

/// How a CARMEN log's laser lines become filter steps. CARMEN lines carry less than a
/// LaserScan does, so what they leave out is a parameter here.
struct CarmenLogParams {
  /// FLASER lines carry ranges only. CARMEN spreads n beams over this field of view starting
  /// at -fov/2, fov/n apart (the convention GMapping and the Freiburg logs follow). [deg]
  double flaser_fov_deg = 180.0;
  /// Readings at or beyond this are "no return". 0 = the log's `PARAM robot_front_laser_max`
  /// when it has one, else `fallback_max_range_m`. ROBOTLASER1 lines state their own. [m]
  double max_range_m = 0.0;
  /// SICK LMS 2xx scanners, behind most CARMEN logs, report 81.91 m for "no return". [m]
  double fallback_max_range_m = 80.0;
  /// The laser's forward offset on the robot for FLASER lines. NaN = the log's
  /// `PARAM robot_frontlaser_offset` when it has one, else 0. [m]
  double laser_offset_x_m = std::numeric_limits<double>::quiet_NaN();
  /// A laser line with fewer usable returns is skipped and counted, not used.
  int min_valid_returns = 10;
  /// A RAWLASER1 line carries no pose: its odometry is interpolated from the ODOM lines around it
  /// (by logger timestamp, the one clock every line of a log shares), and it is skipped when the
  /// nearest is further away than this. Only read in a log without FLASER or ROBOTLASER1 lines,
  /// whose scans are the same laser's with a pose attached. [s]
  double max_odometry_gap_s = 0.5;
  /// A line announcing more beams than this is corrupt (no 2D scanner has that many).
  std::size_t max_beams = 100000;
  /// The log's uncompressed size above which it is refused (memory guard). [bytes]
  std::size_t max_bytes = std::size_t{2} << 30;
  /// The odometry noise the filter samples from.
  OdometryModelParams odometry;
};

/// A CARMEN log as filter steps, with the pose each laser line states for the robot.
struct CarmenLog {
  std::vector<RawlogStep> steps;  ///< odometry increment since the previous used line + scan
  /// The robot pose each used laser line states (FLASER's laser pose less the laser offset,
  /// ROBOTLASER1's robot pose), in the log's frame. In a SLAM-corrected log this is the
  /// reference pose; in a raw log it is odometry.
  std::vector<mrpt::math::TPose2D> logged_poses;
  std::vector<double> timestamps_s;     ///< logger timestamp of each used line [s]
  std::size_t laser_lines = 0;          ///< laser lines read (FLASER + ROBOTLASER1, else RAWLASER1)
  /// The scans are RAWLASER1 lines and their poses the ODOM lines' odometry: never a corrected
  /// reference, whatever the log's name says.
  bool poses_from_odom_lines = false;
  std::size_t skipped_scans = 0;        ///< laser lines with too few usable returns
  std::size_t other_records = 0;        ///< lines of other message types (ODOM, PARAM, ...), ignored
  double max_range_m = 0.0;             ///< the no-return threshold used for FLASER lines [m]
  double laser_offset_x_m = 0.0;        ///< the FLASER laser offset used [m]
  std::string first_skip_reason;        ///< why the first skipped scan was skipped
};

/// Reads a CARMEN log (plain or gzip): FLASER and ROBOTLASER1 lines become steps, odometry
/// from their odometry fields; a log with neither is read from its front laser's RAWLASER1 lines,
/// each with the odometry of the ODOM lines at its time. Every other message type is counted and
/// ignored. Throws
/// InputError naming the file and line for a missing or unreadable file, a malformed or
/// truncated laser line, non-finite numbers, or a log with no usable laser line.
CarmenLog readCarmenLog(const std::string& path, const CarmenLogParams& params = {});

/// Writes a simulated trial as a raw CARMEN log, atomically: one ROBOTLASER1 line per step
/// (exact beam angles, the scan's maximum range for no return), with the robot pose integrated
/// from the trial's noisy odometry from (0, 0, 0) as a robot would log it. The truth stays in
/// the ground-truth file `writeTrialRawlog` writes. Timestamps are the step numbers [s].
void writeTrialCarmenLog(const Trial& trial, const std::string& path);

}  // namespace krp
