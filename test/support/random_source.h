#pragma once

// The seeded random numbers every randomised test, benchmark and oracle check draws from: a fixed
// seed makes a failure repeat. Tests derive their own generators (random ellipses, placements)
// from it.
#include <cmath>
#include <cstdint>
#include <random>

namespace ellipse_collision::test {

class RandomSource {
 public:
  explicit RandomSource(std::uint64_t seed) : rng_(seed) {}

  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  /// Log-uniform in [lo, hi), both > 0: every order of magnitude equally likely.
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  /// True with probability p_true.
  bool coin(double p_true = 0.5) { return uniform(0.0, 1.0) < p_true; }
  /// Uniform in {0, ..., size - 1}.
  int index(int size) { return std::uniform_int_distribution<int>(0, size - 1)(rng_); }
  /// Uniform in {lo, ..., hi}.
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  /// Standard normal.
  double normal() { return std::normal_distribution<double>(0.0, 1.0)(rng_); }

  std::mt19937_64& engine() { return rng_; }

 private:
  std::mt19937_64 rng_;
};

}  // namespace ellipse_collision::test
