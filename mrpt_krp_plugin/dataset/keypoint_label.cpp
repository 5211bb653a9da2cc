// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/dataset/keypoint_label.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace krp {

std::vector<Keypoint> projectLandmarks(const ZoneLandmarks& landmarks, const mrpt::poses::CPose2D& robot_pose,
                                       const LocalGrid& grid, const KeypointLabelParams& params) {
  std::vector<Keypoint> out;
  const int n = grid.sizePx();
  const int r = params.observed_radius_cells;
  for (const auto& lm : landmarks.points) {
    double lx, ly;
    robot_pose.inverseComposePoint(lm.x, lm.y, lx, ly);
    Keypoint k;
    k.px = grid.robotToPixel({lx, ly});
    const double lo = -kPixelCentreOffset, hi = n - kPixelCentreOffset;
    const bool inside = k.px.x >= lo && k.px.y >= lo && k.px.x < hi && k.px.y < hi;
    if (inside) {
      k.visibility = KeypointVisibility::kInsideNotObserved;
      const int cx = static_cast<int>(std::lround(k.px.x)), cy = static_cast<int>(std::lround(k.px.y));
      for (int y = std::max(0, cy - r); y <= std::min(n - 1, cy + r); ++y)
        for (int x = std::max(0, cx - r); x <= std::min(n - 1, cx + r); ++x)
          if (grid.at(x, y) == CellState::kOccupied) k.visibility = KeypointVisibility::kObserved;
    }
    out.push_back(k);
  }
  return out;
}

std::optional<std::string> yoloPoseLabel(int class_id, const std::vector<Keypoint>& keypoints, int image_size_px,
                                         const KeypointLabelParams& params) {
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  bool any = false;
  for (const auto& k : keypoints) {
    if (k.visibility == KeypointVisibility::kOutside) continue;
    any = true;
    x0 = std::min(x0, k.px.x), y0 = std::min(y0, k.px.y), x1 = std::max(x1, k.px.x), y1 = std::max(y1, k.px.y);
  }
  if (!any) return std::nullopt;
  const double lo = -kPixelCentreOffset, hi = image_size_px - kPixelCentreOffset, s = image_size_px;
  x0 = std::clamp(x0 - params.box_margin_px, lo, hi), y0 = std::clamp(y0 - params.box_margin_px, lo, hi);
  x1 = std::clamp(x1 + params.box_margin_px, lo, hi), y1 = std::clamp(y1 + params.box_margin_px, lo, hi);
  std::ostringstream o;
  o.precision(6);
  o << std::fixed << class_id << " " << ((x0 + x1) / 2 + kPixelCentreOffset) / s << " " << ((y0 + y1) / 2 + kPixelCentreOffset) / s << " "
    << (x1 - x0) / s << " " << (y1 - y0) / s;
  for (const auto& k : keypoints) {
    if (k.visibility == KeypointVisibility::kOutside) o << " 0 0 0";
    else o << " " << (k.px.x + kPixelCentreOffset) / s << " " << (k.px.y + kPixelCentreOffset) / s << " " << static_cast<int>(k.visibility);
  }
  return o.str();
}

}  // namespace krp
