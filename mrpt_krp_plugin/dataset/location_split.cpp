// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/dataset/location_split.h"

#include <cmath>

#include "mrpt_krp_plugin/common/random.h"

namespace krp {

const char* splitName(Split s) {
  switch (s) {
    case Split::kTrain: return "train";
    case Split::kVal: return "val";
    case Split::kTest: return "test";
  }
  return "?";
}

Split LocationSplit::of(const mrpt::math::TPoint2D& p) const {
  const auto bx = static_cast<int64_t>(std::floor(p.x / block_m));
  const auto by = static_cast<int64_t>(std::floor(p.y / block_m));
  // A block's own seeded draw: the same block always lands in the same split.
  Rng rng(deriveSeed(deriveSeed(seed, static_cast<uint64_t>(bx)), static_cast<uint64_t>(by)));
  const double u = rng.uniform(0.0, 1.0);
  if (u < train_fraction) return Split::kTrain;
  if (u < train_fraction + val_fraction) return Split::kVal;
  return Split::kTest;
}

std::string LocationSplit::blockId(const mrpt::math::TPoint2D& p) const {
  return std::to_string(static_cast<int64_t>(std::floor(p.x / block_m))) + "_" +
         std::to_string(static_cast<int64_t>(std::floor(p.y / block_m)));
}

}  // namespace krp
