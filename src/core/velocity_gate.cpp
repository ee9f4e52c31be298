#include "ellipse_collision/core/velocity_gate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <utility>

#include "ellipse_collision/core/base_braking.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/unique_names.h"
#include "gate_search.h"
#include "rotating_contact.h"
#include "twist_motion_detail.h"

namespace ellipse_collision::core {
namespace {

using detail::kReachWidening;

constexpr double kPi = 3.14159265358979323846;
// Witness points closer than this (relative to the radii) give no reliable direction: the pair is
// then treated as touching (contact-scale rule).
constexpr double kReliableGap = 1e-6;
// Touching or overlapping pairs are shrunk to this fraction of their contact scale: a gap of
// ~1e-4 of their size, where distance()'s witness direction is accurate to ~1e-10.
constexpr double kTouchShrink = 1.0 - 1e-4;
// A rate of the distance within this fraction of the speeds involved is rounding (a slide).
constexpr double kRateRounding = 1e-12;

/// Where `a` and `b` (apart, touching or overlapping) meet, and the unit normal from a to b.
struct Touch {
  bool found{false};
  Eigen::Vector2d point_a{0.0, 0.0};
  Eigen::Vector2d point_b{0.0, 0.0};
  Eigen::Vector2d normal{0.0, 0.0};
};

Touch touchOf(const Ellipse& a, const Ellipse& b, const Clearance& now) {
  const double size = boundingRadius(a) + boundingRadius(b);
  if (now.separated && now.distance > kReliableGap * size) {
    const Eigen::Vector2d gap = now.point_b - now.point_a;
    return {true, now.point_a, now.point_b, gap / gap.norm()};
  }
  // Perram-Wertheim: scaled about their centres by contactScale() the two touch; just below it
  // they are apart, and their witness points give the normal, and scaled back by kTouchShrink
  // about each centre, the contact point on each rim.
  const double scale = contactScale(a, b) * kTouchShrink;
  if (!(scale * inscribedRadius(a) >= kMinRadius && scale * inscribedRadius(b) >= kMinRadius)) {
    return {};  // concentric, or nearly: no direction
  }
  Ellipse sa = a, sb = b;
  sa.radius_x *= scale, sa.radius_y *= scale, sb.radius_x *= scale, sb.radius_y *= scale;
  const Clearance c = distance(sa, sb);
  const Eigen::Vector2d gap = c.point_b - c.point_a;
  const double length = gap.norm();
  if (!c.separated || !(length > 0.0)) return {};
  return {true, a.center + (c.point_a - a.center) / kTouchShrink,
          b.center + (c.point_b - b.center) / kTouchShrink, gap / length};
}

bool standing(const Ellipse& e, const Motion& m) {
  return m.velocity.x() == 0.0 && m.velocity.y() == 0.0 &&
         (m.angular_velocity == 0.0 || e.radius_x == e.radius_y);
}

/// Squared distance from `p` to the segment from `a` to `a + d`. NaN in, NaN out.
double segmentDistanceSquared(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                              const Eigen::Vector2d& d) {
  const Eigen::Vector2d w = p - a;
  const double dd = d.squaredNorm();
  double s = dd > 0.0 ? w.dot(d) / dd : 0.0;
  s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);  // NaN stays NaN
  return (w - s * d).squaredNorm();
}

/// `bound` widened against rounding of coordinates up to `coordinate` [m].
double widened(double bound, double coordinate) {
  return bound * (1.0 + kReachWidening) + 1e-12 * coordinate;
}

std::string settingsReason(const GateSettings& s) {
  const auto violation = findInvalidGateSettings(s);
  return violation ? detail::violationText(*violation) : std::string();
}

/// Everything gateTwist() checks on every call (no work per obstacle).
std::string cheapGateReason(const PathScene& scene, const Twist& twist, const GateSettings& s) {
  if (std::string r = settingsReason(s); !r.empty()) return "settings: " + r;
  if (std::string r = invalidTwistReason(twist, s.horizon); !r.empty()) return r;
  if (scene.obstacle_motions.size() != scene.obstacles.size()) {
    return "obstacle_motions has " + std::to_string(scene.obstacle_motions.size()) +
           " entries for " + std::to_string(scene.obstacles.size()) + " obstacles";
  }
  for (const NamedEllipse& link : scene.links) {
    if (std::string r = invalidReason(link.ellipse); !r.empty()) {
      return "link '" + link.name + "': " + r;
    }
    if (std::string r = detail::linkReachReason(link.ellipse, twist, s.horizon); !r.empty()) {
      return "link '" + link.name + "': " + r;
    }
  }
  return {};
}

std::string obstacleReason(const NamedEllipse& obstacle, const Motion& motion, double horizon) {
  if (std::string r = invalidMotionReason(obstacle.ellipse, motion, horizon); !r.empty()) {
    return "obstacle '" + obstacle.name + "': " + r;
  }
  return {};
}

}  // namespace

