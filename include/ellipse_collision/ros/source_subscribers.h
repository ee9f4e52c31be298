#pragma once

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/Range.h>
#include <tf2_ros/buffer.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "ellipse_collision/app/fleet_roster.h"
#include "ellipse_collision/app/sensor_obstacle_series.h"
#include "ellipse_collision/ros/messages.h"
#include "ellipse_collision/ros/node_config.h"

namespace ellipse_collision {

/// The node's obstacle sources: ~obstacles (the monitor's source 0) and each listed source
/// (`sources`; source i + 1 is sources[i]), one subscriber each. A scan or cloud source runs the
/// scan_obstacles pipeline and its tracks, a robots source keeps its FleetRoster; every message's
/// obstacles go to the monitor, and a refusal is logged naming the source.
class SourceSubscribers {
 public:
  /// Subscribes at once. `config`, `monitor` and `tf_buffer` must outlive this.
  SourceSubscribers(ros::NodeHandle nh, ros::NodeHandle private_nh, const NodeConfig& config,
                    app::CollisionMonitor& monitor, const tf2_ros::Buffer& tf_buffer);

  /// Whether any robots source is listed.
  bool hasRobots() const;
  /// Every robots source's health values (FleetRoster::healthValues()), each key prefixed with
  /// "source '<name>' ".
  std::vector<std::pair<std::string, std::string>> robotsValues(double now_s) const;

 private:
  void subscribe(std::size_t index, const app::SourceSpec& source);
  void onEllipses(std::size_t source, const EllipseArray::ConstPtr& msg);
  void onScan(std::size_t source, const sensor_msgs::LaserScan::ConstPtr& msg);
  void onCloud(std::size_t source, const sensor_msgs::PointCloud2::ConstPtr& msg);
  void onRange(std::size_t source, const sensor_msgs::Range::ConstPtr& msg);
  /// A robots source's footprint message: kept by the source's FleetRoster (own robot ignored,
  /// a bad message refused whole), every other robot's links handed to the monitor.
  void onRobots(std::size_t source, const EllipseArray::ConstPtr& msg);
  /// Drops the robots of every robots source silent past its timeout, logging each.
  void onRosterTimer(const ros::TimerEvent& event);
  /// The tracked velocities of a scan or cloud source's obstacles (trackSensorObstacles()).
  void track(std::size_t source, app::SensorObstacles& obstacles, const std_msgs::Header& header,
             bool cloud);
  /// The scan pipeline's obstacles of one message (skipped clusters logged), handed on.
  void replaceSensorObstacles(std::size_t source, const app::SensorObstacles& obstacles,
                              const ros::Time& stamp);
  /// A message that could not be converted: logged and reported for the source.
  void refuse(std::size_t source, const std::string& why);
  void replace(std::size_t source, const std::vector<app::EllipseSpec>& specs,
               const ros::Time& stamp);
  /// tf answering for the fixed frame at the latest time, waiting up to `timeout`.
  app::TransformLookup lookup(const ros::Duration& timeout) const;
  /// The listed source `source` (>= 1).
  const app::SourceSpec& spec(std::size_t source) const;

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;
  const NodeConfig& config_;
  app::CollisionMonitor& monitor_;
  const tf2_ros::Buffer& tf_buffer_;
  ros::Subscriber obstacles_sub_;
  std::vector<ros::Subscriber> subscribers_;  ///< one per listed source
  /// A scan or cloud source's pipeline state (cuts and names kept from message to message), by
  /// source index; null for other sources.
  std::vector<std::unique_ptr<app::SensorObstacleSeries>> series_;
  /// A robots source's robots, by source index; null for other sources.
  std::vector<std::unique_ptr<app::FleetRoster>> rosters_;
  ros::Timer roster_timer_;
};

}  // namespace ellipse_collision
