#pragma once

// Reproducible inputs shared by the collision benchmarks: random robot scenes and the pair mixes,
// with the quad-precision oracle's verdict on every stored pair.

#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/scene.h"

namespace ellipse_collision::core::bench {

/// Seeded source of random ellipses.
class EllipseSampler {
 public:
  explicit EllipseSampler(std::uint64_t seed) : rng_(seed) {}

  double uniform(double lo, double hi);
  double logUniform(double lo, double hi);

  /// Centre uniform in [-half_width, half_width]^2 [m], major semi-axis log-uniform in
  /// [min_major, max_major] [m], axis ratio log-uniform in [1, max_ratio], any angle [rad].
  Ellipse ellipse(double half_width, double min_major, double max_major, double max_ratio);

 private:
  std::mt19937_64 rng_;
};

/// A robot of `links` ellipses within 1 m of the origin, among `obstacles` ellipses spread over a
/// square world of side `world_size` [m] centred on the robot.
struct RobotScene {
  std::vector<Ellipse> links;
  std::vector<Ellipse> obstacles;
};

RobotScene robotScene(int links, int obstacles, double world_size, std::uint64_t seed);

/// A 0.8 x 0.5 m base of `links` ellipses (wheels, bumper, arm segments) on a ring within 0.5 m of
/// the frame's origin, named link0, link1, ..., sizes drawn from `rng` (the path and gate
/// benchmarks' robot).
std::vector<NamedEllipse> ringBase(int links, std::mt19937& rng);

/// Stored pairs, as indices into the stored ellipses (so that a method may prepare each ellipse
/// once, as a scene check would), and the oracle's verdicts, computed once before any timing.
/// With rows > 0 the pairs are every (i, j), i < rows <= j, in that order (links against
/// obstacles); otherwise the ellipses come in pairs (0, 1), (2, 3), ...
struct PairMix {
  std::string name;
  std::vector<Ellipse> ellipses;
  std::size_t rows{0};
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<bool> truth;       ///< oracle: t* <= 1
  std::vector<bool> ambiguous;   ///< |t* - 1| <= 1e-12: no double-input method can be judged there
  int pass_bounding_circles{0};  ///< pairs whose centre distance <= sum of bounding radii

  const Ellipse& a(std::size_t pair) const { return ellipses[pairs[pair].first]; }
  const Ellipse& b(std::size_t pair) const { return ellipses[pairs[pair].second]; }
  int counted() const;      ///< pairs that are not ambiguous
  int overlapping() const;  ///< pairs the oracle finds overlapping (t* <= 1)
};

/// All pairs of 50 links and count / 50 obstacles in a 10 m x 10 m room, in the order a scene
/// check visits them (link by link, obstacles in order): most are far apart.
PairMix sceneLikeMix(int count, std::uint64_t seed);

/// Centres uniform in the disk of radius 1.5x the sum of the bounding radii; two ellipses per
/// pair.
PairMix nearMix(int count, std::uint64_t seed);

/// Placed with the oracle's helper at t* = 1 +- delta, delta log-uniform in [1e-9, 1e-6]; two
/// ellipses per pair.
PairMix tangencyMix(int count, std::uint64_t seed);

/// Independent random pairs: both ellipses of each pair drawn alike, centres uniform in a
/// 20 m x 20 m square, major semi-axis log-uniform in [0.2, 1.8] m, axis ratio log-uniform in
/// [1, 5], any angle; about 1 % of such pairs overlap. Two ellipses per pair.
PairMix randomPairsMix(int count, std::uint64_t seed);

/// One against many: one ellipse drawn as randomPairsMix() draws them but centred in the square,
/// against `count` ellipses drawn alike (rows = 1, named "one-to-<count>").
PairMix oneToManyMix(int count, std::uint64_t seed);

/// Number of pairs where `verdicts` disagrees with the oracle, ambiguous pairs left out.
int misclassified(const PairMix& mix, const std::vector<bool>& verdicts);

}  // namespace ellipse_collision::core::bench
