// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/onnx_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numeric>
#include <unistd.h>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/inference/keypoint_detector.h"
#include "mrpt_krp_plugin/inference/zone_classifier.h"

namespace krp {
namespace {

namespace fs = std::filesystem;

// The office models the project ships (made by krp-train-map; see models/office_two_zone/REPORT.md).
const std::string kShippedModels = std::string(KRP_SOURCE_DIR) + "/models/office_two_zone";

TEST(OnnxModel, MissingFileIsAnInputErrorNamingIt) {
  try {
    OnnxModel m("/nonexistent/model.onnx");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/model.onnx"), std::string::npos);
  }
}

TEST(OnnxModel, CorruptFileIsAnInputError) {
  const fs::path path = fs::temp_directory_path() / ("krp_corrupt_" + std::to_string(::getpid()) + ".onnx");
  std::ofstream(path) << "this is not a protobuf";
  EXPECT_THROW(OnnxModel m(path.string()), InputError);
  fs::remove(path);
}

TEST(OnnxModel, TruncatedShippedModelIsAnInputError) {
  const fs::path src = kShippedModels + "/keypoints.onnx";
  const fs::path path = fs::temp_directory_path() / ("krp_truncated_" + std::to_string(::getpid()) + ".onnx");
  {
    std::ifstream in(src, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    ASSERT_GT(bytes.size(), 1000u);
    std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  EXPECT_THROW(OnnxModel m(path.string()), InputError);
  fs::remove(path);
}

// What was read (and checked against the manifest) is what runs: a file replaced after it was
// read does not reach the session.
TEST(OnnxModel, LoadsTheBytesItWasGivenNotTheFileAsItIsNow) {
  const fs::path path = fs::temp_directory_path() / ("krp_replaced_" + std::to_string(::getpid()) + ".onnx");
  fs::copy_file(kShippedModels + "/zone_classifier.onnx", path, fs::copy_options::overwrite_existing);
  const OnnxModelFile file = readOnnxModelFile(path.string());
  std::ofstream(path, std::ios::trunc) << "this is not a protobuf";
  OnnxModel m(file);
  EXPECT_EQ(m.path(), path.string());
  EXPECT_EQ(m.inputShape().size(), 4u);
  EXPECT_THROW(OnnxModel again(path.string()), InputError) << "the file on disk is no model now";
  fs::remove(path);
}

TEST(ShippedModels, ClassifierGivesAProbabilityPerZone) {
  const auto manifest = readModelManifest(kShippedModels);
  const ZoneClassifier classifier(manifest);
  const cv::Mat unknown(manifest.submap_size_px, manifest.submap_size_px, CV_8UC1, cv::Scalar(128));
  const auto p = classifier.probabilities(unknown);
  ASSERT_EQ(p.size(), manifest.zones.size());
  EXPECT_NEAR(std::accumulate(p.begin(), p.end(), 0.0), 1.0, 1e-5);
}

TEST(ShippedModels, WrongImageSizeIsRefused) {
  const auto manifest = readModelManifest(kShippedModels);
  const ZoneClassifier classifier(manifest);
  const KeypointDetector detector(manifest);
  EXPECT_THROW(classifier.probabilities(cv::Mat(64, 64, CV_8UC1, cv::Scalar(128))), InputError);
  EXPECT_THROW(detector.detect(cv::Mat(manifest.submap_size_px, manifest.submap_size_px, CV_8UC1)), InputError);
}

}  // namespace
}  // namespace krp
