// What the node's parameter tests share: a valid private namespace to change one key of, and the
// message parseNodeConfig() refuses it with. No ROS master needed.
#pragma once

#include <gtest/gtest.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <string>

#include "ellipse_collision/ros/node_config.h"

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

namespace ellipse_collision::test {

using XmlRpc::XmlRpcValue;

/// One entry of `links` or `obstacles`: a circle of `radius` [m] at (x, 0) in `frame`.
inline XmlRpcValue ellipseEntry(const std::string& name, const std::string& frame, double x = 0.0,
                                double radius = 0.2) {
  XmlRpcValue e;
  e["name"] = name;
  e["frame"] = frame;
  e["x"] = x;
  e["y"] = 0.0;
  e["angle"] = 0.0;
  e["radius_x"] = radius;
  e["radius_y"] = radius;
  return e;
}

inline XmlRpcValue pair(const std::string& a, const std::string& b) {
  XmlRpcValue p;
  p[0] = a;
  p[1] = b;
  return p;
}

/// One entry of `sources`.
inline XmlRpcValue sourceEntry(const std::string& name, const std::string& type,
                               const std::string& topic) {
  XmlRpcValue e;
  e["name"] = name;
  e["type"] = type;
  e["topic"] = topic;
  return e;
}

/// A complete valid configuration: links arm, hand; obstacle table; allowed pair (arm, hand).
inline XmlRpcValue validParams() {
  XmlRpcValue p;
  p["fixed_frame"] = "map";
  p["rate"] = 5.0;
  p["tf_timeout"] = 0.5;
  p["padding"] = 0.01;
  p["self_collision"] = false;
  p["warning_distance"] = 0.25;
  p["links"][0] = ellipseEntry("arm", "arm_link");
  p["links"][1] = ellipseEntry("hand", "hand_link", 1.0, 0.1);
  p["links"][1]["padding"] = 0.02;
  p["obstacles"][0] = ellipseEntry("table", "map", 3.0, 0.5);
  p["allowed_pairs"][0] = pair("arm", "hand");
  return p;
}

/// The ConfigError message of `read()`, or "" when it returns.
template <typename Read>
std::string refusalOf(const Read& read) {
  try {
    read();
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

/// The ConfigError message of parsing `params`, or "" when it parses.
inline std::string errorOf(const XmlRpcValue& params) {
  return refusalOf([&] { parseNodeConfig(params); });
}

}  // namespace ellipse_collision::test
