// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace krp {

/// One named line of a plot.
struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
};

struct LinePlotParams {
  int width_px = 900, height_px = 560;
  bool log_y = false;
};

/// A small line chart (axes, ticks, legend) drawn with OpenCV, so reports need no Python.
cv::Mat drawLinePlot(const std::string& title, const std::string& x_label, const std::string& y_label,
                     const std::vector<PlotSeries>& series, const LinePlotParams& params = {});

/// Draws and writes a PNG atomically.
void writeLinePlot(const std::string& png_path, const std::string& title, const std::string& x_label,
                   const std::string& y_label, const std::vector<PlotSeries>& series, const LinePlotParams& params = {});

}  // namespace krp
