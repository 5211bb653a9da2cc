// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "mrpt_krp_plugin/relocalize/async_relocalizer.h"

namespace krp {
namespace {

using namespace std::chrono_literals;

RelocalizationRequest requestStamped(uint64_t stamp_ns) {
  RelocalizationRequest r;
  r.scan = mrpt::obs::CObservation2DRangeScan::Create();
  r.stamp_ns = stamp_ns;
  return r;
}

/// A source that holds each call until released, and records the scans' order of arrival.
struct GatedSource {
  std::mutex mutex;
  std::condition_variable cv;
  int released = 0, started = 0;

  HypothesisSource source() {
    return [this](const mrpt::obs::CObservation2DRangeScan&) {
      std::unique_lock<std::mutex> lock(mutex);
      const int me = started++;
      cv.notify_all();
      cv.wait(lock, [&] { return released > me; });
      Ranking r;
      r.localized = true;
      return r;
    };
  }
  void waitStarted(int n) {
    std::unique_lock<std::mutex> lock(mutex);
    cv.wait(lock, [&] { return started >= n; });
  }
  void release() {
    std::lock_guard<std::mutex> lock(mutex);
    ++released;
    cv.notify_all();
  }
};

TEST(AsyncRelocalizer, SubmitReturnsBeforeTheSourceFinishes) {
  GatedSource gate;
  AsyncRelocalizer async(gate.source());
  auto f = async.submit(requestStamped(1));
  gate.waitStarted(1);
  EXPECT_EQ(f.wait_for(0ms), std::future_status::timeout);
  EXPECT_TRUE(async.busy());
  gate.release();
  const auto& reply = f.get();
  EXPECT_TRUE(reply.ranking.localized);
  EXPECT_FALSE(reply.dropped);
  EXPECT_EQ(reply.request.stamp_ns, 1u);
}

TEST(AsyncRelocalizer, KeepsOnlyTheNewestWaitingRequest) {
  GatedSource gate;
  std::atomic<int> callbacks{0};
  AsyncRelocalizer async(gate.source(), [&](const RelocalizationReply&) { ++callbacks; });
  auto running = async.submit(requestStamped(1));
  gate.waitStarted(1);
  std::vector<std::shared_future<RelocalizationReply>> stale;
  for (uint64_t s = 2; s <= 10; ++s) stale.push_back(async.submit(requestStamped(s)));
  auto newest = async.submit(requestStamped(11));
  // Every replaced request is answered at once, as dropped, while the first still runs.
  for (auto& f : stale) {
    ASSERT_EQ(f.wait_for(1s), std::future_status::ready);
    EXPECT_TRUE(f.get().dropped);
  }
  gate.release();
  gate.release();
  EXPECT_FALSE(running.get().dropped);
  const auto& last = newest.get();
  EXPECT_FALSE(last.dropped);
  EXPECT_EQ(last.request.stamp_ns, 11u);
  const auto s = async.stats();
  EXPECT_EQ(s.submitted, 11u);
  EXPECT_EQ(s.dropped, 9u);
  EXPECT_EQ(s.completed, 2u);
  EXPECT_EQ(callbacks.load(), 11);
}

TEST(AsyncRelocalizer, ASourceThatThrowsIsReportedAndTheWorkerGoesOn) {
  int calls = 0;
  AsyncRelocalizer async([&](const mrpt::obs::CObservation2DRangeScan&) -> Ranking {
    if (++calls == 1) throw std::runtime_error("model exploded");
    return Ranking{};
  });
  const auto first = async.submit(requestStamped(1)).get();
  EXPECT_NE(first.error.find("model exploded"), std::string::npos);
  const auto second = async.submit(requestStamped(2)).get();
  EXPECT_TRUE(second.error.empty());
  EXPECT_EQ(async.stats().failed, 1u);
}

TEST(AsyncRelocalizer, ARequestWithoutAScanIsAnErrorNotACrash) {
  AsyncRelocalizer async([](const mrpt::obs::CObservation2DRangeScan&) { return Ranking{}; });
  const auto reply = async.submit(RelocalizationRequest{}).get();
  EXPECT_NE(reply.error.find("no scan"), std::string::npos);
}

TEST(AsyncRelocalizer, DestructionAnswersTheWaitingRequest) {
  GatedSource gate;
  std::shared_future<RelocalizationReply> waiting;
  std::thread releaser;
  {
    AsyncRelocalizer async(gate.source());
    async.submit(requestStamped(1));
    gate.waitStarted(1);
    waiting = async.submit(requestStamped(2));
    releaser = std::thread([&] {
      std::this_thread::sleep_for(50ms);
      gate.release();
    });
  }
  releaser.join();
  ASSERT_EQ(waiting.wait_for(0ms), std::future_status::ready);
  EXPECT_TRUE(waiting.get().dropped);
}

}  // namespace
}  // namespace krp
