// Pair tests on the same stored pairs, one benchmark per (method, mix): ours (plain and prepared,
// and the batch tests with each culling kernel: a scene-like or one-to-many mix's links each
// against all its obstacles with overlapOneToMany(), the other mixes' pairs with overlapBatch()),
// the eigenvalue and polygonal tests alone, FCL 0.7 and the seed README's method, and overlap()
// with polygonal caps 0..8. Each method keeps what it needs per ellipse (prepared ellipses, FCL
// objects) built before timing; the scene-like pairs share one scene's ellipses. Every benchmark
// carries, as counters, the seconds per pair and its misclassifications against the
// quad-precision oracle on those very pairs (computed once, before timing), and how many of the
// pairs overlap.
//
// The mixes (bench_scenes.h): scene-like (50 links within 1 m of the origin, each against the same
// pairs_per_mix / 50 obstacles of a 10 m room: 40 at the default), near (pairs within 1.5x their
// bounding radii), tangent (within 1e-6 of touching), random-pairs (independent pairs in a
// 20 m square, about 1 % overlapping) and one-to-N (one ellipse against N drawn as the random
// pairs' are: the batch's best use, one overlapOneToMany() call). The last two are timed for our
// plain, prepared and batch tests (also with the batches filled in every call: batch_built) and
// FCL only.
//
// contact_scale/*: contactScale() on the colliding pairs of a robot scene (50 links, 100,000
// obstacles in 50 m x 50 m, the links among themselves too), every one of which a scene check must
// give a contact scale: one pair at a time (plain and prepared), all of them side by side as a scene
// check solves them (batch), and the certified maximisation of Q alone (what a pair whose quartic
// is not done in time takes), with the mean Halley steps and the fallbacks as counters. The core
// is a shared library: the same binary with LD_LIBRARY_PATH at another build of it compares two
// versions on the same pairs.
//
// Extra flags: --pairs_per_mix=N (default 2000: scene-like, near, tangent), --random_pairs=N
// (default 20000), --one_to_many=N,M,... (default 1000,10000). The oracle takes about 1 ms per pair
// (pairs whose bounding circles are well apart are judged without it).

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench_scenes.h"
#include "contact_scale_quartic.h"
#include "ellipse_collision/core/batch_overlap.h"
#include "contact_scale_detail.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/polygonal_early_out.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "overlap_detail.h"
#include "reference_methods.h"
#include "relative_shape.h"

