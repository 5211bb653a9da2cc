// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include "mrpt_krp_plugin/map/map_sanity.h"

namespace krp {

/// The geometry and cells of an MRPT COccupancyGridMap2D archive held in memory. MRPT's own
/// deserializer allocates whatever sizes the file announces (the cells, then option vectors)
/// before it reads them, so a corrupt file could make it allocate gigabytes: this reader checks
/// every size against `limits` and the bytes present first. The options MRPT stores after the
/// cells (insertion and likelihood settings) are not read: the project sets its own.
/// InputError naming `file` for another class, a serialization version this reader does not
/// know, cells of another width than this MRPT build's, a geometry outside `limits`, or fewer
/// cell bytes than the header announces.
mrpt::maps::COccupancyGridMap2D::Ptr readGridmapArchive(const std::vector<uint8_t>& archive,
                                                        const MapSanityLimits& limits, const std::string& file);

}  // namespace krp
