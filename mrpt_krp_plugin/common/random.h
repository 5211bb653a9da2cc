// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <random>

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
