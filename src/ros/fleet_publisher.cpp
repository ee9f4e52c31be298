#include "ellipse_collision/ros/fleet_publisher.h"

#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/messages.h"
#include "ellipse_collision/ros/tf_lookup.h"

namespace ellipse_collision {

FleetPublisher::FleetPublisher(ros::NodeHandle nh, const NodeConfig& config,
                               const app::CollisionMonitor& monitor,
                               const tf2_ros::Buffer& tf_buffer)
    : config_(config), monitor_(monitor), tf_buffer_(tf_buffer) {
  publisher_ = nh.advertise<EllipseArray>(config_.fleet.topic, 1);
  timer_ = nh.createTimer(ros::Duration(1.0 / config_.fleet.rate), &FleetPublisher::onTimer, this);
  ROS_INFO_STREAM("ellipse_collision: fleet: publishing '"
                  << config_.fleet.robot_name << "' (" << config_.links.size() << " links) on "
                  << publisher_.getTopic() << " in '" << config_.fleet.frame << "' at "
                  << core::formatNumber(config_.fleet.rate) << " Hz");
}

void FleetPublisher::onTimer(const ros::TimerEvent& /*event*/) {
  // A robot alone costs nothing (and warns of no missing map): the work waits for a listener.
  if (publisher_.getNumSubscribers() == 0) {
    error_.clear();
    return;
  }
  // No waiting: the latest transforms, in the one callback thread.
  const app::PlacedLinks placed = app::placeLinks(
      config_.links, config_.monitor.check.global_padding_m,
      tfLookup(tf_buffer_, config_.fleet.frame, ros::Time(0), ros::Duration(0)),
      app::Freshness{monitor_.settings().check.max_transform_age_s, ros::Time::now().toSec()});
  if (!placed.error.empty()) {
    // A robot without a map (fleet/frame absent) is normal alone: say it, slowly.
    error_ = placed.error;
    ROS_WARN_STREAM_THROTTLE(30.0, "ellipse_collision: fleet: not publishing '"
                                       << config_.fleet.robot_name << "' in '"
                                       << config_.fleet.frame << "': " << placed.error
                                       << " (fleet/enabled: false turns this off)");
    return;
  }
  error_.clear();
  const ros::Time stamp = placed.stamp_s > 0.0 ? ros::Time(placed.stamp_s) : ros::Time::now();
  EllipseArray msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = config_.fleet.frame;
  for (const app::EllipseSpec& spec : footprint_.update(
           stamp.toSec(), placed.links, config_.fleet.robot_name, config_.fleet.frame)) {
    msg.ellipses.push_back(toMsg(spec));
  }
  publisher_.publish(msg);
  ++sent_;
}

FleetPublisher::Status FleetPublisher::status() const {
  Status status;
  if (!error_.empty()) {
    status.failing = true;
    status.message = "not publishing '" + config_.fleet.robot_name + "' in '" +
                     config_.fleet.frame + "': " + error_ +
                     " (publish fleet/frame in tf, or set fleet/enabled: false)";
  } else {
    status.message =
        (publisher_.getNumSubscribers() > 0 ? "publishing '" : "nobody listening for '") +
        config_.fleet.robot_name + "' on " + publisher_.getTopic();
  }
  status.values.emplace_back("robot name", config_.fleet.robot_name);
  status.values.emplace_back("footprints sent", std::to_string(sent_));
  return status;
}

}  // namespace ellipse_collision
