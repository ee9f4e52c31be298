// The nodelet pipeline as a user sees it (test/ros/scan_pipeline_nodelets.test, whose client also
// runs test_scan_obstacles.cpp): both nodelets live in the one manager, which alone publishes and
// subscribes the obstacle ellipses between them (rostopic info's view); a nodelet with a bad
// configuration is refused with a message naming the key, `nodelet load` exits with status 255
// (what stops a launch that requires it), and the manager goes on serving the pipeline.
#include <gtest/gtest.h>
#include <nodelet/NodeletList.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>

#include <algorithm>
#include <mutex>
#include <string>
#include <vector>

#include "node_test_utils.h"

namespace ellipse_collision {
namespace {

const char* const kManager = "/scan_pipeline_manager";

std::vector<std::string> loadedNodelets() {
  nodelet::NodeletList list;
  EXPECT_TRUE(ros::service::call(std::string(kManager) + "/list", list)) << "no manager";
  return list.response.nodelets;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

/// The nodes the master lists as publishers (`publishers` true) or subscribers of `topic`.
std::vector<std::string> topicNodes(const std::string& topic, bool publishers) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  EXPECT_TRUE(ros::master::execute("getSystemState", request, response, payload, true));
  std::vector<std::string> nodes;
  XmlRpc::XmlRpcValue& entries = payload[publishers ? 0 : 1];
  for (int i = 0; i < entries.size(); ++i) {
    if (static_cast<std::string&>(entries[i][0]) != topic) continue;
    for (int j = 0; j < entries[i][1].size(); ++j) {
      nodes.push_back(static_cast<std::string&>(entries[i][1][j]));
    }
  }
  return nodes;
}

TEST(ScanPipelineNodelets, BothNodeletsRunInOneManagerThatCarriesTheObstacles) {
  ASSERT_TRUE(ros::service::waitForService(std::string(kManager) + "/list", ros::Duration(30)));
  ASSERT_TRUE(test::waitUntil(
      [] {
        const std::vector<std::string> loaded = loadedNodelets();
        return contains(loaded, "/ellipse_collision") && contains(loaded, "/scan_obstacles");
      },
      30.0))
      << "the manager did not load /ellipse_collision and /scan_obstacles";
  const std::string obstacles = test::nodeTopic("obstacles");
  EXPECT_EQ(topicNodes(obstacles, true), std::vector<std::string>{kManager});
  EXPECT_TRUE(contains(topicNodes(obstacles, false), kManager));
  EXPECT_TRUE(contains(topicNodes("/scan", false), kManager));
}

/// Loads `type` as /`name` (its parameters already set) into the manager, as a launch file's
/// `nodelet load` node does, and expects it refused: exit status 255, a fatal log naming the
/// nodelet and containing `key`, and the nodelet not in the manager.
void expectRefused(const std::string& type, const std::string& name, const std::string& key) {
  ros::NodeHandle nh;
  std::mutex mutex;
  std::vector<std::string> fatal;
  ros::Subscriber log_sub = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 100, [&](const rosgraph_msgs::Log::ConstPtr& log) {
        std::lock_guard<std::mutex> lock(mutex);
        if (log->level == rosgraph_msgs::Log::FATAL) fatal.push_back(log->msg);
      });
  ros::AsyncSpinner spinner(1);
  spinner.start();
  // Every node publishes /rosout; the manager's fatal log reaches this subscriber only once it is
  // connected to the manager itself, so wait for a connection to each publisher the master lists.
  ASSERT_TRUE(test::waitUntil(
      [&] {
        const std::vector<std::string> publishers = topicNodes("/rosout", true);
        return contains(publishers, kManager) && log_sub.getNumPublishers() >= publishers.size();
      },
      10.0))
      << log_sub.getNumPublishers() << " of " << topicNodes("/rosout", true).size()
      << " /rosout publishers connected";

  const test::CommandRun run = test::runCommand(
      "rosrun nodelet nodelet load " + type + " " + kManager + " __name:=" + name, 60);
  EXPECT_EQ(run.exit_status, 255) << run.output;
  const std::string expected = "/" + name + ": invalid configuration: ";
  const bool logged = test::waitUntil(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return std::any_of(fatal.begin(), fatal.end(), [&](const std::string& msg) {
          return msg.find(expected) != std::string::npos && msg.find(key) != std::string::npos;
        });
      },
      10.0);
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_TRUE(logged) << "no fatal log '" << expected << "...' naming " << key << "; "
                      << fatal.size() << " fatal logs";
  EXPECT_FALSE(contains(loadedNodelets(), "/" + name));
}

TEST(ScanPipelineNodelets, BadConfigurationIsRefusedAndTheManagerKeepsServing) {
  ASSERT_TRUE(ros::service::waitForService(test::nodeTopic("check_collisions"), ros::Duration(30)));
  XmlRpc::XmlRpcValue no_links;
  no_links["rate"] = 1.0;
  ros::param::set("/bad_collision", no_links);
  expectRefused("ellipse_collision/CollisionNodelet", "bad_collision", "parameter ~links");
  ros::param::set("/bad_scan/min_radius", -1.0);
  expectRefused("ellipse_collision/ScanObstaclesNodelet", "bad_scan", "min_radius");

  // The manager, and the pipeline in it, go on.
  const std::vector<std::string> loaded = loadedNodelets();
  EXPECT_TRUE(contains(loaded, "/ellipse_collision"));
  EXPECT_TRUE(contains(loaded, "/scan_obstacles"));
  test::NodeServiceClient client;
  ros::NodeHandle nh;
  client.connectServices(nh);
  EXPECT_TRUE(client.check().success);
}

}  // namespace
}  // namespace ellipse_collision
