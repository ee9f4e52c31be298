#include "bench_scenes.h"

#include <algorithm>
#include <cmath>

#include "contact_scale_oracle.h"

namespace ellipse_collision::core::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAmbiguousBand = 1e-12;

// Sizes of links and obstacles [m] and their largest axis ratios: a mobile manipulator among
// boxes, poles and people.
constexpr double kLinkMinMajor = 0.05, kLinkMaxMajor = 0.4, kLinkMaxRatio = 8.0;
constexpr double kObstacleMinMajor = 0.05, kObstacleMaxMajor = 0.5, kObstacleMaxRatio = 5.0;

// The random pairs and one-to-many mixes: a 20 m x 20 m square, and sizes large enough that about
// 1 % of independent pairs overlap. The chance that two ellipses dropped at random into the square
// overlap is about the mean area of their Minkowski sum over its 400 m^2; with the major semi-axis
// log-uniform in [0.2, 1.8] m and the axis ratio log-uniform in [1, 5] that mean is about 4 m^2
// (a bit less near the square's edges). The fraction for the fixed seed is counted by the oracle
// and reported (counter `overlapping`).
constexpr double kRandomHalfWidth = 10.0;
constexpr double kRandomMinMajor = 0.2, kRandomMaxMajor = 1.8, kRandomMaxRatio = 5.0;

// A pair whose centres are further apart than this factor times the sum of the bounding radii
// is judged apart without the oracle (about 1 ms a pair): each ellipse lies in its bounding
// circle, so t* >= distance / (sum of the radii) > 1 + 1e-6, far outside the ambiguous band and
// far above the rounding of the double test.
constexpr double kSurelyApart = 1.0 + 1e-6;

/// Fills in the oracle's verdicts once the pairs are stored.
void judge(PairMix* mix) {
  for (std::size_t i = 0; i < mix->pairs.size(); ++i) {
    const Ellipse &a = mix->a(i), &b = mix->b(i);
    const double bound = boundingRadius(a) + boundingRadius(b);
    const double squared_distance = (b.center - a.center).squaredNorm();
    if (squared_distance <= bound * bound) ++mix->pass_bounding_circles;
    if (squared_distance > kSurelyApart * kSurelyApart * bound * bound) {
      mix->truth.push_back(false);
      mix->ambiguous.push_back(false);
      continue;
    }
    const __float128 t = test::oracleContactScale(a, b).quad;
    mix->truth.push_back(t <= 1);
    const __float128 off = t - 1;
    mix->ambiguous.push_back((off < 0 ? -off : off) <= kAmbiguousBand);
  }
}

/// Stores a pair of its own two ellipses.
void addPair(PairMix* mix, const Ellipse& a, const Ellipse& b) {
  mix->pairs.emplace_back(mix->ellipses.size(), mix->ellipses.size() + 1);
  mix->ellipses.push_back(a);
  mix->ellipses.push_back(b);
}

}  // namespace

double EllipseSampler::uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng_);
}

double EllipseSampler::logUniform(double lo, double hi) {
  return std::exp(uniform(std::log(lo), std::log(hi)));
}

Ellipse EllipseSampler::ellipse(double half_width, double min_major, double max_major,
                                double max_ratio) {
  Ellipse e;
  e.center = {uniform(-half_width, half_width), uniform(-half_width, half_width)};
  const double major = logUniform(min_major, max_major);
  const double minor = major / logUniform(1.0, max_ratio);
  const bool x_is_major = uniform(0.0, 1.0) < 0.5;
  e.radius_x = x_is_major ? major : minor;
  e.radius_y = x_is_major ? minor : major;
  e.angle = uniform(-kPi, kPi);
  return e;
}

RobotScene robotScene(int links, int obstacles, double world_size, std::uint64_t seed) {
  EllipseSampler sampler(seed);
  RobotScene scene;
  for (int i = 0; i < links; ++i) {
    scene.links.push_back(sampler.ellipse(1.0, kLinkMinMajor, kLinkMaxMajor, kLinkMaxRatio));
  }
  for (int i = 0; i < obstacles; ++i) {
    scene.obstacles.push_back(
        sampler.ellipse(0.5 * world_size, kObstacleMinMajor, kObstacleMaxMajor, kObstacleMaxRatio));
  }
  return scene;
}

int PairMix::counted() const {
  int n = 0;
  for (const bool a : ambiguous) n += a ? 0 : 1;
  return n;
}

int PairMix::overlapping() const {
  int n = 0;
  for (const bool t : truth) n += t ? 1 : 0;
  return n;
}

