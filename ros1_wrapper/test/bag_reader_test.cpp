// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <mrpt/obs/CActionRobotMovement2D.h>

#include <filesystem>
#include <fstream>

#include "bag_reader.h"
#include "mrpt_krp_plugin/common/input_error.h"
#include "support/test_maps.h"
#include "support/trial_bag.h"

namespace krp::ros1 {
namespace {

Trial smallTrial() {
  TrialParams tp;
  tp.steps = 6;
  return generateTrial(krp::test::asymmetricRoom(), lidarProfileByName("omni_12m"), tp, 4);
}

TEST(RosBagReader, GivesTheTrialsScansAndOdometryBack) {
  const Trial t = smallTrial();
  const std::string path = krp::test::tempDir("bag_reader") + "/trial.bag";
  test::writeTrialBag(t, path);
  const auto bag = readBag(path);
  ASSERT_EQ(bag.steps.size(), t.scans.size());
  EXPECT_EQ(bag.scans_seen, static_cast<int>(t.scans.size()));
  for (size_t i = 1; i < bag.steps.size(); ++i) {
    const auto move = bag.steps[i].action->getBestMovementEstimation();
    ASSERT_TRUE(move);
    const auto got = move->poseChange->getMeanVal();
    EXPECT_NEAR(got.x(), t.odometry[i].x(), 1e-6) << i;
    EXPECT_NEAR(got.y(), t.odometry[i].y(), 1e-6) << i;
    EXPECT_NEAR(got.phi(), t.odometry[i].phi(), 1e-6) << i;
  }
  const auto scan = bag.steps[2].observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->getScanSize(), t.scans[2]->getScanSize());
}

// A robot's bag may be recorded with `rosbag record --bz2` or `--lz4`: the framing check
// decompresses their chunks to check them, and the same scans and odometry come out.
TEST(RosBagReader, CompressedBagsGiveTheSameSteps) {
  const Trial t = smallTrial();
  const std::string dir = krp::test::tempDir("bag_reader_compressed");
  test::writeTrialBag(t, dir + "/plain.bag");
  const auto plain = readBag(dir + "/plain.bag");
  for (const auto compression : {rosbag::compression::BZ2, rosbag::compression::LZ4}) {
    const std::string path = dir + "/compressed_" + std::to_string(static_cast<int>(compression)) + ".bag";
    test::writeTrialBag(t, path, mrpt::math::TPose2D(1.0, -2.0, 0.5), compression);
    ASSERT_NE(std::filesystem::file_size(path), std::filesystem::file_size(dir + "/plain.bag"));
    const auto bag = readBag(path);
    ASSERT_EQ(bag.steps.size(), plain.steps.size());
    for (size_t i = 0; i < bag.steps.size(); ++i) {
      const auto a = bag.steps[i].observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
      const auto b = plain.steps[i].observations->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
      ASSERT_TRUE(a && b);
      ASSERT_EQ(a->getScanSize(), b->getScanSize());
      for (size_t k = 0; k < a->getScanSize(); ++k) ASSERT_EQ(a->getScanRange(k), b->getScanRange(k)) << i << " " << k;
    }
  }
}

// Found by bag_fuzzer: a corrupt record inside an lz4 chunk made roscpp's header parser read
// past its buffer (the framing check used to leave compressed chunks to rosbag).
TEST(RosBagReader, ACorruptRecordInACompressedChunkIsRefused) {
  const std::string path = std::string(KRP_ROS1_DIR) + "/../tests/fuzz/corpus/bag_fuzzer/lz4_chunk_inner_header_overflow_crash";
  try {
    readBag(path);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("corrupt bag at byte"), std::string::npos) << e.what();
  }
}

TEST(RosBagReader, BadBagsAreInputErrors) {
  const Trial t = smallTrial();
  const std::string dir = krp::test::tempDir("bag_reader_bad");
  test::writeTrialBag(t, dir + "/good.bag");
  // Truncated: the first half of a good bag.
  const auto size = std::filesystem::file_size(dir + "/good.bag");
  std::filesystem::copy_file(dir + "/good.bag", dir + "/truncated.bag");
  std::filesystem::resize_file(dir + "/truncated.bag", size / 2);
  krp::test::writeText(dir + "/text.bag", "this is not a bag\n");
  // Found by bag_fuzzer: rosbag reads past its buffers on lengths and positions like these.
  std::ifstream in(dir + "/good.bag", std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(in)), {});
  const size_t magic = std::string("#ROSBAG V2.0\n").size();
  std::string long_field = good;
  const uint32_t huge = 0x7fffffff;
  long_field.replace(magic + sizeof(uint32_t), sizeof(huge), reinterpret_cast<const char*>(&huge), sizeof(huge));
  krp::test::writeText(dir + "/long_field.bag", long_field);
  std::string bad_index = good;
  const uint64_t inside_a_record = magic + 1;
  bad_index.replace(good.find("index_pos=") + 10, sizeof(inside_a_record), reinterpret_cast<const char*>(&inside_a_record),
                    sizeof(inside_a_record));
  krp::test::writeText(dir + "/bad_index.bag", bad_index);
  const std::pair<std::string, std::string> cases[] = {{dir + "/missing.bag", "does not exist"},
                                                       {dir + "/text.bag", "not a ROS bag in format 2.0"},
                                                       {dir + "/truncated.bag", "corrupt bag at byte"},
                                                       {dir + "/long_field.bag", "runs past its header"},
                                                       {dir + "/bad_index.bag", "index position is not a record"}};
  for (const auto& [path, expected] : cases) {
    try {
      readBag(path);
      ADD_FAILURE() << path << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  BagReadParams wrong_topic;
  wrong_topic.scan_topic = "/laser";
  EXPECT_THROW(readBag(dir + "/good.bag", wrong_topic), InputError);
  BagReadParams wrong_frame;
  wrong_frame.base_frame = "base_footprint";
  try {
    readBag(dir + "/good.bag", wrong_frame);
    ADD_FAILURE() << "no scan has a transform to base_footprint";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no transform"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace krp::ros1
