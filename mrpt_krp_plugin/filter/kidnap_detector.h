// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace krp {

struct KidnapDetectorParams {
  bool enabled = false;  ///< off: the filter never re-initializes by itself
  /// While tracking, the scan at the filter's mean pose should be explained by the map; below
  /// this fraction of returns (ScanFit) the update counts as suspicious [0..1].
  double min_fit_fraction = 0.45;
  /// This many suspicious updates in a row is a kidnap: one bad scan (a crowd, a door) is not.
  int consecutive_updates = 3;
  /// Updates after an initialization before detection starts: the filter needs them to settle.
  int grace_updates = 3;
};

/// Declares a kidnap after a sustained drop of the scan fit at the tracked pose.
class KidnapDetector {
 public:
  explicit KidnapDetector(KidnapDetectorParams params = {}) : params_(params) {}

  /// Feeds one update's fit fraction; true when this update completes a kidnap (the detector
  /// then resets itself, grace period included).
  bool update(double fit_fraction);
  void reset() { suspicious_ = 0, since_reset_ = 0; }

 private:
  KidnapDetectorParams params_;
  int suspicious_ = 0;
  int since_reset_ = 0;
};

}  // namespace krp
