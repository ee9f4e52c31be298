// Test helper node: broadcasts the frames of the rostests (Debian ships no
// static_transform_publisher binary).
//   ~static_frames, ~dynamic_frames: lists of {parent, child, x, y, z, roll, pitch, yaw}
//                                    ([m], [rad]); static ones are latched once, dynamic ones are
//                                    re-stamped and sent at ~rate [Hz] (default 50).
//   ~set_transform (geometry_msgs/TransformStamped): adds or moves a dynamic frame; the header
//                                    stamp is ignored.
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

double number(XmlRpc::XmlRpcValue& value) {
  if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(value);
  return static_cast<double>(value);
}

std::vector<geometry_msgs::TransformStamped> readFrames(const ros::NodeHandle& nh,
                                                        const std::string& key) {
  std::vector<geometry_msgs::TransformStamped> frames;
  XmlRpc::XmlRpcValue list;
  if (!nh.getParam(key, list)) return frames;
  for (int i = 0; i < list.size(); ++i) {
    XmlRpc::XmlRpcValue& entry = list[i];
    geometry_msgs::TransformStamped t;
    t.header.frame_id = static_cast<std::string>(entry["parent"]);
    t.child_frame_id = static_cast<std::string>(entry["child"]);
    t.transform.translation.x = number(entry["x"]);
    t.transform.translation.y = number(entry["y"]);
    t.transform.translation.z = number(entry["z"]);
    tf2::Quaternion q;
    q.setRPY(number(entry["roll"]), number(entry["pitch"]), number(entry["yaw"]));
    t.transform.rotation.x = q.x();
    t.transform.rotation.y = q.y();
    t.transform.rotation.z = q.z();
    t.transform.rotation.w = q.w();
    frames.push_back(t);
  }
  return frames;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "tf_test_broadcaster");
  ros::NodeHandle private_nh("~");
  tf2_ros::StaticTransformBroadcaster static_broadcaster;
  tf2_ros::TransformBroadcaster broadcaster;

  std::vector<geometry_msgs::TransformStamped> static_frames =
      readFrames(private_nh, "static_frames");
  for (geometry_msgs::TransformStamped& t : static_frames) t.header.stamp = ros::Time::now();
  if (!static_frames.empty()) static_broadcaster.sendTransform(static_frames);

  std::map<std::string, geometry_msgs::TransformStamped> dynamic_frames;
  for (const auto& t : readFrames(private_nh, "dynamic_frames"))
    dynamic_frames[t.child_frame_id] = t;

  const ros::Subscriber set_transform = private_nh.subscribe<geometry_msgs::TransformStamped>(
      "set_transform", 10, [&dynamic_frames](const geometry_msgs::TransformStamped::ConstPtr& t) {
        dynamic_frames[t->child_frame_id] = *t;
      });
  const ros::Timer timer = private_nh.createTimer(
      ros::Duration(1.0 / private_nh.param("rate", 50.0)), [&](const ros::TimerEvent&) {
        std::vector<geometry_msgs::TransformStamped> frames;
        for (auto& named : dynamic_frames) {
          named.second.header.stamp = ros::Time::now();
          frames.push_back(named.second);
        }
        if (!frames.empty()) broadcaster.sendTransform(frames);
      });
  ros::spin();
  return 0;
}
