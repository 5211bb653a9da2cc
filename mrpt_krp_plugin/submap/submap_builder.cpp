// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/submap/submap_builder.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/submap/scan_beams.h"
#include "mrpt_krp_plugin/submap/wall_axes.h"

namespace krp {
namespace {

// cv::line works in integer pixels; fixed-point sub-pixel coordinates keep rays straight.
constexpr int kLineShiftBits = 4;
constexpr double kLineScale = 1 << kLineShiftBits;

cv::Point toFixed(const cv::Point2d& p) {
  return {static_cast<int>(std::lround(p.x * kLineScale)), static_cast<int>(std::lround(p.y * kLineScale))};
}

}  // namespace

Submap buildSubmap(const std::vector<PosedScan>& scans, const SubmapParams& params, double image_heading_rad) {
  validateSubmapParams(params);
  if (!std::isfinite(image_heading_rad)) throw InputError("submap builder", "the image heading is not finite");
  Submap out;
  out.grid.resolution_m = params.resolutionM();
  out.grid.image_heading_rad = image_heading_rad;
  out.grid.cells = cv::Mat::zeros(params.size_px, params.size_px, CV_8U);  // all unknown
  cv::Mat free = out.grid.cells.clone(), occupied = out.grid.cells.clone();
  for (const auto& ps : scans) {
    if (!ps.scan) throw InputError("submap builder", "a posed scan has no scan");
    const auto beams = scanBeams(*ps.scan);
    out.beams_rejected += beams.rejected;
    const mrpt::poses::CPose2D sensor = ps.robot_pose + mrpt::poses::CPose2D(ps.scan->sensorPose);
    const cv::Point2d origin = out.grid.robotToPixel({sensor.x(), sensor.y()});
    const double no_return_range = params.no_return_free_fraction * ps.scan->maxRange;
    for (const auto& b : beams.beams) {
      const double r = b.hit ? b.range_m : no_return_range;
      const mrpt::poses::CPose2D end_local(r * std::cos(b.angle_rad), r * std::sin(b.angle_rad), 0);
      const mrpt::poses::CPose2D end = sensor + end_local;
      const cv::Point2d end_px = out.grid.robotToPixel({end.x(), end.y()});
      cv::line(free, toFixed(origin), toFixed(end_px), cv::Scalar(255), 1, cv::LINE_8, kLineShiftBits);
      ++out.beams_used;
      if (!b.hit) continue;
      ++out.hits;
      const cv::Point hit(static_cast<int>(std::lround(end_px.x)), static_cast<int>(std::lround(end_px.y)));
      if (hit.x < 0 || hit.y < 0 || hit.x >= params.size_px || hit.y >= params.size_px) continue;
      if (params.hit_radius_cells == 0) occupied.at<uint8_t>(hit) = 255;
      else cv::circle(occupied, hit, params.hit_radius_cells, cv::Scalar(255), cv::FILLED);
    }
  }
  out.grid.cells.setTo(static_cast<int>(CellState::kFree), free);
  out.grid.cells.setTo(static_cast<int>(CellState::kOccupied), occupied);
  return out;
}

Submap buildSubmap(const mrpt::obs::CObservation2DRangeScan& scan, const SubmapParams& params,
                   double image_heading_rad) {
  return buildSubmap(std::vector<PosedScan>{{&scan, mrpt::poses::CPose2D()}}, params, image_heading_rad);
}

std::vector<double> submapImageHeadings(const mrpt::obs::CObservation2DRangeScan& scan, const SubmapParams& params) {
  if (params.orientation == SubmapOrientation::kHeadingUp) return {kHeadingUpRad};
  return wallAlignedImageHeadings(scanWallAxes(scan));
}

}  // namespace krp
