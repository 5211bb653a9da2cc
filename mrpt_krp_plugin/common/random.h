// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace krp {

/// The project's random source: every random choice takes one of these, built from an
/// explicit seed, so that a trial is bit-reproducible whatever ran before it.
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  /// A fresh distribution per draw: no cached deviate carries over between calls.
  double normal(double mean, double stddev) {
    if (stddev <= 0.0) return mean;
    return std::normal_distribution<double>(mean, stddev)(engine_);
  }
  bool bernoulli(double p) { return uniform(0.0, 1.0) < p; }
  int uniformInt(int lo, int hi_inclusive) { return std::uniform_int_distribution<int>(lo, hi_inclusive)(engine_); }
  uint64_t next() { return engine_(); }

  /// Puts `v` in random order (Fisher-Yates, from the back).
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[static_cast<std::size_t>(uniformInt(0, static_cast<int>(i) - 1))]);
  }
  /// Moves a uniformly drawn `count` of `v`'s elements, in random order, to its front (the
  /// first `count` steps of Fisher-Yates, from the front); the rest keep no particular order.
  template <class T>
  void sampleToFront(std::vector<T>& v, std::size_t count) {
    for (std::size_t k = 0; k < std::min(count, v.size()); ++k)
      std::swap(v[k], v[static_cast<std::size_t>(uniformInt(static_cast<int>(k), static_cast<int>(v.size()) - 1))]);
  }

 private:
  std::mt19937_64 engine_;
};

/// Reseeds MRPT's global generator (used inside its particle filter) and clears the
/// normal deviate that `randomize()` leaves cached in MRPT 2.5.8, so that the filter's
/// draws depend only on `seed`.
void reseedMrptGlobalRandom(uint32_t seed);

/// Derives an independent seed for a sub-stream (trial i, component name) from a base seed.
uint64_t deriveSeed(uint64_t base, uint64_t stream);

}  // namespace krp
