// SPDX-License-Identifier: BSD-3-Clause
#include "message_bounds.h"

#include <cstring>

namespace krp::ros1 {
namespace {

// The ROS 1 wire format: fixed-size fields in place, strings and arrays as a uint32 count
// followed by their elements (wiki.ros.org/msg, "Serialization").
class Cursor {
 public:
  Cursor(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  bool skip(size_t bytes, const char* field) {
    if (!problem_.empty()) return false;
    if (bytes > size_ - pos_) {
      problem_ = std::string("field '") + field + "' runs past the message's " + std::to_string(size_) + " bytes";
      return false;
    }
    pos_ += bytes;
    return true;
  }

  /// A count, then that many elements of `element_bytes` (1 for a string's characters).
  bool counted(size_t element_bytes, const char* field) {
    uint32_t n = 0;
    if (!count(n, field, element_bytes)) return false;
    pos_ += static_cast<size_t>(n) * element_bytes;
    return true;
  }

  /// A count whose elements take at least `min_element_bytes` each; the caller walks them.
  bool count(uint32_t& n, const char* field, size_t min_element_bytes) {
    if (!problem_.empty() || !read(n, field)) return false;
    if (static_cast<uint64_t>(n) * min_element_bytes > size_ - pos_) {
      problem_ = std::string("field '") + field + "' states " + std::to_string(n) +
                 " elements, more than the message's remaining " + std::to_string(size_ - pos_) + " bytes hold";
      return false;
    }
    return true;
  }

  void header(const char* what) {
    skip(3 * sizeof(uint32_t), what);  // seq, stamp.sec, stamp.nsec
    counted(1, "header.frame_id");
  }

  std::string finish() {
    if (problem_.empty() && pos_ != size_)
      problem_ = std::to_string(size_ - pos_) + " bytes are left over after the message's last field";
    return problem_;
  }

 private:
  bool read(uint32_t& v, const char* field) {
    if (sizeof(v) > size_ - pos_) {
      problem_ = std::string("field '") + field + "' length is cut off";
      return false;
    }
    std::memcpy(&v, data_ + pos_, sizeof(v));
    pos_ += sizeof(v);
    return true;
  }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  std::string problem_;
};

constexpr size_t kLaserScanFloats = 7;  // angle_min .. range_max
constexpr size_t kTransformDoubles = 7;  // translation xyz, rotation xyzw
// header (seq, stamp, empty frame_id) + empty child_frame_id + the transform
constexpr size_t kMinTransformStampedBytes = 4 * sizeof(uint32_t) + sizeof(uint32_t) + kTransformDoubles * sizeof(double);

}  // namespace

std::string laserScanBoundsProblem(const uint8_t* data, size_t size) {
  Cursor c(data, size);
  c.header("header");
  c.skip(kLaserScanFloats * sizeof(float), "angle_min..range_max");
  c.counted(sizeof(float), "ranges");
  c.counted(sizeof(float), "intensities");
  return c.finish();
}

std::string tfMessageBoundsProblem(const uint8_t* data, size_t size) {
  Cursor c(data, size);
  uint32_t n = 0;
  if (c.count(n, "transforms", kMinTransformStampedBytes))
    for (uint32_t i = 0; i < n; ++i) {
      c.header("transforms[].header");
      c.counted(1, "transforms[].child_frame_id");
      if (!c.skip(kTransformDoubles * sizeof(double), "transforms[].transform")) break;
    }
  return c.finish();
}

}  // namespace krp::ros1
