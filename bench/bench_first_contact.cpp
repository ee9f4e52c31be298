// First contact under translation on the same random pairs, side by side: firstContact() (the
// entry of the path into the Minkowski sum), the secant method on the contact scale it replaced
// (secantFirstContact(), reference_methods.h), FCL 0.7's continuousCollide on fcl::Ellipsoid (z
// radius = the smaller radius, motion in the plane) and sampling overlap() at 100 steps. FCL's
// conservative advancement has no ellipsoid entry in its function table (it prints "not
// supported" and reports no contact; checked once and reported), so the FCL figure is its naive
// solver (collide() at num_max_iterations = 100 time steps), the only FCL solver that accepts this
// pair. Every benchmark carries as counters its misclassifications
// and worst time error (relative to the horizon) against the quad-precision oracle
// (first_contact_oracle.h), computed once before timing; a summary with the speed ratios is printed
// at the end: CPU time per pair, the median of kSummaryRounds rounds in which every method runs
// once in turn, so that all share the machine's noise.
//
// Then a rotating mix (makeRotatingCases()): firstContact()'s second-order steps beside the plain
// conservative advancement it replaced (plainAdvancementFirstContact(), reference_methods.h),
// timed in alternating rounds, with each method's distance() calls, pairs at its step cap, and
// how early or late it answers against the oracle; and the same for turning passes from head-on
// to grazing 1e-12 deep (compareTurningPasses()) of each caller of the rotating method:
// firstContact(), twistContact() (a link's centre on an arc) and segmentContact() (an offset
// link's centre on a line plus an arc), and firstContact() on two needles of axis ratio 1e8
// turning at different rates (drawNeedlePairPass(): tip to tip, tip to flat side).
//
// Extra flag: --pairs=N (default 5000; --pairs=64 for a smoke run, which also shrinks the
// rotating mix to 28 pairs and the turning passes to 14 per caller).

#include <benchmark/benchmark.h>
#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcl/fcl.h>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/twist_motion.h"
#include "first_contact_oracle.h"
#include "grazing_passes.h"
#include "random_source.h"
#include "reference_methods.h"
#include "rotating_contact.h"
#include "twist_motion_detail.h"

namespace ellipse_collision::core::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHorizon = 1.0;  // [s]
constexpr int kSteps = 100;       // sampling and FCL naive time steps
constexpr double kBand = 1e-9;    // grazing band excluded from the misclassification count
constexpr int kSummaryRounds = 5;

struct Case {
  Ellipse a, b;
  Motion ma, mb;
  bool oracle_contact;
  double oracle_time;
  bool in_band;
};

struct Verdict {
  bool contact;
  double time;
};

std::vector<Case> makeCases(int count) {
  ellipse_collision::test::RandomSource r(2024);
  std::vector<Case> cases;
  while (static_cast<int>(cases.size()) < count) {
    // Sizes 0.05..2 m, axis ratios 1..100, either axis the major one.
    auto ellipse = [&]() {
      const double major = r.logUniform(0.05, 2.0), minor = major / r.logUniform(1.0, 100.0);
      const bool x_major = r.coin();
      return Ellipse{{0, 0}, x_major ? major : minor, x_major ? minor : major, r.uniform(-kPi, kPi)};
    };
    Ellipse a = ellipse(), b = ellipse();
    a.center = {r.uniform(-5, 5), r.uniform(-5, 5)};
    // b starts some metres away and heads roughly towards a: some hit, some pass.
    const double phi = r.uniform(-kPi, kPi);
    b.center = a.center + Eigen::Vector2d(std::cos(phi), std::sin(phi)) * r.uniform(3.0, 8.0);
    const Eigen::Vector2d aim = a.center + Eigen::Vector2d(r.uniform(-2, 2), r.uniform(-2, 2));
    const Motion ma{{r.uniform(-1, 1), r.uniform(-1, 1)}, 0.0};
    const Motion mb{ma.velocity + (aim - b.center) * r.uniform(0.8, 2.0), 0.0};
    if (!invalidMotionReason(a, ma, b, mb, kHorizon).empty()) continue;
    const auto o = test::oracleFirstContact(a, ma, b, mb, kHorizon);
    cases.push_back({a, b, ma, mb, o.contact, static_cast<double>(o.time),
                     fabsq(o.min_scale - 1) <= kBand});
  }
  return cases;
}