namespace detail {

/// A violation in the core's words: "stop_time = 2 must be within [0, 1.5] (at most
/// time_before_collision)".
std::string violationText(const GateSettingViolation& v) {
  return std::string(v.field) + " = " + formatNumber(v.value) + " must be within " +
         (v.min_excluded ? "(" : "[") + formatNumber(v.min) + ", " + formatNumber(v.max) + "]" +
         (v.max_field ? std::string(" (at most ") + v.max_field + ")" : std::string());
}

/// A computed time, distance or scale for a reason, to 4 significant digits ("0.42", not
/// "0.41999999999999"); given settings are quoted exactly with formatNumber().
std::string readable(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return formatNumber(std::strtod(text, nullptr));
}

Eigen::Vector2d contactPoint(const Ellipse& a, const Ellipse& b) {
  const Touch touch = touchOf(a, b, distance(a, b));
  if (touch.found) return 0.5 * (touch.point_a + touch.point_b);
  return 0.5 * (a.center + b.center);
}

GateContact Gate::describe(const PairTime& p, double k) const {
  GateContact c;
  if (!p.found) return c;
  c.found = true;
  c.link = scene_.links[p.link].name;
  c.obstacle = scene_.obstacles[p.obstacle].name;
  c.time = p.time;
  c.scale = k;
  c.point = contactPoint(
      linkAfter(scene_.links[p.link].ellipse, scaled(twist_, k), p.time),
      movedBy(scene_.obstacles[p.obstacle].ellipse, scene_.obstacle_motions[p.obstacle], p.time));
  return c;
}

bool Gate::findCandidates() {
  // Link l stays within |v_c| H + R_l of its centre at t = 0 under k twist for every k in [0, 1]:
  // its centre moves at the constant speed k |v_c| (the frame turns with it). Braking, H is the
  // twist-time the base covers before it rests; obstacles move for as long.
  const double horizon = sigma_horizon_;
  double robot_reach = 0.0;
  std::vector<double> reach(scene_.links.size()), speed(scene_.links.size());
  for (std::size_t l = 0; l < scene_.links.size(); ++l) {
    const Ellipse& e = scene_.links[l].ellipse;
    speed[l] = pointVelocity(twist_, e.center).norm();
    reach[l] = speed[l] * horizon + boundingRadius(e);
    robot_reach = std::max(robot_reach, e.center.norm() + reach[l]);
  }
  candidates_.clear();
  for (std::size_t o = 0; o < scene_.obstacles.size(); ++o) {
    const Ellipse& e = scene_.obstacles[o].ellipse;
    const Motion& m = scene_.obstacle_motions[o];
    const Eigen::Vector2d sweep = m.velocity * time_horizon_;
    const double grown = boundingRadius(e) + settings_.margin;
    const double coordinate = e.center.cwiseAbs().maxCoeff() + sweep.cwiseAbs().maxCoeff();
    const double bound = widened(robot_reach + grown, coordinate);
    // Not `<=`: a NaN obstacle is never skipped, and is refused below.
    if (segmentDistanceSquared(Eigen::Vector2d::Zero(), e.center, sweep) > bound * bound) continue;
    if (std::string r = obstacleReason(scene_.obstacles[o], m, time_horizon_); !r.empty()) {
      result_.error = r;
      return false;
    }
    const bool still = standing(e, m);
    for (std::size_t l = 0; l < scene_.links.size(); ++l) {
      const double pair_bound = widened(reach[l] + grown, coordinate);
      if (segmentDistanceSquared(scene_.links[l].ellipse.center, e.center, sweep) >
          pair_bound * pair_bound) {
        continue;
      }
      if (scene_.allowed.contains(scene_.links[l].name, scene_.obstacles[o].name)) continue;
      const Ellipse& link = scene_.links[l].ellipse;
      const double radii = boundingRadius(link) + boundingRadius(e);
      // Less the grazing band (5e-10 of the inscribed radii) and the rounding of coordinates.
      const double gap = (e.center - link.center).norm() - radii -
                         kReachWidening * (radii + link.center.cwiseAbs().maxCoeff() +
                                           e.center.cwiseAbs().maxCoeff());
      candidates_.push_back({l, o, still, false, gap, speed[l], m.velocity.norm()});
    }
  }
  return true;
}

void Gate::measureClearance(std::vector<ClosePair>& close) {
  double best = std::numeric_limits<double>::infinity();
  for (Candidate& c : candidates_) {
    const Ellipse& link = scene_.links[c.link].ellipse;
    const Ellipse& obstacle = scene_.obstacles[c.obstacle].ellipse;
    // The bounding circles' gap is a lower bound of the distance: a pair neither close nor nearer
    // than the best so far needs no distance() call.
    if (c.gap >= settings_.margin && c.gap > best) continue;
    ++result_.pair_tests;
    const Clearance now = distance(link, obstacle);
    c.overlapping = !now.separated;
    if (now.distance < best || !result_.has_clearance) {
      best = now.distance;
      result_.has_clearance = true;
      result_.clearance = now.distance;
      result_.clearance_link = scene_.links[c.link].name;
      result_.clearance_obstacle = scene_.obstacles[c.obstacle].name;
    }
    if (c.overlapping || now.distance < settings_.margin) close.push_back({c, now});
  }
}

bool Gate::pushesIn(const std::vector<ClosePair>& close) {
  for (const auto& [c, now] : close) {
    const Ellipse& link = scene_.links[c.link].ellipse;
    const Ellipse& obstacle = scene_.obstacles[c.obstacle].ellipse;
    const Touch touch = touchOf(link, obstacle, now);
    const Eigen::Vector2d velocity = pointVelocity(twist_, touch.point_a);
    // The distance's rate at t = 0 from the robot's motion alone is -n . velocity (the envelope
    // theorem on the support-function dual, distance.h); a slide along the rim is rate 0.
    const double closing = touch.normal.dot(velocity);
    const double rounding = kRateRounding * (Eigen::Vector2d(twist_.vx, twist_.vy).norm() +
                                             std::fabs(twist_.wz) * touch.point_a.norm());
    const bool still = twist_.vx == 0.0 && twist_.vy == 0.0 && twist_.wz == 0.0;
    if ((touch.found && closing <= rounding) || still) continue;
    result_.limiting.found = true;
    result_.limiting.link = scene_.links[c.link].name;
    result_.limiting.obstacle = scene_.obstacles[c.obstacle].name;
    result_.limiting.time = 0.0;
    result_.limiting.scale = 1.0;
    result_.limiting.point =
        touch.found ? Eigen::Vector2d(0.5 * (touch.point_a + touch.point_b)) : link.center;
    result_.action = GateAction::Stop;
    result_.scale = 0.0;
    result_.reason = "pushes into '" + result_.limiting.obstacle + "': link '" +
                     result_.limiting.link + "' " +
                     (c.overlapping ? std::string("overlaps it")
                                    : "is " + readable(now.distance) + " m from it") +
                     (touch.found ? " and the command closes in at " + readable(closing) + " m/s"
                                  : " with no direction to judge the command by");
    return true;
  }
  return false;
}

void Gate::scaleRule(bool escaping) {
  const double horizon = settings_.horizon;
  const double before = settings_.time_before_collision;
  const double res = settings_.resolution;
  // The first contact of every pair at k = 1 over the horizon: `standing_first`, the earliest
  // standing pair's; `moving_first`, the earliest moving pair's when it comes no later than
  // `standing_first` (only then can it decide: after a standing contact before T_b the moving
  // search runs whatever it is, and otherwise one after `standing_first` is not before T_b);
  // `first`, the earlier of the two.
  PairTime standing_first, moving_first;
  std::size_t moving_count = 0;
  for (const Candidate& c : candidates_) moving_count += !c.overlapping && !c.standing;
  keepEarliest(standing_first, true, 1.0, horizon);
  if (moving_count > 0) {
    keepEarliest(moving_first, false, 1.0, standing_first.found ? standing_first.time : horizon);
  }
  PairTime first = standing_first;
  keepEarlier(first, moving_first);
  // The grid: k_n = n res for n = 0 .. top, and 1 (top_n: the largest n with n res < 1).
  const long top = static_cast<long>(std::ceil(1.0 / res)) - 1;  // n res < 1 for n <= top
  double k = 1.0;
  long n = top + 1;
  PairTime limiting = first;
  double limiting_scale = 1.0;
  std::string why;
  if (first.found && first.time <= settings_.stop_time) {
    k = 0.0;
    why = " within stop_time " + formatNumber(settings_.stop_time) + " s";
  } else {
    if (standing_first.found && standing_first.time < before) {
      // The largest grid k with t_s / k >= T_b, from below t_s / T_b (rounded down).
      n = std::min(top, static_cast<long>(std::floor(standing_first.time / before / res)));
      while (n > 0 && standing_first.time / (n * res) < before) --n;
      k = gridScale(n, top);
      limiting = standing_first;
    }
    if (moving_count > 0 && k == 1.0 && moving_first.found && moving_first.time < before) {
      // k = 1 was judged over the horizon already: the search starts below it. A standing
      // command is the same at every scale: nothing to search.
      limiting = moving_first;
      const bool still_command = twist_.vx == 0.0 && twist_.vy == 0.0 && twist_.wz == 0.0;
      n = still_command ? 0 : top;
      k = gridScale(n, top);
    }
    if (moving_count > 0 && k > 0.0 && k < 1.0) {
      // Searched down the grid: under k twist a moving obstacle may arrive sooner or later. Only
      // the moving pairs that may touch before T_b at k = 1 are looked at: a smaller k only puts
      // off the bound (earliestPossible() grows as k falls). Which pair rules a k out does not
      // change the k taken: they go soonest bound first, and a pair that fails moves to the
      // front, since it most likely fails the next k too.
      std::vector<std::pair<double, const Candidate*>> near;
      for (const Candidate& c : candidates_) {
        if (c.overlapping || c.standing) continue;
        const double bound = earliestPossible(c, 1.0, early_);
        if (bound < before) near.emplace_back(bound, &c);
      }
      std::sort(near.begin(), near.end(), [](const auto& a, const auto& b) {
        return a.first < b.first || (a.first == b.first && a.second < b.second);
      });
      for (; n > 0; --n) {
        k = gridScale(n, top);
        const Twist command = scaled(twist_, k);
        const auto fails = [&](const Candidate& c) {
          if (earliestPossible(c, k, early_) >= before)
            return false;  // no contact reported before T_b
          const FirstContact contact = contactOf(c, command, before, before);
          if (!contact.contact || contact.time >= before) return false;
          limiting = {true, contact.time, c.link, c.obstacle};
          limiting_scale = k;
          return true;
        };
        const auto failing =
            std::find_if(near.begin(), near.end(), [&](const auto& p) { return fails(*p.second); });
        if (failing == near.end()) break;
        std::rotate(near.begin(), failing, failing + 1);
      }
      if (n == 0) k = 0.0;
    }
  }
  // The braking rule (a base that is not ideal) may lower the scale further: gate_braking.cpp.
  const BrakingOutcome braking =
      braking_ ? brakingRule(k, n, top, standing_first, limiting, limiting_scale)
               : BrakingOutcome();
  const std::string& braking_text = braking.text;
  const bool braked = braking.braked;
  const std::optional<ScaleProfile>& limiting_profile = braking.limiting_profile;
  result_.scale = k;
  result_.limiting = limiting_profile ? describeBraking(limiting, *limiting_profile, limiting_scale)
                                      : describe(limiting, limiting_scale);
  // The first contact under the output command over the horizon.
  PairTime output;
  if (k == 1.0) {
    output = first;
  } else {
    if (k > 0.0 && standing_first.found && standing_first.time <= k * horizon) {
      output = {true, standing_first.time / k, standing_first.link, standing_first.obstacle};
    }
    if (moving_count > 0) keepEarliest(output, false, k, horizon);
  }
  result_.contact = describe(output, k);

  // The action and its reason.
  const GateContact& lim = result_.limiting;
  std::string text;
  if (escaping) {
    text = "moves every close pair apart (nearest: link '" + result_.clearance_link + "' " +
           readable(result_.clearance) + " m from '" + result_.clearance_obstacle + "'); ";
  }
  const std::string under_full =
      first.found
          ? "contact of " + pairText(describe(first, 1.0)) + " in " + readable(first.time) +
                " s under the full command"
          : "no contact within horizon " + formatNumber(horizon) + " s under the full command";
  if (k == 1.0) {
    result_.action = escaping ? GateAction::Escape : GateAction::Pass;
    text += under_full +
            (first.found ? ", no sooner than time_before_collision " + formatNumber(before) + " s"
                         : std::string());
  } else if (k > 0.0) {
    result_.action = escaping ? GateAction::Escape : GateAction::Slow;
    text +=
        under_full + "; slowed to " + readable(k) + (braked ? " by the braking rule" : " so that ");
    if (!braked)
      text += limiting_scale < 1.0
                  ? "no moving obstacle comes sooner than time_before_collision " +
                        formatNumber(before) + " s (at " + readable(lim.scale) + ", " +
                        pairText(lim) + " in " + readable(lim.time) + " s)"
                  : "it comes no sooner than time_before_collision " + formatNumber(before) + " s";
  } else {
    result_.action = GateAction::Stop;
    text += under_full;
    if (!braked)
      text += !why.empty() ? why
                           : "; no scale above 0 on the " + formatNumber(res) +
                                 " grid keeps every contact beyond time_before_collision " +
                                 formatNumber(before) + " s";
  }
  if (k == 0.0 && result_.contact.found) {
    text += "; standing still, '" + result_.contact.obstacle + "' reaches link '" +
            result_.contact.link + "' in " + readable(result_.contact.time) +
            " s (stopping cannot avoid it)";
  }
  result_.reason = std::move(text) + braking_text;
}

/// Keeps in `best` the earliest of it and the first contacts over the horizon under k twist of the
/// pairs not overlapping now that are standing (or moving), as keepEarlier() would over all of
/// them, but only up to `until` [s] (<= horizon). A pair is searched only up to the earliest
/// contact kept so far (twistContactUntil(): the same time when it comes no later) and not at
/// all when earliestPossible() is later; pairs go in order of that bound (buckets of
/// 1/kBoundBuckets of the window), so that the earliest contacts come first and cut the rest.
void Gate::keepEarliest(PairTime& best, bool standing, double k, double until) {
  constexpr std::size_t kBoundBuckets = 64;
  const double horizon = std::max(settings_.horizon, until);
  const Twist command = scaled(twist_, k);
  const double window = best.found ? std::min(best.time, until) : until;
  bounds_.resize(candidates_.size());
  bucket_starts_.assign(kBoundBuckets + 1, 0);
  const auto bucketOf = [&](double bound) {  // bound <= window
    const double share = bound / window;     // NaN for 0 / 0
    return share < 1.0 ? static_cast<std::size_t>(share * static_cast<double>(kBoundBuckets))
                       : kBoundBuckets - 1;
  };
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const Candidate& c = candidates_[i];
    const bool wanted = !c.overlapping && c.standing == standing;
    bounds_[i] = wanted ? earliestPossible(c, k, early_) : std::numeric_limits<double>::infinity();
    if (bounds_[i] <= window) ++bucket_starts_[bucketOf(bounds_[i]) + 1];
  }
  for (std::size_t b = 0; b < kBoundBuckets; ++b) bucket_starts_[b + 1] += bucket_starts_[b];
  order_.resize(bucket_starts_[kBoundBuckets]);
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    if (bounds_[i] <= window) order_[bucket_starts_[bucketOf(bounds_[i])]++] = i;
  }
  for (const std::size_t i : order_) {
    const double limit = best.found ? std::min(best.time, until) : until;
    if (bounds_[i] > limit) continue;
    const Candidate& c = candidates_[i];
    keepEarlier(best, c, contactOf(c, command, horizon, limit));
  }
}

