// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/logs/carmen_log.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string_view>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/logs/odometry_timeline.h"

namespace krp {
namespace {

// Fields of a FLASER line around its n ranges: the name and n, then x y theta odom_x odom_y
// odom_theta ipc_timestamp ipc_hostname logger_timestamp.
constexpr std::size_t kFlaserFieldsBesidesRanges = 11;
// ROBOTLASER1: name, 7 laser settings, n, [ranges], m, [remissions], laser pose (3), robot pose
// (3), tv rv forward_safety side_safety turn_axis, ipc_timestamp ipc_hostname logger_timestamp.
constexpr std::size_t kRobotLaserHeaderFields = 8;
constexpr std::size_t kRobotLaserTrailerFields = 14;
// RAWLASER1: ROBOTLASER1's header, ranges and remissions, then ipc_timestamp ipc_hostname
// logger_timestamp, and no pose.
constexpr std::size_t kRawLaserTrailerFields = 3;
// ODOM x y theta tv rv accel ipc_timestamp ipc_hostname logger_timestamp.
constexpr std::size_t kOdomFields = 10;

// The whole (decompressed) file; zlib reads plain files as they are.
std::string readWholeFile(const std::string& path, std::size_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "file does not exist");
  if (!fs::is_regular_file(path, ec)) throw InputError(path, "is not a regular file");
  std::unique_ptr<gzFile_s, int (*)(gzFile)> f(gzopen(path.c_str(), "rb"), gzclose);
  if (!f) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
  std::string text;
  char buf[1 << 16];
  for (;;) {
    const int got = gzread(f.get(), buf, sizeof(buf));
    if (got < 0) {
      int code = 0;
      throw InputError(path, std::string("corrupt or truncated compressed data (") + gzerror(f.get(), &code) + ")");
    }
    if (got == 0) {
      // zlib returns what a gzip stream cut short held and then flags it here.
      int code = Z_OK;
      gzerror(f.get(), &code);
      if (code == Z_BUF_ERROR) throw InputError(path, "the compressed data ends early (truncated .gz)");
      break;
    }
    text.append(buf, static_cast<std::size_t>(got));
    if (text.size() > max_bytes) throw InputError(path, "larger than " + std::to_string(max_bytes) + " bytes uncompressed");
  }
  return text;
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// A parse position inside one line, with errors that name the file, the line and the field.
class LineFields {
 public:
  LineFields(const std::string& path, std::size_t line_no, std::vector<std::string_view> fields)
      : path_(path), line_no_(line_no), fields_(std::move(fields)) {}

  std::size_t size() const { return fields_.size(); }
  std::string_view name() const { return fields_[0]; }
  std::string_view field(std::size_t index) const { return fields_[index]; }

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(path_, "line " + std::to_string(line_no_) + " (" + std::string(name()) + "): " + problem);
  }

  void requireCount(std::size_t expected, const char* layout) const {
    if (size() != expected)
      fail("has " + std::to_string(size()) + " fields, expected " + std::to_string(expected) + " (" + layout +
           (size() < expected ? "; truncated?)" : ")"));
  }

  double number(std::size_t index, const char* what) const {
    if (index >= size()) fail("ends after " + std::to_string(size()) + " fields, before its " + what + " (truncated?)");
    const std::string text(fields_[index]);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0') fail(std::string(what) + " '" + text + "' is not a number");
    if (!std::isfinite(v)) fail(std::string(what) + " is not finite");
    return v;
  }

  std::size_t count(std::size_t index, const char* what, std::size_t max) const {
    const double v = number(index, what);
    if (v < 0 || v != std::floor(v) || v > static_cast<double>(max))
      fail(std::string(what) + " " + std::string(fields_[index]) + " is not a count in 0.." + std::to_string(max));
    return static_cast<std::size_t>(v);
  }

  mrpt::math::TPose2D pose(std::size_t index, const char* what) const {
    return {number(index, what), number(index + 1, what), number(index + 2, what)};
  }

