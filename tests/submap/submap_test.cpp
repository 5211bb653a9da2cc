// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/common/png_file.h"
#include "mrpt_krp_plugin/sim/scan_simulator.h"
#include "mrpt_krp_plugin/submap/occupancy_image.h"
#include "mrpt_krp_plugin/submap/scan_beams.h"
#include "mrpt_krp_plugin/submap/sdt_image.h"
#include "mrpt_krp_plugin/submap/seismic_colormap.h"
#include "mrpt_krp_plugin/submap/submap_builder.h"
#include "support/test_maps.h"

namespace krp {
namespace {

LidarProfile noiselessOmni() {
  LidarProfile p = lidarProfileByName("omni_12m");
  p.range_noise_std_m = 0.0;
  p.dropout_probability = 0.0;
  return p;
}

// An open floor with a single wall at x = wall_x, seen from the origin.
mrpt::maps::COccupancyGridMap2D wallAhead(double wall_x) {
  mrpt::maps::COccupancyGridMap2D g(-10, 10, -10, 10, 0.05f);
  g.fill(1.0f);
  for (unsigned y = 0; y < g.getSizeY(); ++y) g.setCell(g.x2idx(wall_x), y, 0.0f);
  return g;
}

// True if a cell within one cell of the robot-frame point is occupied (hits round to the
// nearest cell, so an exact cell would test the rounding, not the geometry).
bool occupiedNear(const LocalGrid& g, const mrpt::math::TPoint2D& p) {
  const auto px = g.robotToPixel(p);
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc)
      if (g.at(static_cast<int>(std::lround(px.x)) + dc, static_cast<int>(std::lround(px.y)) + dr) == CellState::kOccupied)
        return true;
  return false;
}

TEST(LocalGrid, RobotAtCentreHeadingUp) {
  LocalGrid g;
  g.cells = cv::Mat::zeros(100, 100, CV_8U);
  g.resolution_m = 0.1;
  const auto centre = g.robotToPixel({0, 0});
  EXPECT_DOUBLE_EQ(centre.x, 49.5);
  EXPECT_DOUBLE_EQ(centre.y, 49.5);
  const auto ahead = g.robotToPixel({2.0, 0});  // forward is up: smaller row
  EXPECT_DOUBLE_EQ(ahead.y, 29.5);
  EXPECT_DOUBLE_EQ(ahead.x, 49.5);
  const auto left = g.robotToPixel({0, 1.0});  // left is left: smaller column
  EXPECT_DOUBLE_EQ(left.x, 39.5);
  const auto back = g.pixelToRobot(g.robotToPixel({1.3, -0.7}));
  EXPECT_NEAR(back.x, 1.3, 1e-12);
  EXPECT_NEAR(back.y, -0.7, 1e-12);
}

TEST(SubmapParams, SizedForTheLidar) {
  EXPECT_DOUBLE_EQ(submapParamsForLidar(lidarProfileByName("lds01")).size_m, 8.0);
  EXPECT_DOUBLE_EQ(submapParamsForLidar(lidarProfileByName("omni_12m")).size_m, 24.0);
  EXPECT_DOUBLE_EQ(submapParamsForLidar(lidarProfileByName("safety_270")).size_m, 24.0);
  SubmapParams bad;
  bad.size_px = 3;
  EXPECT_THROW(validateSubmapParams(bad), InputError);
}

TEST(SubmapBuilder, WallAheadIsOccupiedFreeSpaceBeforeItUnknownBehind) {
  const auto world = wallAhead(3.0);
  Rng rng(1);
  const auto scan = ScanSimulator(noiselessOmni()).simulate(world, mrpt::poses::CPose2D(0, 0, 0), rng);
  SubmapParams p;
  p.size_m = 12.8;
  p.size_px = 128;  // 0.1 m cells
  const auto sub = buildSubmap(*scan, p);
  EXPECT_EQ(sub.beams_rejected, 0);
  EXPECT_GT(sub.hits, 100);
  const auto& g = sub.grid;
  auto stateAt = [&](double x, double y) {
    const auto px = g.robotToPixel({x, y});
    return g.at(static_cast<int>(std::lround(px.x)), static_cast<int>(std::lround(px.y)));
  };
  EXPECT_EQ(stateAt(0.0, 0.0), CellState::kFree);
  EXPECT_EQ(stateAt(1.5, 0.0), CellState::kFree);
  EXPECT_TRUE(occupiedNear(g, {3.0, 0.0}));
  EXPECT_TRUE(occupiedNear(g, {3.0, 1.0}));
  EXPECT_EQ(stateAt(4.5, 0.0), CellState::kUnknown);
  // Behind the robot nothing returned: unknown by default, since a lidar flags a dropout the
  // same way as open space; free only when no-return beams are asked to carry free space.
  EXPECT_EQ(stateAt(-5.0, 0.0), CellState::kUnknown);
  SubmapParams open_floor = p;
  open_floor.no_return_free_fraction = 0.9;
  const auto open_sub = buildSubmap(*scan, open_floor);
  const auto behind = open_sub.grid.robotToPixel({-5.0, 0.0});
  EXPECT_EQ(open_sub.grid.at(static_cast<int>(std::lround(behind.x)), static_cast<int>(std::lround(behind.y))),
            CellState::kFree);

  // The robot turned left by 90 deg sees the same wall on its right, not ahead.
  const auto turned = ScanSimulator(noiselessOmni()).simulate(world, mrpt::poses::CPose2D(0, 0, M_PI / 2), rng);
  const auto sub2 = buildSubmap(*turned, p);
  EXPECT_TRUE(occupiedNear(sub2.grid, {0.0, -3.0}));
  EXPECT_FALSE(occupiedNear(sub2.grid, {3.0, 0.0}));
}

TEST(SubmapBuilder, OlderScanPlacedByItsRelativePose) {
  // The robot scanned at x = -1 and then moved 1 m forward: the older scan, placed 1 m
  // behind, must see the wall at the same submap place as the newer one.
  const auto world = wallAhead(3.0);
  Rng rng(1);
  ScanSimulator sim(noiselessOmni());
  const auto older = sim.simulate(world, mrpt::poses::CPose2D(-1, 0, 0), rng);
  SubmapParams p;
  p.size_m = 12.8;
  p.size_px = 128;
  const auto sub = buildSubmap({{older.get(), mrpt::poses::CPose2D(-1, 0, 0)}}, p);
  EXPECT_TRUE(occupiedNear(sub.grid, {3.0, 0.0}));
  EXPECT_FALSE(occupiedNear(sub.grid, {4.0, 0.0}));
}

TEST(SubmapBuilder, NanAndNegativeRangesAreRejectedNotDrawn) {
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->aperture = static_cast<float>(M_PI);
  scan->maxRange = 10.0f;
  scan->resizeScan(5);
  const float ranges[5] = {2.0f, std::numeric_limits<float>::quiet_NaN(), -1.0f,
                           std::numeric_limits<float>::infinity(), 2.0f};
  for (size_t i = 0; i < 5; ++i) {
    scan->setScanRange(i, ranges[i]);
    scan->setScanRangeValidity(i, true);
  }
  const auto beams = scanBeams(*scan);
  EXPECT_EQ(beams.rejected, 3);
  EXPECT_EQ(beams.beams.size(), 2u);
  const auto sub = buildSubmap(*scan, SubmapParams{});
  EXPECT_EQ(sub.beams_rejected, 3);
  EXPECT_EQ(sub.hits, 2);

  auto empty = mrpt::obs::CObservation2DRangeScan::Create();
  empty->aperture = 1.0f;
  empty->maxRange = 5.0f;
  EXPECT_THROW(buildSubmap(*empty, SubmapParams{}), InputError);
}

TEST(SeismicColormap, BlueWhiteRedEnds) {
  const cv::Mat& lut = seismicLutBgr();
  ASSERT_EQ(lut.cols, 256);
  EXPECT_EQ(lut.at<cv::Vec3b>(0, 0), cv::Vec3b(77, 0, 0));    // dark blue (BGR)
  EXPECT_EQ(lut.at<cv::Vec3b>(0, 255), cv::Vec3b(0, 0, 128));  // dark red
  const auto mid = lut.at<cv::Vec3b>(0, 128);
  EXPECT_GT(mid[0], 240);
  EXPECT_GT(mid[1], 240);
  EXPECT_GT(mid[2], 240);
}

TEST(Renderers, OccupancyLevelsAndSdtSigns) {
  LocalGrid g;
  g.resolution_m = 0.1;
  g.cells = cv::Mat(64, 64, CV_8U, cv::Scalar(static_cast<int>(CellState::kFree)));
  g.cells.colRange(0, 10).setTo(static_cast<int>(CellState::kUnknown));
  g.cells.col(10).setTo(static_cast<int>(CellState::kOccupied));
  const cv::Mat occ = renderOccupancyImage(g);
  EXPECT_EQ(occ.at<uint8_t>(5, 5), 128);
  EXPECT_EQ(occ.at<uint8_t>(5, 10), 0);
  EXPECT_EQ(occ.at<uint8_t>(5, 30), 255);

  const cv::Mat sdt = signedDistanceM(g);
  EXPECT_NEAR(sdt.at<float>(5, 30), 2.0, 1e-3);   // 20 cells right of the wall
  EXPECT_LT(sdt.at<float>(5, 3), 0.0f);           // unknown: negative
  const cv::Mat img = renderSdtImage(g, SdtImageParams{1.0});
  ASSERT_EQ(img.type(), CV_8UC3);
  const auto far_free = img.at<cv::Vec3b>(5, 60);  // clipped at +1: dark red
  EXPECT_EQ(far_free, cv::Vec3b(0, 0, 128));
  const auto deep_unknown = img.at<cv::Vec3b>(5, 0);  // clipped at -1: dark blue
  EXPECT_EQ(deep_unknown, cv::Vec3b(77, 0, 0));
  EXPECT_THROW(renderSdtImage(g, SdtImageParams{0.0}), InputError);
}

TEST(Renderers, PngRoundTripIsLossless) {
  // The dataset stores images as PNG and the runtime renders them in memory; both must be
  // the same pixels for the same scan.
  const auto world = test::asymmetricRoom();
  Rng rng(3);
  const auto scan = ScanSimulator(noiselessOmni()).simulate(world, mrpt::poses::CPose2D(2.0, 1.5, 0.3), rng);
  const auto sub = buildSubmap(*scan, submapParamsForLidar(noiselessOmni()));
  const auto dir = test::tempDir("render_png");
  const cv::Mat sdt = renderSdtImage(sub.grid), occ = renderOccupancyImage(sub.grid);
  writePngAtomically(dir + "/sdt.png", sdt);
  writePngAtomically(dir + "/occ.png", occ);
  EXPECT_EQ(cv::norm(cv::imread(dir + "/sdt.png", cv::IMREAD_UNCHANGED), sdt, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(cv::imread(dir + "/occ.png", cv::IMREAD_UNCHANGED), occ, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace krp