/// One method's misclassifications and worst time error against the oracle.
struct Score {
  int wrong = 0, missed = 0, false_alarms = 0;
  double worst_time_error = 0.0;
  double seconds_per_pair = 0.0;
};

template <typename Method>
Score score(const std::vector<Case>& cases, Method method) {
  Score s;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const Verdict v = method(i);
    if (c.in_band) continue;
    if (v.contact != c.oracle_contact) {
      ++s.wrong;
      (v.contact ? s.false_alarms : s.missed) += 1;
    } else if (v.contact) {
      s.worst_time_error =
          std::max(s.worst_time_error, std::fabs(v.time - c.oracle_time) / kHorizon);
    }
  }
  return s;
}

fcl::Transform3d pose(const Ellipse& e, const Eigen::Vector2d& offset) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = fcl::AngleAxisd(e.angle, fcl::Vector3d::UnitZ()).toRotationMatrix();
  tf.translation() = fcl::Vector3d(e.center.x() + offset.x(), e.center.y() + offset.y(), 0.0);
  return tf;
}

struct FclPair {
  std::shared_ptr<fcl::Ellipsoidd> a, b;
  fcl::Transform3d a0, a1, b0, b1;
};

FclPair fclPair(const Case& c) {
  auto ellipsoid = [](const Ellipse& e) {
    return std::make_shared<fcl::Ellipsoidd>(e.radius_x, e.radius_y, inscribedRadius(e));
  };
  // In a's starting frame, as firstContact works, so that FCL loses nothing to far centres.
  Ellipse a = c.a, b = c.b;
  const Eigen::Vector2d origin = c.a.center;
  a.center -= origin, b.center -= origin;
  return {ellipsoid(c.a), ellipsoid(c.b), pose(a, {0, 0}), pose(a, c.ma.velocity * kHorizon),
          pose(b, {0, 0}), pose(b, c.mb.velocity * kHorizon)};
}

Verdict fclContact(const FclPair& p, fcl::CCDSolverType solver) {
  fcl::ContinuousCollisionRequestd request(kSteps, 1e-4, fcl::CCDM_TRANS, fcl::GST_LIBCCD, solver);
  fcl::ContinuousCollisionResultd result;
  fcl::continuousCollide(p.a.get(), p.a0, p.a1, p.b.get(), p.b0, p.b1, request, result);
  return {result.is_collide, result.time_of_contact * kHorizon};
}

Verdict sampled(const Case& c) {
  for (int k = 0; k <= kSteps; ++k) {
    const double t = kHorizon * k / kSteps;
    Ellipse a = c.a, b = c.b;
    a.center += c.ma.velocity * t;
    b.center += c.mb.velocity * t;
    if (overlap(a, b)) return {true, t};
  }
  return {false, 0.0};
}

std::map<std::string, Score> g_scores;

template <typename Method>
void registerMethod(const std::string& name, const std::vector<Case>& cases, Method method) {
  g_scores[name] = score(cases, method);
  const Score s = g_scores[name];
  benchmark::RegisterBenchmark(("first_contact/" + name).c_str(),
                               [&cases, method, s, name](benchmark::State& state) {
                                 for (auto _ : state) {
                                   for (std::size_t i = 0; i < cases.size(); ++i) {
                                     benchmark::DoNotOptimize(method(i));
                                   }
                                 }
                                 const double pairs = static_cast<double>(cases.size());
                                 state.counters["s_per_pair"] = benchmark::Counter(
                                     pairs, benchmark::Counter::kIsIterationInvariantRate |
                                                benchmark::Counter::kInvert);
                                 state.counters["misclassified"] = s.wrong;
                                 state.counters["missed"] = s.missed;
                                 state.counters["worst_dt_over_h"] = s.worst_time_error;
                               })
      ->Unit(benchmark::kMicrosecond);
}

