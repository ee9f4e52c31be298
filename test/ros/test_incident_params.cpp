// params::readIncident() (src/ros/incident_params.cpp): the `incident` dict's keys, types and
// defaults, and every refusal naming the key and the value; no ROS master needed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/ros/param_sections.h"
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

TEST(IncidentParams, NumberKeysRefuseNaNInfinityNegativeAndHugeValuesNamingKeyAndValue) {
  const std::pair<double, const char*> bad[] = {
      {kNaN, "got nan"}, {kInf, "got inf"}, {-1.0, "got -1"}, {1e12, "got 1e+12"}};
  for (const char* key : {"before", "after", "min_interval", "max_megabytes", "max_files"}) {
    for (const auto& [number, actual] : bad) {
      XmlRpcValue value;
      value[key] = number;
      const std::string refusal = refusalOf([&] { params::readIncident(value); });
      EXPECT_CONTAINS(refusal,
                      "parameter ~incident, key 'incident/" + std::string(key) + "': expected ");
      EXPECT_CONTAINS(refusal, actual);
    }
  }
}

TEST(IncidentParams, WrongTypesNameTheKeyExpectedAndActual) {
  XmlRpcValue value;
  value["directory"] = 3;
  EXPECT_EQ(refusalOf([&] { params::readIncident(value); }),
            "parameter ~incident, key 'incident/directory': expected a string, got 3 (an int)");
  value = XmlRpcValue();
  value["enabled"] = "yes";
  EXPECT_EQ(refusalOf([&] { params::readIncident(value); }),
            "parameter ~incident, key 'incident/enabled': expected true or false, got 'yes' (a "
            "string)");
  value = XmlRpcValue();
  value["actions"] = "STOP";
  EXPECT_EQ(refusalOf([&] { params::readIncident(value); }),
            "parameter ~incident, key 'incident/actions': expected a list of gate actions, got "
            "'STOP' (a string)");
  value = XmlRpcValue();
  value["actions"][0] = "STOP";
  value["actions"][1] = 2;
  EXPECT_EQ(refusalOf([&] { params::readIncident(value); }),
            "parameter ~incident, key 'incident/actions[1]': expected a string, got 2 (an int)");
  value = XmlRpcValue();
  value["actions"].setSize(0);
  EXPECT_EQ(refusalOf([&] { params::readIncident(value); }),
            "parameter ~incident, key 'incident/actions': expected a non-empty list of gate "
            "actions, got []");
  value = XmlRpcValue();
  value["max_files"] = 0;
  EXPECT_CONTAINS(refusalOf([&] { params::readIncident(value); }),
                  "key 'incident/max_files': expected ");
  EXPECT_CONTAINS(refusalOf([&] { params::readIncident(value); }), "got 0");
}

TEST(IncidentParams, TheBoundsAreAcceptedAndReadBack) {
  XmlRpcValue value;
  value["before"] = app::kMaxIncidentWindowS;
  value["after"] = 0;
  value["min_interval"] = app::kMaxIncidentIntervalS;
  value["max_files"] = 1;
  value["max_megabytes"] = app::kMaxIncidentMegabytes;
  const app::IncidentSettings read = params::readIncident(value);
  EXPECT_EQ(read.before_s, app::kMaxIncidentWindowS);
  EXPECT_EQ(read.after_s, 0.0);
  EXPECT_EQ(read.min_interval_s, app::kMaxIncidentIntervalS);
  EXPECT_EQ(read.max_files, 1u);
  EXPECT_EQ(read.max_megabytes, app::kMaxIncidentMegabytes);
}

TEST(IncidentParams, TheIncidentRecorderIsOnByDefaultAndItsKeysAreReadAndChecked) {
  const app::IncidentSettings defaults = parseNodeConfig(validParams()).monitor.incident;
  EXPECT_TRUE(defaults.enabled);
  EXPECT_EQ(defaults.actions.size(), 4u);
  EXPECT_EQ(defaults.directory, "");
  XmlRpcValue p = validParams();
  p["incident"]["enabled"] = false;
  p["incident"]["before"] = 5;
  p["incident"]["after"] = 1.5;
  p["incident"]["min_interval"] = 0.0;
  p["incident"]["max_files"] = 3;
  p["incident"]["max_megabytes"] = 50.0;
  p["incident"]["directory"] = "/var/incidents";
  p["incident"]["actions"][0] = "STOP";
  p["incident"]["actions"][1] = "SLOW";
  const app::IncidentSettings read = parseNodeConfig(p).monitor.incident;
  EXPECT_FALSE(read.enabled);
  EXPECT_EQ(read.before_s, 5.0);
  EXPECT_EQ(read.after_s, 1.5);
  EXPECT_EQ(read.min_interval_s, 0.0);
  EXPECT_EQ(read.max_files, 3u);
  EXPECT_EQ(read.max_megabytes, 50.0);
  EXPECT_EQ(read.directory, "/var/incidents");
  EXPECT_EQ(read.actions,
            (std::vector<core::GateAction>{core::GateAction::Stop, core::GateAction::Slow}));

  p["incident"]["actions"][1] = "HALT";
  EXPECT_EQ(errorOf(p),
            "parameter ~incident, key 'incident/actions': expected gate actions among PASS, SLOW, "
            "STOP, ESCAPE, TIMEOUT, INCOMPLETE, DISABLED, got 'HALT'");
  p["incident"]["actions"][1] = "STOP";
  EXPECT_NE(errorOf(p).find("'STOP' twice"), std::string::npos) << errorOf(p);
  p["incident"]["actions"][1] = "SLOW";
  p["incident"]["max_files"] = 2.5;
  EXPECT_NE(errorOf(p).find("key 'incident/max_files': expected a whole number"), std::string::npos)
      << errorOf(p);
  p["incident"]["max_files"] = 3;
  p["incident"]["before"] = 0.0;
  EXPECT_EQ(errorOf(p),
            "parameter ~incident, key 'incident/before': expected a number within (0, 600], got 0");
  p["incident"]["before"] = std::numeric_limits<double>::infinity();
  EXPECT_NE(errorOf(p).find("key 'incident/before'"), std::string::npos) << errorOf(p);
  p["incident"]["before"] = 5;
  p["incident"]["afterwards"] = 1.0;
  EXPECT_NE(errorOf(p).find("parameter ~incident/afterwards: unknown key"), std::string::npos)
      << errorOf(p);
  XmlRpcValue q = validParams();
  q["incident"] = "on";
  EXPECT_NE(errorOf(q).find("expected a dict of incident parameters"), std::string::npos)
      << errorOf(q);
}

}  // namespace
}  // namespace ellipse_collision
