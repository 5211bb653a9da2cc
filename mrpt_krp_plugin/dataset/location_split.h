// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <cstdint>
#include <string>

namespace krp {

enum class Split { kTrain, kVal, kTest };

const char* splitName(Split s);

/// Assigns sample locations to train / val / test by the floor block they stand in, so that
/// no two splits hold views from the same spot (nearby poses see nearly the same submap).
struct LocationSplit {
  double block_m = 2.0;         ///< side of the square floor blocks that go to one split [m]
  double train_fraction = 0.60;
  double val_fraction = 0.25;   ///< the rest (0.15 by default) is test
  uint64_t seed = 1;

  /// The split of the block holding `p` (deterministic in seed and block).
  Split of(const mrpt::math::TPoint2D& p) const;
  /// An id of the block holding `p`, for the dataset's sample list.
  std::string blockId(const mrpt::math::TPoint2D& p) const;
};

}  // namespace krp
