// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/ros_map_yaml.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/yaml_file.h"
#include "mrpt_krp_plugin/map/grid_image.h"
#include "mrpt_krp_plugin/map/pgm_header.h"

namespace fs = std::filesystem;

namespace krp {
namespace {

// map_server's trinary output values, as written by map_saver.
constexpr uint8_t kPgmOccupied = 0;
constexpr uint8_t kPgmFree = 254;
constexpr uint8_t kPgmUnknown = 205;

template <typename T>
T scalar(const YAML::Node& node, const std::string& key, const std::string& file) {
  try {
    return node[key].as<T>();
  } catch (const YAML::Exception&) {
    throw InputError(file, "key '" + key + "' is not a valid " + (std::is_same_v<T, std::string> ? "string" : "number"));
  }
}

bool parseNegate(const YAML::Node& n, const std::string& file) {
  const auto s = n.as<std::string>();
  if (s == "0" || s == "false" || s == "False") return false;
  if (s == "1" || s == "true" || s == "True") return true;
  throw InputError(file, "key 'negate' must be 0 or 1, got '" + s + "'");
}

cv::Mat readImage(const std::string& path, const std::string& yaml_path, const MapSanityLimits& limits) {
  if (!fs::exists(path)) throw InputError(yaml_path, "image file '" + path + "' does not exist");
  std::string ext = fs::path(path).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(c));
  if (ext == ".pgm") checkPgmFile(path, limits.max_cells);  // OpenCV accepts truncated PGMs silently
  cv::Mat img;
  try {
    img = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw InputError(path, std::string("cannot decode image: ") + e.what());
  }
  if (img.empty()) throw InputError(path, "cannot decode image (not a PGM/PNG, or truncated)");
  if (static_cast<double>(img.total()) > limits.max_cells)
    throw InputError(path, "image has " + std::to_string(img.total()) + " pixels, more than the limit");
  return img;
}

}  // namespace

namespace {
RosMapMetadata interpretRosMapMetadata(const YAML::Node& root, const std::string& yaml_path,
                                       const MapSanityLimits& limits) {
  if (!root.IsMap()) throw InputError(yaml_path, "expected a YAML mapping with map_server keys");

  static const std::set<std::string> kKnown = {"image", "resolution", "origin", "negate",
                                               "occupied_thresh", "free_thresh", "mode"};
  for (const auto& kv : root) {
    const auto key = kv.first.as<std::string>();
    if (!kKnown.count(key))
      throw InputError(yaml_path, "unknown key '" + key +
                                      "' (known: image, resolution, origin, negate, occupied_thresh, free_thresh, mode)");
  }
  for (const char* req : {"image", "resolution", "origin"})
    if (!root[req]) throw InputError(yaml_path, std::string("missing required key '") + req + "'");

  RosMapMetadata m;
  m.image = scalar<std::string>(root, "image", yaml_path);
  m.resolution = scalar<double>(root, "resolution", yaml_path);
  const auto origin = root["origin"];
  if (!origin.IsSequence() || origin.size() != 3)
    throw InputError(yaml_path, "key 'origin' must be a list [x, y, yaw]");
  try {
    m.origin_x = origin[0].as<double>();
    m.origin_y = origin[1].as<double>();
    m.origin_yaw = origin[2].as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(yaml_path, "key 'origin' must hold three numbers");
  }
  if (root["negate"]) m.negate = parseNegate(root["negate"], yaml_path);
  if (root["occupied_thresh"]) m.occupied_thresh = scalar<double>(root, "occupied_thresh", yaml_path);
  if (root["free_thresh"]) m.free_thresh = scalar<double>(root, "free_thresh", yaml_path);
  if (root["mode"]) m.mode = scalar<std::string>(root, "mode", yaml_path);

  if (!std::isfinite(m.resolution) || m.resolution < limits.min_resolution_m || m.resolution > limits.max_resolution_m)
    throw InputError(yaml_path, "resolution " + std::to_string(m.resolution) + " m is not a plausible cell size");
  if (!std::isfinite(m.origin_x) || !std::isfinite(m.origin_y) || !std::isfinite(m.origin_yaw))
    throw InputError(yaml_path, "origin holds a NaN or infinite value");
  if (!(m.free_thresh >= 0.0 && m.occupied_thresh <= 1.0 && m.free_thresh < m.occupied_thresh))
    throw InputError(yaml_path, "thresholds must satisfy 0 <= free_thresh < occupied_thresh <= 1");
  if (m.mode != "trinary" && m.mode != "scale" && m.mode != "raw")
    throw InputError(yaml_path, "mode '" + m.mode + "' is not one of trinary, scale, raw");
  if (m.image.empty()) throw InputError(yaml_path, "key 'image' is empty");
  const fs::path img(m.image);
  m.image_path = img.is_absolute() ? img.string() : (fs::path(yaml_path).parent_path() / img).string();
  return m;
}
}  // namespace