/// CPU seconds per pair of `method` over all cases, for the summary: whole passes over the cases
/// for at least `min_seconds` of CPU time.
template <typename Method>
double secondsPerPair(std::size_t count, Method method, double min_seconds) {
  int rounds = 0;
  const std::clock_t start = std::clock();
  double elapsed = 0.0;
  do {
    for (std::size_t i = 0; i < count; ++i) benchmark::DoNotOptimize(method(i));
    ++rounds;
    elapsed = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  } while (elapsed < min_seconds);
  return elapsed / (rounds * static_cast<double>(count));
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// ---- rotating mix: the second-order steps beside plain conservative advancement ---------------
// Two families, horizon 1 s: the benchmark's pairs with both ellipses turning at up to 3 rad/s
// (oracle: the quad gauge scanned at 2000 samples and bisected), and an eccentric ellipse (axis
// ratio 2..20) spinning in place whose tip passes a disc at a gap of +-1e-6, +-1e-8 or +-3e-9 of
// R + rho, the pairs that brought plain advancement to its cap (oracle: the gap's sign, and the
// quad gauge bisected on the quarter turn before the tip points at the disc).
constexpr int kRotationSamples = 2000;

std::vector<Case> makeRotatingCases(int mixed, int grazing) {
  ellipse_collision::test::RandomSource r(2025);
  std::vector<Case> cases;
  while (static_cast<int>(cases.size()) < mixed) {
    auto ellipse = [&]() {
      const double major = r.logUniform(0.05, 2.0), minor = major / r.logUniform(1.0, 100.0);
      const bool x_major = r.coin();
      return Ellipse{{0, 0}, x_major ? major : minor, x_major ? minor : major, r.uniform(-kPi, kPi)};
    };
    Ellipse a = ellipse(), b = ellipse();
    a.center = {r.uniform(-5, 5), r.uniform(-5, 5)};
    const double phi = r.uniform(-kPi, kPi);
    b.center = a.center + Eigen::Vector2d(std::cos(phi), std::sin(phi)) * r.uniform(3.0, 8.0);
    const Eigen::Vector2d aim = a.center + Eigen::Vector2d(r.uniform(-2, 2), r.uniform(-2, 2));
    const Motion ma{{r.uniform(-1, 1), r.uniform(-1, 1)}, r.uniform(-3, 3)};
    const Motion mb{ma.velocity + (aim - b.center) * r.uniform(0.8, 2.0), r.uniform(-3, 3)};
    if (!invalidMotionReason(a, ma, b, mb, kHorizon).empty()) continue;
    const auto o = test::oracleFirstContact(a, ma, b, mb, kHorizon, kRotationSamples);
    cases.push_back({a, b, ma, mb, o.contact, static_cast<double>(o.time),
                     fabsq(o.min_scale - 1) <= kBand});
  }
  constexpr double kGaps[] = {1e-6, 1e-8, 3e-9};
  for (int i = 0; i < grazing; ++i) {
    const double major = r.logUniform(0.1, 10.0), minor = major / r.logUniform(2.0, 20.0);
    const bool x_major = r.coin(), touching = (i / 3) % 2;
    Ellipse a{{r.uniform(-100, 100), r.uniform(-100, 100)}, x_major ? major : minor,
              x_major ? minor : major, 0.0};
    const double rho = major * r.logUniform(0.2, 2.0), phi = r.uniform(-kPi, kPi);
    const double gap = (touching ? -1.0 : 1.0) * kGaps[i % 3] * (major + rho);
    const Ellipse b{a.center + Eigen::Vector2d(std::cos(phi), std::sin(phi)) * (major + rho + gap),
                    rho, rho, 0.0};
    const double omega = (r.coin() ? 1.0 : -1.0) * r.uniform(0.5, 3.0);
    const double t_tip = r.uniform(0.2, 0.5);  // |omega| t_tip < pi / 2
    a.angle = phi - omega * t_tip - (x_major ? 0.0 : kPi / 2);
    const Motion ma{{0, 0}, omega}, mb{{0, 0}, 0.0};
    __float128 time = 0;
    if (touching) {
      __float128 lo = 0, hi = t_tip;
      for (int k = 0; k < 100; ++k) {
        const __float128 mid = (lo + hi) / 2;
        (test::oracleScaleAt(a, ma, b, mb, mid) <= 1 ? hi : lo) = mid;
      }
      time = hi;
    }
    cases.push_back({a, b, ma, mb, touching, static_cast<double>(time), false});
  }
  return cases;
}

/// One rotating method's accuracy (never late, how early) and work against the oracle.
struct RotationScore {
  int wrong = 0, false_alarms = 0, capped = 0;
  double worst_early = 0.0, worst_late = 0.0;  // (oracle - ours) / horizon, (ours - oracle) / h
  double mean_calls = 0.0;
  int most_calls = 0;
};

/// `method(i, &calls)` answers case i and reports its distance() calls.
template <typename Method>
RotationScore scoreRotation(const std::vector<Case>& cases, Method method, int cap) {
  RotationScore s;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    int calls = 0;
    const Verdict v = method(i, &calls);
    s.mean_calls += calls;
    s.most_calls = std::max(s.most_calls, calls);
    s.capped += calls >= cap;
    const Case& c = cases[i];
    if (c.in_band) continue;
    if (v.contact != c.oracle_contact) {
      ++s.wrong;
      s.false_alarms += v.contact;
    } else if (v.contact) {
      const double error = (v.time - c.oracle_time) / kHorizon;
      s.worst_late = std::max(s.worst_late, error);
      s.worst_early = std::max(s.worst_early, -error);
    }
  }
  s.mean_calls /= static_cast<double>(cases.size());
  return s;
}