void Gate::run() {
  if (!prepareBraking()) return;
  if (!findCandidates()) return;
  std::vector<ClosePair> close;
  measureClearance(close);
  if (!close.empty() && pushesIn(close)) return;
  scaleRule(!close.empty());
}

}  // namespace detail

namespace {

std::optional<GateSettingViolation> outsideRange(const char* field, double value, double min,
                                                 double max, bool min_excluded = false,
                                                 const char* max_field = nullptr) {
  const bool above_min = min_excluded ? value > min : value >= min;
  if (above_min && value <= max) return std::nullopt;  // NaN is within no range
  return GateSettingViolation{field, value, min, max, min_excluded, max_field};
}

}  // namespace

std::optional<GateSettingViolation> findInvalidBaseDynamics(const BaseDynamics& d) {
  if (auto v = outsideRange("reaction_time", d.reaction_time, 0.0, kMaxReactionTimeS)) return v;
  if (auto v =
          outsideRange("max_linear_deceleration", d.linear_deceleration, 0.0, kMaxDeceleration)) {
    return v;
  }
  return outsideRange("max_angular_deceleration", d.angular_deceleration, 0.0, kMaxDeceleration);
}

std::optional<GateSettingViolation> findInvalidGateSettings(const GateSettings& s) {
  if (auto v = outsideRange("horizon", s.horizon, 0.0, kMaxGateHorizonS, true)) return v;
  if (auto v = outsideRange("time_before_collision", s.time_before_collision, 0.0, s.horizon, false,
                            "horizon")) {
    return v;
  }
  if (auto v = outsideRange("stop_time", s.stop_time, 0.0, s.time_before_collision, false,
                            "time_before_collision")) {
    return v;
  }
  if (auto v = outsideRange("margin", s.margin, 0.0, kMaxRadius)) return v;
  return outsideRange("resolution", s.resolution, kMinGateResolution, 1.0);
}

