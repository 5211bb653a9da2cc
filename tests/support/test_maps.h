// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace krp::test {

/// A rectangular room (walls all round) with an L-shaped inner wall so that it has no
/// symmetry: a pose in it is unique from one scan.
mrpt::maps::COccupancyGridMap2D asymmetricRoom(double width_m = 8.0, double height_m = 6.0, double resolution_m = 0.05);

/// The default asymmetricRoom with `pillars` square pillars (side `pillar_m`) on a circle of
/// `radius_m` around (x, y): clutter the map does not hold, hiding most walls from a lidar there.
mrpt::maps::COccupancyGridMap2D asymmetricRoomWithPillarsAround(double x, double y, int pillars, double radius_m,
                                                               double pillar_m);

/// Two copies of the default asymmetricRoom, side by side `gap_m` apart, walls all round each:
/// a pose in the first room and the same pose `kTwinRoomsShiftM` east look the same from any scan.
mrpt::maps::COccupancyGridMap2D twinRooms(double gap_m = 1.0);
/// How far east the second of twinRooms() lies (8 m room + 1 m border + gap) [m].
double twinRoomsShiftM(double gap_m = 1.0);

/// A fresh temporary folder for one test, removed when the test process exits
/// (kept when the environment variable KRP_KEEP_TEST_DIRS is set).
std::string tempDir(const std::string& name);

/// Writes `content` to `path` (creating folders).
void writeText(const std::string& path, const std::string& content);

}  // namespace krp::test
