// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/mrpt_gridmap_reader.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {
constexpr int kGzipLevel = 6;  ///< zlib level: a good size/speed balance for map files
}  // namespace

OccupancyMap readMrptGridmap(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path, "file does not exist");
  if (std::filesystem::file_size(path) == 0) throw InputError(path, "file is empty");
  auto grid = std::make_shared<mrpt::maps::COccupancyGridMap2D>();
  try {
    // CFileGZInputStream reads plain and gzip'ed files alike.
    mrpt::io::CFileGZInputStream in(path);
    auto arch = mrpt::serialization::archiveFrom(in);
    arch >> *grid;
  } catch (const std::exception& e) {
    std::string what = e.what();
    if (what.size() > 300) what = what.substr(0, 300) + "...";
    throw InputError(path, "not a readable MRPT COccupancyGridMap2D (" + what + ")");
  }
  if (grid->getSizeX() == 0 || grid->getSizeY() == 0) throw InputError(path, "the gridmap has no cells");
  if (countFreeCells(*grid) == 0) throw InputError(path, "the gridmap has no free cell");
  return OccupancyMap{grid, 0.0, path};
}

void writeMrptGridmap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path) {
  AtomicFile f(path);
  {
    const bool gz = path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
    if (gz) {
      mrpt::io::CFileGZOutputStream out(f.tempPath(), mrpt::io::OpenMode::TRUNCATE, kGzipLevel);
      mrpt::serialization::archiveFrom(out) << grid;
    } else {
      mrpt::io::CFileOutputStream out(f.tempPath());
      mrpt::serialization::archiveFrom(out) << grid;
    }
  }
  f.commit();
}

}  // namespace krp
