#pragma once

// One tally of first-contact answers on grazing passes (grazing_passes.h) against the quad
// oracle, and the loop that draws and checks them, shared by test_first_contact,
// test_velocity_gate and test_path_check (which see src/core's rotating_contact.h).
#include <gtest/gtest.h>
#include <quadmath.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "ellipse_collision/core/first_contact.h"
#include "grazing_passes.h"
#include "random_source.h"
#include "rotating_contact.h"

namespace ellipse_collision::core::test {

/// Passes clear by at most this much (of the contact scale) may be reported in contact: the
/// band around grazing of firstContact()'s contract.
inline constexpr double kGrazingBand = 1e-9;
/// Answers may be this much earlier than the oracle's first contact [horizon] ...
inline constexpr double kGrazingEarly = 1e-9;
/// ... and this much later (rounding of the times and poses, not a margin) [horizon].
inline constexpr double kGrazingLate = 1e-12;

/// The answers of one family on grazing passes, against the oracle: a touching pass is found
/// no later than kGrazingLate and no earlier than kGrazingEarly of the horizon from its first
/// contact; a clear one is clear, or (within kGrazingBand) reported in contact.
class GrazingTally {
 public:
  explicit GrazingTally(const char* family) : family_(family) {}
  ~GrazingTally() {
    std::printf(
        "[grazing] %-34s passes %3d (contact %3d), wrong %d, clear reported in contact "
        "%d (within the band), worst early %.3g, worst late %.3g (of the horizon), "
        "distance() calls %.1f mean, %d at most, at the cap %d\n",
        family_, passes_, contacts_, wrong_, conservative_, worst_early_, worst_late_,
        passes_ > 0 ? static_cast<double>(total_calls_) / passes_ : 0.0, most_calls_, capped_);
  }

  void check(const FirstContact& got, const OracleGrazingPass& pass, double depth, double horizon,
             const std::string& what) {
    ++passes_;
    if (!pass.contact) {
      if (!got.contact) return;
      if (depth <= kGrazingBand) {
        ++conservative_;
        return;
      }
      ++wrong_;
      ADD_FAILURE() << "contact at " << got.time << " for a pass clear by " << depth << ": "
                    << what;
      return;
    }
    ++contacts_;
    if (!got.contact) {
      ++wrong_;
      ADD_FAILURE() << "clear for a pass " << depth << " deep: " << what;
      return;
    }
    const double error =
        static_cast<double>((static_cast<__float128>(got.time) - pass.contact_time) / horizon);
    worst_late_ = std::max(worst_late_, error);
    worst_early_ = std::max(worst_early_, -error);
    EXPECT_LE(error, kGrazingLate) << "late, " << depth << " deep: " << what;
    EXPECT_GE(error, -kGrazingEarly) << "early, " << depth << " deep: " << what;
  }
  /// The work of the rotating path on the same pass: no call may reach the step cap.
  void work(int distance_calls, bool capped, const std::string& what) {
    most_calls_ = std::max(most_calls_, distance_calls);
    total_calls_ += distance_calls;
    capped_ += capped;
    EXPECT_FALSE(capped) << "step cap reached: " << what;
  }
  int passes() const { return passes_; }
  int wrong() const { return wrong_; }

 private:
  const char* family_;
  int passes_ = 0, contacts_ = 0, wrong_ = 0, conservative_ = 0, most_calls_ = 0, capped_ = 0;
  long total_calls_ = 0;
  double worst_early_ = 0.0, worst_late_ = 0.0;
};

/// Draws `count` passes with `draw(rng, target, &pass)` (grazing_passes.h) at kGrazingDepths in
/// turn, touching and clear alternately by threes, and checks each: `answer(pass)`, the public
/// call, against the oracle, and `direct(pass, &work)`, the rotating path on the same pass, for
/// the same verdict and its work.
template <class Draw, class Answer, class Direct>
void checkGrazingPasses(GrazingTally& tally, ellipse_collision::test::RandomSource& rng, Draw draw,
                        Answer answer, Direct direct, int count = 90) {
  for (int tries = 0; tally.passes() < count && tries < 3000; ++tries) {
    const int k = tally.passes();
    const double depth = kGrazingDepths[k % 3];
    const bool touching = (k / 3) % 2;
    TurningPass p;
    if (!draw(rng, touching ? 1.0 - depth : 1.0 + depth, &p)) continue;
    const FirstContact got = answer(p);
    tally.check(got, p.pass, depth, p.horizon, p.text);
    detail::RotationWork work;
    EXPECT_EQ(direct(p, &work).contact, got.contact) << p.text;
    tally.work(work.distance_calls, work.capped, p.text);
  }
  EXPECT_EQ(tally.passes(), count);
  EXPECT_EQ(tally.wrong(), 0);
}

}  // namespace ellipse_collision::core::test
