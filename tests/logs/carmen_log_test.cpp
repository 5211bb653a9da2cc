// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/logs/carmen_log.h"

#include <gtest/gtest.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <zlib.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/sim/lidar_profile.h"
#include "mrpt_krp_plugin/sim/trial.h"
#include "support/test_maps.h"

namespace krp {
namespace {

using test::tempDir;
using test::writeText;

constexpr double kPi = 3.14159265358979323846;

// A FLASER line: n ranges, laser pose, odometry pose, timestamps.
std::string flaser(const std::vector<double>& ranges, mrpt::math::TPose2D laser, mrpt::math::TPose2D odom, double t) {
  std::ostringstream s;
  s.precision(10);
  s << "FLASER " << ranges.size();
  for (double r : ranges) s << " " << r;
  s << " " << laser.x << " " << laser.y << " " << laser.phi << " " << odom.x << " " << odom.y << " " << odom.phi << " " << t
    << " testhost " << t << "\n";
  return s.str();
}

std::vector<double> constantRanges(std::size_t n, double r) { return std::vector<double>(n, r); }

std::string header() {
  return "# message formats defined: PARAM SYNC ODOM FLASER RLASER\n"
         "PARAM robot_front_laser_max 30.0 nohost 0\n"
         "PARAM robot_frontlaser_offset 0.25 nohost 0\n"
         "ODOM 0 0 0 0 0 0 1.0 testhost 1.0\n";
}

std::shared_ptr<mrpt::obs::CObservation2DRangeScan> scanOf(const RawlogStep& s) {
  return s.observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
}

std::vector<mrpt::math::TPoint2D> returnsInRobotFrame(const mrpt::obs::CObservation2DRangeScan& scan) {
  mrpt::maps::CSimplePointsMap pts;
  pts.insertionOptions.minDistBetweenLaserPoints = 0;
  pts.loadFromRangeScan(scan);
  std::vector<mrpt::math::TPoint2D> out;
  for (size_t i = 0; i < pts.size(); ++i) {
    float x, y;
    pts.getPoint(i, x, y);
    out.emplace_back(x, y);
  }
  return out;
}

TEST(CarmenLog, FlaserBeamsPointWhereCarmenSaysAndPosesLoseTheLaserOffset) {
  const auto dir = tempDir("carmen_flaser");
  const std::size_t n = 8;
  std::vector<double> ranges(n);
  for (std::size_t i = 0; i < n; ++i) ranges[i] = 1.0 + 0.5 * static_cast<double>(i);
  const mrpt::math::TPose2D laser0(2.0, 3.0, 0.5), odom0(10.0, 0.0, 0.0), odom1(11.0, 0.0, kPi / 2);
  writeText(dir + "/log.txt", header() + flaser(ranges, laser0, odom0, 5.0) + flaser(ranges, laser0, odom1, 6.0));
  CarmenLogParams few_beams;
  few_beams.min_valid_returns = 3;
  const auto log = readCarmenLog(dir + "/log.txt", few_beams);
  ASSERT_EQ(log.steps.size(), 2u);
  EXPECT_EQ(log.other_records, 3u);  // 2 PARAM + 1 ODOM
  EXPECT_DOUBLE_EQ(log.max_range_m, 30.0);
  EXPECT_DOUBLE_EQ(log.laser_offset_x_m, 0.25);

  // Beam i at -90 deg + i * 180/n deg, 0.25 m ahead of the robot centre, as MRPT projects it.
  const auto pts = returnsInRobotFrame(*scanOf(log.steps[0]));
  ASSERT_EQ(pts.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = -kPi / 2 + static_cast<double>(i) * kPi / static_cast<double>(n);
    EXPECT_NEAR(pts[i].x, 0.25 + ranges[i] * std::cos(a), 1e-4) << "beam " << i;
    EXPECT_NEAR(pts[i].y, ranges[i] * std::sin(a), 1e-4) << "beam " << i;
  }
  // The robot sits 0.25 m behind the logged laser pose.
  EXPECT_NEAR(log.logged_poses[0].x, 2.0 - 0.25 * std::cos(0.5), 1e-9);
  EXPECT_NEAR(log.logged_poses[0].y, 3.0 - 0.25 * std::sin(0.5), 1e-9);
  EXPECT_NEAR(log.logged_poses[0].phi, 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(log.timestamps_s[1], 6.0);

  // The second step's odometry: 1 m forward and a quarter turn, from the odometry fields.
  const auto move = log.steps[1].action->getBestMovementEstimation();
  ASSERT_TRUE(move);
  const auto inc = move->poseChange->getMeanVal();
  EXPECT_NEAR(inc.x(), 1.0, 1e-6);
  EXPECT_NEAR(inc.y(), 0.0, 1e-6);
  EXPECT_NEAR(inc.phi(), kPi / 2, 1e-6);
}

TEST(CarmenLog, ReadingsAtTheMaximumRangeAreNoReturns) {
  const auto dir = tempDir("carmen_max");
  auto ranges = constantRanges(20, 2.0);
  ranges[3] = 30.0;   // the logged maximum: no return
  ranges[4] = 81.91;  // SICK's no-return code
  ranges[5] = 0.0;    // no reading
  writeText(dir + "/log.txt", header() + flaser(ranges, {0, 0, 0}, {0, 0, 0}, 1.0));
  const auto scan = scanOf(readCarmenLog(dir + "/log.txt").steps[0]);
  EXPECT_FALSE(scan->getScanRangeValidity(3));
  EXPECT_FALSE(scan->getScanRangeValidity(4));
  EXPECT_FALSE(scan->getScanRangeValidity(5));
  EXPECT_TRUE(scan->getScanRangeValidity(6));
  EXPECT_FLOAT_EQ(scan->maxRange, 30.0f);
}

TEST(CarmenLog, ParametersOverrideTheLogsOwnSettings) {
  const auto dir = tempDir("carmen_params");
  writeText(dir + "/log.txt", header() + flaser(constantRanges(20, 2.0), {0, 0, 0}, {0, 0, 0}, 1.0));
  CarmenLogParams p;
  p.max_range_m = 12.0;
  p.laser_offset_x_m = -0.1;
  const auto log = readCarmenLog(dir + "/log.txt", p);
  EXPECT_DOUBLE_EQ(log.max_range_m, 12.0);
  EXPECT_NEAR(scanOf(log.steps[0])->sensorPose.x(), -0.1, 1e-9);
}

TEST(CarmenLog, RobotLaserLinesUseTheirOwnAnglesAndLaserPose) {
  const auto dir = tempDir("carmen_robotlaser");
  // 5 beams from -60 deg, 30 deg apart; laser 0.3 m ahead of the robot; 2 remissions.
  std::ostringstream l;
  const double start = -kPi / 3, res = kPi / 6;
  l << "ROBOTLASER1 0 " << start << " " << 4 * res << " " << res << " 20.0 0.01 0 5 1 2 3 4 5 2 0.5 0.5 "
    << "1.3 2.0 0.0 1.0 2.0 0.0 0.1 0 0.5 0.2 100 7.0 host 7.0\n";
  writeText(dir + "/log.txt", l.str());
  CarmenLogParams few_beams;
  few_beams.min_valid_returns = 3;
  const auto log = readCarmenLog(dir + "/log.txt", few_beams);
  ASSERT_EQ(log.steps.size(), 1u);
  EXPECT_NEAR(log.logged_poses[0].x, 1.0, 1e-9);
  const auto pts = returnsInRobotFrame(*scanOf(log.steps[0]));
  ASSERT_EQ(pts.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    const double a = start + i * res, r = 1.0 + i;
    EXPECT_NEAR(pts[i].x, 0.3 + r * std::cos(a), 1e-4) << "beam " << i;
    EXPECT_NEAR(pts[i].y, r * std::sin(a), 1e-4) << "beam " << i;
  }
}

// A RAWLASER1 line: `n` beams from `start`, `res` apart, and no pose.
std::string rawlaser(const std::vector<double>& ranges, double start, double res, double t, const char* name = "RAWLASER1") {
  std::ostringstream s;
  s.precision(10);
  s << name << " 0 " << start << " " << res * static_cast<double>(ranges.size() - 1) << " " << res << " 20.0 0.01 0 "
    << ranges.size();
  for (double r : ranges) s << " " << r;
  s << " 0 " << t + 100.0 << " testhost " << t << "\n";
  return s.str();
}

std::string odom(mrpt::math::TPose2D pose, double t) {
  std::ostringstream s;
  s.precision(10);
  s << "ODOM " << pose.x << " " << pose.y << " " << pose.phi << " 0 0 0 " << t + 100.0 << " testhost " << t << "\n";
  return s.str();
}

TEST(CarmenLog, RawLaserLinesTakeTheOdometryOfTheirTimeAndTheFrontLasersOffset) {
  const auto dir = tempDir("carmen_rawlaser");
  const double start = -kPi / 2, res = kPi / 4;
  const std::vector<double> ranges{1.0, 2.0, 3.0, 4.0, 5.0};
  // ODOM at 1 s and 2 s; scans at 1.5 s (halfway) and 2.0 s (on the second ODOM line).
  writeText(dir + "/log.txt", "PARAM robot_frontlaser_offset 0.2 nohost 0\n" + odom({0, 0, 0}, 1.0) +
                                  rawlaser(ranges, start, res, 1.5) + odom({2.0, 0, kPi / 2}, 2.0) +
                                  rawlaser(ranges, start, res, 2.0) + rawlaser(ranges, start, res, 2.2, "RAWLASER2"));
  CarmenLogParams few_beams;
  few_beams.min_valid_returns = 3;
  const auto log = readCarmenLog(dir + "/log.txt", few_beams);
  ASSERT_EQ(log.steps.size(), 2u);
  EXPECT_TRUE(log.poses_from_odom_lines);
  EXPECT_EQ(log.laser_lines, 2u);
  EXPECT_EQ(log.other_records, 4u);  // PARAM, 2 ODOM, the rear laser's RAWLASER2
  EXPECT_NEAR(log.logged_poses[0].x, 1.0, 1e-9);
  EXPECT_NEAR(log.logged_poses[0].phi, kPi / 4, 1e-9);
  EXPECT_DOUBLE_EQ(log.timestamps_s[1], 2.0);
  const auto inc = log.steps[1].action->getBestMovementEstimation()->poseChange->getMeanVal();
  const mrpt::poses::CPose2D expected = mrpt::poses::CPose2D(2.0, 0, kPi / 2) - mrpt::poses::CPose2D(1.0, 0, kPi / 4);
  EXPECT_NEAR(inc.x(), expected.x(), 1e-6);
  EXPECT_NEAR(inc.y(), expected.y(), 1e-6);
  EXPECT_NEAR(inc.phi(), kPi / 4, 1e-6);
  // The line's own beam settings, 0.2 m ahead of the robot centre.
  const auto pts = returnsInRobotFrame(*scanOf(log.steps[0]));
  ASSERT_EQ(pts.size(), ranges.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double a = start + static_cast<double>(i) * res;
    EXPECT_NEAR(pts[i].x, 0.2 + ranges[i] * std::cos(a), 1e-4) << "beam " << i;
    EXPECT_NEAR(pts[i].y, ranges[i] * std::sin(a), 1e-4) << "beam " << i;
  }
}

TEST(CarmenLog, RawLaserLinesRepeatingPosedScansAreNotReadTwice) {
  const auto dir = tempDir("carmen_rawlaser_dup");
  const auto ranges = constantRanges(20, 2.0);
  writeText(dir + "/log.txt", header() + rawlaser(ranges, -kPi / 2, kPi / 19, 1.0) +
                                  flaser(ranges, {0, 0, 0}, {0, 0, 0}, 1.0) + rawlaser(ranges, -kPi / 2, kPi / 19, 2.0) +
                                  flaser(ranges, {1, 0, 0}, {1, 0, 0}, 2.0));
  const auto log = readCarmenLog(dir + "/log.txt");
  EXPECT_FALSE(log.poses_from_odom_lines);
  ASSERT_EQ(log.steps.size(), 2u);
  EXPECT_EQ(scanOf(log.steps[0])->sensorLabel, "FLASER");
  EXPECT_EQ(log.other_records, 5u);  // 2 PARAM, 1 ODOM, 2 RAWLASER1
}

TEST(CarmenLog, RawLaserLinesFarFromAnyOdometryAreSkippedAndSaidWhy) {
  const auto dir = tempDir("carmen_rawlaser_gap");
  const auto ranges = constantRanges(20, 2.0);
  writeText(dir + "/log.txt", odom({0, 0, 0}, 1.0) + rawlaser(ranges, -kPi / 2, kPi / 19, 5.0) +
                                  rawlaser(ranges, -kPi / 2, kPi / 19, 1.1));
  const auto log = readCarmenLog(dir + "/log.txt");
  ASSERT_EQ(log.steps.size(), 1u);
  EXPECT_EQ(log.skipped_scans, 1u);
  EXPECT_NE(log.first_skip_reason.find("line 2: no ODOM line within 0.5 s"), std::string::npos) << log.first_skip_reason;
}

// Writes `text` gzip-compressed, keeping only the first `keep_fraction` of the compressed bytes.
void writeGzip(const std::string& path, const std::string& text, double keep_fraction = 1.0) {
  const std::string tmp = path + ".full";
  gzFile f = gzopen(tmp.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  gzwrite(f, text.data(), static_cast<unsigned>(text.size()));
  gzclose(f);
  std::ifstream in(tmp, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  writeText(path, bytes.substr(0, static_cast<std::size_t>(keep_fraction * static_cast<double>(bytes.size()))));
}

TEST(CarmenLog, ReadsGzipAsPlainText) {
  const auto dir = tempDir("carmen_gz");
  std::string text = header();
  for (int i = 0; i < 5; ++i) text += flaser(constantRanges(50, 1.0 + i), {double(i), 0, 0}, {double(i), 0, 0}, i);
  writeGzip(dir + "/log.gz", text);
  writeText(dir + "/log.txt", text);
  const auto a = readCarmenLog(dir + "/log.gz"), b = readCarmenLog(dir + "/log.txt");
  ASSERT_EQ(a.steps.size(), 5u);
  ASSERT_EQ(b.steps.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(a.logged_poses[i].x, b.logged_poses[i].x);
}

TEST(CarmenLog, ScansWithTooFewReturnsAreSkippedAndCounted) {
  const auto dir = tempDir("carmen_skip");
  writeText(dir + "/log.txt", header() + flaser(constantRanges(20, 50.0), {0, 0, 0}, {0, 0, 0}, 1.0) +
                                  flaser(constantRanges(20, 2.0), {1, 0, 0}, {1, 0, 0}, 2.0));
  const auto log = readCarmenLog(dir + "/log.txt");
  EXPECT_EQ(log.steps.size(), 1u);
  EXPECT_EQ(log.skipped_scans, 1u);
  EXPECT_NE(log.first_skip_reason.find("line 5"), std::string::npos) << log.first_skip_reason;
}

// Each bad log gives an InputError whose message names the file and says `expected`.
void expectRefused(const std::string& name, const std::string& content, const std::string& expected) {
  const auto dir = tempDir("carmen_bad_" + name);
  writeText(dir + "/log.txt", content);
  try {
    readCarmenLog(dir + "/log.txt");
    ADD_FAILURE() << name << ": accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(dir + "/log.txt"), std::string::npos) << name << ": " << what;
    EXPECT_NE(what.find(expected), std::string::npos) << name << ": " << what;
  }
}

TEST(CarmenLog, BadLogsAreRefusedNamingFileLineAndProblem) {
  const auto good = flaser(constantRanges(20, 2.0), {0, 0, 0}, {0, 0, 0}, 1.0);
  expectRefused("truncated", header() + good.substr(0, good.size() / 2), "line 5 (FLASER): has");
  expectRefused("nan", header() + "FLASER 2 nan 1.0 0 0 0 0 0 0 1 h 1\n", "not finite");
  expectRefused("word", header() + "FLASER 2 abc 1.0 0 0 0 0 0 0 1 h 1\n", "'abc' is not a number");
  expectRefused("count", header() + "FLASER -3 1 1 1\n", "beam count -3 is not a count");
  expectRefused("huge_count", header() + "FLASER 1e12 1 1 1\n", "is not a count");
  expectRefused("extra_fields", header() + "FLASER 2 1.0 1.0 0 0 0 0 0 0 1 h 1 surplus\n", "expected 13");
  expectRefused("no_laser", header(), "no usable laser line");
  expectRefused("binary", std::string("FLASER\0\x01\x02", 9), "binary");
  expectRefused("bad_param", "PARAM robot_front_laser_max far nohost 0\n" + good, "robot_front_laser_max 'far'");
  const auto raw = rawlaser(constantRanges(20, 2.0), -1.5, 0.15, 1.0);
  expectRefused("raw_without_odom", raw, "1 read, 1 skipped; first: line 1: no ODOM line within 0.5 s of its time; the log "
                                         "has no ODOM line");
  expectRefused("raw_truncated", odom({0, 0, 0}, 1.0) + raw.substr(0, raw.size() / 2), "line 2 (RAWLASER1): ends after");
  expectRefused("odom_truncated", "ODOM 0 0 0 0 0 0 1 h\n" + raw, "line 1 (ODOM): has 9 fields, expected 10");
  expectRefused("bad_resolution", "ROBOTLASER1 0 0 1 -0.1 20 0 0 2 1 1 0 0 0 0 0 0 0 0 0 0 0 0 1 h 1\n",
                "angular resolution must be > 0");
}

TEST(CarmenLog, MissingAndTruncatedCompressedFilesAreRefused) {
  EXPECT_THROW(readCarmenLog("/nonexistent/log.gz"), InputError);
  const auto dir = tempDir("carmen_gz_cut");
  std::string text = header();
  for (int i = 0; i < 200; ++i) text += flaser(constantRanges(100, 1.0 + 0.01 * i), {double(i), 0, 0}, {double(i), 0, 0}, i);
  writeGzip(dir + "/log.gz", text, 0.5);
  try {
    readCarmenLog(dir + "/log.gz");
    ADD_FAILURE() << "a truncated .gz was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ends early"), std::string::npos) << e.what();
  }
}

TEST(CarmenLog, SimulatedTrialRoundTripsThroughRobotLaserLines) {
  const auto room = test::asymmetricRoom();
  TrialParams tp;
  tp.steps = 4;
  const auto trial = generateTrial(room, lidarProfileByName("safety_270"), tp, 11);
  const auto dir = tempDir("carmen_roundtrip");
  writeTrialCarmenLog(trial, dir + "/trial.carmen.log");
  const auto log = readCarmenLog(dir + "/trial.carmen.log");
  ASSERT_EQ(log.steps.size(), trial.scans.size());
  for (std::size_t i = 0; i < trial.scans.size(); ++i) {
    const auto& original = *trial.scans[i];
    const auto read = scanOf(log.steps[i]);
    ASSERT_EQ(read->getScanSize(), original.getScanSize());
    // Same returns where MRPT projects them, to float precision.
    const auto a = returnsInRobotFrame(original), b = returnsInRobotFrame(*read);
    ASSERT_EQ(a.size(), b.size()) << "step " << i;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k].x, b[k].x, 1e-3) << "step " << i << " beam " << k;
      EXPECT_NEAR(a[k].y, b[k].y, 1e-3) << "step " << i << " beam " << k;
    }
    // The odometry increments survive the integration into logged poses.
    const auto inc = log.steps[i].action->getBestMovementEstimation()->poseChange->getMeanVal();
    EXPECT_NEAR(inc.x(), trial.odometry[i].x(), 1e-6);
    EXPECT_NEAR(inc.y(), trial.odometry[i].y(), 1e-6);
    EXPECT_NEAR(inc.phi(), trial.odometry[i].phi(), 1e-6);
  }
}

}  // namespace
}  // namespace krp
