#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "ellipse_collision/app/field_error.h"

namespace ros {
class NodeHandle;
}

namespace ellipse_collision {

/// A configuration the node cannot run with; what() names the entry, the key, expected and actual.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How a configuration error reads, at start-up and when reconfigured: "<where>, key '<key>':
/// expected <expected>, got <actual>" (where: "parameter ~rate", "links[2]").
std::string describeConfigError(const std::string& where, const app::FieldError& error);

/// Reading typed values out of XmlRpc parameters, shared by every parameter section of the node
/// and of scan_obstacles. `where` names the place in messages ("parameter ~gate", "links[2]"),
/// `key` the key; every failure throws ConfigError as describeConfigError() renders it.
namespace params {

/// The whole private namespace of `private_nh` as the parameter server holds it, or an empty
/// (invalid) value when it holds none: the one read each node parses its parameters from.
XmlRpc::XmlRpcValue privateNamespace(const ros::NodeHandle& private_nh);

/// The first key of the dict `value` that is not one of `keys`, or nothing: every dict of the
/// configuration refuses unknown keys (a typo would otherwise be ignored silently).
std::optional<std::string> unknownKey(const XmlRpc::XmlRpcValue& value,
                                      const std::vector<std::string>& keys);

/// Throws "<prefix><key>: unknown key (expected one of <keys>)" for the first unknown key of the
/// dict `value` (prefix: "parameter ~" for the private namespace, "parameter ~gate/" for a dict).
void refuseUnknownKeys(const XmlRpc::XmlRpcValue& value, const std::vector<std::string>& keys,
                       const std::string& prefix);

/// A value as a message shows it: "3 (an int)", "'x' (a string)", "a list of 2", "nothing".
std::string describeValue(const XmlRpc::XmlRpcValue& value);

[[noreturn]] void fail(const std::string& where, const std::string& key,
                       const std::string& expected, const std::string& actual);

/// Renders a violation of the application layer's setting rules as a configuration error.
void failOn(const std::optional<app::FieldError>& error, const std::string& where);

/// A number, accepting ints where a double is expected (YAML `1` is an int).
double readNumber(const XmlRpc::XmlRpcValue& value, const std::string& where,
                  const std::string& key);
std::string readString(const XmlRpc::XmlRpcValue& value, const std::string& where,
                       const std::string& key);
bool readBool(const XmlRpc::XmlRpcValue& value, const std::string& where, const std::string& key);

/// A finite number >= 0 within [min, max] (or exactly 0 when zero_allowed, for "off"):
/// app::findOutsideSettingRange(). Refused, never clamped.
double readInRange(const XmlRpc::XmlRpcValue& value, const std::string& where,
                   const std::string& key, double min, double max, bool zero_allowed = false);

/// Top-level scalar parameter `key` ("rate") in its range from the one table,
/// app::settingRange(): the same rule reconfigure applies.
double readSetting(const XmlRpc::XmlRpcValue& root, const std::string& key);

/// A whole number within [1, max] (YAML `100000` is an int; 1e5 as a double is accepted if whole).
double readWhole(const XmlRpc::XmlRpcValue& value, const std::string& where, const std::string& key,
                 double max);

/// A non-empty tf2 frame id without a leading '/'.
std::string readFrame(const XmlRpc::XmlRpcValue& value, const std::string& where,
                      const std::string& key);

}  // namespace params
}  // namespace ellipse_collision
