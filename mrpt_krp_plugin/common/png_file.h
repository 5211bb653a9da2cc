// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace krp {

/// Writes an image as PNG through a temporary file and a rename (see AtomicFile), so a
/// failed write never leaves a half-written picture. Throws InputError.
void writePngAtomically(const std::string& png_path, const cv::Mat& image);

}  // namespace krp
