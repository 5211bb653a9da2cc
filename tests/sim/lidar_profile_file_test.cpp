// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "mrpt_krp_plugin/sim/lidar_profile_file.h"
#include "mrpt_krp_plugin/sim/world.h"
#include "support/input_error_message.h"

namespace krp {
namespace {

namespace fs = std::filesystem;

class LidarProfileFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("krp_lidar_profile_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const auto path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  fs::path dir_;
};

TEST_F(LidarProfileFile, ARoundTripKeepsEveryField) {
  LidarProfile p;
  p.name = "sick_lms200";
  p.fov_rad = M_PI;
  p.beams = 361;
  p.max_range_m = 80.0;
  p.range_noise_std_m = 0.02;
  p.dropout_probability = 0.05;
  p.mount_x_m = 0.25;
  const auto path = (dir_ / "sick.yaml").string();
  writeLidarProfileFile(p, path);
  const auto q = readLidarProfileFile(path);
  EXPECT_EQ(q.name, p.name);
  EXPECT_DOUBLE_EQ(q.fov_rad, p.fov_rad);
  EXPECT_EQ(q.beams, p.beams);
  EXPECT_DOUBLE_EQ(q.max_range_m, p.max_range_m);
  EXPECT_DOUBLE_EQ(q.range_noise_std_m, p.range_noise_std_m);
  EXPECT_DOUBLE_EQ(q.dropout_probability, p.dropout_probability);
  EXPECT_DOUBLE_EQ(q.mount_x_m, p.mount_x_m);
}

TEST_F(LidarProfileFile, ThreeKeysSufficeAndTheFileNamesTheProfile) {
  const auto q = lidarProfile(write("my_scanner.yaml", "fov_deg: 270\nbeams: 1081\nmax_range_m: 30\n"));
  EXPECT_EQ(q.name, "my_scanner");
  EXPECT_NEAR(q.fov_rad, 1.5 * M_PI, 1e-12);
  EXPECT_EQ(q.beams, 1081);
  EXPECT_DOUBLE_EQ(q.max_range_m, 30.0);
  EXPECT_FALSE(q.isFullCircle());
  const LidarProfile defaults;
  EXPECT_DOUBLE_EQ(q.range_noise_std_m, defaults.range_noise_std_m);
  EXPECT_DOUBLE_EQ(q.dropout_probability, defaults.dropout_probability);
  EXPECT_DOUBLE_EQ(q.mount_x_m, 0.0);
}

TEST_F(LidarProfileFile, BadFilesAreRefusedNamingTheFileAndTheKey) {
  const std::pair<std::string, std::string> cases[] = {
      {"fov_deg: 180\nbeams: 361\n", "missing required key 'max_range_m'"},
      {"fov_deg: 180\nbeams: 361\nmax_range_m: 80\nrange: 3\n", "unknown key 'range'"},
      {"fov_deg: 0\nbeams: 361\nmax_range_m: 80\n", "key 'fov_deg' = 0 is outside (0, 360]"},
      {"fov_deg: 400\nbeams: 361\nmax_range_m: 80\n", "key 'fov_deg' = 400 is outside"},
      {"fov_deg: 180\nbeams: 1\nmax_range_m: 80\n", "key 'beams' = 1 is outside [2,"},
      {"fov_deg: 180\nbeams: 360.5\nmax_range_m: 80\n", "key 'beams' must be a whole number"},
      {"fov_deg: 180\nbeams: 361\nmax_range_m: 8000\n", "key 'max_range_m' = 8000 is outside"},
      {"fov_deg: 180\nbeams: 361\nmax_range_m: eighty\n", "key 'max_range_m' is not a number"},
      {"fov_deg: 180\nbeams: 361\nmax_range_m: 80\ndropout_probability: 1.5\n", "key 'dropout_probability' = 1.5"},
      {"- 180\n- 361\n", "expected a YAML mapping"},
  };
  int i = 0;
  for (const auto& [text, problem] : cases) {
    const auto path = write("bad" + std::to_string(i++) + ".yaml", text);
    const auto message = test::inputErrorMessage([&] { readLidarProfileFile(path); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << "wanted '" << problem << "' in: " << message;
  }
  const auto missing = (dir_ / "absent.yaml").string();
  EXPECT_NE(test::inputErrorMessage([&] { lidarProfile(missing); }).find("does not exist"), std::string::npos);
}

TEST_F(LidarProfileFile, ANameIsBuiltInAndAnUnknownNameSaysAFileWorksToo) {
  EXPECT_EQ(lidarProfile("lds01").beams, 360);
  const auto message = test::inputErrorMessage([] { lidarProfile("sick_lms200"); });
  EXPECT_NE(message.find("lds01, omni_12m, safety_270"), std::string::npos) << message;
  EXPECT_NE(message.find("NAME.yaml"), std::string::npos) << message;
}

TEST_F(LidarProfileFile, AWorldFindsItsProfileFileBesideItAndWritesItBackRelative) {
  fs::create_directories(dir_ / "world");
  write("world/sick.yaml", "name: sick\nfov_deg: 180\nbeams: 361\nmax_range_m: 80\n");
  write("world/w.zones.yaml", "zones:\n  - name: a\n    polygon: [[0, 0], [1, 0], [1, 1]]\n");
  const auto world_path = write("world/w.world.yaml",
                                "name: w\nmap: w.yaml\nzones: w.zones.yaml\nlidar_profiles: [omni_12m, sick.yaml]\n"
                                "default_lidar_profile: sick.yaml\nlidar_overrides: {range_noise_std_m: 0.03}\n");
  const World w = readWorld(world_path);
  const auto sick = w.lidar(w.default_lidar_profile);
  EXPECT_EQ(sick.name, "sick");
  EXPECT_EQ(sick.beams, 361);
  EXPECT_DOUBLE_EQ(sick.range_noise_std_m, 0.03) << "the world's overrides apply to a file's profile too";
  // The same file named another way is the same profile; a profile the world does not list is not.
  EXPECT_EQ(w.lidar((dir_ / "world" / "." / "sick.yaml").string()).name, "sick");
  EXPECT_FALSE(test::inputErrorMessage([&] { w.lidar("lds01"); }).empty());
  const auto copy = (dir_ / "world" / "copy.world.yaml").string();
  writeWorld(w, copy);
  const World again = readWorld(copy);
  EXPECT_EQ(again.lidar(again.default_lidar_profile).name, "sick");
  std::ifstream in(copy);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("lidar_profiles: [omni_12m, sick.yaml]"), std::string::npos) << text;
}

}  // namespace
}  // namespace krp
