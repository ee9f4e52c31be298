#pragma once

// The velocity gate's search (gateTwist()), shared by its two files: velocity_gate.cpp (the
// candidates, the escape rule, the contact rule) and gate_braking.cpp (the braking rule).
#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/core/base_braking.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/velocity_gate.h"
#include "twist_motion_detail.h"

namespace ellipse_collision::core::detail {

// Relative widening of the broadphase's bounds: far above their rounding, far below any size.
constexpr double kReachWidening = 1e-9;

/// A computed time, distance or scale for a reason, to 4 significant digits ("0.42", not
/// "0.41999999999999"); given settings are quoted exactly with formatNumber().
std::string readable(double value);

/// A settings violation in the core's words: "stop_time = 2 must be within [0, 1.5] (at most
/// time_before_collision)".
std::string violationText(const GateSettingViolation& v);

/// Velocity of the robot-fixed point `p` (in the robot frame at t = 0) at t = 0: v + wz z x p.
inline Eigen::Vector2d pointVelocity(const Twist& twist, const Eigen::Vector2d& p) {
  return {twist.vx - twist.wz * p.y(), twist.vy + twist.wz * p.x()};
}

/// Where `a` and `b` (apart, touching or overlapping) meet: the midpoint of their witness points.
Eigen::Vector2d contactPoint(const Ellipse& a, const Ellipse& b);

// ---- the gate ---------------------------------------------------------------------------------

struct Candidate {
  std::size_t link{0};
  std::size_t obstacle{0};
  bool standing{true};
  bool overlapping{false};  // now: excluded from the contact rule (escape rule instead)
  /// The gap between the bounding circles now, less twistContact()'s grazing band and rounding
  /// [m]: a lower bound of distance() now, and of the distance at which a contact is reported in
  /// the grazing band (earliestPossible()).
  double gap{0.0};
  double link_speed{0.0};      ///< |v_c|, the link centre's speed under the full command [m/s]
  double obstacle_speed{0.0};  ///< |v_o| [m/s]
};

/// No contact of the pair under k twist is reported before this time [s]: the bounding circles
/// (which hold the ellipses whatever their turn) close at most at k |v_c| + |v_o| (the link centre
/// moves at the constant speed k |v_c|, the obstacle's at |v_o|), so the pair touches no sooner
/// than gap / that speed. twistContact() reports a contact either at a distance within its grazing
/// band, which `gap` has taken off, or at most one resolution (detail::kRotationResolution of the
/// horizon of the call) before the first contact, which `early` (that of the gate's horizon, the
/// longest any call has) takes off; an exact translation's early rounding is within the rounding
/// allowance of `gap`. (The one exception would be a pair stopped at the safety cap on the steps,
/// which no test or benchmark reaches, whose claimed time may be earlier: it is then late only
/// against that claim, never against the motion.)
inline double earliestPossible(const Candidate& c, double k, double early) {
  if (!(c.gap > 0.0)) return 0.0;
  const double speed = (k * c.link_speed + c.obstacle_speed) * (1.0 + kReachWidening);
  return speed > 0.0 ? std::max(0.0, c.gap / speed - early)
                     : std::numeric_limits<double>::infinity();
}

struct ClosePair {
  Candidate pair;
  Clearance now;
};

/// What the braking rule did to the contact rule's scale: why (appended to the reason), whether it
/// lowered it, and the braking motion under which the limiting contact was met.
struct BrakingOutcome {
  std::string text;
  bool braked{false};
  std::optional<ScaleProfile> limiting_profile;
};

struct PairTime {
  bool found{false};
  double time{0.0};
  std::size_t link{0};
  std::size_t obstacle{0};
};

class Gate {
 public:
  Gate(const PathScene& scene, const Twist& twist, const GateSettings& settings,
       const BaseState& base, GateResult& result)
      : scene_(scene),
        twist_(twist),
        settings_(settings),
        base_(base),
        result_(result),
        early_(detail::kRotationResolution * settings.horizon),
        sigma_horizon_(settings.horizon),
        time_horizon_(settings.horizon) {}

  void run();

