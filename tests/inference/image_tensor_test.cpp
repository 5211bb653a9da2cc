// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/image_tensor.h"

#include <gtest/gtest.h>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {

TEST(ImageTensor, GreyImageIsOneNormalizedPlane) {
  cv::Mat grey(2, 3, CV_8UC1, cv::Scalar(128));
  grey.at<uint8_t>(1, 2) = 255;
  const Tensor t = imageToTensor(grey, {1.0 / 255.0, 0.5, 0.5});
  ASSERT_EQ(t.shape, (std::vector<int64_t>{1, 1, 2, 3}));
  EXPECT_NEAR(t.values[0], (128.0 / 255.0 - 0.5) / 0.5, 1e-6);
  EXPECT_NEAR(t.values[5], 1.0, 1e-6);
}

TEST(ImageTensor, ColourImageBecomesRgbPlanes) {
  cv::Mat bgr(1, 2, CV_8UC3, cv::Scalar(10, 20, 30));  // B=10, G=20, R=30
  const Tensor t = imageToTensor(bgr, {1.0, 0.0, 1.0});
  ASSERT_EQ(t.shape, (std::vector<int64_t>{1, 3, 1, 2}));
  EXPECT_FLOAT_EQ(t.values[0], 30);  // plane 0 is red
  EXPECT_FLOAT_EQ(t.values[2], 20);
  EXPECT_FLOAT_EQ(t.values[4], 10);
}

TEST(ImageTensor, RejectsEmptyAndFloatImages) {
  EXPECT_THROW(imageToTensor(cv::Mat(), {}), InputError);
  EXPECT_THROW(imageToTensor(cv::Mat(2, 2, CV_32FC1), {}), InputError);
}

}  // namespace
}  // namespace krp
