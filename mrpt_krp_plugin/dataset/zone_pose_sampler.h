// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

#include "mrpt_krp_plugin/common/random.h"
#include "mrpt_krp_plugin/zones/zone.h"

namespace krp {

/// Draws robot poses uniformly over each zone's free space (clear of walls by a margin), with
/// headings uniform over the full circle.
class ZonePoseSampler {
 public:
  /// Throws InputError naming a zone that has no free cell with the clearance.
  ZonePoseSampler(const mrpt::maps::COccupancyGridMap2D& map, const std::vector<Zone>& zones, double clearance_m);
  mrpt::poses::CPose2D sample(size_t zone, Rng& rng) const;

 private:
  const mrpt::maps::COccupancyGridMap2D& map_;
  std::vector<std::vector<cv::Point>> cells_;  ///< per zone: candidate cells (image pixels)
};

}  // namespace krp