/// One line of a rotating table.
void printScore(const char* name, double seconds, const RotationScore& s) {
  std::printf(
      "  %-30s %9.3f us/pair  distance() calls mean %7.1f max %5d, at the cap %3d  "
      "misclassified %d (false %d)  worst early %.3g, worst late %.3g (of h)\n",
      name, seconds * 1e6, s.mean_calls, s.most_calls, s.capped, s.wrong, s.false_alarms,
      s.worst_early, s.worst_late);
}

/// The rotating mix: both methods timed in alternating rounds, then one table.
void compareRotation(int mixed, int grazing, double min_seconds) {
  static std::vector<Case> cases;
  cases = makeRotatingCases(mixed, grazing);
  int contacts = 0, in_band = 0;
  for (const Case& c : cases) contacts += c.oracle_contact, in_band += c.in_band;
  auto counted_new = [](std::size_t i, int* calls) {
    const Case& c = cases[i];
    const FirstContact r = firstContact(c.a, c.ma, c.b, c.mb, kHorizon);
    // The same pair through the rotating path directly, for its distance() count.
    const detail::RotatingPair p = detail::rotatingPair(c.a, c.ma.velocity, Eigen::Vector2d::Zero(),
                                                        c.ma.angular_velocity, c.b, c.mb);
    detail::RotationWork work;
    if (!overlap(c.a, c.b)) detail::rotatingContact(p, kHorizon, &work);
    *calls = work.capped ? detail::kMaxRotationSteps : work.distance_calls;
    return Verdict{r.contact, r.time};
  };
  auto counted_old = [](std::size_t i, int* calls) {
    const Case& c = cases[i];
    const FirstContact r = plainAdvancementFirstContact(c.a, c.ma, c.b, c.mb, kHorizon, calls);
    return Verdict{r.contact, r.time};
  };
  const RotationScore s_new = scoreRotation(cases, counted_new, detail::kMaxRotationSteps);
  const RotationScore s_old = scoreRotation(cases, counted_old, kPlainAdvancementCap);
  auto timed_new = [](std::size_t i) {
    const Case& c = cases[i];
    return firstContact(c.a, c.ma, c.b, c.mb, kHorizon);
  };
  auto timed_old = [](std::size_t i) {
    const Case& c = cases[i];
    return plainAdvancementFirstContact(c.a, c.ma, c.b, c.mb, kHorizon);
  };
  std::vector<double> t_new, t_old;
  for (int round = 0; round < kSummaryRounds; ++round) {
    t_new.push_back(secondsPerPair(cases.size(), timed_new, min_seconds));
    t_old.push_back(secondsPerPair(cases.size(), timed_old, min_seconds));
  }
  std::printf("\nRotating mix: %d pairs of the benchmark's kind turning at up to 3 rad/s and %d "
              "eccentric tips grazing a disc (gaps +-1e-6, +-1e-8, +-3e-9), horizon %g s; %d in "
              "contact per the oracle, %d in the grazing band (excluded); CPU time per pair, median "
              "of %d rounds\n",
              mixed, grazing, kHorizon, contacts, in_band, kSummaryRounds);
  printScore("ours (second-order steps)", median(t_new), s_new);
  printScore("plain advancement (before)", median(t_old), s_old);
  std::printf("  speed ratio: before / ours = %.1fx\n", median(t_old) / median(t_new));
}