 private:
  const std::string& path_;
  std::size_t line_no_;
  std::vector<std::string_view> fields_;
};

// One laser line, before it is turned into a step.
struct LaserLine {
  std::vector<double> ranges;
  double first_angle_rad = 0.0;
  double increment_rad = 0.0;
  double max_range_m = 0.0;
  mrpt::poses::CPose2D laser_on_robot;
  mrpt::math::TPose2D logged_pose;  ///< robot, reference frame of the log
  mrpt::math::TPose2D odometry;     ///< robot, odometry frame
  double timestamp_s = 0.0;
};

struct LogSettings {
  double max_range_m = 0.0;
  double laser_offset_x_m = 0.0;
};

std::vector<double> readRanges(const LineFields& f, std::size_t first, std::size_t n) {
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = f.number(first + i, "range");
  return r;
}

LaserLine parseFlaser(const LineFields& f, const CarmenLogParams& p, const LogSettings& s) {
  const std::size_t n = f.count(1, "beam count", p.max_beams);
  f.requireCount(n + kFlaserFieldsBesidesRanges, "FLASER n ranges x y theta odom_x odom_y odom_theta ipc_ts host logger_ts");
  LaserLine l;
  l.ranges = readRanges(f, 2, n);
  const double fov = p.flaser_fov_deg * M_PI / 180.0;
  l.increment_rad = n > 0 ? fov / static_cast<double>(n) : 0.0;
  l.first_angle_rad = -0.5 * fov;
  l.max_range_m = s.max_range_m;
  l.laser_on_robot = mrpt::poses::CPose2D(s.laser_offset_x_m, 0.0, 0.0);
  const mrpt::poses::CPose2D laser(f.pose(2 + n, "laser pose"));
  l.logged_pose = (laser + (-l.laser_on_robot)).asTPose();
  l.odometry = f.pose(5 + n, "odometry pose");
  l.timestamp_s = f.number(10 + n, "logger timestamp");
  return l;
}

// The fields ROBOTLASER1 and RAWLASER1 share: the beam settings (fields 2-5), the n ranges and
// the m remissions, then `trailer_fields` more (`layout` names them all, for the count's error).
// Where the trailer starts.
std::size_t readBeamFields(const LineFields& f, const CarmenLogParams& p, std::size_t trailer_fields, const char* layout,
                           LaserLine* l) {
  const std::size_t n = f.count(kRobotLaserHeaderFields, "beam count", p.max_beams);
  const std::size_t m = f.count(kRobotLaserHeaderFields + 1 + n, "remission count", p.max_beams);
  l->first_angle_rad = f.number(2, "start angle");
  l->increment_rad = f.number(4, "angular resolution");
  l->max_range_m = f.number(5, "maximum range");
  if (!(l->increment_rad > 0)) f.fail("angular resolution must be > 0");
  if (!(l->max_range_m > 0)) f.fail("maximum range must be > 0");
  const std::size_t trailer = kRobotLaserHeaderFields + 2 + n + m;
  f.requireCount(trailer + trailer_fields, layout);
  l->ranges = readRanges(f, kRobotLaserHeaderFields + 1, n);
  return trailer;
}

LaserLine parseRobotLaser(const LineFields& f, const CarmenLogParams& p) {
  LaserLine l;
  const std::size_t poses = readBeamFields(
      f, p, kRobotLaserTrailerFields,
      "ROBOTLASER1 type start fov resolution max_range accuracy remission_mode n ranges m remissions laser_pose "
      "robot_pose tv rv forward_safety side_safety turn_axis ipc_ts host logger_ts",
      &l);
  const mrpt::poses::CPose2D laser(f.pose(poses, "laser pose"));
  const mrpt::poses::CPose2D robot(f.pose(poses + 3, "robot pose"));
  l.laser_on_robot = laser - robot;
  l.logged_pose = robot.asTPose();
  l.odometry = robot.asTPose();
  l.timestamp_s = f.number(f.size() - 1, "logger timestamp");
  return l;
}

// A RAWLASER1 line; its odometry comes from the ODOM lines (`odometry`), the laser's offset from
// the front laser's setting. Nothing when no ODOM line is near its time.
std::optional<LaserLine> parseRawLaser(const LineFields& f, const CarmenLogParams& p, const LogSettings& s,
                                       const OdometryTimeline& odometry) {
  LaserLine l;
  readBeamFields(f, p, kRawLaserTrailerFields,
                 "RAWLASER1 type start fov resolution max_range accuracy remission_mode n ranges m remissions ipc_ts "
                 "host logger_ts",
                 &l);
  l.laser_on_robot = mrpt::poses::CPose2D(s.laser_offset_x_m, 0.0, 0.0);
  l.timestamp_s = f.number(f.size() - 1, "logger timestamp");
  const auto pose = odometry.at(l.timestamp_s);
  if (!pose) return std::nullopt;
  l.odometry = *pose;
  l.logged_pose = *pose;
  return l;
}

// The ODOM lines' poses by logger timestamp.
OdometryTimeline readOdometry(const std::string& path, const std::vector<std::pair<std::size_t, std::string_view>>& lines,
                              const CarmenLogParams& p) {
  std::vector<OdometryTimeline::Sample> samples;
  for (const auto& [line_no, text] : lines) {
    if (text.rfind("ODOM ", 0) != 0) continue;
    LineFields f(path, line_no, splitFields(text));
    f.requireCount(kOdomFields, "ODOM x y theta tv rv accel ipc_ts host logger_ts");
    samples.push_back({f.number(kOdomFields - 1, "logger timestamp"), f.pose(1, "odometry pose")});
  }
  return OdometryTimeline(std::move(samples), p.max_odometry_gap_s);
}

std::string secondsText(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

bool hasPosedLaserLines(const std::vector<std::pair<std::size_t, std::string_view>>& lines) {
  for (const auto& [line_no, text] : lines)
    if (text.rfind("FLASER ", 0) == 0 || text.rfind("ROBOTLASER1 ", 0) == 0) return true;
  return false;
}

// MRPT's scans are centred on the sensor's x axis and spaced aperture/(n-1): a field of view
// that is not centred becomes a centred one on a sensor turned by the centre angle.
mrpt::obs::CObservation2DRangeScan::Ptr toScan(const LaserLine& l, const std::string& label, std::size_t* valid) {
  const std::size_t n = l.ranges.size();
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->sensorLabel = label;
  scan->aperture = static_cast<float>(l.increment_rad * static_cast<double>(n - 1));
  scan->rightToLeft = true;
  scan->maxRange = static_cast<float>(l.max_range_m);
  const double centre = l.first_angle_rad + 0.5 * l.increment_rad * static_cast<double>(n - 1);
  scan->sensorPose = mrpt::poses::CPose3D(l.laser_on_robot.x(), l.laser_on_robot.y(), 0.0, l.laser_on_robot.phi() + centre, 0, 0);
  scan->timestamp = mrpt::Clock::fromDouble(l.timestamp_s);
  scan->resizeScan(n);
  *valid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = l.ranges[i];
    const bool ok = r > 0.0 && r < l.max_range_m;
    scan->setScanRange(i, static_cast<float>(ok ? r : l.max_range_m));
    scan->setScanRangeValidity(i, ok);
    *valid += ok ? 1 : 0;
  }
  return scan;
}

// The PARAM lines the laser lines depend on, wherever in the file they are.
LogSettings readSettings(const std::string& path, const std::vector<std::pair<std::size_t, std::string_view>>& lines,
                         const CarmenLogParams& p) {
  std::optional<double> logged_max, logged_offset;
  for (const auto& [line_no, text] : lines) {
    if (text.rfind("PARAM ", 0) != 0) continue;
    LineFields f(path, line_no, splitFields(text));
    if (f.size() < 3) continue;
    const auto key = f.field(1);
    if (key == "robot_front_laser_max") logged_max = f.number(2, "robot_front_laser_max");
    if (key == "robot_frontlaser_offset") logged_offset = f.number(2, "robot_frontlaser_offset");
  }
  LogSettings s;
  s.max_range_m = p.max_range_m > 0 ? p.max_range_m : logged_max.value_or(p.fallback_max_range_m);
  s.laser_offset_x_m = std::isfinite(p.laser_offset_x_m) ? p.laser_offset_x_m : logged_offset.value_or(0.0);
  if (!(s.max_range_m > 0)) throw InputError(path, "the laser's maximum range must be > 0");
  return s;
}

}  // namespace