namespace ellipse_collision::core::bench {
namespace {

constexpr int kMaxStudiedCap = 8;

/// Calls visit(i, j) for the ellipse indices of every pair of the mix, in its order, as a scene
/// check would loop: a link against every obstacle, or each pair's own two ellipses.
template <typename Visit>
void forEachPair(const PairMix& mix, Visit&& visit) {
  if (mix.rows > 0) {
    for (std::size_t i = 0; i < mix.rows; ++i) {
      for (std::size_t j = mix.rows; j < mix.ellipses.size(); ++j) visit(i, j);
    }
  } else {
    for (std::size_t i = 0; i + 1 < mix.ellipses.size(); i += 2) visit(i, i + 1);
  }
}

/// The counters every pair benchmark carries: seconds per pair, `wrong` misclassifications, and the
/// mix's pairs counted, within their bounding circles and overlapping.
void addPairCounters(benchmark::State& state, const PairMix& mix, int wrong) {
  using benchmark::Counter;
  state.counters["sec_per_pair"] = Counter(static_cast<double>(mix.pairs.size()),
                                           Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["misclassified"] = wrong;
  state.counters["counted"] = mix.counted();
  state.counters["pass_bounding"] = mix.pass_bounding_circles;
  state.counters["overlapping"] = mix.overlapping();
}

/// Registers "pair/<method>/<mix>". `verdict(i, j)` answers the pair of ellipses i and j of the
/// mix; it is run once untimed to count misclassifications, then timed over all pairs per
/// iteration.
template <typename Verdict>
void registerMethod(const std::string& method, const PairMix& mix, Verdict verdict,
                    int fallbacks = -1) {
  std::vector<bool> verdicts;
  forEachPair(mix, [&](std::size_t i, std::size_t j) { verdicts.push_back(verdict(i, j)); });
  const int wrong = misclassified(mix, verdicts);
  const std::string name = "pair/" + method + "/" + mix.name;
  benchmark::RegisterBenchmark(name.c_str(), [&mix, verdict, wrong,
                                              fallbacks](benchmark::State& state) {
    for (auto _ : state) {
      unsigned hits = 0;
      forEachPair(mix, [&](std::size_t i, std::size_t j) { hits += verdict(i, j) ? 1u : 0u; });
      benchmark::DoNotOptimize(hits);
    }
    addPairCounters(state, mix, wrong);
    if (fallbacks >= 0) state.counters["unknown_fallbacks"] = fallbacks;
  });
}

/// Everything one mix needs stored before timing, per ellipse; kept alive for the whole run.
struct MixData {
  PairMix mix;
  std::vector<PreparedEllipse> prepared;
  std::vector<FclEllipse> fcl;
  // The batch tests' input: for a scene-like mix the obstacles in `second` (each link against
  // all of them, overlapOneToMany()); otherwise each pair's ellipses in `first` and `second`.
  EllipseBatch first;
  EllipseBatch second;
};

/// The batch tests, in forEachPair()'s order, into `out`.
void batchVerdicts(const MixData& data, detail::BatchKernel kernel, std::uint8_t* out) {
  const PairMix& mix = data.mix;
  if (mix.rows == 0) {
    detail::overlapBatchWith(kernel, data.first, data.second, out);
    return;
  }
  for (std::size_t i = 0; i < mix.rows; ++i) {
    detail::overlapOneToManyWith(kernel, data.prepared[i], data.second,
                                 out + i * data.second.size());
  }
}

/// Registers "pair/batch_<kernel>/<mix>": overlapBatch() (pairs) or overlapOneToMany() (a link
/// against all obstacles) on the mix, with its counters as registerMethod() gives them.
void registerBatch(const std::string& kernel_name, detail::BatchKernel kernel,
                   const MixData* data) {
  const PairMix& mix = data->mix;
  std::vector<std::uint8_t> out(mix.pairs.size());
  batchVerdicts(*data, kernel, out.data());
  const int wrong = misclassified(mix, std::vector<bool>(out.begin(), out.end()));
  const std::string name = "pair/batch_" + kernel_name + "/" + mix.name;
  benchmark::RegisterBenchmark(name.c_str(), [data, kernel, wrong](benchmark::State& state) {
    const PairMix& mix = data->mix;
    std::vector<std::uint8_t> verdicts(mix.pairs.size());
    for (auto _ : state) {
      batchVerdicts(*data, kernel, verdicts.data());
      benchmark::DoNotOptimize(verdicts.data());
      benchmark::ClobberMemory();
    }
    addPairCounters(state, mix, wrong);
  });
}

/// Registers "pair/batch_built/<mix>": the public overlapBatch() / overlapOneToMany() (the
/// processor's best kernel) with their EllipseBatch filled anew in every iteration, as a caller
/// whose ellipses change with every call pays it: every ellipse of the batches is prepared again
/// (for a one-to-many mix the obstacles' batch; the one ellipse is prepared by the call).
void registerBatchBuilt(const MixData* data) {
  const PairMix& mix = data->mix;
  const std::string name = "pair/batch_built/" + mix.name;
  std::vector<std::uint8_t> out(mix.pairs.size());
  const auto run = [data](EllipseBatch* first, EllipseBatch* second, std::uint8_t* verdicts) {
    const PairMix& mix = data->mix;
    first->clear();
    second->clear();
    if (mix.rows == 0) {
      for (std::size_t i = 0; i + 1 < mix.ellipses.size(); i += 2) {
        first->add(mix.ellipses[i]);
        second->add(mix.ellipses[i + 1]);
      }
      overlapBatch(*first, *second, verdicts);
      return;
    }
    for (std::size_t j = mix.rows; j < mix.ellipses.size(); ++j) second->add(mix.ellipses[j]);
    for (std::size_t i = 0; i < mix.rows; ++i) {
      overlapOneToMany(mix.ellipses[i], *second, verdicts + i * second->size());
    }
  };
  EllipseBatch first, second;
  run(&first, &second, out.data());
  const int wrong = misclassified(mix, std::vector<bool>(out.begin(), out.end()));
  benchmark::RegisterBenchmark(name.c_str(), [data, run, wrong](benchmark::State& state) {
    const PairMix& mix = data->mix;
    std::vector<std::uint8_t> verdicts(mix.pairs.size());
    EllipseBatch first, second;  // their capacity kept from one iteration to the next
    for (auto _ : state) {
      run(&first, &second, verdicts.data());
      benchmark::DoNotOptimize(verdicts.data());
      benchmark::ClobberMemory();
    }
    addPairCounters(state, mix, wrong);
  });
}

/// Registers every method on the mix; with `study` false only ours (plain, prepared, batch, and
/// the batch with its EllipseBatch filled in every call) and FCL, the rest being studies of the
/// stages that the first three mixes answer.
void registerMix(MixData* data, bool study) {
  const PairMix& mix = data->mix;
  for (const Ellipse& e : mix.ellipses) {
    data->prepared.emplace_back(e);
    data->fcl.emplace_back(e);
  }
  // Raw pointers, captured by value: the compiler keeps them in registers across the timed loop
  // instead of reloading them through the vectors for every pair.
  const Ellipse* const e = mix.ellipses.data();
  const PreparedEllipse* const prepared = data->prepared.data();
  const FclEllipse* const fcl = data->fcl.data();

  if (mix.rows > 0) {
    for (std::size_t j = mix.rows; j < mix.ellipses.size(); ++j) data->second.add(mix.ellipses[j]);
  } else {
    for (std::size_t i = 0; i + 1 < mix.ellipses.size(); i += 2) {
      data->first.add(mix.ellipses[i]);
      data->second.add(mix.ellipses[i + 1]);
    }
  }
  registerBatch("portable", detail::BatchKernel::Portable, data);
  if (detail::avx2Supported()) registerBatch("avx2", detail::BatchKernel::Avx2, data);

  registerMethod("ours_overlap", mix,
                 [e](std::size_t i, std::size_t j) { return overlap(e[i], e[j]); });
  registerMethod("ours_prepared", mix, [prepared](std::size_t i, std::size_t j) {
    return overlap(prepared[i], prepared[j]);
  });
  registerMethod("fcl", mix,
                 [fcl](std::size_t i, std::size_t j) { return fclCollide(fcl[i], fcl[j]); });
  if (!study) {
    registerBatchBuilt(data);
    return;
  }
  registerMethod("eigenvalue_alone", mix,
                 [e](std::size_t i, std::size_t j) { return eigenvalueOverlap(e[i], e[j]); });
  int fallbacks = 0;
  for (std::size_t k = 0; k < mix.pairs.size(); ++k) {
    fallbacks += polygonalTest(mix.a(k), mix.b(k)) == PolygonalResult::Unknown ? 1 : 0;
  }
  registerMethod(
      "polygonal_alone", mix,
      [e](std::size_t i, std::size_t j) {
        switch (polygonalTest(e[i], e[j])) {
          case PolygonalResult::Overlap:
            return true;
          case PolygonalResult::Separate:
            return false;
          case PolygonalResult::Unknown:
            break;
        }
        return eigenvalueOverlap(e[i], e[j]);  // its fallback, timed with it
      },
      fallbacks);
  registerMethod("seed_readme", mix,
                 [e](std::size_t i, std::size_t j) { return seedReadmeOverlap(e[i], e[j]); });
  for (int cap = 0; cap <= kMaxStudiedCap; ++cap) {
    registerMethod("cap_study_" + std::to_string(cap), mix, [e, cap](std::size_t i, std::size_t j) {
      return detail::overlapWithPolygonalCap(e[i], e[j], cap);
    });
  }
}

/// The pairs of robotScene(50, 100000, 50, 7) that overlap() reports, the mean Halley steps of
/// their contact scales' quartic (contact_scale_quartic.h) and how many of them take the
/// certified maximisation of Q instead.
struct CollidingPairs {
  std::vector<std::pair<Ellipse, Ellipse>> plain;
  std::vector<std::pair<PreparedEllipse, PreparedEllipse>> prepared;
  double mean_steps{0.0};
  int fallbacks{0};
};

/// Built on first use, so that runs filtered to other benchmarks do not pay for the scene.
const CollidingPairs& collidingPairs() {
  static const CollidingPairs pairs = [] {
    CollidingPairs result;
    const RobotScene scene = robotScene(50, 100000, 50.0, 7);
    const auto keep = [&result](const Ellipse& a, const Ellipse& b) {
      if (!overlap(a, b)) return;
      result.plain.emplace_back(a, b);
      result.prepared.emplace_back(PreparedEllipse(a), PreparedEllipse(b));
    };
    for (std::size_t i = 0; i < scene.links.size(); ++i) {
      for (const Ellipse& obstacle : scene.obstacles) keep(scene.links[i], obstacle);
      for (std::size_t j = i + 1; j < scene.links.size(); ++j) keep(scene.links[i], scene.links[j]);
    }
    long steps = 0;
    for (const auto& [a, b] : result.plain) {
      const int taken = detail::quarticStepsOf(detail::canonicalRelativeShape(a, b));
      steps += taken;
      result.fallbacks += taken > detail::kMaxQuarticSteps ? 1 : 0;
    }
    result.mean_steps = static_cast<double>(steps) / result.plain.size();
    return result;
  }();
  return pairs;
}

void addContactScaleCounters(benchmark::State& state, std::size_t pairs) {
  using benchmark::Counter;
  state.counters["sec_per_pair"] = Counter(static_cast<double>(pairs),
                                           Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(pairs);
  state.counters["quartic_steps"] = collidingPairs().mean_steps;
  state.counters["fallbacks"] = collidingPairs().fallbacks;
}

/// Registers "contact_scale/<name>": `measure(a, b)` summed over all the colliding pairs.
template <typename Pairs, typename Measure>
void registerContactScale(const std::string& name, const Pairs& (*pairs_of)(), Measure measure) {
  const std::string full_name = "contact_scale/" + name;
  benchmark::RegisterBenchmark(full_name.c_str(), [pairs_of, measure](benchmark::State& state) {
    const Pairs& pairs = pairs_of();
    for (auto _ : state) {
      double sum = 0.0;
      for (const auto& [a, b] : pairs) sum += measure(a, b);
      benchmark::DoNotOptimize(sum);
    }
    addContactScaleCounters(state, pairs.size());
  });
}

const std::vector<std::pair<Ellipse, Ellipse>>& plainCollidingPairs() {
  return collidingPairs().plain;
}
const std::vector<std::pair<PreparedEllipse, PreparedEllipse>>& preparedCollidingPairs() {
  return collidingPairs().prepared;
}

void registerContactScales() {
  registerContactScale("plain", &plainCollidingPairs,
                       [](const Ellipse& a, const Ellipse& b) { return contactScale(a, b); });
  registerContactScale("prepared", &preparedCollidingPairs,
                       [](const PreparedEllipse& a, const PreparedEllipse& b) {
                         return contactScale(a, b);
                       });
  registerContactScale("certified_alone", &preparedCollidingPairs,
                       [](const PreparedEllipse& a, const PreparedEllipse& b) {
                         return detail::contactScalePrincipal(
                             detail::principalShape(detail::canonicalRelativeShape(a, b)));
                       });
  // As a scene check solves them: every pair's quartic side by side (solveContactScales()).
  benchmark::RegisterBenchmark("contact_scale/batch", [](benchmark::State& state) {
    const auto& pairs = preparedCollidingPairs();
    std::vector<detail::ScaleProblem> problems(pairs.size());
    std::vector<double> scales(pairs.size());
    for (auto _ : state) {
      for (std::size_t i = 0; i < pairs.size(); ++i) {
        problems[i] = detail::scaleProblem(
            detail::canonicalRelativeShape(pairs[i].first, pairs[i].second));
      }
      detail::solveContactScales(problems.data(), problems.size(), scales.data());
      benchmark::DoNotOptimize(scales.data());
    }
    addContactScaleCounters(state, pairs.size());
  });
}

/// Removes `flag`VALUE from argv (Google Benchmark rejects unknown flags) and returns VALUE, or
/// `fallback` if the flag is absent.
std::string takeFlag(int* argc, char** argv, const char* flag, const std::string& fallback) {
  std::string value = fallback;
  int kept = 0;
  for (int i = 0; i < *argc; ++i) {
    if (std::strncmp(argv[i], flag, std::strlen(flag)) == 0) {
      value = argv[i] + std::strlen(flag);
    } else {
      argv[kept++] = argv[i];
    }
  }
  *argc = kept;
  return value;
}

/// The positive counts of a comma-separated list ("1000,10000"), or an empty vector after a
/// message naming the flag and the value if any is not one.
std::vector<int> parseCounts(const char* flag, const std::string& text) {
  std::vector<int> counts;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    char* end = nullptr;
    const long count = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || count <= 0 || count > 100000000) {
      std::fprintf(stderr, "%s%s: '%s' is not a positive count\n", flag, text.c_str(),
                   item.c_str());
      return {};
    }
    counts.push_back(static_cast<int>(count));
  }
  if (counts.empty()) std::fprintf(stderr, "%s%s: no count given\n", flag, text.c_str());
  return counts;
}

}  // namespace
}  // namespace ellipse_collision::core::bench