// ---- turning passes: links on arcs (twistContact(), segmentContact()) and turning pairs --------
// Passes drawn by grazing_passes.h for each caller of the rotating path, made to pass at smallest
// contact scales 1 -+ {0.5, 1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12} (head-on to grazing 1e-12 deep,
// and as far clear): an eccentric link (axis ratio 3..30) against an eccentric obstacle (1..20)
// that translates and turns. Oracle: oracleGrazingPass(), the quad gauge of the exact motion
// bisected on the falling side of the single dip. Each caller's new path beside the plain
// conservative advancement it replaced (reference_methods.h), timed in alternating rounds.
constexpr double kPassDepths[] = {0.5, 1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12};

enum class PassKind { kMotion, kTwist, kSegment, kNeedles };

// The needles' axis ratio; their contacts go tip to tip, flat of a, flat of b in turn.
constexpr double kNeedleRatio = 1e8;

std::vector<test::TurningPass> makePasses(PassKind kind, int per_depth) {
  ellipse_collision::test::RandomSource rng(kind == PassKind::kMotion    ? 31
                                            : kind == PassKind::kTwist   ? 32
                                            : kind == PassKind::kSegment ? 33
                                                                         : 34);
  const test::NeedleContact contacts[] = {test::NeedleContact::kTips,
                                          test::NeedleContact::kFlatOfA,
                                          test::NeedleContact::kFlatOfB};
  std::vector<test::TurningPass> passes;
  for (const double depth : kPassDepths) {
    for (int i = 0; i < 2 * per_depth; ++i) {
      const double target = i % 2 ? 1.0 - depth : 1.0 + depth;
      test::TurningPass p;
      bool found = false;
      while (!found) {
        found = kind == PassKind::kMotion    ? test::drawMotionPass(rng, target, &p)
                : kind == PassKind::kTwist   ? test::drawTwistPass(rng, target, &p)
                : kind == PassKind::kSegment ? test::drawSegmentPass(rng, target, &p)
                                             : test::drawNeedlePairPass(rng, kNeedleRatio,
                                                                        contacts[passes.size() % 3],
                                                                        target, &p);
      }
      passes.push_back(p);
    }
  }
  return passes;
}

/// The new path's answer for pass `p` and, when `work` is given, its work.
FirstContact newAnswer(PassKind kind, const test::TurningPass& p, detail::RotationWork* work) {
  if (work) {
    // The same pass through the rotating path directly (the passes are apart at t = 0).
    const detail::RotatingPair pair =
        kind == PassKind::kMotion || kind == PassKind::kNeedles
            ? detail::rotatingPair(p.a, p.motion_a.velocity, Eigen::Vector2d::Zero(),
                                   p.motion_a.angular_velocity, p.b, p.motion_b)
        : kind == PassKind::kTwist ? detail::twistPair(p.a, p.twist, p.b, p.motion_b)
                                   : detail::segmentPair(p.a, p.segment, p.b, p.motion_b);
    detail::rotatingContact(pair, p.horizon, work);
  }
  switch (kind) {
    case PassKind::kMotion:
    case PassKind::kNeedles:
      return firstContact(p.a, p.motion_a, p.b, p.motion_b, p.horizon);
    case PassKind::kTwist:
      return twistContact(p.a, p.twist, p.b, p.motion_b, p.horizon);
    case PassKind::kSegment:
      return segmentContact(p.a, p.segment, p.b, p.motion_b);
  }
  return {};
}

