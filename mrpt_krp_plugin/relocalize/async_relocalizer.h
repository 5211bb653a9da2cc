// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <chrono>
#include <cstdint>
#include <future>
#include <mutex>
#include <string>

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "mrpt_krp_plugin/common/latest_only_worker.h"
#include "mrpt_krp_plugin/relocalize/hypothesis_source.h"

namespace krp {

/// One scan to relocalize, with what the caller needs to use the answer later.
struct RelocalizationRequest {
  mrpt::obs::CObservation2DRangeScan::ConstPtr scan;
  uint64_t stamp_ns = 0;             ///< the scan's time, passed through [ns]
  mrpt::math::TPose2D odom_at_scan;  ///< the odometry pose at the scan's time, passed through
};

struct RelocalizationReply {
  RelocalizationRequest request;
  Ranking ranking;
  bool dropped = false;   ///< replaced by a newer request before it started: no ranking
  std::string error;      ///< the hypothesis source threw: its message; no ranking
  double latency_ms = 0;  ///< from submit() to the answer [ms]
};

struct AsyncRelocalizerStats {
  uint64_t submitted = 0, completed = 0, dropped = 0, failed = 0;
};

/// Runs a hypothesis source on its own thread so that a caller's callbacks never wait for
/// inference. At most one request waits (LatestOnlyWorker): a relocalization from a stale
/// scan is worth less than one from the newest, so a newer request replaces a waiting one,
/// which is answered as dropped.
class AsyncRelocalizer {
 public:
  using Callback = std::function<void(const RelocalizationReply&)>;

  /// `on_reply` (optional) runs on the worker thread for every request, dropped ones included,
  /// before its future is answered. It must not throw.
  explicit AsyncRelocalizer(HypothesisSource source, Callback on_reply = {});

  /// Never blocks on inference. The future is answered when the request is done or dropped.
  std::shared_future<RelocalizationReply> submit(RelocalizationRequest request);

  bool busy() const { return worker_.busy(); }  ///< a request is running or waiting
  AsyncRelocalizerStats stats() const;

 private:
  struct Job {
    RelocalizationRequest request;
    std::shared_ptr<std::promise<RelocalizationReply>> promise;
    std::chrono::steady_clock::time_point submitted;
  };
  void process(Job& job);
  void answer(Job& job, RelocalizationReply reply);

  HypothesisSource source_;
  Callback on_reply_;
  mutable std::mutex stats_mutex_;
  uint64_t completed_ = 0, failed_ = 0;
  LatestOnlyWorker<Job> worker_;  ///< last: its thread starts once the rest exists
};

}  // namespace krp
