#include "ellipse_collision/ros/param_reading.h"

#include <ros/node_handle.h>
#include <ros/param.h>

#include <algorithm>
#include <cmath>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/tunable_settings.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision {

using XmlRpc::XmlRpcValue;

std::string describeConfigError(const std::string& where, const app::FieldError& error) {
  return where + ", key '" + error.key + "': expected " + error.expected + ", got " + error.actual;
}

namespace params {

XmlRpcValue privateNamespace(const ros::NodeHandle& private_nh) {
  XmlRpcValue value;
  if (!ros::param::get(private_nh.getNamespace(), value)) return XmlRpcValue();
  return value;
}

std::optional<std::string> unknownKey(const XmlRpcValue& value,
                                      const std::vector<std::string>& keys) {
  XmlRpcValue copy = value;  // begin() and end() of XmlRpcValue are not const
  for (auto it = copy.begin(); it != copy.end(); ++it) {
    if (std::find(keys.begin(), keys.end(), it->first) == keys.end()) return it->first;
  }
  return std::nullopt;
}

std::string describeValue(const XmlRpcValue& value) {
  XmlRpcValue copy = value;  // the conversion operators of XmlRpcValue are not const
  switch (copy.getType()) {
    case XmlRpcValue::TypeBoolean:
      return std::string(static_cast<bool&>(copy) ? "true" : "false") + " (a bool)";
    case XmlRpcValue::TypeInt:
      return std::to_string(static_cast<int&>(copy)) + " (an int)";
    case XmlRpcValue::TypeDouble:
      return core::formatNumber(static_cast<double&>(copy)) + " (a double)";
    case XmlRpcValue::TypeString:
      return "'" + static_cast<std::string&>(copy) + "' (a string)";
    case XmlRpcValue::TypeArray:
      return "a list of " + std::to_string(copy.size());
    case XmlRpcValue::TypeStruct:
      return "a dict";
    case XmlRpcValue::TypeDateTime:
      return "a date";
    case XmlRpcValue::TypeBase64:
      return "binary data";
    case XmlRpcValue::TypeInvalid:
      break;
  }
  return "nothing";
}

void fail(const std::string& where, const std::string& key, const std::string& expected,
          const std::string& actual) {
  throw ConfigError(describeConfigError(where, {key, expected, actual}));
}

double readNumber(const XmlRpcValue& value, const std::string& where, const std::string& key) {
  XmlRpcValue copy = value;
  if (copy.getType() == XmlRpcValue::TypeDouble) return static_cast<double&>(copy);
  if (copy.getType() == XmlRpcValue::TypeInt) return static_cast<int&>(copy);
  fail(where, key, "a number", describeValue(value));
}

std::string readString(const XmlRpcValue& value, const std::string& where, const std::string& key) {
  XmlRpcValue copy = value;
  if (copy.getType() != XmlRpcValue::TypeString) fail(where, key, "a string", describeValue(value));
  return static_cast<std::string&>(copy);
}

bool readBool(const XmlRpcValue& value, const std::string& where, const std::string& key) {
  XmlRpcValue copy = value;
  if (copy.getType() != XmlRpcValue::TypeBoolean) {
    fail(where, key, "true or false", describeValue(value));
  }
  return static_cast<bool&>(copy);
}

void failOn(const std::optional<app::FieldError>& error, const std::string& where) {
  if (error) fail(where, error->key, error->expected, error->actual);
}

double readInRange(const XmlRpcValue& value, const std::string& where, const std::string& key,
                   double min, double max, bool zero_allowed) {
  const double number = readNumber(value, where, key);
  failOn(app::findOutsideSettingRange(key, number, min, max, zero_allowed), where);
  return number;
}

double readSetting(const XmlRpcValue& root, const std::string& key) {
  const std::string where = "parameter ~" + key;
  const double number = readNumber(root[key], where, key);
  failOn(app::findOutsideSettingRange(key, number), where);
  return number;
}

double readWhole(const XmlRpcValue& value, const std::string& where, const std::string& key,
                 double max) {
  const double number = readInRange(value, where, key, 1.0, max);
  if (number != std::floor(number)) fail(where, key, "a whole number", core::formatNumber(number));
  return number;
}

std::string readFrame(const XmlRpcValue& value, const std::string& where, const std::string& key) {
  const std::string frame = readString(value, where, key);
  if (frame.empty()) fail(where, key, "a non-empty tf frame id", "''");
  if (frame.front() == '/') {
    fail(where, key, "a tf2 frame id without a leading '/'", "'" + frame + "'");
  }
  return frame;
}

void refuseUnknownKeys(const XmlRpcValue& value, const std::vector<std::string>& keys,
                       const std::string& prefix) {
  if (const auto key = unknownKey(value, keys)) {
    throw ConfigError(prefix + *key + ": unknown key (expected one of " +
                      app::joinText(keys, ", ") + ")");
  }
}

}  // namespace params
}  // namespace ellipse_collision
