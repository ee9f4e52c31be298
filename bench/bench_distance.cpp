// ns per pair of distance() beside FCL's distance query on the same stored pairs, with the accuracy
// of each against the quad-precision oracle of test/support/distance_oracle.h as counters:
//   max_rel_err, median_rel_err   |distance - oracle| / oracle over the whole set;
//   nonpositive                    fraction of these separated pairs given a distance <= 0.
// A 2D ellipse is an FCL ellipsoid centred in the z = 0 plane: both shapes are symmetric about that
// plane, so the closest points lie in it and the 3D distance is the 2D one.
// Run with --benchmark_repetitions=N and compare medians; every iteration handles one pair.

#include <benchmark/benchmark.h>
#include <fcl/fcl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "distance_oracle.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kPairsPerSet = 512;

enum class Set { Separated, Near, Thin };

struct PairSet {
  std::vector<std::pair<Ellipse, Ellipse>> pairs;
  std::vector<double> truth;  // oracle distance [m]
};

double logUniform(std::mt19937_64& rng, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
}

Ellipse randomShape(std::mt19937_64& rng, double max_ratio) {
  Ellipse e;
  e.radius_x = logUniform(rng, 0.05, 2.0);
  e.radius_y = e.radius_x / logUniform(rng, 1.0, max_ratio);
  e.angle = std::uniform_real_distribution<double>(-kPi, kPi)(rng);
  return e;
}

Eigen::Vector2d supportOffset(const Ellipse& e, const Eigen::Vector2d& n) {
  const double c = std::cos(e.angle), s = std::sin(e.angle);
  const double p = n.x() * c + n.y() * s, q = -n.x() * s + n.y() * c;
  const double h = std::hypot(e.radius_x * p, e.radius_y * q);
  const double lx = e.radius_x * e.radius_x * p / h, ly = e.radius_y * e.radius_y * q / h;
  return {c * lx - s * ly, s * lx + c * ly};
}

/// Pairs with a random contact normal and a gap drawn log-uniformly, relative to the larger
/// radius; the oracle, not the construction, gives their true distance.
PairSet makeSet(Set set) {
  std::mt19937_64 rng(set == Set::Separated ? 1 : set == Set::Near ? 2 : 3);
  const double max_ratio = set == Set::Thin ? 1e3 : set == Set::Near ? 100.0 : 10.0;
  const double gap_lo = set == Set::Separated ? 1e-2 : 1e-6;
  const double gap_hi = set == Set::Near ? 1e-2 : 3.0;
  PairSet out;
  while (static_cast<int>(out.pairs.size()) < kPairsPerSet) {
    Ellipse a = randomShape(rng, max_ratio);
    Ellipse b = randomShape(rng, max_ratio);
    a.center = {std::uniform_real_distribution<double>(-5, 5)(rng),
                std::uniform_real_distribution<double>(-5, 5)(rng)};
    const double angle = std::uniform_real_distribution<double>(-kPi, kPi)(rng);
    const Eigen::Vector2d n(std::cos(angle), std::sin(angle));
    const double gap =
        logUniform(rng, gap_lo, gap_hi) * std::max(boundingRadius(a), boundingRadius(b));
    b.center = a.center + supportOffset(a, n) + gap * n + supportOffset(b, n);
    if (overlap(a, b)) continue;  // rounding can close the smallest gaps
    out.truth.push_back(static_cast<double>(test::oracleDistance(a, b).distance));
    out.pairs.emplace_back(a, b);
  }
  return out;
}

const PairSet& pairSet(Set set) {
  static const PairSet sets[] = {makeSet(Set::Separated), makeSet(Set::Near), makeSet(Set::Thin)};
  return sets[static_cast<int>(set)];
}

/// The same pairs as FCL objects.
struct FclPair {
  std::shared_ptr<fcl::Ellipsoidd> a, b;
  fcl::Transform3d ta, tb;
};

fcl::Transform3d toFcl(const Ellipse& e) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.translate(fcl::Vector3d(e.center.x(), e.center.y(), 0.0));
  t.rotate(fcl::AngleAxisd(e.angle, fcl::Vector3d::UnitZ()));
  return t;
}