CarmenLog readCarmenLog(const std::string& path, const CarmenLogParams& params) {
  if (!(params.flaser_fov_deg > 0 && params.flaser_fov_deg <= 360))
    throw InputError("flaser_fov_deg", "must be in (0, 360]");
  if (!(params.max_odometry_gap_s >= 0) || !std::isfinite(params.max_odometry_gap_s))
    throw InputError("max_odometry_gap_s", "must be finite and >= 0");
  const std::string text = readWholeFile(path, params.max_bytes);
  if (text.find('\0') != std::string::npos) throw InputError(path, "is binary, not a CARMEN text log");

  std::vector<std::pair<std::size_t, std::string_view>> lines;
  std::string_view rest(text);
  for (std::size_t line_no = 1; !rest.empty(); ++line_no) {
    const auto end = rest.find('\n');
    auto line = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.emplace_back(line_no, line);
  }

  const LogSettings settings = readSettings(path, lines, params);
  CarmenLog log;
  log.max_range_m = settings.max_range_m;
  log.laser_offset_x_m = settings.laser_offset_x_m;
  // FLASER and ROBOTLASER1 lines are the front laser's scans with a pose attached; where a log has
  // them, its RAWLASER1 lines repeat those scans without one.
  log.poses_from_odom_lines = !hasPosedLaserLines(lines);
  const OdometryTimeline odometry_lines =
      log.poses_from_odom_lines ? readOdometry(path, lines, params) : OdometryTimeline({}, params.max_odometry_gap_s);
  std::optional<mrpt::poses::CPose2D> previous_odometry;
  for (const auto& [line_no, line] : lines) {
    auto fields = splitFields(line);
    if (fields.empty() || fields[0].front() == '#') continue;
    LineFields f(path, line_no, std::move(fields));
    std::optional<LaserLine> l;
    if (f.name() == "FLASER")
      l = parseFlaser(f, params, settings);
    else if (f.name() == "ROBOTLASER1")
      l = parseRobotLaser(f, params);
    else if (f.name() == "RAWLASER1" && log.poses_from_odom_lines)
      l = parseRawLaser(f, params, settings, odometry_lines);
    else {
      ++log.other_records;
      continue;
    }
    ++log.laser_lines;
    if (!l) {
      if (log.first_skip_reason.empty())
        log.first_skip_reason = "line " + std::to_string(line_no) + ": no ODOM line within " +
                                secondsText(params.max_odometry_gap_s) + " s of its time";
      ++log.skipped_scans;
      continue;
    }
    std::size_t valid = 0;
    auto scan = l->ranges.size() >= 2 ? toScan(*l, std::string(f.name()), &valid) : nullptr;
    if (!scan || valid < static_cast<std::size_t>(params.min_valid_returns)) {
      if (log.first_skip_reason.empty())
        log.first_skip_reason = "line " + std::to_string(line_no) + ": " + std::to_string(valid) + " usable returns of " +
                                std::to_string(l->ranges.size()) + " (need " + std::to_string(params.min_valid_returns) + ")";
      ++log.skipped_scans;
      continue;
    }
    const mrpt::poses::CPose2D odometry(l->odometry);
    const mrpt::poses::CPose2D increment = previous_odometry ? odometry - *previous_odometry : mrpt::poses::CPose2D();
    previous_odometry = odometry;
    log.steps.push_back(makeRawlogStep(increment, scan, params.odometry));
    log.logged_poses.push_back(l->logged_pose);
    log.timestamps_s.push_back(l->timestamp_s);
  }
  if (log.steps.empty()) {
    std::ostringstream why;
    why << "no usable laser line (FLASER, ROBOTLASER1, or RAWLASER1 with ODOM lines): " << log.laser_lines << " read";
    if (log.skipped_scans) why << ", " << log.skipped_scans << " skipped; first: " << log.first_skip_reason;
    if (log.poses_from_odom_lines && odometry_lines.size() == 0 && log.laser_lines > 0) why << "; the log has no ODOM line";
    throw InputError(path, why.str());
  }
  return log;
}

