#include "ellipse_collision/app/obstacle_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"

namespace ellipse_collision::app {

std::optional<FieldError> findInvalidSetting(const TrackingSettings& s) {
  if (s.fixed_frame.empty() || s.fixed_frame.front() == '/') {
    return FieldError{"tracking/fixed_frame", "a tf2 frame id, non-empty, without a leading '/'",
                      "'" + s.fixed_frame + "'"};
  }
  if (auto e = findOutsideRange("tracking/max_speed", s.max_speed, 0.0, core::kMaxSpeed, true)) {
    return e;
  }
  if (auto e = findOutsideRange("tracking/max_size", s.max_size, 0.0, core::kMaxRadius, true)) {
    return e;
  }
  if (auto e = findOutsideRange("tracking/confirm_count", s.confirm_count, 2, 1000)) return e;
  if (auto e = findOutsideRange("tracking/min_speed", s.min_speed, 0.0, s.max_speed)) return e;
  if (auto e = findOutsideRange("tracking/position_sigma", s.position_sigma, 0.0, 1.0, true)) {
    return e;
  }
  return std::nullopt;
}

ObstacleTracker::Fit ObstacleTracker::fit(const Track& track) const {
  Fit result;
  const std::size_t n = track.samples.size();
  if (n < 2) {
    result.sigma = std::numeric_limits<double>::infinity();
    return result;
  }
  double mean_t = 0.0;
  Eigen::Vector2d mean_p(0.0, 0.0);
  for (const Sample& s : track.samples) mean_t += s.t, mean_p += s.centre;
  mean_t /= n;
  mean_p /= static_cast<double>(n);
  double stt = 0.0;
  Eigen::Vector2d stp(0.0, 0.0);
  for (const Sample& s : track.samples) {
    stt += (s.t - mean_t) * (s.t - mean_t);
    stp += (s.t - mean_t) * (s.centre - mean_p);
  }
  if (!(stt > 0.0)) {
    result.sigma = std::numeric_limits<double>::infinity();
    return result;
  }
  result.velocity = stp / stt;
  // The centres' spread about the line (2 parameters per axis), never below the stated noise:
  // a few centres that happen to line up do not make a sure velocity.
  double residual = 0.0;
  for (const Sample& s : track.samples) {
    residual += (s.centre - mean_p - (s.t - mean_t) * result.velocity).squaredNorm();
  }
  double variance = settings_.position_sigma * settings_.position_sigma;
  if (n > 2) variance = std::max(variance, residual / (2.0 * (n - 2)));
  result.sigma = std::sqrt(variance / stt);
  return result;
}

bool ObstacleTracker::trackable(const SensorObject& object) const {
  return object.extent <= settings_.max_size && !object.occluded;
}

Eigen::Vector2d ObstacleTracker::reportedVelocity(const Track& track, const Fit& f,
                                                  double drift) const {
  const double speed = f.velocity.norm();
  if (track.updates < settings_.confirm_count || speed < settings_.min_speed ||
      !(speed > 3.0 * f.sigma + drift)) {
    return Eigen::Vector2d::Zero();
  }
  return f.velocity;
}

void standStill(SensorObstacles& obstacles) {
  for (EllipseSpec& o : obstacles.ellipses) o.vx = o.vy = o.angular_velocity = 0.0;
}

void ObstacleTracker::keepWindow(std::vector<Sample>& samples, double stamp_s) {
  samples.erase(samples.begin(), std::find_if(samples.begin(), samples.end(), [&](const Sample& x) {
                  return stamp_s - x.t <= kWindowS;
                }));
}

void ObstacleTracker::track(double stamp_s, const core::PathPose& sensor,
                            SensorObstacles& obstacles) {
  standStill(obstacles);
  if (!settings_.enabled) return;
  if (last_stamp_s_ && !(stamp_s > *last_stamp_s_)) tracks_.clear(), sensor_.clear();
  last_stamp_s_ = stamp_s;

  const double c = std::cos(sensor.yaw), s = std::sin(sensor.yaw);
  // The sensor's velocity over the window, for the view's drift.
  const Eigen::Vector2d sensor_at(sensor.x, sensor.y);
  sensor_.push_back({stamp_s, sensor_at});
  keepWindow(sensor_, stamp_s);
  const Eigen::Vector2d sensor_velocity =
      sensor_.size() < 2
          ? Eigen::Vector2d(0.0, 0.0)
          : Eigen::Vector2d((sensor_at - sensor_.front().centre) / (stamp_s - sensor_.front().t));
  std::vector<Track> known = std::move(tracks_);
  tracks_.clear();
  // Tracks not seen for kMaxUnseenS are gone.
  known.erase(
      std::remove_if(known.begin(), known.end(),
                     [&](const Track& t) { return stamp_s - t.samples.back().t > kMaxUnseenS; }),
      known.end());
  std::vector<Eigen::Vector2d> predicted(known.size());
  std::vector<double> gate(known.size());
  for (std::size_t t = 0; t < known.size(); ++t) {
    const Sample& last = known[t].samples.back();
    predicted[t] = last.centre + (stamp_s - last.t) * fit(known[t]).velocity;
    gate[t] = settings_.max_speed * (stamp_s - last.t) + kAssociationSlack;
  }
  // Candidate pairs within their gate, nearest first; each track and object used once.
  const std::vector<SensorObject>& objects = obstacles.objects;
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  std::vector<Eigen::Vector2d> centres(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Eigen::Vector2d& p = objects[i].centroid;
    centres[i] =
        Eigen::Vector2d(sensor.x + c * p.x() - s * p.y(), sensor.y + s * p.x() + c * p.y());
    if (!trackable(objects[i])) continue;
    for (std::size_t t = 0; t < known.size(); ++t) {
      const double d = (centres[i] - predicted[t]).norm();
      if (d <= gate[t]) pairs.emplace_back(d, t, i);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<char> track_used(known.size(), 0);
  std::vector<int> track_of(objects.size(), -1);
  for (const auto& [d, t, i] : pairs) {
    if (track_used[t] || track_of[i] >= 0) continue;
    track_used[t] = 1;
    track_of[i] = static_cast<int>(t);
  }
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (!trackable(objects[i])) continue;
    Track track;
    if (track_of[i] >= 0) track = std::move(known[static_cast<std::size_t>(track_of[i])]);
    track.samples.push_back({stamp_s, centres[i]});
    ++track.updates;
    keepWindow(track.samples, stamp_s);
    // The direction the object is seen from turns at |v_sensor x d| / |d|^2.
    const Eigen::Vector2d d = centres[i] - sensor_at;
    const double turn = std::abs(sensor_velocity.x() * d.y() - sensor_velocity.y() * d.x()) /
                        std::max(d.squaredNorm(), 1e-12);
    const Eigen::Vector2d v = reportedVelocity(track, fit(track), objects[i].extent * turn);
    for (const std::size_t e : objects[i].ellipses) {
      // Into the sensor frame's axes (the node turns it back by the frame's orientation).
      obstacles.ellipses[e].vx = c * v.x() + s * v.y();
      obstacles.ellipses[e].vy = -s * v.x() + c * v.y();
    }
    tracks_.push_back(std::move(track));
  }
  // Tracks missed this time live on (occlusion, a dropped return) until kMaxUnseenS; their gate
  // grows with the time since they were seen.
  for (std::size_t t = 0; t < known.size(); ++t) {
    if (!track_used[t]) tracks_.push_back(std::move(known[t]));
  }
}

}  // namespace ellipse_collision::app
