// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/inference/model_manifest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json validManifest() {
  auto model = [](const char* file, int channels, const char* input, const char* output) {
    return json{{"file", file},
                {"sha256", "00"},
                {"input",
                 {{"name", input},
                  {"shape", {1, channels, 160, 160}},
                  {"normalize", {{"scale", 1.0 / 255}, {"mean", 0.5}, {"std", 0.5}}}}},
                {"output", {{"name", output}}}};
  };
  return {{"format", "mrpt_krp_plugin-models"},
          {"format_version", 1},
          {"world", "w"},
          {"lidar", {{"name", "omni_12m"}, {"fov_deg", 360.0}, {"max_range_m", 12.0}}},
          {"submap", {{"size_m", 24.0}, {"size_px", 160}}},
          {"sdt_clip_m", 2.0},
          {"zones", {"a", "b"}},
          {"landmarks",
           {{"keypoints_per_zone", 2},
            {"zones",
             {{{"zone", "a"}, {"points", {{1.0, 2.0}, {3.0, 4.0}}}},
              {{"zone", "b"}, {"points", {{5.0, 6.0}, {7.0, 8.0}}}}}}}},
          {"classifier", model("c.onnx", 1, "occupancy", "zone_probabilities")},
          {"keypoints", model("k.onnx", 3, "images", "output0")}};
}

class ManifestTest : public ::testing::Test {
 protected:
  std::string write(const json& j) {
    dir_ = fs::temp_directory_path() / ("krp_manifest_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "manifest.json") << j.dump();
    return dir_.string();
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(ManifestTest, ReadsAValidManifest) {
  const auto m = readModelManifest(write(validManifest()));
  EXPECT_EQ(m.zones, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(m.keypointsPerZone(), 2);
  EXPECT_DOUBLE_EQ(m.landmarks[1][0].x, 5.0);
  EXPECT_EQ(m.classifier.input_name, "occupancy");
  EXPECT_DOUBLE_EQ(m.classifier.normalization.std, 0.5);
  EXPECT_EQ(m.keypointsPath(), dir_.string() + "/k.onnx");
}

TEST_F(ManifestTest, SubmapOrientationIsReadHeadingUpWhenAbsentAndUnknownOnesRefused) {
  EXPECT_EQ(readModelManifest(write(validManifest())).submap_orientation, SubmapOrientation::kHeadingUp);
  json j = validManifest();
  j["submap"]["orientation"] = "wall_axes";
  EXPECT_EQ(readModelManifest(write(j)).submap_orientation, SubmapOrientation::kWallAxes);
  j["submap"]["orientation"] = "north_up";
  try {
    readModelManifest(write(j));
    FAIL() << "accepted an unknown orientation";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("north_up"), std::string::npos) << e.what();
  }
  j["submap"]["orientation"] = 3;
  EXPECT_THROW(readModelManifest(write(j)), InputError);
}

TEST_F(ManifestTest, NamesAMissingField) {
  json j = validManifest();
  j["submap"].erase("size_px");
  try {
    readModelManifest(write(j));
    FAIL() << "accepted a manifest without submap.size_px";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("submap.size_px"), std::string::npos) << e.what();
  }
}

TEST_F(ManifestTest, RejectsLandmarksThatAreNotTheZones) {
  json j = validManifest();
  j["landmarks"]["zones"][1]["zone"] = "c";
  EXPECT_THROW(readModelManifest(write(j)), InputError);
}

TEST_F(ManifestTest, RejectsAnInputShapeThatIsNotTheSubmap) {
  json j = validManifest();
  j["keypoints"]["input"]["shape"] = {1, 3, 224, 224};
  EXPECT_THROW(readModelManifest(write(j)), InputError);
}

TEST_F(ManifestTest, RejectsTruncatedJsonAndAMissingFolder) {
  const std::string folder = write(validManifest());
  std::ofstream(fs::path(folder) / "manifest.json") << "{\"format\": \"mrpt_krp_plugin-mo";
  EXPECT_THROW(readModelManifest(folder), InputError);
  EXPECT_THROW(readModelManifest("/nonexistent/models"), InputError);
}

// Found by model_manifest_fuzzer: a number too large for a double escaped as another exception
// type, and a float where an integer belongs was cast with undefined behaviour.
TEST_F(ManifestTest, RejectsHugeNumbersAndFloatsWhereIntegersBelong) {
  const std::string folder = write(validManifest());
  std::ofstream(fs::path(folder) / "manifest.json") << "{\"format\": 1.0e5000}";
  EXPECT_THROW(readModelManifest(folder), InputError);
  for (const double bad : {1.5, 1e300}) {
    json j = validManifest();
    j["submap"]["size_px"] = bad;
    EXPECT_THROW(readModelManifest(write(j)), InputError) << bad;
    j = validManifest();
    j["classifier"]["input"]["shape"] = {1.0, 1.0, bad, 160.0};
    EXPECT_THROW(readModelManifest(write(j)), InputError) << bad;
  }
}

TEST_F(ManifestTest, RejectsAModelFileOutsideTheFolder) {
  json j = validManifest();
  j["classifier"]["file"] = "../elsewhere.onnx";
  EXPECT_THROW(readModelManifest(write(j)), InputError);
}

// Manifests written before krp-train-map copied the zones beside the models have none.
TEST_F(ManifestTest, ZoneOutlinesAreOptionalAndStayInTheFolder) {
  EXPECT_EQ(readModelManifest(write(validManifest())).zoneOutlinesPath(), "");
  json j = validManifest();
  j["zone_outlines"] = {{"file", "zones.yaml"}, {"sha256", "00"}};
  EXPECT_EQ(readModelManifest(write(j)).zoneOutlinesPath(), dir_.string() + "/zones.yaml");
  j["zone_outlines"]["file"] = "../zones.yaml";
  EXPECT_THROW(readModelManifest(write(j)), InputError);
  j["zone_outlines"] = {{"sha256", "00"}};
  EXPECT_THROW(readModelManifest(write(j)), InputError);
}

}  // namespace
}  // namespace krp
