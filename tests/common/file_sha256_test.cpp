// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/file_sha256.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "mrpt_krp_plugin/common/input_error.h"
#include "support/test_maps.h"

namespace krp {
namespace {

// FIPS 180-2's test vectors: what sha256sum and Python's hashlib print for the same bytes.
TEST(FileSha256, GivesTheStandardDigests) {
  const std::filesystem::path dir = test::tempDir("file_sha256");
  std::ofstream(dir / "empty");
  std::ofstream(dir / "abc") << "abc";
  EXPECT_EQ(fileSha256((dir / "empty").string()), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(fileSha256((dir / "abc").string()), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // Longer than one read chunk: 200,000 bytes of 'a' (the digest from Python's hashlib).
  std::ofstream(dir / "long") << std::string(200000, 'a');
  EXPECT_EQ(fileSha256((dir / "long").string()), "2287d207f24a941ff3b56c04c8a25ad56b63e3023207b3bb5b4ac0c9869d74be");
}

TEST(FileSha256, NamesAFileItCannotRead) {
  const auto missing = (std::filesystem::path(test::tempDir("file_sha256_missing")) / "nothing.onnx").string();
  try {
    fileSha256(missing);
    FAIL() << "no error for a missing file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace krp
