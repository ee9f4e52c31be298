// Fuzz target: parseNodeConfig(), the node's parameter parser, fed XmlRpc trees built from the
// input: the documented keys with values of the right or a wrong type (ints, hostile doubles,
// strings, bools, lists, dicts, dates, binary), missing and unknown keys, duplicate names.
//
// Invariants:
//  - the only way to refuse is ConfigError, whose message names where the problem is
//    ("parameter ~rate", "links[2] (name 'arm')", "allowed_pairs[0][1]", ...); no other
//    exception (XmlRpcException, std::exception) escapes;
//  - an accepted configuration is usable: every ellipse passes findInvalidField() and is valid for
//    the core once padded, names are unique, allowed pairs name two different configured
//    entries, the registry can be built from it, and the node's timer period 1 / rate and tf
//    timeout are representable as ros::Duration (the node builds both from them).

#include <ros/duration.h>
#include <xmlrpcpp/XmlRpcException.h>

#include <cmath>
#include <cstdint>
#include <ctime>
#include <exception>
#include <set>
#include <string>

#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/ros/node_config.h"
#include "fuzz_input.h"

namespace ellipse_collision::fuzz {
namespace {

using XmlRpc::XmlRpcValue;

const char* const kRootKeys[] = {
    "fixed_frame",   "rate",           "tf_timeout",       "padding",   "links", "obstacles",
    "allowed_pairs", "self_collision", "warning_distance", "tf_timout", ""};
const char* const kEllipseKeys[] = {"name",     "frame",    "x",     "y",    "angle",
                                    "radius_x", "radius_y", "padding", "z",  "roll",
                                    "pitch",    "radius_z", "rad"};
/// The keys of an ellipsoid: each present less often than the others, so that most entries
/// stay planar.
bool isDepthKey(const std::string& key) {
  return key == "z" || key == "roll" || key == "pitch" || key == "radius_z";
}
const char* const kNames[] = {"body", "arm", "crate", "", "a/b", "body "};
const char* const kFrames[] = {"base_link", "odom", "/odom", "", "arm link"};

template <std::size_t N>
const char* pick(FuzzInput& input, const char* const (&table)[N]) {
  return table[input.integer(0, N - 1)];
}

XmlRpcValue number(FuzzInput& input) {
  if (input.flag()) return XmlRpcValue(input.integer(-3, 200) - 100);  // an int
  return XmlRpcValue(input.number());
}

XmlRpcValue anyValue(FuzzInput& input, int depth) {
  switch (input.integer(0, 7)) {
    case 0:
      return XmlRpcValue(input.flag());
    case 1:
      return XmlRpcValue(input.integer(0, 255) - 128);
    case 2:
      return XmlRpcValue(input.number());
    case 3:
      return XmlRpcValue(std::string(pick(input, kNames)));
    case 4: {
      XmlRpcValue list;
      list.setSize(depth > 0 ? input.integer(0, 3) : 0);
      for (int i = 0; i < list.size(); ++i) list[i] = anyValue(input, depth - 1);
      return list;
    }
    case 5: {
      XmlRpcValue dict;
      for (int i = depth > 0 ? input.integer(0, 3) : 0; i > 0; --i) {
        dict[pick(input, kEllipseKeys)] = anyValue(input, depth - 1);
      }
      return dict;
    }
    case 6: {
      std::tm date{};
      return XmlRpcValue(&date);
    }
    default: {
      char bytes[3] = {1, 2, 3};
      return XmlRpcValue(bytes, 3);
    }
  }
}

/// A value for `key` of the right type, unless the input asks for an arbitrary one.
XmlRpcValue valueFor(const std::string& key, FuzzInput& input, int depth);

XmlRpcValue ellipseEntry(FuzzInput& input, int depth) {
  XmlRpcValue entry;  // stays "nothing" when every key is left out
  for (const char* key : kEllipseKeys) {
    const bool unknown = std::string(key) == "rad";
    const int presence = input.integer(0, 7);
    if (presence == 0 || (unknown && presence != 1)) continue;  // a missing key
    if (isDepthKey(key) && presence < 5) continue;
    entry[key] = presence == 7 ? anyValue(input, depth - 1) : valueFor(key, input, depth - 1);
  }
  return entry;
}

XmlRpcValue valueFor(const std::string& key, FuzzInput& input, int depth) {
  if (input.integer(0, 15) == 0 || depth <= 0) return anyValue(input, 1);
  if (key == "fixed_frame" || key == "frame") return XmlRpcValue(std::string(pick(input, kFrames)));
  if (key == "name") return XmlRpcValue(std::string(pick(input, kNames)));
  if (key == "self_collision") return XmlRpcValue(input.flag());
  if (key == "links" || key == "obstacles") {
    XmlRpcValue list;
    list.setSize(input.integer(0, 4));
    for (int i = 0; i < list.size(); ++i) list[i] = ellipseEntry(input, depth - 1);
    return list;
  }
  if (key == "allowed_pairs") {
    XmlRpcValue list;
    list.setSize(input.integer(0, 3));
    for (int i = 0; i < list.size(); ++i) {
      list[i].setSize(input.integer(0, 7) == 0 ? input.integer(0, 3) : 2);
      for (int k = 0; k < list[i].size(); ++k) list[i][k] = std::string(pick(input, kNames));
    }
    return list;
  }
  return number(input);  // rate, tf_timeout, padding, x, y, angle, radius_x, radius_y, unknown
}

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

void checkAccepted(const NodeConfig& config) {
  FUZZ_REQUIRE(!config.monitor.check.fixed_frame.empty() && config.monitor.check.fixed_frame.front() != '/',
               "accepted fixed_frame '" + config.monitor.check.fixed_frame + "'");
  for (double value :
       {config.monitor.rate_hz, config.tf_timeout_s, config.monitor.check.global_padding_m, config.monitor.check.rules.warning_distance}) {
    FUZZ_REQUIRE(std::isfinite(value) && value >= 0.0, "accepted a negative or non-finite number");
  }
  // The documented ranges (node_config.h): a timer period and a tf wait ros::Duration can hold.
  FUZZ_REQUIRE(config.monitor.rate_hz == 0.0 || (config.monitor.rate_hz >= kMinRateHz && config.monitor.rate_hz <= kMaxRateHz),
               "accepted rate " + std::to_string(config.monitor.rate_hz));
  FUZZ_REQUIRE(config.tf_timeout_s <= kMaxDurationS,
               "accepted tf_timeout " + std::to_string(config.tf_timeout_s));
  FUZZ_REQUIRE(config.monitor.check.global_padding_m <= core::kMaxRadius, "accepted padding " + std::to_string(config.monitor.check.global_padding_m));
  std::set<std::string> names;
  for (const auto* list : {&config.links, &config.obstacles}) {
    for (const app::EllipseSpec& spec : *list) {
      const auto invalid = app::findInvalidField(spec, "frame");
      FUZZ_REQUIRE(!invalid, "accepted ellipse '" + spec.name + "' with bad " +
                                 (invalid ? invalid->key : std::string()));
      FUZZ_REQUIRE(names.insert(spec.name).second, "accepted duplicate name '" + spec.name + "'");
      const core::Ellipse padded = app::paddedEllipse(spec, config.monitor.check.global_padding_m);
      FUZZ_REQUIRE(
          core::invalidReason(padded).empty(),
          "accepted ellipse '" + spec.name + "' that the core refuses: " + core::invalidReason(padded));
      if (spec.ellipsoid) {
        const std::string refused =
            core::invalidReason(app::paddedEllipsoid(spec, config.monitor.check.global_padding_m));
        FUZZ_REQUIRE(refused.empty(), "accepted ellipsoid '" + spec.name +
                                          "' that the core refuses: " + refused);
      }
    }
  }
  for (const auto& [a, b] : config.monitor.check.rules.allowed.pairs()) {
    FUZZ_REQUIRE(a != b && names.count(a) && names.count(b),
                 "accepted allowed pair [" + a + ", " + b + "]");
  }
  app::EllipseRegistry registry(config.links, config.obstacles);  // throws on a duplicate or empty name
  // The node builds ros::Duration(1 / rate) and ros::Duration(tf_timeout), which throw
  // std::runtime_error outside +-2^31 s: an accepted configuration must not make them throw.
  // A positive rate must also give a positive period: a zero-period timer would spin.
  try {
    if (config.monitor.rate_hz > 0.0) {
      const ros::Duration period(1.0 / config.monitor.rate_hz);
      FUZZ_REQUIRE(period > ros::Duration(0),
                   "accepted rate " + text(config.monitor.rate_hz) + " Hz whose timer period rounds to 0");
    }
    const ros::Duration timeout(config.tf_timeout_s);
  } catch (const std::exception& e) {
    fail("accepted rate " + text(config.monitor.rate_hz) + " Hz / tf_timeout " + text(config.tf_timeout_s) +
         " s that ros::Duration refuses: " + e.what());
  }
}

}  // namespace
}  // namespace ellipse_collision::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellipse_collision;
  using namespace ellipse_collision::fuzz;
  FuzzInput input(data, size);
  XmlRpc::XmlRpcValue root;
  if (input.integer(0, 31) == 0) {
    root = anyValue(input, 2);  // the private namespace is not even a dict
  } else {
    for (int i = input.integer(0, 9); i > 0; --i) {
      const std::string key = pick(input, kRootKeys);
      root[key] = valueFor(key, input, 4);
    }
  }

  NodeConfig config;
  try {
    config = parseNodeConfig(root);
  } catch (const ConfigError& error) {
    const std::string message = error.what();
    FUZZ_REQUIRE(startsWith(message, "parameter ~") || startsWith(message, "links[") ||
                     startsWith(message, "obstacles[") || startsWith(message, "allowed_pairs[") ||
                     startsWith(message, "private namespace"),
                 "ConfigError names no entry: " + message);
    return 0;
  } catch (const XmlRpc::XmlRpcException& error) {
    fail("XmlRpcException escaped parseNodeConfig: " + error.getMessage());
  } catch (const std::exception& error) {
    fail(std::string("exception escaped parseNodeConfig: ") + error.what());
  }
  checkAccepted(config);
  return 0;
}
