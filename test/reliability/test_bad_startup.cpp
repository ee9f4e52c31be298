// rostest client: bad configuration files, started the way a user starts the node, through the
// package's launch file: roslaunch <package>/launch/ellipse_collision.launch config:=FILE
// (by path, so that the test does not depend on how the workspace links the package).
// Each file in bad_config/ spoils one thing of good.yaml; the node must stop at start-up with
// exit status 1 and a message naming the entry and the key. These are the cases beyond
// test/ros/test_bad_config.cpp (which sets parameters directly): YAML's own pitfalls, values
// that are finite and positive yet outside what the core or ros::Duration can take, and wrong
// shapes of the lists.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <string>
#include <vector>

#include "reliability_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

struct BadFile {
  const char* file;                  ///< in test/reliability/bad_config/, without .yaml
  std::vector<const char*> message;  ///< parts the node's output must contain
};

std::ostream& operator<<(std::ostream& out, const BadFile& c) { return out << c.file; }

/// roslaunch's line for a process that ended: "process has died [pid N, exit code C, cmd ...]".
int exitCodeOf(const std::string& output) {
  const std::string marker = "exit code ";
  const std::size_t at = output.find(marker);
  if (at == std::string::npos) return -1000;  // never died
  return std::stoi(output.substr(at + marker.size()));
}

CommandRun launch(const std::string& file, const std::string& node_name, int seconds) {
  const std::string source = ELLIPSE_COLLISION_SOURCE_DIR;
  const std::string path = source + "/test/reliability/bad_config/" + file + ".yaml";
  return runCommand("roslaunch " + source + "/launch/ellipse_collision.launch config:=" + path +
                        " node_name:=" + node_name,
                    seconds);
}

TEST(BadStartup, GoodFileKeepsTheNodeRunning) {
  // The control case: the harness tells a running node from one that stopped.
  const CommandRun run = launch("good", "good_startup", 8);
  EXPECT_EQ(run.exit_status, 124) << run.output;
  EXPECT_EQ(exitCodeOf(run.output), -1000) << run.output;
}

class BadStartup : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadStartup, NodeStopsWithExitStatus1NamingEntryAndKey) {
  const BadFile& c = GetParam();
  const CommandRun run = launch(c.file, std::string("bad_") + c.file, 20);
  EXPECT_NE(run.exit_status, 124) << "the node kept running:\n" << run.output;
  EXPECT_EQ(exitCodeOf(run.output), 1) << run.output;
  EXPECT_NE(run.output.find("invalid configuration"), std::string::npos) << run.output;
  for (const char* part : c.message) {
    EXPECT_NE(run.output.find(part), std::string::npos) << "missing '" << part << "' in:\n"
                                                        << run.output;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Files, BadStartup,
    ::testing::Values(
        BadFile{"scientific_without_dot",
                {"links[1] (name 'arm'), key 'radius_x'", "'1e-3' (a string)"}},
        BadFile{"yaml_nan", {"obstacles[0] (name 'crate'), key 'radius_y'", "nan"}},
        BadFile{"radius_below_core_range", {"links[0] (name 'body'), key 'radius_x'", "1e-12"}},
        BadFile{"radius_above_core_range", {"links[0] (name 'body'), key 'radius_y'", "1e+12"}},
        BadFile{"padding_beyond_core_range", {"parameter ~padding"}},
        BadFile{"rate_too_low", {"parameter ~rate"}}, BadFile{"rate_too_high", {"parameter ~rate"}},
        BadFile{"tf_timeout_too_long", {"parameter ~tf_timeout"}},
        BadFile{"links_not_a_list", {"parameter ~links", "a dict"}},
        BadFile{"entry_not_a_dict", {"links[1]", "'arm' (a string)"}},
        BadFile{"allowed_pair_of_three", {"allowed_pairs[0]", "two names"}},
        BadFile{"self_collision_not_bool", {"parameter ~self_collision", "1 (an int)"}},
        BadFile{"frame_with_slash", {"links[0] (name 'body'), key 'frame'", "'/base_link'"}},
        BadFile{"unknown_entry_key", {"obstacles[0] (name 'crate')", "unknown key 'radius'"}},
        BadFile{"empty", {"parameter ~links"}},
        BadFile{"urdf_param_missing",
                {"parameter ~links_from_urdf", "parameter 'no_such_robot_description'"}}),
    [](const ::testing::TestParamInfo<BadFile>& info) { return std::string(info.param.file); });

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_bad_startup");
  ros::NodeHandle nh;  // roslaunch below uses the master rostest started
  return RUN_ALL_TESTS();
}