std::shared_ptr<fcl::Ellipsoidd> toFclShape(const Ellipse& e) {
  // Any z radius gives the same distance; the smaller in-plane one keeps the shape compact.
  return std::make_shared<fcl::Ellipsoidd>(e.radius_x, e.radius_y, inscribedRadius(e));
}

const std::vector<FclPair>& fclPairs(Set set) {
  static const auto make = [](Set s) {
    std::vector<FclPair> out;
    for (const auto& [a, b] : pairSet(s).pairs) {
      out.push_back({toFclShape(a), toFclShape(b), toFcl(a), toFcl(b)});
    }
    return out;
  };
  static const std::vector<FclPair> sets[] = {make(Set::Separated), make(Set::Near),
                                              make(Set::Thin)};
  return sets[static_cast<int>(set)];
}

/// FCL's distance query with nearest points, as distance() also returns its witness points.
double fclDistance(const FclPair& p, fcl::GJKSolverType solver) {
  fcl::DistanceRequestd request(true);
  request.gjk_solver_type = solver;
  fcl::DistanceResultd result;
  return fcl::distance(p.a.get(), p.ta, p.b.get(), p.tb, request, result);
}

/// Sets max_rel_err and median_rel_err from each pair's computed distance.
template <typename Compute>
void reportAccuracy(benchmark::State& state, const PairSet& set, Compute compute) {
  std::vector<double> errors;
  int nonpositive = 0;  // separated pairs reported as touching or in collision
  for (size_t i = 0; i < set.pairs.size(); ++i) {
    const double computed = compute(i);
    if (!(computed > 0.0)) ++nonpositive;
    errors.push_back(std::abs(computed - set.truth[i]) / set.truth[i]);
  }
  std::sort(errors.begin(), errors.end());
  state.counters["max_rel_err"] = errors.back();
  state.counters["median_rel_err"] = errors[errors.size() / 2];
  state.counters["nonpositive"] = static_cast<double>(nonpositive) / set.pairs.size();
}

void BM_Ours(benchmark::State& state, Set which) {
  const PairSet& set = pairSet(which);
  reportAccuracy(state, set, [&](size_t i) {
    return distance(set.pairs[i].first, set.pairs[i].second).distance;
  });
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(distance(set.pairs[i].first, set.pairs[i].second));
    if (++i == set.pairs.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

/// overlap() alone, which distance() calls first: the rest of distance()'s time is the solve.
void BM_OverlapOnly(benchmark::State& state, Set which) {
  const PairSet& set = pairSet(which);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(overlap(set.pairs[i].first, set.pairs[i].second));
    if (++i == set.pairs.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Fcl(benchmark::State& state, Set which, fcl::GJKSolverType solver) {
  const PairSet& set = pairSet(which);
  const std::vector<FclPair>& pairs = fclPairs(which);
  reportAccuracy(state, set, [&](size_t i) { return fclDistance(pairs[i], solver); });
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fclDistance(pairs[i], solver));
    if (++i == pairs.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK_CAPTURE(BM_Ours, separated, Set::Separated);
BENCHMARK_CAPTURE(BM_OverlapOnly, separated, Set::Separated);
BENCHMARK_CAPTURE(BM_Fcl, separated_libccd, Set::Separated, fcl::GST_LIBCCD);
BENCHMARK_CAPTURE(BM_Fcl, separated_indep, Set::Separated, fcl::GST_INDEP);
BENCHMARK_CAPTURE(BM_Ours, near, Set::Near);
BENCHMARK_CAPTURE(BM_OverlapOnly, near, Set::Near);
BENCHMARK_CAPTURE(BM_Fcl, near_libccd, Set::Near, fcl::GST_LIBCCD);
BENCHMARK_CAPTURE(BM_Fcl, near_indep, Set::Near, fcl::GST_INDEP);
BENCHMARK_CAPTURE(BM_Ours, thin, Set::Thin);
BENCHMARK_CAPTURE(BM_OverlapOnly, thin, Set::Thin);
BENCHMARK_CAPTURE(BM_Fcl, thin_libccd, Set::Thin, fcl::GST_LIBCCD);
BENCHMARK_CAPTURE(BM_Fcl, thin_indep, Set::Thin, fcl::GST_INDEP);

}  // namespace
}  // namespace ellipse_collision::core

BENCHMARK_MAIN();
