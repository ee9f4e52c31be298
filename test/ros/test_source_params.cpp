// params::readSources() (src/ros/source_params.cpp): the `sources` list's entries, keys per type,
// defaults, and every refusal naming the entry, the key and the value; no ROS master needed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/ros/param_sections.h"
#include "ellipse_collision/ros/scan_params.h"
#include "node_config_fixture.h"

namespace ellipse_collision {
namespace {

using test::errorOf;
using test::refusalOf;
using test::sourceEntry;
using test::validParams;
using XmlRpc::XmlRpcValue;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string sourcesRefusal(const XmlRpcValue& list) {
  return refusalOf([&] { params::readSources(list, "map", "/fleet/footprints"); });
}

TEST(SourceParams, EveryNumberKeyOfAScanSourceRefusesNaNNamingEntryKeyAndValue) {
  std::vector<std::string> keys = {"timeout"};
  for (const std::string& key : params::scanKeys()) {
    if (key != "name_prefix") keys.push_back(key);
  }
  for (const char* key :
       {"max_speed", "max_size", "confirm_count", "min_speed", "position_sigma"}) {
    keys.push_back(std::string("tracking/") + key);
  }
  for (const std::string& key : keys) {
    for (const char* type : {"scan", "cloud"}) {
      XmlRpcValue list;
      list[0] = sourceEntry("front", "scan", "front/scan");
      list[1] = sourceEntry("depth", type, "depth/points");
      const std::size_t slash = key.find('/');
      XmlRpcValue& dict = slash == std::string::npos ? list[1] : list[1]["tracking"];
      const std::string leaf = slash == std::string::npos ? key : key.substr(slash + 1);
      // The integer keys are refused as not integers, the others as not finite.
      const bool integer = leaf == "min_cluster_points" || leaf == "confirm_count";
      dict[leaf] = kNaN;
      const std::string refusal = sourcesRefusal(list);
      EXPECT_CONTAINS(refusal, "parameter ~sources, key 'sources[1]." + key + "': expected " +
                                   (integer ? "an integer" : ""));
      EXPECT_CONTAINS(refusal, "got nan");
    }
  }
}

TEST(SourceParams, NegativeAndHugeValuesNameEntryKeyAndValue) {
  const std::pair<const char*, double> cases[] = {
      {"timeout", -1.0},    {"timeout", 1e12},          {"cluster_distance", -0.5},
      {"min_radius", 1e12}, {"range_noise_sigma", 2.0}, {"free_space_tolerance", -1.0}};
  for (const auto& [key, number] : cases) {
    XmlRpcValue list;
    list[0] = sourceEntry("front", "scan", "front/scan");
    list[0][key] = number;
    const std::string refusal = sourcesRefusal(list);
    EXPECT_CONTAINS(refusal, "parameter ~sources, key 'sources[0]." + std::string(key) + "'");
    EXPECT_CONTAINS(refusal, "got " + core::formatNumber(number));
  }
  XmlRpcValue list;
  list[0] = sourceEntry("sonar", "range", "sonar/range");
  list[0]["min_radius"] = -0.1;
  EXPECT_EQ(sourcesRefusal(list),
            "parameter ~sources, key 'sources[0].min_radius': expected a number within [1e-09, "
            "1e+09], got -0.1");
}

TEST(SourceParams, EachTypeTakesItsOwnKeysOnly) {
  XmlRpcValue list;
  list[0] = sourceEntry("sonar", "range", "sonar/range");
  list[0]["min_radius"] = 0.1;
  list[1] = sourceEntry("fleet", "robots", "/fleet/footprints");
  list[1]["required"] = true;
  list[2] = sourceEntry("depth", "cloud", "depth/points");
  list[2]["z_max"] = 1.5;
  const std::vector<app::SourceSpec> read = params::readSources(list, "odom", "/unused");
  ASSERT_EQ(read.size(), 3u);
  EXPECT_EQ(read[0].type, app::SourceType::Range);
  EXPECT_EQ(read[0].scan.min_radius, 0.1);
  EXPECT_TRUE(read[1].required);
  EXPECT_EQ(read[2].type, app::SourceType::Cloud);
  EXPECT_EQ(read[2].scan.z_max, 1.5);
  EXPECT_EQ(read[2].tracking.fixed_frame, "odom") << "the node's fixed frame";
  list[0]["z_max"] = 1.0;
  EXPECT_EQ(sourcesRefusal(list),
            "parameter ~sources, key 'sources[0].z_max': expected one of name, type, topic, "
            "timeout, min_radius (type range), got an unknown key");
}

TEST(SourceParams, AnEntryWithoutNameOrTypeNamesTheMissingKey) {
  XmlRpcValue list;
  list[0]["type"] = "scan";
  list[0]["topic"] = "scan";
  EXPECT_EQ(sourcesRefusal(list),
            "parameter ~sources, key 'sources[0].name': expected a value (required), got nothing");
  list[0]["name"] = "front";
  list[0]["type"] = 1;
  EXPECT_EQ(sourcesRefusal(list),
            "parameter ~sources, key 'sources[0].type': expected a string, got 1 (an int)");
}

TEST(SourceParams, SourcesAreReadWithTheirScanSettings) {
  XmlRpcValue p = validParams();
  EXPECT_TRUE(parseNodeConfig(p).monitor.sources.empty()) << "only ~obstacles by default";
  p["sources"][0] = sourceEntry("front_scan", "scan", "front/scan");
  p["sources"][0]["timeout"] = 0.5;
  p["sources"][0]["range_noise_sigma"] = 0.02;
  p["sources"][0]["min_cluster_points"] = 3;
  p["sources"][1] = sourceEntry("people", "ellipses", "~people");
  const NodeConfig config = parseNodeConfig(p);
  ASSERT_EQ(config.monitor.sources.size(), 2u);
  const app::SourceSpec& front = config.monitor.sources[0];
  EXPECT_EQ(front.name, "front_scan");
  EXPECT_EQ(front.type, app::SourceType::Scan);
  EXPECT_EQ(front.topic, "front/scan");
  EXPECT_EQ(front.timeout_s, 0.5);
  EXPECT_EQ(front.scan.range_noise_sigma, 0.02);
  EXPECT_EQ(front.scan.min_cluster_points, 3);
  EXPECT_EQ(front.scan.min_radius, app::ScanObstacleSettings().min_radius);
  EXPECT_EQ(config.monitor.sources[1].type, app::SourceType::Ellipses);
  EXPECT_EQ(config.monitor.sources[1].timeout_s, 0.0) << "no watchdog by default";
  // Tracked by default, in the node's fixed frame; a source may say otherwise.
  EXPECT_TRUE(front.tracking.enabled);
  EXPECT_EQ(front.tracking.fixed_frame, config.monitor.check.fixed_frame);
  p["sources"][0]["tracking"]["fixed_frame"] = "odom";
  p["sources"][0]["tracking"]["confirm_count"] = 5;
  const NodeConfig tracked = parseNodeConfig(p);
  EXPECT_EQ(tracked.monitor.sources[0].tracking.fixed_frame, "odom");
  EXPECT_EQ(tracked.monitor.sources[0].tracking.confirm_count, 5);
}

TEST(SourceParams, BadSourcesStopTheNodeNamingEntryKeyAndValue) {
  const auto with = [](void (*change)(XmlRpcValue&)) {
    XmlRpcValue p = validParams();
    p["sources"][0] = sourceEntry("front_scan", "scan", "front/scan");
    p["sources"][1] = sourceEntry("rear_scan", "scan", "rear/scan");
    change(p["sources"]);
    return errorOf(p);
  };
  EXPECT_EQ(with([](XmlRpcValue&) {}), "");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[1]["name"] = "front_scan"; }),
                  "key 'sources[1].name': expected a name used by no other source, got "
                  "'front_scan', the name of sources[0]");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[1]["topic"] = "front/scan"; }),
                  "key 'sources[1].topic'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["topic"] = ""; }), "key 'sources[0].topic'");
  EXPECT_CONTAINS(
      with([](XmlRpcValue& s) { s[0]["type"] = "sonar"; }),
      "key 'sources[0].type': expected 'ellipses', 'scan', 'cloud', 'range' or 'robots', got "
      "'sonar'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["timeout"] = std::nan(""); }),
                  "key 'sources[0].timeout'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["timeout"] = -1.0; }), "key 'sources[0].timeout'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["timeout"] = "soon"; }),
                  "key 'sources[0].timeout': expected a number");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["min_radius"] = -1.0; }),
                  "key 'sources[0].min_radius'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[1]["colour"] = "red"; }), "key 'sources[1].colour'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) {
                    s[1]["type"] = "ellipses";
                    s[1]["min_radius"] = 0.1;
                  }),
                  "key 'sources[1].min_radius'")
      << "scan settings belong to scan sources";
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["tracking"]["confirm_count"] = 1; }),
                  "key 'sources[0].tracking/confirm_count': expected a number within [2, 1000], "
                  "got 1");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["tracking"]["max_sped"] = 1.0; }),
                  "key 'sources[0].tracking/max_sped': expected one of enabled");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) {
                    s[1]["type"] = "ellipses";
                    s[1]["tracking"]["enabled"] = false;
                  }),
                  "key 'sources[1].tracking'")
      << "tracking belongs to scan and cloud sources";
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0] = XmlRpcValue("front"); }), "key 'sources[0]'");
  XmlRpcValue no_topic = validParams();
  no_topic["sources"][0]["name"] = "a";
  no_topic["sources"][0]["type"] = "scan";
  EXPECT_CONTAINS(errorOf(no_topic), "key 'sources[0].topic': expected a value (required)");
  XmlRpcValue not_a_list = validParams();
  not_a_list["sources"] = "front";
  EXPECT_CONTAINS(errorOf(not_a_list), "key 'sources'");
}