RosMapMetadata readRosMapMetadata(const std::string& yaml_path, const MapSanityLimits& limits) {
  return readYamlFile(yaml_path, [&](const YAML::Node& root) { return interpretRosMapMetadata(root, yaml_path, limits); });
}

OccupancyMap readRosMap(const std::string& yaml_path, const MapSanityLimits& limits) {
  const RosMapMetadata m = readRosMapMetadata(yaml_path, limits);
  cv::Mat img = readImage(m.image_path, yaml_path, limits);

  // map_server averages the colour channels and reads alpha as "unknown" when it is zero.
  cv::Mat alpha;
  if (img.channels() == 4) cv::extractChannel(img, alpha, 3);
  cv::Mat grey;
  if (img.channels() == 1) {
    grey = img;
  } else if (img.channels() >= 3) {
    cv::Mat bgr = img;
    if (img.channels() == 4) cv::cvtColor(img, bgr, cv::COLOR_BGRA2BGR);
    cv::transform(bgr, grey, cv::Matx13f(1.f / 3, 1.f / 3, 1.f / 3));
  } else {
    throw InputError(m.image_path, "unsupported image with " + std::to_string(img.channels()) + " channels");
  }
  if (grey.depth() == CV_16U) grey.convertTo(grey, CV_8U, 1.0 / 257.0);
  if (grey.depth() != CV_8U) throw InputError(m.image_path, "unsupported pixel depth (expected 8 or 16 bit)");

  const int w = grey.cols, h = grey.rows;
  checkGridGeometry({m.origin_x, m.origin_y, m.resolution, static_cast<double>(w), static_cast<double>(h)}, limits,
                    yaml_path);
  auto grid = std::make_shared<mrpt::maps::COccupancyGridMap2D>();
  grid->setSize(m.origin_x, m.origin_x + w * m.resolution, m.origin_y, m.origin_y + h * m.resolution,
                static_cast<float>(m.resolution), static_cast<float>(kUnknownOccupancy));
  if (static_cast<int>(grid->getSizeX()) != w || static_cast<int>(grid->getSizeY()) != h)
    throw InputError(yaml_path, "internal: grid size does not match the image size");

  std::size_t free_cells = 0;
  for (int row = 0; row < h; ++row) {
    const auto* g = grey.ptr<uint8_t>(row);
    const auto* a = alpha.empty() ? nullptr : alpha.ptr<uint8_t>(row);
    const int cy = h - 1 - row;
    for (int cx = 0; cx < w; ++cx) {
      double occ = kUnknownOccupancy;
      if (m.mode == "raw") {
        occ = occupancyFromGridValue(g[cx]);
      } else if (a == nullptr || a[cx] != 0) {
        const double p = m.negate ? g[cx] / 255.0 : (255.0 - g[cx]) / 255.0;
        if (p > m.occupied_thresh) occ = 1.0;
        else if (p < m.free_thresh) occ = 0.0;
        else if (m.mode == "scale") occ = (p - m.free_thresh) / (m.occupied_thresh - m.free_thresh);
      }
      grid->setCell(cx, cy, static_cast<float>(1.0 - occ));
      if (occ < CellClassParams{}.max_free_occupancy) ++free_cells;
    }
  }
  if (free_cells == 0)
    throw InputError(yaml_path, "the map has no free cell: check 'negate', the thresholds and the image");
  return OccupancyMap{grid, m.origin_yaw, yaml_path};
}

void writeRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& yaml_path,
                 const CellClassParams& classes) {
  const fs::path yp(yaml_path);
  const std::string pgm_name = yp.stem().string() + ".pgm";
  const fs::path pgm_path = yp.parent_path() / pgm_name;
  const int w = static_cast<int>(grid.getSizeX()), h = static_cast<int>(grid.getSizeY());
  cv::Mat img(h, w, CV_8UC1, cv::Scalar(kPgmUnknown));
  const cv::Mat free = freeMask(grid, classes), occ = occupiedMask(grid, classes);
  img.setTo(kPgmFree, free);
  img.setTo(kPgmOccupied, occ);

  AtomicFile pgm(pgm_path.string());
  {
    std::ofstream f(pgm.tempPath(), std::ios::binary);
    f << "P5\n" << w << " " << h << "\n255\n";
    f.write(reinterpret_cast<const char*>(img.data), static_cast<std::streamsize>(img.total()));
    if (!f) throw InputError(pgm_path.string(), "write failed");
  }
  AtomicFile yml(yaml_path);
  {
    std::ofstream f(yml.tempPath());
    f.precision(10);
    f << "image: " << pgm_name << "\nresolution: " << grid.getResolution() << "\norigin: [" << grid.getXMin() << ", "
      << grid.getYMin() << ", 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n";
    if (!f) throw InputError(yaml_path, "write failed");
  }
  pgm.commit();
  yml.commit();
}

}  // namespace krp
