// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/random.h"

#include <mrpt/random/RandomGenerators.h>

namespace krp {
namespace {
// The cached deviate lives in a protected member; a pointer-to-member taken through a
// derived class reaches it without changing MRPT.
struct GeneratorAccess : mrpt::random::CRandomGenerator {
  static void resetNormalCache(mrpt::random::CRandomGenerator& g) {
    (g.*(&GeneratorAccess::m_normdistribution)).reset();
  }
};
}  // namespace

void reseedMrptGlobalRandom(uint32_t seed) {
  auto& g = mrpt::random::getRandomGenerator();
  g.randomize(seed);
  GeneratorAccess::resetNormalCache(g);
}

uint64_t deriveSeed(uint64_t base, uint64_t stream) {
  // splitmix64 finalizer: nearby inputs give unrelated outputs.
  uint64_t z = base + 0x9E3779B97F4A7C15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace krp
