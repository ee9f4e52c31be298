// rostest client: starts the node binary with bad configurations and checks that it exits with
// status 1 and a message naming the entry and the key. Each case spoils a copy of the shared scene
// (test_scene.yaml, loaded under /good_config by bad_config.test) and runs the node under its own
// name, so that its private namespace holds exactly that copy.
#include <functional>
#include <limits>

#include "node_test_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

using XmlRpc::XmlRpcValue;

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

/// Runs the node as /<name> for at most `seconds`, with stdout and stderr captured.
CommandRun runNode(const std::string& name, int seconds) {
  return runCommand(std::string(ELLIPSE_COLLISION_NODE_BIN) + " __name:=" + name, seconds);
}

XmlRpcValue goodConfig() {
  XmlRpcValue config;
  EXPECT_TRUE(ros::param::get("/good_config", config)) << "bad_config.test loads /good_config";
  return config;
}

/// Sets a spoiled copy of the good configuration as /<name> and runs the node with it.
CommandRun runWith(const std::string& name, const std::function<void(XmlRpcValue&)>& spoil,
                   int seconds = 30) {
  XmlRpcValue config = goodConfig();
  spoil(config);
  ros::param::del("/" + name);
  ros::param::set("/" + name, config);
  return runNode(name, seconds);
}

/// The entry whose name is `name` in a configuration read from the shared YAML.
XmlRpcValue& entryNamed(XmlRpcValue& list, const std::string& name) {
  for (int i = 0; i < list.size(); ++i) {
    if (static_cast<std::string&>(list[i]["name"]) == name) return list[i];
  }
  ADD_FAILURE() << "no entry " << name;
  return list[0];
}

TEST(BadConfig, GoodConfigurationKeepsTheNodeRunning) {
  // The control case: the harness does tell a running node from one that stopped.
  const CommandRun run = runWith(
      "good_node", [](XmlRpcValue&) {}, 4);
  EXPECT_EQ(run.exit_status, 124) << run.output;
}

TEST(BadConfig, MissingLinksStopsTheNode) {
  XmlRpcValue empty;
  empty["rate"] = 1.0;
  ros::param::set("/bad_missing_links", empty);
  const CommandRun run = runNode("bad_missing_links", 30);
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output, "parameter ~links");
}

TEST(BadConfig, MissingKeyNamesEntryAndKey) {
  const CommandRun run = runWith("bad_missing_key", [](XmlRpcValue& c) {
    XmlRpcValue& arm = entryNamed(c["links"], "arm");
    XmlRpcValue without;
    for (auto it = arm.begin(); it != arm.end(); ++it) {
      if (it->first != "radius_y") without[it->first] = it->second;
    }
    arm = without;
  });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output, "links[2] (name 'arm'): missing key 'radius_y'");
}

TEST(BadConfig, WrongTypeNamesEntryKeyExpectedAndActual) {
  const CommandRun run =
      runWith("bad_type", [](XmlRpcValue& c) { entryNamed(c["obstacles"], "crate")["x"] = "two"; });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output,
                  "obstacles[0] (name 'crate'), key 'x': expected a number, got 'two' (a string)");
}

TEST(BadConfig, NonPositiveRadiusStopsTheNode) {
  const CommandRun run = runWith(
      "bad_radius", [](XmlRpcValue& c) { entryNamed(c["links"], "body")["radius_x"] = -0.5; });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output,
                  "links[0] (name 'body'), key 'radius_x': expected a finite number > 0, got -0.5");
}

TEST(BadConfig, NanStopsTheNode) {
  const CommandRun run = runWith("bad_nan", [](XmlRpcValue& c) {
    entryNamed(c["links"], "plate")["angle"] = std::numeric_limits<double>::quiet_NaN();
  });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output,
                  "links[3] (name 'plate'), key 'angle': expected a finite number, got nan");
}

TEST(BadConfig, DuplicateNameStopsTheNode) {
  const CommandRun run = runWith(
      "bad_duplicate", [](XmlRpcValue& c) { entryNamed(c["obstacles"], "spare")["name"] = "arm"; });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output, "obstacles[3] (name 'arm'), key 'name'");
  EXPECT_CONTAINS(run.output, "duplicate of links[2]");
}

TEST(BadConfig, UnknownAllowedPairNameStopsTheNode) {
  const CommandRun run =
      runWith("bad_pair", [](XmlRpcValue& c) { c["allowed_pairs"][0][1] = "bumpr"; });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output, "allowed_pairs[0][1] = 'bumpr'");
}

TEST(BadConfig, MisspelledParameterStopsTheNode) {
  const CommandRun run = runWith("bad_key", [](XmlRpcValue& c) { c["tf_timout"] = 0.1; });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output, "parameter ~tf_timout: unknown key");
}

TEST(BadConfig, NegativeRateStopsTheNode) {
  const CommandRun run = runWith("bad_rate", [](XmlRpcValue& c) { c["rate"] = -10; });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output,
                  "parameter ~rate, key 'rate': expected a finite number >= 0, got -10");
}

TEST(BadConfig, NegativeWarningDistanceStopsTheNode) {
  const CommandRun run =
      runWith("bad_warning", [](XmlRpcValue& c) { c["warning_distance"] = -0.05; });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output,
                  "parameter ~warning_distance, key 'warning_distance': expected a finite number "
                  ">= 0, got -0.05");
}

TEST(BadConfig, NanWarningDistanceStopsTheNode) {
  const CommandRun run = runWith("bad_warning_nan", [](XmlRpcValue& c) {
    c["warning_distance"] = std::numeric_limits<double>::quiet_NaN();
  });
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_CONTAINS(run.output,
                  "parameter ~warning_distance, key 'warning_distance': expected a finite number "
                  ">= 0, got nan");
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_bad_config");
}
