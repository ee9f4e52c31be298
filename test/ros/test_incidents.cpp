// The incident recorder through the real node (incidents.test): a provoked STOP is written to a
// bag under incident/directory with the decisions around it and what they judged, and its replay
// reproduces every decision (braking on); ~save_incident writes one; max_files is kept; an
// unwritable directory warns and gating goes on.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <std_msgs/String.h>
#include <std_srvs/Trigger.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/GateState.h"
#include "ellipse_collision/RecordedDecision.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace {

namespace fs = std::filesystem;
using test::waitUntil;

const std::string kNode = "/ellipse_collision/";
const std::string kUnwritable = "/ellipse_collision_unwritable/";

std::vector<std::string> bagsIn(const std::string& directory) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory, ec)) {
    if (entry.path().extension() == ".bag") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class Incidents : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ros::param::get("/incident_directory", directory_));
    for (const std::string& node : {kNode, kUnwritable}) {
      cmd_pubs_.push_back(nh_.advertise<geometry_msgs::Twist>(node + "cmd_vel_in", 10));
      out_subs_.push_back(nh_.subscribe<geometry_msgs::Twist>(
          node + "cmd_vel_out", 100, [this, node](const geometry_msgs::Twist::ConstPtr&) {
            std::lock_guard<std::mutex> lock(mutex_);
            ++outputs_[node == kNode ? 0 : 1];
          }));
    }
    state_sub_ =
        nh_.subscribe<GateState>(kNode + "gate_state", 100, [this](const GateState::ConstPtr& msg) {
          std::lock_guard<std::mutex> lock(mutex_);
          actions_.push_back(msg->action);
        });
    diagnostics_sub_ = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 10, [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const auto& status : msg->status) {
            if (status.name == "/ellipse_collision_unwritable: incident recorder") {
              unwritable_status_ = status;
            }
          }
        });
    for (std::size_t i = 0; i < 2; ++i) {
      ASSERT_TRUE(waitUntil([&] { return cmd_pubs_[i].getNumSubscribers() > 0; }, 30.0));
      ASSERT_TRUE(waitUntil([&] { return out_subs_[i].getNumPublishers() > 0; }, 30.0));
    }
    ASSERT_TRUE(waitUntil([&] { return state_sub_.getNumPublishers() > 0; }, 30.0));
  }

  /// Sends `speed` forward to node `i` and waits for its ~cmd_vel_out.
  bool command(std::size_t i, double speed) {
    std::size_t before;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      before = outputs_[i];
    }
    geometry_msgs::Twist twist;
    twist.linear.x = speed;
    cmd_pubs_[i].publish(twist);
    return waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          return outputs_[i] > before;
        },
        5.0);
  }

  std_srvs::Trigger::Response saveIncident(const std::string& node) {
    ros::ServiceClient client = nh_.serviceClient<std_srvs::Trigger>(node + "save_incident");
    EXPECT_TRUE(client.waitForExistence(ros::Duration(30.0)));
    std_srvs::Trigger call;
    EXPECT_TRUE(client.call(call));
    return call.response;
  }

  ros::NodeHandle nh_;
  std::string directory_;
  std::vector<ros::Publisher> cmd_pubs_;
  std::vector<ros::Subscriber> out_subs_;
  ros::Subscriber state_sub_;
  ros::Subscriber diagnostics_sub_;
  std::mutex mutex_;
  std::size_t outputs_[2] = {0, 0};
  std::vector<std::string> actions_;
  std::optional<diagnostic_msgs::DiagnosticStatus> unwritable_status_;
};

