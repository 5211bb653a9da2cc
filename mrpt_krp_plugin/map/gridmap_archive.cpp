// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/gridmap_archive.h"

#include <cstring>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {
// MRPT 2's archive of one object: a byte 0x80 | name length, the class name, the class's
// serialization version, then the object. COccupancyGridMap2D version 6 starts with bits per
// cell (uint8), size_x, size_y (uint32), x_min, x_max, y_min, y_max, resolution (float32), all
// little-endian, then the cells.
constexpr uint8_t kNewFormatFlag = 0x80;
constexpr const char* kClassName = "mrpt::maps::COccupancyGridMap2D";
constexpr uint8_t kKnownVersion = 6;

class Reader {
 public:
  Reader(const std::vector<uint8_t>& bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  template <typename T>
  T next(const char* what) {
    if (pos_ + sizeof(T) > bytes_.size()) throw InputError(file_, std::string("truncated gridmap: no ") + what);
    T v;
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));  // both MRPT and x86 are little-endian
    pos_ += sizeof(T);
    return v;
  }
  std::string text(size_t n) {
    if (pos_ + n > bytes_.size()) throw InputError(file_, "truncated gridmap: no class name");
    std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), n);
    pos_ += n;
    return s;
  }
  size_t remaining() const { return bytes_.size() - pos_; }
  const uint8_t* here() const { return bytes_.data() + pos_; }

 private:
  const std::vector<uint8_t>& bytes_;
  const std::string& file_;
  size_t pos_ = 0;
};
}  // namespace

mrpt::maps::COccupancyGridMap2D::Ptr readGridmapArchive(const std::vector<uint8_t>& archive,
                                                        const MapSanityLimits& limits, const std::string& file) {
  Reader in(archive, file);
  const auto name_byte = in.next<uint8_t>("class header");
  if (!(name_byte & kNewFormatFlag)) throw InputError(file, "not an MRPT archive of a COccupancyGridMap2D");
  const std::string name = in.text(name_byte & ~kNewFormatFlag);
  if (name != kClassName) throw InputError(file, "the archive holds a '" + name + "', not a " + kClassName);
  const auto version = in.next<uint8_t>("version");
  if (version != kKnownVersion) {
    std::ostringstream s;
    s << "COccupancyGridMap2D serialization version " << int(version) << " is not supported (this reader knows "
      << int(kKnownVersion) << ", written by MRPT 2)";
    throw InputError(file, s.str());
  }
  const auto bits = in.next<uint8_t>("bits per cell");
  using Cell = mrpt::maps::COccupancyGridMap2D::cellType;
  if (bits != 8 * sizeof(Cell))
    throw InputError(file, "the map has " + std::to_string(bits) + "-bit cells; this MRPT build uses " +
                               std::to_string(8 * sizeof(Cell)) + "-bit cells");
  const auto size_x = in.next<uint32_t>("size_x"), size_y = in.next<uint32_t>("size_y");
  const auto x_min = in.next<float>("x_min");
  const auto x_max = in.next<float>("x_max");
  const auto y_min = in.next<float>("y_min");
  const auto y_max = in.next<float>("y_max");
  const auto resolution = in.next<float>("resolution");
  checkGridGeometry({x_min, y_min, resolution, static_cast<double>(size_x), static_cast<double>(size_y)}, limits, file);
  const size_t cell_bytes = static_cast<size_t>(size_x) * size_y * sizeof(Cell);
  if (cell_bytes > in.remaining()) {
    std::ostringstream s;
    s << "truncated gridmap: the header announces " << size_x << " x " << size_y << " cells, the file holds "
      << in.remaining() << " bytes after it";
    throw InputError(file, s.str());
  }
  auto grid = mrpt::maps::COccupancyGridMap2D::Create();
  try {
    grid->setSize(x_min, x_max, y_min, y_max, resolution);
  } catch (const std::exception&) {
    throw InputError(file, "the header's extent does not describe a grid");
  }
  if (grid->getSizeX() != size_x || grid->getSizeY() != size_y) {
    std::ostringstream s;
    s << "the header's extent makes " << grid->getSizeX() << " x " << grid->getSizeY() << " cells, not the "
      << size_x << " x " << size_y << " it announces";
    throw InputError(file, s.str());
  }
  // Rows are stored bottom-up, each size_x cells, as MRPT keeps them in memory.
  const uint8_t* cells = in.here();
  for (uint32_t y = 0; y < size_y; ++y)
    std::memcpy(grid->getRow(static_cast<int>(y)), cells + static_cast<size_t>(y) * size_x * sizeof(Cell),
                size_x * sizeof(Cell));
  return grid;
}

}  // namespace krp
