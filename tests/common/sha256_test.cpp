// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/sha256.h"

#include <gtest/gtest.h>

#include <string>

namespace krp {
namespace {

// FIPS 180-2's test vectors, and a longer text whose digest is Python's hashlib's: what
// sha256sum prints for files holding the same bytes.
TEST(Sha256, GivesTheStandardDigests) {
  EXPECT_EQ(sha256Hex({}), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex({'a', 'b', 'c'}), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const std::string long_text(200000, 'a');
  EXPECT_EQ(sha256Hex(std::vector<char>(long_text.begin(), long_text.end())),
            "2287d207f24a941ff3b56c04c8a25ad56b63e3023207b3bb5b4ac0c9869d74be");
}

}  // namespace
}  // namespace krp