TEST(SourceParams, ARobotsSourceListensOnTheFleetTopicAndIsWatchedOnlyWhenRequired) {
  XmlRpcValue p = validParams();
  p["fleet"]["topic"] = "/site/footprints";
  p["sources"][0]["name"] = "fleet";
  p["sources"][0]["type"] = "robots";
  const NodeConfig config = parseNodeConfig(p, {}, "r1");
  ASSERT_EQ(config.monitor.sources.size(), 1u);
  const app::SourceSpec& robots = config.monitor.sources[0];
  EXPECT_EQ(robots.type, app::SourceType::Robots);
  EXPECT_EQ(robots.topic, "/site/footprints") << "fleet/topic by default";
  EXPECT_EQ(robots.timeout_s, app::kDefaultRobotsTimeoutS);
  EXPECT_FALSE(robots.required);
  EXPECT_FALSE(app::watchesSilence(robots)) << "robots leave: no INCOMPLETE by default";
  p["sources"][0]["required"] = true;
  p["sources"][0]["timeout"] = 2.0;
  const NodeConfig required = parseNodeConfig(p, {}, "r1");
  EXPECT_TRUE(app::watchesSilence(required.monitor.sources[0]));
  EXPECT_EQ(required.monitor.sources[0].timeout_s, 2.0);
  p["sources"][0]["timeout"] = 0.0;
  EXPECT_CONTAINS(errorOf(p), "key 'sources[0].timeout': expected a number within (0, 3600]");
  p["sources"][0]["timeout"] = 1.0;
  p["sources"][0]["min_radius"] = 0.1;
  EXPECT_CONTAINS(errorOf(p), "key 'sources[0].min_radius'");
  XmlRpcValue scan = validParams();
  scan["sources"][0] = sourceEntry("front_scan", "scan", "front/scan");
  scan["sources"][0]["required"] = true;
  EXPECT_CONTAINS(errorOf(scan), "key 'sources[0].required'") << "robots sources only";
}