std::string invalidGateReason(const PathScene& scene, const Twist& twist,
                              const GateSettings& settings) {
  if (std::string r = cheapGateReason(scene, twist, settings); !r.empty()) return r;
  const auto names = [](const std::vector<NamedEllipse>& entries, const char* role) -> std::string {
    const auto problem = findNameProblem(
        entries.size(), [&](std::size_t i) -> const std::string& { return entries[i].name; });
    if (!problem) return {};
    if (problem->kind == NameProblem::Kind::Empty) {
      return std::string(role) + " " + std::to_string(problem->index) + ": empty name";
    }
    return std::string(role) + " " + std::to_string(problem->index) + ": name '" +
           entries[problem->index].name + "' repeats " + role + " " +
           std::to_string(problem->first_index);
  };
  if (std::string r = names(scene.links, "link"); !r.empty()) return r;
  if (std::string r = names(scene.obstacles, "obstacle"); !r.empty()) return r;
  for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
    if (std::string r =
            obstacleReason(scene.obstacles[o], scene.obstacle_motions[o], settings.horizon);
        !r.empty()) {
      return r;
    }
  }
  return {};
}

GateResult gateTwist(const PathScene& scene, const Twist& twist, const GateSettings& settings,
                     const BaseState& base) {
  GateResult result;
  if (std::string r = cheapGateReason(scene, twist, settings); !r.empty()) {
    result.error = std::move(r);
    result.reason = "cannot judge the command: " + result.error;
    return result;
  }
  detail::Gate(scene, twist, settings, base, result).run();
  if (!result.ok()) {
    result.action = GateAction::Stop;
    result.scale = 0.0;
    result.reason = "cannot judge the command: " + result.error;
  }
  return result;
}

}  // namespace ellipse_collision::core
