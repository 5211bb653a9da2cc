// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/octomap_slice.h"

#include <octomap/AbstractOcTree.h>
#include <octomap/OcTree.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {
constexpr float kUnknownFreeness = 0.5f;
constexpr char kBinaryHeader[] = "# Octomap OcTree binary file";
constexpr char kFullHeader[] = "# Octomap OcTree file";

bool startsWith(const std::string& path, const char* header) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::getline(in, line);
  return line.rfind(header, 0) == 0;
}
}  // namespace

OccupancyMap sliceOctree(const octomap::OcTree& tree, const OctomapSliceParams& p, const std::string& source,
                         const MapSanityLimits& limits) {
  if (!(std::isfinite(p.z_min_m) && std::isfinite(p.z_max_m) && p.z_min_m < p.z_max_m))
    throw InputError(source, "slice band must satisfy z_min < z_max (finite)");
  if (tree.size() == 0) throw InputError(source, "the octree is empty");
  const double res = p.resolution_m > 0.0 ? p.resolution_m : tree.getResolution();
  double x0, y0, z0, x1, y1, z1;
  tree.getMetricMin(x0, y0, z0);
  tree.getMetricMax(x1, y1, z1);
  if (z1 < p.z_min_m || z0 > p.z_max_m)
    throw InputError(source, "the octree spans z in [" + std::to_string(z0) + ", " + std::to_string(z1) +
                                 "] m, which misses the slice band");
  // A corrupt file can hold a tiny resolution or far-flung nodes: check before allocating.
  checkGridGeometry({x0, y0, res, std::ceil((x1 - x0) / res), std::ceil((y1 - y0) / res)}, limits, source);
  auto grid = std::make_shared<mrpt::maps::COccupancyGridMap2D>();
  grid->setSize(x0, x1, y0, y1, static_cast<float>(res), kUnknownFreeness);
  const int w = static_cast<int>(grid->getSizeX()), h = static_cast<int>(grid->getSizeY());
  std::vector<uint8_t> seen_free(static_cast<size_t>(w) * h, 0), seen_occ(static_cast<size_t>(w) * h, 0);

  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const double size = it.getSize(), half = size / 2.0;
    const double cz = it.getZ();
    if (cz + half < p.z_min_m || cz - half > p.z_max_m) continue;
    const bool occupied = tree.isNodeOccupied(*it);
    // A coarse leaf covers several 2D cells: mark every cell whose centre it contains.
    const int ix0 = std::max(0, grid->x2idx(it.getX() - half + res / 2));
    const int ix1 = std::min(w - 1, grid->x2idx(it.getX() + half - res / 2));
    const int iy0 = std::max(0, grid->y2idx(it.getY() - half + res / 2));
    const int iy1 = std::min(h - 1, grid->y2idx(it.getY() + half - res / 2));
    for (int iy = iy0; iy <= iy1; ++iy)
      for (int ix = ix0; ix <= ix1; ++ix) (occupied ? seen_occ : seen_free)[static_cast<size_t>(iy) * w + ix] = 1;
  }
  std::size_t free_cells = 0;
  for (int iy = 0; iy < h; ++iy)
    for (int ix = 0; ix < w; ++ix) {
      const size_t k = static_cast<size_t>(iy) * w + ix;
      if (seen_occ[k]) grid->setCell(ix, iy, 0.0f);
      else if (seen_free[k]) { grid->setCell(ix, iy, 1.0f); ++free_cells; }
    }
  if (free_cells == 0) throw InputError(source, "the slice holds no free cell (is the band at the lidar's height?)");
  return OccupancyMap{grid, 0.0, source};
}

OccupancyMap readOctomapSlice(const std::string& path, const OctomapSliceParams& params,
                              const MapSanityLimits& limits) {
  if (!std::filesystem::exists(path)) throw InputError(path, "file does not exist");
  std::unique_ptr<octomap::OcTree> tree;
  if (startsWith(path, kBinaryHeader)) {
    tree = std::make_unique<octomap::OcTree>(0.1);
    if (!tree->readBinary(path)) throw InputError(path, "corrupt or truncated OctoMap binary (.bt) file");
  } else if (startsWith(path, kFullHeader)) {
    std::unique_ptr<octomap::AbstractOcTree> abstract(octomap::AbstractOcTree::read(path));
    if (!abstract) throw InputError(path, "corrupt or truncated OctoMap (.ot) file");
    auto* oc = dynamic_cast<octomap::OcTree*>(abstract.get());
    if (!oc) throw InputError(path, "OctoMap tree type '" + abstract->getTreeType() + "' is not supported (need OcTree)");
    abstract.release();
    tree.reset(oc);
  } else {
    throw InputError(path, "not an OctoMap file (no '# Octomap OcTree' header)");
  }
  return sliceOctree(*tree, params, path, limits);
}

}  // namespace krp
