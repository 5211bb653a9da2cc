// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/async_relocalizer.h"

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

AsyncRelocalizer::AsyncRelocalizer(HypothesisSource source, Callback on_reply)
    : source_(std::move(source)), on_reply_(std::move(on_reply)) {
  if (!source_) throw InputError("async relocalizer", "no hypothesis source");
  worker_ = std::thread([this] { run(); });
}

AsyncRelocalizer::~AsyncRelocalizer() {
  std::optional<Job> left;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    left.swap(waiting_);
  }
  wake_.notify_all();
  worker_.join();
  if (left) {
    RelocalizationReply r;
    r.dropped = true;
    answer(*left, std::move(r));
  }
}

std::shared_future<RelocalizationReply> AsyncRelocalizer::submit(RelocalizationRequest request) {
  Job job{std::move(request), {}, std::chrono::steady_clock::now()};
  std::shared_future<RelocalizationReply> future = job.promise.get_future().share();
  std::optional<Job> replaced;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.submitted;
    replaced.swap(waiting_);
    waiting_.emplace(std::move(job));
  }
  wake_.notify_one();
  if (replaced) {
    RelocalizationReply r;
    r.dropped = true;
    answer(*replaced, std::move(r));
  }
  return future;
}

bool AsyncRelocalizer::busy() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return running_job_ || waiting_.has_value();
}

AsyncRelocalizerStats AsyncRelocalizer::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

void AsyncRelocalizer::answer(Job& job, RelocalizationReply reply) {
  reply.request = job.request;
  reply.latency_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - job.submitted).count();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (reply.dropped) ++stats_.dropped;
    else if (!reply.error.empty()) ++stats_.failed;
    else ++stats_.completed;
  }
  // The callback first, so that whoever waits on the future sees its effects.
  if (on_reply_) on_reply_(reply);
  job.promise.set_value(std::move(reply));
}

void AsyncRelocalizer::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || waiting_.has_value(); });
      if (stopping_) return;
      job = std::move(*waiting_);
      waiting_.reset();
      running_job_ = true;
    }
    RelocalizationReply reply;
    try {
      if (!job.request.scan) throw InputError("relocalization request", "no scan");
      reply.ranking = source_(*job.request.scan);
    } catch (const std::exception& e) {
      reply.error = e.what();
    }
    answer(job, std::move(reply));
    std::lock_guard<std::mutex> lock(mutex_);
    running_job_ = false;
  }
}

}  // namespace krp
