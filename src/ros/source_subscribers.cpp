#include "ellipse_collision/ros/source_subscribers.h"

#include <algorithm>
#include <optional>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/range_obstacle.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/scan_obstacles.h"
#include "ellipse_collision/ros/tf_lookup.h"

namespace ellipse_collision {

SourceSubscribers::SourceSubscribers(ros::NodeHandle nh, ros::NodeHandle private_nh,
                                     const NodeConfig& config, app::CollisionMonitor& monitor,
                                     const tf2_ros::Buffer& tf_buffer)
    : nh_(std::move(nh)),
      private_nh_(std::move(private_nh)),
      config_(config),
      monitor_(monitor),
      tf_buffer_(tf_buffer) {
  obstacles_sub_ = private_nh_.subscribe<EllipseArray>(
      "obstacles", 10, [this](const EllipseArray::ConstPtr& msg) { onEllipses(0, msg); });
  const std::vector<app::SourceSpec>& sources = config_.monitor.sources;
  series_.resize(sources.size() + 1);
  rosters_.resize(sources.size() + 1);
  double roster_period_s = 0.0;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    subscribe(i + 1, sources[i]);
    if (sources[i].type == app::SourceType::Robots) {
      // Checked four times per timeout: a silent robot goes at most a quarter timeout late.
      const double period_s = sources[i].timeout_s / 4.0;
      roster_period_s = roster_period_s > 0.0 ? std::min(roster_period_s, period_s) : period_s;
    }
  }
  if (roster_period_s > 0.0) {
    roster_timer_ =
        nh_.createTimer(ros::Duration(roster_period_s), &SourceSubscribers::onRosterTimer, this);
  }
}

void SourceSubscribers::subscribe(std::size_t index, const app::SourceSpec& source) {
  // "~x" is private, anything else resolves in the node's namespace.
  const bool is_private = source.topic.front() == '~';
  ros::NodeHandle& handle = is_private ? private_nh_ : nh_;
  const std::string topic = is_private ? source.topic.substr(1) : source.topic;
  if (source.type == app::SourceType::Scan || source.type == app::SourceType::Cloud) {
    series_[index] = std::make_unique<app::SensorObstacleSeries>(source.scan, source.tracking);
  }
  if (source.type == app::SourceType::Scan) {
    subscribers_.push_back(handle.subscribe<sensor_msgs::LaserScan>(
        topic, 1,
        [this, index](const sensor_msgs::LaserScan::ConstPtr& msg) { onScan(index, msg); }));
  } else if (source.type == app::SourceType::Cloud) {
    subscribers_.push_back(handle.subscribe<sensor_msgs::PointCloud2>(
        topic, 1,
        [this, index](const sensor_msgs::PointCloud2::ConstPtr& msg) { onCloud(index, msg); }));
  } else if (source.type == app::SourceType::Robots) {
    rosters_[index] =
        std::make_unique<app::FleetRoster>(config_.fleet.robot_name, source.timeout_s);
    // Every robot's footprints on one topic: room for a round of a large fleet.
    subscribers_.push_back(handle.subscribe<EllipseArray>(
        topic, 100, [this, index](const EllipseArray::ConstPtr& msg) { onRobots(index, msg); }));
  } else if (source.type == app::SourceType::Range) {
    subscribers_.push_back(handle.subscribe<sensor_msgs::Range>(
        topic, 10,
        [this, index](const sensor_msgs::Range::ConstPtr& msg) { onRange(index, msg); }));
  } else {
    subscribers_.push_back(handle.subscribe<EllipseArray>(
        topic, 10, [this, index](const EllipseArray::ConstPtr& msg) { onEllipses(index, msg); }));
  }
  ROS_INFO_STREAM("ellipse_collision: source '"
                  << source.name << "' (" << app::toString(source.type) << ") on "
                  << subscribers_.back().getTopic() << ", "
                  << (source.timeout_s > 0.0
                          ? "silent after " + core::formatNumber(source.timeout_s) + " s"
                          : std::string("no watchdog")));
}

bool SourceSubscribers::hasRobots() const {
  return std::any_of(rosters_.begin(), rosters_.end(),
                     [](const auto& roster) { return roster != nullptr; });
}

std::vector<std::pair<std::string, std::string>> SourceSubscribers::robotsValues(
    double now_s) const {
  std::vector<std::pair<std::string, std::string>> values;
  for (std::size_t source = 1; source < rosters_.size(); ++source) {
    if (!rosters_[source]) continue;
    const std::string prefix = "source '" + spec(source).name + "' ";
    for (const auto& [key, value] : rosters_[source]->healthValues(now_s)) {
      values.emplace_back(prefix + key, value);
    }
  }
  return values;
}

void SourceSubscribers::onRobots(std::size_t source, const EllipseArray::ConstPtr& msg) {
  app::FleetRoster& roster = *rosters_[source];
  const ros::Time now = ros::Time::now();
  if (const auto refused = roster.receive(now.toSec(), fromMsg(*msg), msg->header.stamp.toSec())) {
    refuse(source, *refused);
    return;
  }
  // No wait for tf: every robot's footprint comes through here, many a second.
  const std::string error = monitor_.replaceSourceObstacles(
      source, roster.obstacles(), roster.stamp(), now.toSec(), lookup(ros::Duration(0)));
  if (!error.empty()) {
    ROS_WARN_STREAM_THROTTLE(5.0, "ellipse_collision: refused a footprint on source '"
                                      << spec(source).name
                                      << "', the robots' previous links kept: " << error);
  }
}