 private:
  bool findCandidates();
  void measureClearance(std::vector<ClosePair>& close);
  bool pushesIn(const std::vector<ClosePair>& close);
  /// The contact rule: the scale on the grid, the action and its reason (pairs close now that
  /// the command moves apart make it Escape).
  void scaleRule(bool escaping);
  void keepEarliest(PairTime& best, bool standing, double k, double until);
  /// The braking model of the command (off for an ideal base or a standing command): the base's
  /// scale along the command now, the rate it sheds it, the windows it needs. False on an error.
  bool prepareBraking();
  /// Scale n of the grid {0, res, 2 res, ..., top res, 1}: 1 above top.
  double gridScale(long n, long top) const { return n > top ? 1.0 : n * settings_.resolution; }
  ScaleProfile profileOf(double k) const {
    return ScaleProfile(from_scale_, k, base_.dynamics.reaction_time, base_.command_period,
                        shed_rate_);
  }
  /// The braking rule on grid scale `n` down from the contact rule's: the largest scale whose
  /// braking ends `margin` clear of every contact; -1 when not even 0 does (then `hit` is the
  /// contact braking now meets). `standing_first` is the standing pairs' first contact along the
  /// arc at scale 1 (its time is twist-time).
  long brakingScale(long n, long top, const PairTime& standing_first, PairTime& hit);
  /// The braking rule on the contact rule's scale k (grid index n of top): lowers k, and the
  /// limiting contact, where braking from it would not rest `margin` clear (gate_braking.cpp).
  BrakingOutcome brakingRule(double& k, long n, long top, const PairTime& standing_first,
                             PairTime& limiting, double& limiting_scale);
  /// Where braking under profile `p` first meets an obstacle, `margin` short (none: found false).
  PairTime brakingHit(const ScaleProfile& p, const PairTime& standing_first);

  /// twistContact() over `horizon`, reported only when at or before `until` (<= horizon).
  FirstContact contactOf(const Candidate& c, const Twist& twist, double horizon, double until) {
    ++result_.pair_tests;
    return detail::twistContactUntil(scene_.links[c.link].ellipse, twist,
                                     scene_.obstacles[c.obstacle].ellipse,
                                     scene_.obstacle_motions[c.obstacle], horizon, until);
  }
  /// Keeps the earlier of `best` and `p`; ties to the smaller link, then obstacle name.
  void keepEarlier(PairTime& best, const PairTime& p) const {
    if (!p.found) return;
    if (best.found) {
      if (p.time > best.time) return;
      if (p.time == best.time) {
        const std::string& link = scene_.links[p.link].name;
        const std::string& best_link = scene_.links[best.link].name;
        if (link > best_link) return;
        if (link == best_link &&
            scene_.obstacles[p.obstacle].name >= scene_.obstacles[best.obstacle].name) {
          return;
        }
      }
    }
    best = p;
  }
  void keepEarlier(PairTime& best, const Candidate& c, const FirstContact& contact) const {
    keepEarlier(best, {contact.contact, contact.time, c.link, c.obstacle});
  }
  GateContact describe(const PairTime& p, double k) const;
  /// describe() for a contact met braking under profile `p` (the link where p puts it then).
  GateContact describeBraking(const PairTime& p, const ScaleProfile& profile, double k) const;
  std::string pairText(const GateContact& c) const {
    return "link '" + c.link + "' with '" + c.obstacle + "'";
  }

  const PathScene& scene_;
  const Twist& twist_;
  const GateSettings& settings_;
  const BaseState& base_;
  GateResult& result_;
  /// How much earlier than its first contact a pair's reported contact may come [s].
  double early_;
  /// The braking model (prepareBraking()).
  bool braking_{false};
  double from_scale_{0.0};    ///< the base's velocity now as a scale of the command
  double shed_rate_{0.0};     ///< [1/s]
  double margin_sigma_{0.0};  ///< `margin` as twist-time of the command's fastest link point [s]
  double sigma_horizon_;      ///< twist-time the links may cover (the horizon, or braking's reach)
  double time_horizon_;       ///< time obstacles may move for [s]
  std::vector<Candidate> candidates_;
  // keepEarliest()'s work space: bounds per candidate, candidates grouped by bound.
  std::vector<double> bounds_;
  std::vector<std::size_t> order_;
  std::vector<std::size_t> bucket_starts_;
};

}  // namespace ellipse_collision::core::detail
