// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace krp {

struct LatestOnlyWorkerStats {
  uint64_t submitted = 0, processed = 0, dropped = 0;
};

/// A worker thread with a queue of one: a job submitted while another waits replaces it, and
/// the replaced one is handed to `drop` instead of `process`. For sensor data, where the newest
/// measurement supersedes a waiting older one, this bounds memory and queueing delay whatever
/// the input rate. `process` and `drop` must not throw.
template <class Job>
class LatestOnlyWorker {
 public:
  LatestOnlyWorker(std::function<void(Job&)> process, std::function<void(Job&)> drop)
      : process_(std::move(process)), drop_(std::move(drop)), thread_([this] { run(); }) {}

  /// Finishes the running job, drops the waiting one, joins.
  ~LatestOnlyWorker() {
    std::optional<Job> left;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
      left.swap(waiting_);
    }
    wake_.notify_all();
    thread_.join();
    if (left) dropOne(*left);
  }
  LatestOnlyWorker(const LatestOnlyWorker&) = delete;
  LatestOnlyWorker& operator=(const LatestOnlyWorker&) = delete;

  /// Never blocks on the running job.
  void submit(Job job) {
    std::optional<Job> replaced;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++stats_.submitted;
      replaced.swap(waiting_);
      waiting_.emplace(std::move(job));
    }
    wake_.notify_one();
    if (replaced) dropOne(*replaced);
  }

  bool busy() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return running_ || waiting_.has_value();
  }

  LatestOnlyWorkerStats stats() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stats_;
  }

 private:
  void dropOne(Job& job) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++stats_.dropped;
    }
    drop_(job);
  }

  void run() {
    for (;;) {
      std::optional<Job> job;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return stopping_ || waiting_.has_value(); });
        if (stopping_) return;
        job.swap(waiting_);
        running_ = true;
      }
      process_(*job);
      std::lock_guard<std::mutex> lock(mutex_);
      running_ = false;
      ++stats_.processed;
    }
  }

  std::function<void(Job&)> process_, drop_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Job> waiting_;
  bool running_ = false, stopping_ = false;
  LatestOnlyWorkerStats stats_;
  std::thread thread_;  ///< last: starts after everything it uses exists
};

}  // namespace krp
