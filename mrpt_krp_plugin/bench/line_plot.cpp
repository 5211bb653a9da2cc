// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/bench/line_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "mrpt_krp_plugin/common/png_file.h"
#include "mrpt_krp_plugin/zones/zone_drawing.h"

namespace krp {
namespace {
constexpr int kLeft = 90, kRight = 30, kTop = 50, kBottom = 60, kTicks = 5;
const cv::Scalar kInk(40, 40, 40), kGridInk(225, 225, 225);

std::string fmt(double v) {
  char b[32];
  if (std::abs(v) >= 1000 || (v != 0 && std::abs(v) < 0.01)) std::snprintf(b, sizeof(b), "%.2g", v);
  else std::snprintf(b, sizeof(b), "%.3g", v);
  return b;
}
}  // namespace

cv::Mat drawLinePlot(const std::string& title, const std::string& x_label, const std::string& y_label,
                     const std::vector<PlotSeries>& series, const LinePlotParams& p) {
  cv::Mat img(p.height_px, p.width_px, CV_8UC3, cv::Scalar(255, 255, 255));
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  auto ty = [&](double y) { return p.log_y ? std::log10(std::max(y, 1e-9)) : y; };
  for (const auto& s : series)
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, ty(s.y[i])), y1 = std::max(y1, ty(s.y[i]));
    }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 <= x0) x1 = x0 + 1;
  if (!p.log_y) y0 = std::min(0.0, y0);
  if (y1 <= y0) y1 = y0 + 1;
  const int W = p.width_px - kLeft - kRight, H = p.height_px - kTop - kBottom;
  auto px = [&](double x, double y) {
    return cv::Point(kLeft + static_cast<int>((x - x0) / (x1 - x0) * W), kTop + H - static_cast<int>((ty(y) - y0) / (y1 - y0) * H));
  };
  for (int t = 0; t <= kTicks; ++t) {
    const double xv = x0 + (x1 - x0) * t / kTicks, yv = y0 + (y1 - y0) * t / kTicks;
    const int gx = kLeft + W * t / kTicks, gy = kTop + H - H * t / kTicks;
    cv::line(img, {gx, kTop}, {gx, kTop + H}, kGridInk);
    cv::line(img, {kLeft, gy}, {kLeft + W, gy}, kGridInk);
    cv::putText(img, fmt(xv), {gx - 12, kTop + H + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45, kInk);
    cv::putText(img, fmt(p.log_y ? std::pow(10.0, yv) : yv), {8, gy + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, kInk);
  }
  cv::rectangle(img, {kLeft, kTop}, {kLeft + W, kTop + H}, kInk);
  cv::putText(img, title, {kLeft, 30}, cv::FONT_HERSHEY_SIMPLEX, 0.65, kInk, 2);
  cv::putText(img, x_label, {kLeft + W / 2 - 60, p.height_px - 15}, cv::FONT_HERSHEY_SIMPLEX, 0.5, kInk);
  cv::putText(img, y_label + (p.log_y ? " (log)" : ""), {8, kTop - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.5, kInk);
  for (size_t k = 0; k < series.size(); ++k) {
    const auto& s = series[k];
    const cv::Scalar colour = zoneColour(k) * 0.8;
    std::vector<cv::Point> pts;
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (std::isfinite(s.y[i])) pts.push_back(px(s.x[i], s.y[i]));
    if (pts.size() > 1) cv::polylines(img, pts, false, colour, 2, cv::LINE_AA);
    for (const auto& q : pts) cv::circle(img, q, 2, colour, cv::FILLED);
    const cv::Point legend(kLeft + W - 230, kTop + 20 + 22 * static_cast<int>(k));
    cv::line(img, legend, legend + cv::Point(25, 0), colour, 3);
    cv::putText(img, s.label, legend + cv::Point(32, 5), cv::FONT_HERSHEY_SIMPLEX, 0.5, kInk);
  }
  return img;
}

void writeLinePlot(const std::string& png_path, const std::string& title, const std::string& x_label,
                   const std::string& y_label, const std::vector<PlotSeries>& series, const LinePlotParams& params) {
  const cv::Mat img = drawLinePlot(title, x_label, y_label, series, params);
  writePngAtomically(png_path, img);
}

}  // namespace krp
