// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/relocalize/async_relocalizer.h"

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

namespace {
HypothesisSource requireSource(HypothesisSource source) {
  if (!source) throw InputError("async relocalizer", "no hypothesis source");
  return source;
}
}  // namespace

AsyncRelocalizer::AsyncRelocalizer(HypothesisSource source, Callback on_reply)
    : source_(requireSource(std::move(source))),
      on_reply_(std::move(on_reply)),
      worker_([this](Job& job) { process(job); },
              [this](Job& job) {
                RelocalizationReply r;
                r.dropped = true;
                answer(job, std::move(r));
              }) {}

std::shared_future<RelocalizationReply> AsyncRelocalizer::submit(RelocalizationRequest request) {
  Job job{std::move(request), std::make_shared<std::promise<RelocalizationReply>>(), std::chrono::steady_clock::now()};
  std::shared_future<RelocalizationReply> future = job.promise->get_future().share();
  worker_.submit(std::move(job));
  return future;
}

AsyncRelocalizerStats AsyncRelocalizer::stats() const {
  const auto w = worker_.stats();
  std::lock_guard<std::mutex> lock(stats_mutex_);
  return {w.submitted, completed_, w.dropped, failed_};
}

void AsyncRelocalizer::process(Job& job) {
  RelocalizationReply reply;
  try {
    if (!job.request.scan) throw InputError("relocalization request", "no scan");
    reply.ranking = source_(*job.request.scan);
  } catch (const std::exception& e) {
    reply.error = e.what();
  }
  answer(job, std::move(reply));
}

void AsyncRelocalizer::answer(Job& job, RelocalizationReply reply) {
  reply.request = job.request;
  reply.latency_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - job.submitted).count();
  if (!reply.dropped) {
    // Counted here, before the future is answered, so a caller that waited sees it counted.
    std::lock_guard<std::mutex> lock(stats_mutex_);
    ++(reply.error.empty() ? completed_ : failed_);
  }
  if (on_reply_) on_reply_(reply);
  job.promise->set_value(std::move(reply));
}

}  // namespace krp