PairMix sceneLikeMix(int count, std::uint64_t seed) {
  // Every link-obstacle pair of one scene, in the order a scene check visits them.
  constexpr int kLinks = 50;
  const int obstacles = std::max(1, count / kLinks);
  const RobotScene scene = robotScene(kLinks, obstacles, 10.0, seed);
  PairMix mix;
  mix.name = "scene-like";
  mix.rows = scene.links.size();
  mix.ellipses = scene.links;
  mix.ellipses.insert(mix.ellipses.end(), scene.obstacles.begin(), scene.obstacles.end());
  for (std::size_t link = 0; link < scene.links.size(); ++link) {
    for (std::size_t obstacle = 0; obstacle < scene.obstacles.size(); ++obstacle) {
      mix.pairs.emplace_back(link, scene.links.size() + obstacle);
    }
  }
  judge(&mix);
  return mix;
}

PairMix nearMix(int count, std::uint64_t seed) {
  EllipseSampler sampler(seed);
  PairMix mix;
  mix.name = "near";
  for (int i = 0; i < count; ++i) {
    const Ellipse a = sampler.ellipse(1.0, kLinkMinMajor, kLinkMaxMajor, kLinkMaxRatio);
    Ellipse b = sampler.ellipse(0.0, kObstacleMinMajor, kObstacleMaxMajor, kObstacleMaxRatio);
    const double reach = 1.5 * (boundingRadius(a) + boundingRadius(b));
    const double r = reach * std::sqrt(sampler.uniform(0.0, 1.0));  // uniform over the disk
    const double phi = sampler.uniform(-kPi, kPi);
    b.center = a.center + r * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    addPair(&mix, a, b);
  }
  judge(&mix);
  return mix;
}

PairMix tangencyMix(int count, std::uint64_t seed) {
  EllipseSampler sampler(seed);
  PairMix mix;
  mix.name = "tangent";
  for (int i = 0; i < count; ++i) {
    const Ellipse a = sampler.ellipse(1.0, kLinkMinMajor, kLinkMaxMajor, kLinkMaxRatio);
    Ellipse b = sampler.ellipse(0.0, kObstacleMinMajor, kObstacleMaxMajor, kObstacleMaxRatio);
    const double phi = sampler.uniform(-kPi, kPi);
    b.center = a.center + Eigen::Vector2d(std::cos(phi), std::sin(phi));
    const double delta = sampler.logUniform(1e-9, 1e-6);
    const double target = sampler.uniform(0.0, 1.0) < 0.5 ? 1.0 - delta : 1.0 + delta;
    addPair(&mix, a, test::placeAtContactScale(a, b, target));
  }
  judge(&mix);
  return mix;
}

PairMix randomPairsMix(int count, std::uint64_t seed) {
  EllipseSampler sampler(seed);
  PairMix mix;
  mix.name = "random-pairs";
  for (int i = 0; i < count; ++i) {
    const Ellipse a =
        sampler.ellipse(kRandomHalfWidth, kRandomMinMajor, kRandomMaxMajor, kRandomMaxRatio);
    const Ellipse b =
        sampler.ellipse(kRandomHalfWidth, kRandomMinMajor, kRandomMaxMajor, kRandomMaxRatio);
    addPair(&mix, a, b);
  }
  judge(&mix);
  return mix;
}

PairMix oneToManyMix(int count, std::uint64_t seed) {
  EllipseSampler sampler(seed);
  PairMix mix;
  mix.name = "one-to-" + std::to_string(count);
  mix.rows = 1;
  mix.ellipses.push_back(sampler.ellipse(0.0, kRandomMinMajor, kRandomMaxMajor, kRandomMaxRatio));
  for (int j = 0; j < count; ++j) {
    mix.ellipses.push_back(
        sampler.ellipse(kRandomHalfWidth, kRandomMinMajor, kRandomMaxMajor, kRandomMaxRatio));
    mix.pairs.emplace_back(0, j + 1);
  }
  judge(&mix);
  return mix;
}

int misclassified(const PairMix& mix, const std::vector<bool>& verdicts) {
  int wrong = 0;
  for (std::size_t i = 0; i < mix.pairs.size(); ++i) {
    if (!mix.ambiguous[i] && verdicts[i] != mix.truth[i]) ++wrong;
  }
  return wrong;
}

std::vector<NamedEllipse> ringBase(int links, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<NamedEllipse> base;
  for (int i = 0; i < links; ++i) {
    Ellipse e;
    const double a = 2.0 * M_PI * i / links;
    e.center = {0.35 * std::cos(a), 0.2 * std::sin(a)};
    e.radius_x = 0.08 + 0.05 * u(rng);
    e.radius_y = 0.03 + 0.02 * u(rng);
    e.angle = a;
    base.push_back({"link" + std::to_string(i), EllipseRole::Link, e});
  }
  return base;
}

}  // namespace ellipse_collision::core::bench