void writeTrialCarmenLog(const Trial& trial, const std::string& path) {
  std::ostringstream o;
  o.precision(9);
  o << "# simulated trial (seed " << trial.seed << "), written by mrpt_krp_plugin; robot pose = integrated odometry\n";
  mrpt::poses::CPose2D odometry;
  for (std::size_t i = 0; i < trial.scans.size(); ++i) {
    odometry = odometry + trial.odometry[i];
    const auto& scan = *trial.scans[i];
    const std::size_t n = scan.getScanSize();
    const double step = n > 1 ? scan.aperture / static_cast<double>(n - 1) : 0.0;
    const mrpt::poses::CPose2D laser = odometry + mrpt::poses::CPose2D(scan.sensorPose);
    // ROBOTLASER1 type start fov resolution max_range accuracy remission_mode n ranges m
    // CARMEN beams run counter-clockwise: a clockwise scan is written in reverse.
    o << "ROBOTLASER1 0 " << -0.5 * scan.aperture << " " << scan.aperture << " " << step << " " << scan.maxRange << " 0 0 " << n;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t k = scan.rightToLeft ? j : n - 1 - j;
      o << " " << (scan.getScanRangeValidity(k) ? scan.getScanRange(k) : scan.maxRange);
    }
    // laser pose, robot pose, tv rv forward_safety side_safety turn_axis, ipc_ts host logger_ts
    o << " 0 " << laser.x() << " " << laser.y() << " " << laser.phi() << " " << odometry.x() << " " << odometry.y() << " "
      << odometry.phi() << " 0 0 0 0 0 " << i << " sim " << i << "\n";
  }
  writeFileAtomically(path, o.str());
}

}  // namespace krp
