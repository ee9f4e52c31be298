// scan_obstacles' parameters (src/ros/scan_params.cpp): parseScanObstacleSettings() and
// parseTrackingSettings() on its private namespace: defaults, overrides, every bad value naming the
// key and the value; no ROS master needed.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "ellipse_collision/ros/param_reading.h"
#include "ellipse_collision/ros/scan_params.h"

namespace ellipse_collision {
namespace {

std::string settingsError(const XmlRpc::XmlRpcValue& params) {
  try {
    parseScanObstacleSettings(params);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

std::string trackingError(const XmlRpc::XmlRpcValue& params) {
  try {
    parseTrackingSettings(params);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(TrackingSettings, DefaultsOverridesAndBadValuesNamingTheKey) {
  const app::TrackingSettings defaults = parseTrackingSettings(XmlRpc::XmlRpcValue());
  EXPECT_TRUE(defaults.enabled);
  EXPECT_EQ(defaults.fixed_frame, "odom");
  EXPECT_EQ(defaults.confirm_count, 8);
  XmlRpc::XmlRpcValue params;
  params["tracking"]["enabled"] = false;
  params["tracking"]["fixed_frame"] = "map";
  params["tracking"]["max_speed"] = 2;  // ints are numbers
  params["tracking"]["confirm_count"] = 4;
  const app::TrackingSettings set = parseTrackingSettings(params);
  EXPECT_FALSE(set.enabled);
  EXPECT_EQ(set.fixed_frame, "map");
  EXPECT_EQ(set.max_speed, 2.0);
  EXPECT_EQ(set.confirm_count, 4);
  // The scan keys accept `tracking` beside them.
  EXPECT_EQ(settingsError(params), "");

  params = XmlRpc::XmlRpcValue();
  params["tracking"]["min_speed"] = 4.0;  // above max_speed 3
  EXPECT_EQ(trackingError(params),
            "parameter ~tracking/min_speed, key 'tracking/min_speed': expected a number within "
            "[0, 3], got 4");
  params = XmlRpc::XmlRpcValue();
  params["tracking"]["confirm_count"] = 1.5;
  EXPECT_NE(trackingError(params).find("key 'tracking/confirm_count': expected an integer"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["tracking"]["fixed_frame"] = "/odom";
  EXPECT_NE(trackingError(params).find("key 'tracking/fixed_frame'"), std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["tracking"]["max_sped"] = 1.0;
  EXPECT_NE(trackingError(params).find("parameter ~tracking/max_sped, key 'tracking/max_sped': "
                                       "expected one of enabled, fixed_frame"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["tracking"] = 1.0;
  EXPECT_NE(trackingError(params).find("expected a dict"), std::string::npos);
}

TEST(ScanObstacleSettings, DefaultsAndOverrides) {
  const app::ScanObstacleSettings defaults = parseScanObstacleSettings(XmlRpc::XmlRpcValue());
  EXPECT_EQ(defaults.cluster_distance, 0.1);
  EXPECT_EQ(defaults.min_cluster_points, 1);
  EXPECT_EQ(defaults.min_radius, 0.05);
  EXPECT_EQ(defaults.range_noise_sigma, 0.01);
  EXPECT_EQ(defaults.free_space_tolerance, 0.1);
  EXPECT_EQ(defaults.z_min, 0.0);
  EXPECT_EQ(defaults.z_max, 2.0);
  XmlRpc::XmlRpcValue params;
  params["cluster_distance"] = 1;  // ints are numbers
  params["min_cluster_points"] = 1;
  params["z_min"] = -0.5;
  params["range_noise_sigma"] = 0;
  params["free_space_tolerance"] = 0.03;
  const auto settings = parseScanObstacleSettings(params);
  EXPECT_EQ(settings.range_noise_sigma, 0.0);
  EXPECT_EQ(settings.free_space_tolerance, 0.03);
  EXPECT_EQ(settings.cluster_distance, 1.0);
  EXPECT_EQ(settings.min_cluster_points, 1);
  EXPECT_EQ(settings.z_min, -0.5);
}

TEST(ScanObstacleSettings, BadValuesNameTheKey) {
  XmlRpc::XmlRpcValue params;
  params["cluster_distance"] = -0.1;
  EXPECT_EQ(settingsError(params),
            "parameter ~cluster_distance, key 'cluster_distance': expected a number within "
            "[1e-06, 1000], got -0.1");
  params = XmlRpc::XmlRpcValue();
  params["min_cluster_points"] = 2.5;
  EXPECT_NE(settingsError(params).find("key 'min_cluster_points': expected an integer"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["min_radius"] = 0.0;
  EXPECT_NE(settingsError(params).find("key 'min_radius'"), std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["z_min"] = 1.0;
  params["z_max"] = 0.5;
  EXPECT_NE(settingsError(params).find("key 'z_max': expected a number >= z_min = 1"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["cluster_distanse"] = 0.1;
  EXPECT_NE(settingsError(params).find("parameter ~cluster_distanse: unknown key"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["free_space_tolerance"] = 0.0;
  EXPECT_EQ(settingsError(params),
            "parameter ~free_space_tolerance, key 'free_space_tolerance': expected a number "
            "within [0.001, 10], got 0");
  params = XmlRpc::XmlRpcValue();
  params["range_noise_sigma"] = -0.01;
  EXPECT_EQ(settingsError(params),
            "parameter ~range_noise_sigma, key 'range_noise_sigma': expected a number within "
            "[0, 1], got -0.01");
  params = XmlRpc::XmlRpcValue();
  params["range_noise_sigma"] = "0.01";
  EXPECT_NE(settingsError(params).find("key 'range_noise_sigma'"), std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["z_max"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(settingsError(params).find("key 'z_max'"), std::string::npos);
}

TEST(ScanObstacleSettings, EveryNumberKeyRefusesNaNNamingTheKeyAndTheValue) {
  for (const std::string& key : params::scanKeys()) {
    if (key == "name_prefix") continue;
    XmlRpc::XmlRpcValue params;
    params[key] = std::numeric_limits<double>::quiet_NaN();
    const std::string expected =
        key == "min_cluster_points" ? "expected an integer, got nan" : "got nan";
    const std::string refusal = settingsError(params);
    EXPECT_EQ(refusal.rfind("parameter ~" + key + ", key '" + key + "': expected ", 0), 0u)
        << refusal;
    EXPECT_NE(refusal.find(expected), std::string::npos) << refusal;
  }
  XmlRpc::XmlRpcValue params;
  params["name_prefix"] = "";
  EXPECT_EQ(settingsError(params),
            "parameter ~name_prefix, key 'name_prefix': expected a non-empty string, got ''");
  params = XmlRpc::XmlRpcValue();
  params["min_cluster_points"] = 0;
  EXPECT_NE(settingsError(params).find("key 'min_cluster_points'"), std::string::npos);
  EXPECT_NE(settingsError(params).find("got 0"), std::string::npos);
}

TEST(TrackingSettings, EveryNumberKeyRefusesNaNAndNegativeValuesNamingTheKeyAndTheValue) {
  for (const std::string key :
       {"max_speed", "max_size", "min_speed", "position_sigma", "confirm_count"}) {
    for (const double value : {std::numeric_limits<double>::quiet_NaN(), -1.0}) {
      XmlRpc::XmlRpcValue params;
      params["tracking"][key] = value;
      const std::string refusal = trackingError(params);
      EXPECT_EQ(refusal.rfind("parameter ~tracking/" + key + ", key 'tracking/" + key + "': ", 0),
                0u)
          << refusal;
      EXPECT_NE(refusal.find(value < 0.0 ? "got -1" : "got nan"), std::string::npos) << refusal;
    }
  }
}

TEST(ScanObstacleSettings, AnythingButADictAsTheNamespaceIsRefused) {
  XmlRpc::XmlRpcValue list;
  list[0] = 1;
  EXPECT_EQ(settingsError(list),
            "private namespace: expected a dict of parameters, got a list of 1");
  EXPECT_EQ(trackingError(list), "") << "tracking defaults where there is no dict";
}

}  // namespace
}  // namespace ellipse_collision