FirstContact plainAnswer(PassKind kind, const test::TurningPass& p, int* calls) {
  switch (kind) {
    case PassKind::kMotion:
    case PassKind::kNeedles:
      return plainAdvancementFirstContact(p.a, p.motion_a, p.b, p.motion_b, p.horizon, calls);
    case PassKind::kTwist:
      return plainAdvancementTwistContact(p.a, p.twist, p.b, p.motion_b, p.horizon, calls);
    case PassKind::kSegment:
      return plainAdvancementSegmentContact(p.a, p.segment, p.b, p.motion_b, calls);
  }
  return {};
}

/// Scores `method(i, &calls, &capped)` on the passes: a clear pass within the 1e-9 band may be
/// reported in contact (not counted as wrong); every other must be classified right, and a
/// contact's error is measured against the oracle's.
template <typename Method>
RotationScore scorePasses(const std::vector<test::TurningPass>& passes, Method method) {
  RotationScore s;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    int calls = 0;
    bool capped = false;
    const FirstContact r = method(i, &calls, &capped);
    s.mean_calls += calls;
    s.most_calls = std::max(s.most_calls, calls);
    s.capped += capped;
    const test::OracleGrazingPass& o = passes[i].pass;
    if (!o.contact && fabsq(o.scale - 1) <= kBand) continue;
    if (r.contact != o.contact) {
      ++s.wrong;
      s.false_alarms += r.contact;
    } else if (r.contact) {
      const double error = static_cast<double>((static_cast<__float128>(r.time) - o.contact_time) /
                                               passes[i].horizon);
      s.worst_late = std::max(s.worst_late, error);
      s.worst_early = std::max(s.worst_early, -error);
    }
  }
  s.mean_calls /= static_cast<double>(passes.size());
  return s;
}

void compareTurningPasses(PassKind kind, const char* title, int per_depth, double min_seconds) {
  static std::vector<test::TurningPass> passes;
  static PassKind kind_now;
  passes = makePasses(kind, per_depth);
  kind_now = kind;
  int contacts = 0;
  for (const test::TurningPass& p : passes) contacts += p.pass.contact;
  const RotationScore s_new = scorePasses(passes, [](std::size_t i, int* calls, bool* capped) {
    detail::RotationWork work;
    const FirstContact r = newAnswer(kind_now, passes[i], &work);
    *calls = work.distance_calls, *capped = work.capped;
    return r;
  });
  const RotationScore s_old = scorePasses(passes, [](std::size_t i, int* calls, bool* capped) {
    const FirstContact r = plainAnswer(kind_now, passes[i], calls);
    *capped = *calls >= kPlainAdvancementCap;
    return r;
  });
  auto timed_new = [](std::size_t i) { return newAnswer(kind_now, passes[i], nullptr); };
  auto timed_old = [](std::size_t i) { return plainAnswer(kind_now, passes[i], nullptr); };
  std::vector<double> t_new, t_old;
  for (int round = 0; round < kSummaryRounds; ++round) {
    t_new.push_back(secondsPerPair(passes.size(), timed_new, min_seconds));
    t_old.push_back(secondsPerPair(passes.size(), timed_old, min_seconds));
  }
  std::printf(
      "\n%s: %zu passes at smallest contact scales 1 -+ {0.5 .. 1e-12} (%d per depth and "
      "side), %d in contact per the oracle; CPU time per pass, median of %d rounds\n",
      title, passes.size(), per_depth, contacts, kSummaryRounds);
  printScore("ours (second-order steps)", median(t_new), s_new);
  printScore("plain advancement (before)", median(t_old), s_old);
  std::printf("  speed ratio: before / ours = %.1fx\n", median(t_old) / median(t_new));
}

int takePairsFlag(int* argc, char** argv) {
  int pairs = 5000;
  int kept = 1;
  for (int i = 1; i < *argc; ++i) {
    if (std::strncmp(argv[i], "--pairs=", 8) == 0) {
      pairs = std::max(1, std::atoi(argv[i] + 8));
    } else {
      argv[kept++] = argv[i];
    }
  }
  *argc = kept;
  return pairs;
}

}  // namespace
}  // namespace ellipse_collision::core::bench

