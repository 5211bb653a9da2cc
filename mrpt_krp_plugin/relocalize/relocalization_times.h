// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace krp {

/// Wall-clock time of each stage of one relocalization [ms]. Its own header so that what only
/// reports these times (the seeded initializer, the bench) need not see the ONNX models.
struct RelocalizationTimes {
  double submap_ms = 0, classifier_ms = 0, keypoints_ms = 0, alignment_ms = 0, verification_ms = 0;
  double zone_search_ms = 0;  ///< the zone search, the scoring of its poses and the re-ranking, when they ran
  double cross_check_ms = 0;  ///< the same for the cross-check
  double total_ms = 0;
};

}  // namespace krp
