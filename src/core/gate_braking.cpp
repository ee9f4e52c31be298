#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/path_motion.h"
#include "gate_search.h"

// The velocity gate's braking rule (doc/velocity_gate.md, "Braking"): the base's motion under an
// output as a time warp of the command's arc (base_braking.h), the largest grid scale from which
// braking rests `margin` clear of every contact.
namespace ellipse_collision::core::detail {

GateContact Gate::describeBraking(const PairTime& p, const ScaleProfile& profile, double k) const {
  GateContact c = describe(p, k);
  if (!p.found) return c;
  c.point = contactPoint(
      linkAfter(scene_.links[p.link].ellipse, twist_, profile.sigmaAt(p.time)),
      movedBy(scene_.obstacles[p.obstacle].ellipse, scene_.obstacle_motions[p.obstacle], p.time));
  return c;
}

bool Gate::prepareBraking() {
  const Twist& v = twist_;
  const bool still_command = v.vx == 0.0 && v.vy == 0.0 && v.wz == 0.0;
  braking_ = !base_.dynamics.ideal() && !still_command;
  if (!braking_) return true;
  // The node's ranges (one home: findInvalidBaseDynamics()).
  if (const auto v = findInvalidBaseDynamics(base_.dynamics)) {
    result_.error = "base: " + violationText(*v);
    return false;
  }
  if (!(base_.command_period >= 0.0 && base_.command_period <= kMaxGateHorizonS)) {
    result_.error = "base: command_period = " + formatNumber(base_.command_period) +
                    " must be within [0, " + formatNumber(kMaxGateHorizonS) + "]";
    return false;
  }
  if (std::string r =
          invalidVelocityReason(Motion{{base_.velocity.vx, base_.velocity.vy}, base_.velocity.wz},
                                0.0, {"base.velocity.vx", "base.velocity.vy", "base.velocity.wz"});
      !r.empty()) {
    result_.error = r;
    return false;
  }
  // The base's velocity as a scale of the command: exact when it lies on the command's arc (the
  // gate's own output, a scaled command, or a measured velocity along it); otherwise the scale
  // of the part that runs fastest against the command's (the bend between the arcs is not
  // modelled, doc/velocity_gate.md).
  const Twist& now = base_.velocity;
  const double along =
      (now.vx * v.vx + now.vy * v.vy + now.wz * v.wz) / (v.vx * v.vx + v.vy * v.vy + v.wz * v.wz);
  const double off =
      std::hypot(now.vx - along * v.vx, now.vy - along * v.vy) + std::fabs(now.wz - along * v.wz);
  const double size =
      std::hypot(now.vx, now.vy) + std::fabs(now.wz) + std::hypot(v.vx, v.vy) + std::fabs(v.wz);
  if (along >= 0.0 && off <= 1e-9 * size) {
    from_scale_ = along;
  } else {
    const double linear = std::hypot(v.vx, v.vy);
    from_scale_ = std::max(linear > 0.0 ? std::hypot(now.vx, now.vy) / linear : 0.0,
                           v.wz != 0.0 ? std::fabs(now.wz) / std::fabs(v.wz) : 0.0);
  }
  shed_rate_ = brakingRate(v, base_.dynamics);
  double fastest = 0.0;  // the fastest link point under the full command [m/s]
  for (const NamedEllipse& link : scene_.links) {
    fastest = std::max(fastest, pointVelocity(v, link.ellipse.center).norm() +
                                    std::fabs(v.wz) * boundingRadius(link.ellipse));
  }
  margin_sigma_ = fastest > 0.0 ? settings_.margin / fastest : 0.0;
  const ScaleProfile widest = profileOf(std::max(1.0, from_scale_));
  sigma_horizon_ = std::max(settings_.horizon, widest.stopSigma() + margin_sigma_);
  time_horizon_ = std::max(settings_.horizon, widest.stopTime());
  early_ = detail::kRotationResolution * std::max(sigma_horizon_, time_horizon_);
  if (std::string r = invalidTwistReason(v, sigma_horizon_); !r.empty()) {
    result_.error = "braking: " + r;
    return false;
  }
  for (const NamedEllipse& link : scene_.links) {
    if (std::string r = detail::linkReachReason(link.ellipse, v, sigma_horizon_); !r.empty()) {
      result_.error = "braking: link '" + link.name + "': " + r;
      return false;
    }
  }
  return true;
}

PairTime Gate::brakingHit(const ScaleProfile& p, const PairTime& standing_first) {
  PairTime hit;
  // Standing obstacles: the base stays on the command's arc, so it meets the first one where its
  // twist-time reaches that contact's; it must rest `margin` of the fastest point's path short.
  if (standing_first.found && p.stopSigma() + margin_sigma_ >= standing_first.time) {
    hit = standing_first;
    hit.time = p.timeAtSigma(std::max(0.0, standing_first.time - margin_sigma_));
  }
  // Moving obstacles: certified first contact under the warped motion, `margin` short.
  const double until = hit.found ? hit.time : p.stopTime();
  for (const Candidate& c : candidates_) {
    if (c.overlapping || c.standing) continue;
    if (earliestPossible(c, p.maxScale(), early_) - settings_.margin > until) continue;
    ++result_.pair_tests;
    const FirstContact contact = brakingContact(
        scene_.links[c.link].ellipse, twist_, p, scene_.obstacles[c.obstacle].ellipse,
        scene_.obstacle_motions[c.obstacle], settings_.margin);
    keepEarlier(hit, c, contact);
  }
  return hit;
}

long Gate::brakingScale(long n, long top, const PairTime& standing_first, PairTime& hit) {
  if (standing_first.found && n > 0) {
    // Against standing obstacles the rest point moves on monotonically with the scale: bisect
    // for the largest grid scale that rests `margin` short, then check the moving ones downward.
    const auto rests = [&](long i) {
      return profileOf(gridScale(i, top)).stopSigma() + margin_sigma_ < standing_first.time;
    };
    if (!rests(n)) {
      long lo = 0, hi = n;  // rests(hi) false; lo unknown
      if (rests(0)) {
        while (hi - lo > 1) {
          const long mid = lo + (hi - lo) / 2;
          (rests(mid) ? lo : hi) = mid;
        }
      }
      n = lo;
    }
  }
  for (; n >= 0; --n) {
    hit = brakingHit(profileOf(gridScale(n, top)), standing_first);
    if (!hit.found) return n;
  }
  return -1;
}

BrakingOutcome Gate::brakingRule(double& k, long n, long top, const PairTime& standing_first,
                                 PairTime& limiting, double& limiting_scale) {
  BrakingOutcome outcome;
  const double horizon = settings_.horizon;
  // The braking rule below the contact rule's scale (its grid index n; n = 0 when it stopped).
  if (k == 0.0) n = 0;
  if (k == 1.0) n = top + 1;
  PairTime along = standing_first;  // twist-time at scale 1 is time at k = 1
  if (sigma_horizon_ > horizon && (!along.found || along.time > horizon)) {
    along = PairTime();
    keepEarliest(along, true, 1.0, sigma_horizon_);
  }
  const double linear = std::hypot(twist_.vx, twist_.vy);
  result_.free_distance =
      along.found ? linear * along.time : std::numeric_limits<double>::infinity();
  PairTime hit;
  const long kept = brakingScale(n, top, along, hit);
  const std::string model = " (reaction " + formatNumber(base_.dynamics.reaction_time) +
                            " s, then one command period " + readable(base_.command_period) +
                            " s, then braking at the limits)";
  if (kept < 0) {
    // Not even braking now ends clear: stop, and say how hard it meets what.
    const ScaleProfile now = profileOf(0.0);
    result_.unavoidable = true;
    result_.impact_speed = linear * now.scaleAt(hit.time);
    limiting = hit;
    limiting_scale = 0.0;
    outcome.limiting_profile = now;
    k = 0.0;
    outcome.braked = true;
    outcome.text = "; braking now cannot avoid it: " + pairText(describeBraking(hit, now, 0.0)) +
                   " within margin " + formatNumber(settings_.margin) + " m in " +
                   readable(hit.time) + " s at " + readable(result_.impact_speed) + " m/s" + model;
  } else if (kept < n) {
    const double lowered = gridScale(kept, top);
    const double above = gridScale(kept + 1, top);
    const ScaleProfile tried = profileOf(above);
    limiting = brakingHit(tried, along);
    limiting_scale = above;
    outcome.limiting_profile = tried;
    outcome.braked = true;
    outcome.text = "; braking rule: at " + readable(above) + " the base would need " +
                   readable(linear * tried.stopSigma()) + " m to rest" +
                   (limiting.found ? " and come within margin of " +
                                         pairText(describeBraking(limiting, tried, above))
                                   : std::string()) +
                   model;
    k = lowered;
  }
  result_.braking_distance = linear * profileOf(k).stopSigma();
  if (!outcome.braked) {
    outcome.text = "; braking from " + readable(k) + " ends in " +
                   readable(result_.braking_distance) + " m" + model;
  }
  return outcome;
}

}  // namespace ellipse_collision::core::detail