int main(int argc, char** argv) {
  using namespace ellipse_collision::core;
  using namespace ellipse_collision::core::bench;
  const int pairs = takePairsFlag(&argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  static const std::vector<Case> cases = makeCases(pairs);
  static std::vector<FclPair> fcl_pairs;
  for (const Case& c : cases) fcl_pairs.push_back(fclPair(c));
  int contacts = 0, in_band = 0;
  for (const Case& c : cases) contacts += c.oracle_contact, in_band += c.in_band;

  // FCL's conservative advancement, tried once: it has no ellipsoid entry.
  const Verdict ca = fclContact(fcl_pairs[0], fcl::CCDC_CONSERVATIVE_ADVANCEMENT);
  std::printf("FCL conservative advancement on fcl::Ellipsoid pairs: is_collide %d (no entry in "
              "FCL's conservative advancement table: it warns and answers nothing), so FCL is "
              "measured with its naive solver\n",
              ca.contact);

  auto ours = [](std::size_t i) {
    const Case& c = cases[i];
    const FirstContact r = firstContact(c.a, c.ma, c.b, c.mb, kHorizon);
    return Verdict{r.contact, r.time};
  };
  auto secant = [](std::size_t i) {
    const Case& c = cases[i];
    const FirstContact r = secantFirstContact(c.a, c.ma, c.b, c.mb, kHorizon);
    return Verdict{r.contact, r.time};
  };
  auto fcl_naive = [](std::size_t i) { return fclContact(fcl_pairs[i], fcl::CCDC_NAIVE); };
  auto sampling = [](std::size_t i) { return sampled(cases[i]); };
  registerMethod("ours", cases, ours);
  registerMethod("secant_contact_scale", cases, secant);
  registerMethod("fcl_naive_100_steps", cases, fcl_naive);
  registerMethod("sampling_overlap_100_steps", cases, sampling);

  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  // A smoke run (few pairs) measures briefly.
  const double min_seconds = cases.size() < 1000 ? 0.01 : 0.2;
  std::vector<double> t_ours, t_secant, t_fcl, t_sampling;
  for (int round = 0; round < kSummaryRounds; ++round) {
    t_ours.push_back(secondsPerPair(cases.size(), ours, min_seconds));
    t_secant.push_back(secondsPerPair(cases.size(), secant, min_seconds));
    t_fcl.push_back(secondsPerPair(cases.size(), fcl_naive, min_seconds));
    t_sampling.push_back(secondsPerPair(cases.size(), sampling, min_seconds));
  }
  std::printf("\nSummary: %zu pairs under translation, horizon %g s, %d in contact per the oracle, "
              "%d in the grazing band (excluded); CPU time per pair, median of %d rounds\n",
              cases.size(), kHorizon, contacts, in_band, kSummaryRounds);
  auto line = [&](const char* name, double seconds) {
    const Score& s = g_scores[name];
    std::printf("  %-28s %9.3f us/pair  misclassified %4d (missed %d, false %d)  worst |dt|/h %.3g\n",
                name, seconds * 1e6, s.wrong, s.missed, s.false_alarms, s.worst_time_error);
  };
  const double ours_median = median(t_ours);
  line("ours", ours_median);
  line("secant_contact_scale", median(t_secant));
  line("fcl_naive_100_steps", median(t_fcl));
  line("sampling_overlap_100_steps", median(t_sampling));
  std::printf("  speed ratio: secant / ours = %.1fx, FCL / ours = %.1fx, sampling / ours = %.1fx\n",
              median(t_secant) / ours_median, median(t_fcl) / ours_median,
              median(t_sampling) / ours_median);
  // A smoke run keeps the rotating mix small too (its oracle scans 2000 samples per pair).
  compareRotation(cases.size() < 1000 ? 16 : 300, cases.size() < 1000 ? 12 : 60, min_seconds);
  const int per_depth = cases.size() < 1000 ? 1 : 4;
  compareTurningPasses(PassKind::kMotion, "Turning pairs (firstContact())", per_depth, min_seconds);
  compareTurningPasses(PassKind::kTwist, "Links on arcs under a twist (twistContact())", per_depth,
                       min_seconds);
  compareTurningPasses(PassKind::kSegment,
                       "Offset links along a turning path segment (segmentContact())", per_depth,
                       min_seconds);
  compareTurningPasses(PassKind::kNeedles,
                       "Two needles of axis ratio 1e8 turning at different rates (firstContact())",
                       per_depth, min_seconds);
  return 0;
}
