// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "mrpt_krp_plugin/map/map_loader.h"

namespace krp::fuzz {

/// Maps up to the default limit (2e8 cells) are valid but take seconds each; a smaller limit keeps
/// every run fast while the limit checks themselves stay under test.
inline MapLoadParams fuzzMapLimits() {
  MapLoadParams p;
  p.limits.max_cells = 1e6;
  return p;
}

}  // namespace krp::fuzz
