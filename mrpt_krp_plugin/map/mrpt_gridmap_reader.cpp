// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/mrpt_gridmap_reader.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/map/gridmap_archive.h"

namespace krp {
namespace {
constexpr int kGzipLevel = 6;  ///< zlib level: a good size/speed balance for map files
constexpr size_t kReadChunkBytes = 1 << 20;
// Room for what MRPT stores beside the cells (header, options, likelihood settings).
constexpr size_t kArchiveOverheadBytes = 1 << 20;

// The largest archive a map within the limits can need: 16-bit cells plus the overhead.
size_t maxArchiveBytes(const MapSanityLimits& limits) {
  return static_cast<size_t>(limits.max_cells) * 2 + kArchiveOverheadBytes;
}

// The whole archive in memory, unzipped if it is gzip'ed (CFileGZInputStream reads plain and
// gzip'ed files alike), so that its header can be checked before MRPT reads it.
std::vector<uint8_t> readDecompressed(const std::string& path, size_t max_bytes) {
  std::vector<uint8_t> bytes;
  try {
    mrpt::io::CFileGZInputStream in(path);
    for (;;) {
      const size_t old = bytes.size();
      bytes.resize(old + kReadChunkBytes);
      const size_t got = in.Read(bytes.data() + old, kReadChunkBytes);
      bytes.resize(old + got);
      if (got == 0) break;
      if (bytes.size() > max_bytes)
        throw InputError(path, "the gridmap unpacks to more than " + std::to_string(max_bytes) + " bytes, the limit");
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, std::string("cannot read the file: ") + e.what());
  }
  return bytes;
}
}  // namespace

OccupancyMap readMrptGridmap(const std::string& path, const MapSanityLimits& limits) {
  if (!std::filesystem::exists(path)) throw InputError(path, "file does not exist");
  if (std::filesystem::file_size(path) == 0) throw InputError(path, "file is empty");
  const auto archive = readDecompressed(path, maxArchiveBytes(limits));
  const auto grid = readGridmapArchive(archive, limits, path);
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