void SourceSubscribers::onRosterTimer(const ros::TimerEvent& /*event*/) {
  const ros::Time now = ros::Time::now();
  for (std::size_t source = 1; source < rosters_.size(); ++source) {
    if (!rosters_[source]) continue;
    const std::vector<std::string> dropped = rosters_[source]->dropSilent(now.toSec());
    if (dropped.empty()) continue;
    for (const std::string& robot : dropped) {
      // Robots leave: worth a line, not an error.
      ROS_INFO_STREAM("ellipse_collision: source '"
                      << spec(source).name << "': robot '" << robot << "' silent for more than "
                      << core::formatNumber(spec(source).timeout_s) << " s, its links dropped");
    }
    const std::string error = monitor_.replaceSourceObstacles(source, rosters_[source]->obstacles(),
                                                              rosters_[source]->stamp(),
                                                              now.toSec(), lookup(ros::Duration(0)),
                                                              /*heard=*/false);
    if (!error.empty()) {
      ROS_WARN_STREAM_THROTTLE(
          5.0, "ellipse_collision: source '" << spec(source).name << "': " << error);
    }
  }
}

void SourceSubscribers::onEllipses(std::size_t source, const EllipseArray::ConstPtr& msg) {
  replace(source, fromMsg(*msg), msg->header.stamp);
}

void SourceSubscribers::onScan(std::size_t source, const sensor_msgs::LaserScan::ConstPtr& msg) {
  // The same pipeline as scan_obstacles, its cuts, names and tracks kept per source.
  app::SensorObstacles obstacles = scanObstacles(*msg, *series_[source]);
  track(source, obstacles, msg->header, false);
  replaceSensorObstacles(source, obstacles, msg->header.stamp);
}

void SourceSubscribers::onCloud(std::size_t source, const sensor_msgs::PointCloud2::ConstPtr& msg) {
  std::vector<Eigen::Vector3f> points;
  try {
    points = cloudPoints(*msg);
  } catch (const std::runtime_error& error) {
    refuse(source, std::string("a cloud without x, y, z: ") + error.what());
    return;
  }
  app::SensorObstacles obstacles = series_[source]->cloud(points, msg->header.frame_id);
  track(source, obstacles, msg->header, true);
  replaceSensorObstacles(source, obstacles, msg->header.stamp);
}

void SourceSubscribers::track(std::size_t source, app::SensorObstacles& obstacles,
                              const std_msgs::Header& header, bool cloud) {
  // No wait: the node's one callback thread also gates commands.
  const std::string error = trackSensorObstacles(tf_buffer_, *series_[source], obstacles, header,
                                                 cloud, ros::Duration(0));
  if (!error.empty()) {
    ROS_WARN_STREAM_THROTTLE(5.0,
                             "ellipse_collision: source '" << spec(source).name << "': " << error);
  }
}

void SourceSubscribers::onRange(std::size_t source, const sensor_msgs::Range::ConstPtr& msg) {
  app::SensorObstacles obstacles;
  const std::optional<app::FieldError> invalid =
      app::rangeObstacles(fromMsg(*msg), spec(source).scan.min_radius, &obstacles);
  if (invalid) {
    refuse(source, app::describeFieldError("sensor_msgs/Range", *invalid));
    return;
  }
  replace(source, obstacles.ellipses, msg->header.stamp);
}

void SourceSubscribers::replaceSensorObstacles(std::size_t source,
                                               const app::SensorObstacles& obstacles,
                                               const ros::Time& stamp) {
  if (!obstacles.skipped.empty()) {
    ROS_WARN_STREAM_THROTTLE(5.0, "ellipse_collision: source '"
                                      << spec(source).name << "' skipped "
                                      << app::joinText(obstacles.skipped, "; "));
  }
  replace(source, obstacles.ellipses, stamp);
}

void SourceSubscribers::refuse(std::size_t source, const std::string& why) {
  monitor_.sourceMessageRefused(source, why);
  ROS_WARN_STREAM_THROTTLE(5.0, "ellipse_collision: refused a message of source '"
                                    << spec(source).name
                                    << "', its previous obstacles kept: " << why);
}

void SourceSubscribers::replace(std::size_t source, const std::vector<app::EllipseSpec>& specs,
                                const ros::Time& stamp) {
  const std::string error =
      monitor_.replaceSourceObstacles(source, specs, stamp.toSec(), ros::Time::now().toSec(),
                                      lookup(ros::Duration(config_.tf_timeout_s)));
  if (error.empty()) return;
  const std::string what = source == 0 ? std::string("~obstacles message")
                                       : "message of source '" + spec(source).name + "'";
  ROS_WARN_STREAM_THROTTLE(
      5.0, "ellipse_collision: refused " << what << ", its previous obstacles kept: " << error);
}

app::TransformLookup SourceSubscribers::lookup(const ros::Duration& timeout) const {
  return tfLookup(tf_buffer_, config_.monitor.check.fixed_frame, ros::Time(0), timeout);
}

const app::SourceSpec& SourceSubscribers::spec(std::size_t source) const {
  return config_.monitor.sources[source - 1];
}

}  // namespace ellipse_collision