TEST(SourceParams, ARobotsSourcesPaddingIsReadInMetresAndRefusedOutsideItsRange) {
  XmlRpcValue p = validParams();
  p["sources"][0]["name"] = "fleet";
  p["sources"][0]["type"] = "robots";
  EXPECT_EQ(parseNodeConfig(p, {}, "r1").monitor.sources[0].padding_m, 0.0) << "default";
  p["sources"][0]["padding"] = 0.12;
  EXPECT_EQ(parseNodeConfig(p, {}, "r1").monitor.sources[0].padding_m, 0.12);
  p["sources"][0]["padding"] = -0.1;
  EXPECT_CONTAINS(errorOf(p),
                  "key 'sources[0].padding': expected a number within [0, 10], got -0.1");
  p["sources"][0]["padding"] = std::nan("");
  EXPECT_CONTAINS(errorOf(p), "key 'sources[0].padding'");
  EXPECT_CONTAINS(errorOf(p), "nan");
  p["sources"][0]["padding"] = "wide";
  EXPECT_CONTAINS(errorOf(p), "key 'sources[0].padding'");
  XmlRpcValue scan = validParams();
  scan["sources"][0] = sourceEntry("front_scan", "scan", "front/scan");
  scan["sources"][0]["padding"] = 0.1;
  EXPECT_CONTAINS(errorOf(scan), "key 'sources[0].padding'") << "robots sources only";
}

}  // namespace
}  // namespace ellipse_collision