TEST_F(Incidents, StopIsWrittenWithWhatTheGateJudged) {
  // Standing still passes; driving at the wall 0.2 m ahead at 1 m/s stops (contact in 0.2 s).
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(command(0, 0.0));
    ros::WallDuration(0.05).sleep();
  }
  // Creeping toward it passes: the base's velocity is then not zero when the stop comes.
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(command(0, 0.05));
    ros::WallDuration(0.05).sleep();
  }
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(command(0, 1.0));
    ros::WallDuration(0.05).sleep();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ASSERT_NE(std::find(actions_.begin(), actions_.end(), "STOP"), actions_.end());
  }
  // Then 0.5 s after it (incident/after), and the bag appears.
  for (int i = 0; i < 8; ++i) {
    ASSERT_TRUE(command(0, 0.0));
    ros::WallDuration(0.1).sleep();
  }
  std::vector<std::string> bags;
  ASSERT_TRUE(waitUntil(
      [&] {
        bags = bagsIn(directory_);
        return !bags.empty();
      },
      10.0))
      << "no bag in " << directory_;
  ASSERT_EQ(bags.size(), 1u);
  EXPECT_NE(bags[0].find("_STOP.bag"), std::string::npos) << bags[0];

  rosbag::Bag bag(directory_ + "/" + bags[0], rosbag::bagmode::Read);
  std::string settings;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery("settings"))) {
    settings = m.instantiate<std_msgs::String>()->data;
  }
  EXPECT_NE(settings.find("trigger: 'STOP'"), std::string::npos) << settings;
  EXPECT_NE(settings.find("stop_time: 0.29999999999999999"), std::string::npos) << settings;

  std::vector<RecordedDecision> decisions;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery("decisions"))) {
    decisions.push_back(*m.instantiate<RecordedDecision>());
  }
  ASSERT_GE(decisions.size(), 8u);
  // Oldest first: passes before the stop, the stop with its limiting pair, and decisions after.
  const auto stop = std::find_if(decisions.begin(), decisions.end(), [](const RecordedDecision& d) {
    return d.decision.action == "STOP";
  });
  ASSERT_NE(stop, decisions.end());
  EXPECT_NE(stop, decisions.begin());
  EXPECT_EQ(decisions.front().decision.action, "PASS");
  EXPECT_EQ(stop->decision.link, "body");
  EXPECT_EQ(stop->decision.obstacle, "wall");
  EXPECT_DOUBLE_EQ(stop->decision.input.linear.x, 1.0);
  EXPECT_DOUBLE_EQ(stop->decision.output.linear.x, 0.0);
  EXPECT_TRUE(stop->decision.contact_predicted);
  EXPECT_NEAR(stop->decision.time_to_contact, 0.2, 0.02);
  EXPECT_GT(decisions.back().header.stamp, stop->header.stamp);
  EXPECT_GE((stop->header.stamp - decisions.front().header.stamp).toSec(), 0.1);
  // The scene: the placed link and the wall, written once (the first decision) for the set.
  EXPECT_TRUE(stop->judged_scene);
  ASSERT_EQ(stop->links.ellipses.size(), 1u);
  EXPECT_EQ(stop->links.ellipses[0].name, "body");
  EXPECT_DOUBLE_EQ(stop->links.ellipses[0].radius_x, 0.3);
  EXPECT_TRUE(decisions.front().obstacles_changed);
  ASSERT_EQ(decisions.front().obstacles.ellipses.size(), 1u);
  EXPECT_EQ(decisions.front().obstacles.ellipses[0].name, "wall");
  EXPECT_DOUBLE_EQ(decisions.front().obstacles.ellipses[0].x, 0.7);
  for (std::size_t i = 1; i < decisions.size(); ++i) {
    EXPECT_FALSE(decisions[i].obstacles_changed) << i;
    EXPECT_TRUE(decisions[i].obstacles.ellipses.empty()) << i;
    EXPECT_EQ(decisions[i].obstacle_set, decisions.front().obstacle_set) << i;
  }
  ASSERT_FALSE(stop->source_names.empty());
  EXPECT_EQ(stop->source_names[0], "obstacles");
  EXPECT_EQ(stop->header.frame_id, "base_link");
  bag.close();

  // The replay judges every decision the gate's rules judged again from the bag alone, with the
  // braking rule on and the base moving: all reproduced bit for bit.
  EXPECT_NE(settings.find("max_linear_deceleration: 1.5"), std::string::npos) << settings;
  std::size_t by_rules = 0;
  bool from_moving_base = false;
  for (const RecordedDecision& d : decisions) {
    by_rules += d.judged_by_rules;
    from_moving_base |= d.judged_by_rules && d.base_velocity.linear.x > 0.0;
  }
  EXPECT_TRUE(stop->judged_by_rules);
  EXPECT_TRUE(from_moving_base);
  const test::CommandRun replay = test::runCommand(
      "rosrun ellipse_collision incident_report --replay " + directory_ + "/" + bags[0], 30);
  EXPECT_EQ(replay.exit_status, 0) << replay.output;
  std::cout << replay.output;  // the summary in the test's log
  const std::string all = std::to_string(by_rules);
  EXPECT_NE(replay.output.find("replay: " + all + " of " + all + " decisions reproduced"),
            std::string::npos)
      << replay.output;

  // ~save_incident writes one at once; with max_files 2 the oldest goes.
  std_srvs::Trigger::Response answer = saveIncident(kNode);
  EXPECT_TRUE(answer.success) << answer.message;
  EXPECT_NE(answer.message.find(directory_), std::string::npos) << answer.message;
  ASSERT_TRUE(waitUntil([&] { return bagsIn(directory_).size() == 2; }, 10.0));
  EXPECT_NE(bagsIn(directory_)[1].find("_REQUESTED.bag"), std::string::npos);
  ros::WallDuration(0.01).sleep();
  answer = saveIncident(kNode);
  EXPECT_TRUE(answer.success) << answer.message;
  const std::string newest = fs::path(answer.message.substr(answer.message.find('/'))).filename();
  ASSERT_TRUE(waitUntil(
      [&] {
        const std::vector<std::string> now = bagsIn(directory_);
        return std::find(now.begin(), now.end(), newest) != now.end();
      },
      10.0));
  ros::WallDuration(0.2).sleep();  // the budget is kept right after the bag is written
  bags = bagsIn(directory_);
  EXPECT_EQ(bags.size(), 2u);
  EXPECT_EQ(bags.back(), newest);
  for (const std::string& name : bags) EXPECT_EQ(name.find("_STOP.bag"), std::string::npos) << name;
  std::error_code ec;
  fs::remove_all(directory_, ec);
}

TEST_F(Incidents, UnwritableDirectoryWarnsAndGatingGoesOn) {
  ASSERT_TRUE(command(1, 0.0));
  ASSERT_TRUE(command(1, 1.0));  // a STOP: an incident it cannot write
  const std_srvs::Trigger::Response answer = saveIncident(kUnwritable);
  EXPECT_TRUE(answer.success) << answer.message;
  ASSERT_TRUE(waitUntil(
      [&] {
        std::lock_guard<std::mutex> lock(mutex_);
        return unwritable_status_ &&
               unwritable_status_->level == diagnostic_msgs::DiagnosticStatus::WARN;
      },
      10.0));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    EXPECT_NE(unwritable_status_->message.find("/dev/null/incidents"), std::string::npos)
        << unwritable_status_->message;
  }
  // The gate still answers every command.
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(command(1, 0.0));
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_incidents");
}
