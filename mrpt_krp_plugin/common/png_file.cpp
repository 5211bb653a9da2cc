// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/png_file.h"

#include <cstdio>
#include <opencv2/imgcodecs.hpp>

#include "mrpt_krp_plugin/common/atomic_file.h"
#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

void writePngAtomically(const std::string& png_path, const cv::Mat& image) {
  AtomicFile f(png_path);
  // OpenCV picks the encoder from the extension, so the temporary must end in .png.
  const std::string tmp_png = f.tempPath() + ".png";
  if (!cv::imwrite(tmp_png, image)) throw InputError(png_path, "cannot write PNG");
  if (std::rename(tmp_png.c_str(), f.tempPath().c_str()) != 0) {
    std::remove(tmp_png.c_str());
    throw InputError(png_path, "cannot move the finished temporary file into place");
  }
  f.commit();
}

}  // namespace krp