int main(int argc, char** argv) {
  using namespace ellipse_collision::core::bench;
  const char* const kPairsFlag = "--pairs_per_mix=";
  const char* const kRandomFlag = "--random_pairs=";
  const char* const kOneToManyFlag = "--one_to_many=";
  const std::vector<int> pairs = parseCounts(kPairsFlag, takeFlag(&argc, argv, kPairsFlag, "2000"));
  const std::vector<int> random_pairs =
      parseCounts(kRandomFlag, takeFlag(&argc, argv, kRandomFlag, "20000"));
  const std::vector<int> one_to_many =
      parseCounts(kOneToManyFlag, takeFlag(&argc, argv, kOneToManyFlag, "1000,10000"));
  if (pairs.size() != 1 || random_pairs.size() != 1 || one_to_many.empty()) return 2;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  std::deque<MixData> mixes;  // stable addresses: the benchmarks hold references
  mixes.push_back({sceneLikeMix(pairs[0], 1), {}, {}, {}, {}});
  mixes.push_back({nearMix(pairs[0], 2), {}, {}, {}, {}});
  mixes.push_back({tangencyMix(pairs[0], 3), {}, {}, {}, {}});
  for (MixData& data : mixes) registerMix(&data, true);
  mixes.push_back({randomPairsMix(random_pairs[0], 4), {}, {}, {}, {}});
  registerMix(&mixes.back(), false);
  for (const int count : one_to_many) {
    mixes.push_back({oneToManyMix(count, 5), {}, {}, {}, {}});
    registerMix(&mixes.back(), false);
  }
  registerContactScales();

  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
